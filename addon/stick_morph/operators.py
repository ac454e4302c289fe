"""The bake operator: object.stick_morph_bake.

All checks (selection, faces, vertex counts, edge sets, planarity, the
engine's validation and compatibility) and the morph itself run before any
data is created, so that an error leaves the scene exactly as it was;
building the result is wrapped so that a failure removes what it created.
"""

import time

import bpy
from bpy.props import BoolProperty, IntProperty, StringProperty

from . import baking, core
from .preferences import OPTION_NAMES, addon_preferences, option_properties


def _resolve(context, source_name, target_name):
    """The source and target objects. Raises core.StickMorphError."""
    def named(name, role):
        obj = bpy.data.objects.get(name)
        if obj is None:
            raise core.StickMorphError(f"there is no object named '{name}' ({role})")
        return obj

    if source_name or target_name:
        if not (source_name and target_name):
            raise core.StickMorphError("give both source and target, or neither (then the "
                                       "selection is used)")
        source, target = named(source_name, "source"), named(target_name, "target")
    else:
        selected = list(context.selected_objects)
        active = context.active_object
        if len(selected) != 2 or active not in selected:
            raise core.StickMorphError(
                f"select two mesh objects, the target last (active); {len(selected)} selected"
                + ("" if active in selected or not selected else ", none of them active"))
        target = active
        source = selected[0] if selected[1] == active else selected[1]
    for obj, role in ((source, "source"), (target, "target")):
        if obj.type != "MESH":
            raise core.StickMorphError(
                f"not two mesh objects: the {role} '{obj.name}' is a {obj.type.lower()}, not a mesh")
    if source == target:
        raise core.StickMorphError(f"source and target are the same object '{source.name}'")
    return source, target


class STICKMORPH_OT_bake(bpy.types.Operator):
    """Bake a self-intersection-free morph between two edge meshes (source, then target active) into a new object with shape keys"""
    bl_idname = "object.stick_morph_bake"
    bl_label = "Bake Stick Morph"
    bl_options = {"REGISTER", "UNDO"}

    __annotations__ = {
        "source": StringProperty(name="Source", description="Source object name (empty: the selected non-active mesh)"),
        "target": StringProperty(name="Target", description="Target object name (empty: the active object)"),
        "frame_start": IntProperty(name="Start Frame", description="Frame showing the source", default=1),
        **option_properties(),
    }

    @classmethod
    def poll(cls, context):
        if context.scene is None:
            cls.poll_message_set("No scene to bake into")
            return False
        if context.mode != "OBJECT":
            cls.poll_message_set("Switch to Object Mode to bake a Stick Morph")
            return False
        return True

    def _apply_preferences(self, context):
        prefs = addon_preferences(context)
        if prefs is None:
            return
        for name in OPTION_NAMES:
            if not self.properties.is_property_set(name):
                setattr(self, name, getattr(prefs, name))

    def execute(self, context):
        self._apply_preferences(context)
        wm = context.window_manager
        wm.progress_begin(0, 100)
        try:
            return self._bake(context, wm)
        except core.StickMorphError as error:
            self.report({"ERROR"}, f"Stick Morph: {error}")
            return {"CANCELLED"}
        finally:
            wm.progress_end()

    def _bake(self, context, wm):
        started = time.perf_counter()
        source, target = _resolve(context, self.source.strip(), self.target.strip())
        source_world, source_edges, source_faces = baking.mesh_world_data(source)
        target_world, target_edges, target_faces = baking.mesh_world_data(target)
        prepared = core.prepare_pair(source_world, source_edges, source_faces, source.name,
                                     target_world, target_edges, target_faces, target.name,
                                     plane=self.plane, planarity_tolerance=self.planarity_tolerance)
        core.check_pair(prepared, source.name, target.name)
        wm.progress_update(10)
        morph = core.compute_morph(prepared, self.frame_count, steiner=self.steiner, weights=self.weights,
                                   enclosure_sides=self.enclosure_sides, easing=self.easing,
                                   source_name=source.name, target_name=target.name)
        wm.progress_update(50)
        previous = baking.previous_results(source.name, target.name)
        count = self.frame_count

        def progress(k):
            wm.progress_update(50 + int(45 * k / max(count, 1)))

        try:
            result, created = baking.build_result(
                context, source, target, prepared, morph, frame_start=self.frame_start,
                renderable=self.renderable, tube_radius_factor=self.tube_radius,
                show_triangulation=self.show_triangulation, report_progress=progress)
        except Exception as error:  # build_result removed what it made
            raise core.StickMorphError(f"building the result failed: {error}") from error
        for obj in previous:
            baking.remove_result_object(obj)
        # With the previous result gone, the new one takes the plain names.
        for obj, name in created.names.items():
            if obj.name != name and name not in bpy.data.objects:
                obj.name = name
                obj.data.name = name
        if self.set_frame_range:
            context.scene.frame_start = self.frame_start
            context.scene.frame_end = self.frame_start + count - 1
        baking.select_only(context, result)
        milliseconds = (time.perf_counter() - started) * 1000.0
        steiner = int(morph.stats.get("steiner_vertices", 0))
        settings = getattr(context.scene, "stick_morph", None)
        if settings is not None:
            settings.last_result = result.name
            settings.last_vertices = len(prepared.source_xy)
            settings.last_steiner = steiner
            settings.last_frames = count
            settings.last_milliseconds = milliseconds
        self.report({"INFO"}, f"Stick Morph: '{result.name}': {len(prepared.source_xy)} vertices, "
                              f"{steiner} Steiner vertices, {count} frames, {milliseconds:.0f} ms")
        return {"FINISHED"}


classes = (STICKMORPH_OT_bake,)


register, unregister = bpy.utils.register_classes_factory(classes)
