"""The key-pose operators (issue 28), thin over sequence.py:

- object.stick_morph_bake_sequence: one morph through the selected edge
  meshes (or a collection's) as key poses, baked into one result object;
- object.stick_morph_rebake_shape_keys: the active mesh's pose-to-pose
  shape-key animation morphed through its poses, as a new object.

As with the pair bake, everything is read and checked, and the engine runs,
before any data is created; an error is an ERROR report with the scene
unchanged, and execute depends only on its properties and the file (redo).
Bake Key Poses runs modal from the GUI, cancellable with Esc, as the pair
bake does (operators.ModalBake).
"""

import json
import time

import bpy
from bpy.props import IntProperty, StringProperty

from .common import BakeSettings, StickMorphError, is_pin_group
from .operators import BakeExecute, ModalBake, show_in_status_bar
from .properties import (MESH_OPTIONS, REBAKE_OPTIONS, SEQUENCE_OPTIONS, key_pose_properties,
                         mesh_option_properties, option_properties)

KEY_FRAME_PROPERTY = "stick_morph_key_frame"
KEYS_TAG = "stick_morph_keys"  # a sequence result's keys, JSON, to replace it when rebaked
SEQUENCE_ROLE = "sequence_result"
REBAKE_ROLE = "rebake_result"


def _options(names):
    every = option_properties()
    return {name: every[name] for name in names}


def _settings(op, names, frame_start, **fixed):
    return BakeSettings(frame_start=frame_start, **{name: getattr(op, name) for name in names + MESH_OPTIONS},
                        **fixed)


def _finish(op, context, result, previous, created, settings, first_frame, frame_count, sequence, names,
            milliseconds, what, loop=False, stages=None):
    """Replaces the previous result, sets the frame range and the panel's
    last-bake box, makes the result active and reports per segment."""
    from . import baking, sequence as seq
    baking.replace_previous(previous, created)
    if settings.set_frame_range:
        context.scene.frame_start = first_frame
        # A loop's closing frame is its first pose again: the scene's range
        # stops one frame short, so that Blender's looping playback shows
        # that pose once per cycle (the closing frame stays baked).
        context.scene.frame_end = first_frame + frame_count - (2 if loop else 1)
    baking.select_only(context, result)
    vertices = sequence.frames_world.shape[1]
    steiner = sum(int(s.get("steiner_vertices", 0)) for s in sequence.segments)
    match = f"matched ({sequence.why})" if sequence.matched else "by index"
    if sequence.overlap is not None:
        match += (f"; local timing: the delay group '{settings.delay_group}' lags by {sequence.overlap:.3g} "
                  "of each segment")
    scene_settings = getattr(context.scene, "stick_morph", None)
    if scene_settings is not None:
        scene_settings.last_result = result.name
        scene_settings.last_vertices = vertices
        scene_settings.last_steiner = steiner
        scene_settings.last_frames = frame_count
        scene_settings.last_milliseconds = milliseconds
        scene_settings.last_motion = f"Rigid, {len(names)} keys"
        scene_settings.last_correspondence = "Matched" if sequence.matched else "By index"
        if stages is not None:
            scene_settings.last_stages = stages
    text = (f"Stick Morph: '{result.name}': {what} of {len(names)} keys, {vertices} vertices, "
            f"{len(sequence.segments)} segments, {steiner} Steiner vertices, {frame_count} frames "
            f"(frames {first_frame}-{first_frame + frame_count - 1}), {milliseconds:.0f} ms; {match}")
    op.report({"INFO"}, text)
    for line in seq.segment_summary(sequence, names, first_frame):
        op.report({"INFO"}, f"Stick Morph: {line}")
    show_in_status_bar(context, text)


class STICKMORPH_OT_bake_sequence(ModalBake, bpy.types.Operator):
    """Bake one morph through the selected edge meshes as key poses (ordered by name, or a collection's objects in its order) into a new object with shape keys, free of self-intersection"""
    bl_idname = "object.stick_morph_bake_sequence"
    bl_label = "Bake Key Poses"
    bl_options = {"REGISTER", "UNDO"}

    __annotations__ = {
        # SKIP_SAVE as the pair bake's source and target: a later call uses
        # its own selection; redo keeps the names this run resolved.
        "keys": StringProperty(name="Keys", options={"SKIP_SAVE"},
                               description="The key objects' names, a JSON list (empty: the selection or the collection)"),
        "collection": StringProperty(name="Collection", options={"SKIP_SAVE"},
                                     description="Take the mesh objects of this collection as the keys, in its "
                                                 "order (empty: the selected meshes, ordered by name)"),
        "frame_start": IntProperty(name="Start", options={"SKIP_SAVE"},
                                   description="Frame of the first key when the keys have no key frames of "
                                               "their own (not set: the scene's current frame)"),
        **key_pose_properties(),
        **_options(SEQUENCE_OPTIONS),
        **mesh_option_properties(),
    }

    preference_options = SEQUENCE_OPTIONS

    def draw(self, context):
        from . import ui
        ui.draw_key_pose_operator(self.layout, self, ("collection", "frame_start", "frame_step"), ("loop", "hold"),
                                  SEQUENCE_OPTIONS)

    def _key_objects(self, context):
        from . import baking, sequence
        if self.keys.strip():
            try:
                names = json.loads(self.keys)
                assert isinstance(names, list) and all(isinstance(n, str) for n in names)
            except (ValueError, AssertionError):
                raise StickMorphError(f"Keys must be a JSON list of object names, got {self.keys!r}") from None
            objects = []
            for name in names:
                obj = bpy.data.objects.get(name)
                if obj is None:
                    raise StickMorphError(f"there is no object named '{name}' (a key)")
                objects.append(obj)
        elif self.collection.strip():
            collection = bpy.data.collections.get(self.collection.strip())
            if collection is None:
                raise StickMorphError(f"there is no collection named '{self.collection.strip()}'")
            objects = [obj for obj in collection.objects if obj.type == "MESH"]
            if len(objects) < 2:
                raise StickMorphError(f"the collection '{collection.name}' holds {len(objects)} mesh "
                                      f"object{'' if len(objects) == 1 else 's'}; key poses need two or more")
        else:
            # An earlier bake's result is not a key, even if it is selected.
            selected = [obj for obj in context.selected_objects if baking.ROLE not in obj]
            objects = [selected[k] for k in sequence.order_by_name([obj.name for obj in selected])]
            if len(objects) < 2:
                raise StickMorphError(
                    f"select two or more edge meshes, the key poses (ordered by name); {len(objects)} selected"
                    + (f": '{objects[0].name}'" if objects else ""))
        for k, obj in enumerate(objects):
            if obj.type != "MESH":
                raise StickMorphError(f"key {k + 1} '{obj.name}' is a {obj.type.lower()}, not a mesh")
        if len({obj.name for obj in objects}) != len(objects):
            raise StickMorphError("an object is a key twice: " + ", ".join(f"'{obj.name}'" for obj in objects))
        return objects

    def start(self, context, progress):
        from . import baking, sequence

        self._started = time.perf_counter()
        objects = self._key_objects(context)
        names = [obj.name for obj in objects]
        self.keys = json.dumps(names)
        if not self.properties.is_property_set("frame_start"):
            self.frame_start = context.scene.frame_current
        settings = _settings(self, SEQUENCE_OPTIONS, self.frame_start)
        sequence.refuse_unsupported_options(settings)
        frames = sequence.key_frames(names, [int(getattr(obj, KEY_FRAME_PROPERTY, 0)) for obj in objects],
                                     self.frame_start, self.frame_step)
        frame_count, keys_at = sequence.timeline(frames, self.frame_step, self.loop)
        depsgraph = baking.evaluated_depsgraph(context)
        data = [baking.mesh_world_data(obj, depsgraph) for obj in objects]
        groups = [baking.vertex_groups(obj, is_pin_group) for obj in objects]
        # Local timing (issue 31): the delay group of the first key.
        delay = baking.delay_weights(objects[0], len(data[0][0]), settings.delay_group, "the first key")
        progress.stage("read", 5)
        loop, hold = self.loop, [self.hold] * len(names) if self.hold else None

        def work(timer):  # free of bpy: the worker thread of a modal bake
            prepared = sequence.prepare_keys([d[0] for d in data], [d[1] for d in data], [d[2] for d in data],
                                             names, settings, groups, delay)
            timer.stage("check", 15)
            result = sequence.morph_keys(prepared, settings, frame_count, keys_at, loop, hold)
            timer.stage("morph", 70)
            return names, settings, frames, frame_count, prepared, result

        return work

    def finish(self, context, progress, computed):
        from . import baking, core

        names, settings, frames, frame_count, prepared, result = computed
        tag = json.dumps(names)
        previous = baking.results_tagged(SEQUENCE_ROLE, KEYS_TAG, tag)
        try:
            obj, created = baking.build_tagged_result(
                context, core.result_name(names[0], names[-1]), result.frames_world, result.edges,
                prepared.plane.origin, frames[0], settings, prepared.size, {baking.ROLE: SEQUENCE_ROLE, KEYS_TAG: tag})
        except Exception as error:  # build_tagged_result removed what it made
            raise StickMorphError(f"building the result failed: {error}") from error
        progress.stage("build", 100)
        _finish(self, context, obj, previous, created, settings, frames[0], frame_count, result, names,
                (time.perf_counter() - self._started) * 1000.0, "key poses", loop=self.loop,
                stages=progress.summary())
        return {"FINISHED"}


# ------------------------------------------------------------- rebake ----

def shape_key_animation(obj):
    """(frames, key blocks but the basis, values (F, J)) of a mesh object's
    shape-key animation: every keyframe of the value F-curves of its
    non-basis keys, and each key's value there (a key without an F-curve
    keeps its value, a muted key counts as 0). Raises StickMorphError for
    what cannot be pose to pose (absolute keys, a key relative to another
    key or limited to a vertex group, no animation)."""
    from . import baking
    import numpy as np
    key = obj.data.shape_keys if obj.type == "MESH" else None
    if key is None or len(key.key_blocks) < 2:
        raise StickMorphError(f"'{obj.name}' has no shape keys to morph between (Rebake Shape Keys needs a "
                              "basis and a shape key per pose, animated pose to pose)")
    if not key.use_relative:
        raise StickMorphError(f"'{obj.name}' has absolute shape keys (Relative is off): Rebake Shape Keys reads "
                              "relative keys animated pose to pose")
    basis = key.reference_key
    blocks = [block for block in key.key_blocks if block != basis]
    for block in blocks:
        if block.relative_key != basis:
            raise StickMorphError(f"the shape key '{block.name}' of '{obj.name}' is relative to "
                                  f"'{block.relative_key.name}', not to the basis '{basis.name}'")
        if block.vertex_group:
            raise StickMorphError(f"the shape key '{block.name}' of '{obj.name}' is limited to the vertex group "
                                  f"'{block.vertex_group}': its value does not give its shape")
    anim = key.animation_data
    curves = []
    for block in blocks:
        path = f'key_blocks["{bpy.utils.escape_identifier(block.name)}"].value'
        curves.append(baking.find_fcurve(anim, path) if anim is not None else None)
    frames = sorted({round(float(point.co[0]), 6) for curve in curves if curve is not None
                     for point in curve.keyframe_points})
    if not frames:
        raise StickMorphError(f"the shape keys of '{obj.name}' are not animated (no keyframes on their values)")
    values = np.array([[0.0 if block.mute else (curve.evaluate(f) if curve is not None else block.value)
                        for block, curve in zip(blocks, curves)] for f in frames], dtype=np.float64)
    return frames, blocks, values


class STICKMORPH_OT_rebake_shape_keys(BakeExecute, bpy.types.Operator):
    """Morph the active mesh's pose-to-pose shape-key animation through its poses (at each keyframe one shape key on, or none: the basis) into a new object, free of self-intersection; the mesh and its animation stay as they are"""
    bl_idname = "object.stick_morph_rebake_shape_keys"
    bl_label = "Rebake Shape Keys"
    bl_options = {"REGISTER", "UNDO"}

    __annotations__ = {
        "object": StringProperty(name="Object", options={"SKIP_SAVE"},
                                 description="The mesh whose shape-key animation to rebake (empty: the active object)"),
        "hold": key_pose_properties()["hold"],
        **_options(REBAKE_OPTIONS),
        **mesh_option_properties(),
    }

    preference_options = REBAKE_OPTIONS

    def draw(self, context):
        from . import ui
        ui.draw_key_pose_operator(self.layout, self, ("object",), ("hold",), REBAKE_OPTIONS)

    def run(self, context, progress):
        from . import baking, sequence

        started = time.perf_counter()
        name = self.object.strip()
        obj = bpy.data.objects.get(name) if name else context.active_object
        if obj is None:
            raise StickMorphError(f"there is no object named '{name}'" if name else
                                  "no active object: make the mesh with the shape-key animation active")
        if obj.type != "MESH":
            raise StickMorphError(f"'{obj.name}' is a {obj.type.lower()}, not a mesh")
        self.object = obj.name
        frames, blocks, values = shape_key_animation(obj)
        basis = obj.data.shape_keys.reference_key
        poses = sequence.pose_to_pose(obj.name, frames, [b.name for b in blocks], values, basis.name)
        settings = _settings(self, REBAKE_OPTIONS, poses[0].frame, motion="RIGID", correspondence="INDEX")
        depsgraph = baking.evaluated_depsgraph(context)
        _, edges, faces = baking.mesh_world_data(obj, depsgraph)
        shapes = [baking.shape_key_world(obj, basis if pose.key < 0 else blocks[pose.key], depsgraph)
                  for pose in poses]
        names = [f"{basis.name if pose.key < 0 else blocks[pose.key].name}, frame {pose.frame}" for pose in poses]
        # Local timing (issue 31): a vertex group of the mesh itself.
        delay = baking.delay_weights(obj, len(shapes[0]), settings.delay_group, "the mesh")
        progress.stage("read", 5)
        prepared = sequence.prepare_keys(shapes, [edges] * len(poses), [faces] * len(poses), names, settings,
                                         delay=delay)
        first = poses[0].frame
        frame_count = poses[-1].frame - first + 1
        hold = [a or self.hold for a in sequence.pose_holds(poses)]
        result = sequence.morph_keys(prepared, settings, frame_count, [pose.frame - first for pose in poses],
                                     False, hold if any(hold) else None)
        progress.stage("morph", 70)
        previous = baking.results_tagged(REBAKE_ROLE, baking.SOURCE, obj.name)
        try:
            new, created = baking.build_tagged_result(
                context, f"{obj.name}_rebaked", result.frames_world, result.edges, prepared.plane.origin, first,
                settings, prepared.size, {baking.ROLE: REBAKE_ROLE, baking.SOURCE: obj.name})
        except Exception as error:  # build_tagged_result removed what it made
            raise StickMorphError(f"building the result failed: {error}") from error
        progress.stage("build", 100)
        _finish(self, context, new, previous, created, settings, first, frame_count, result, names,
                (time.perf_counter() - started) * 1000.0, "shape-key poses", stages=progress.summary())
        return {"FINISHED"}


classes = (STICKMORPH_OT_bake_sequence, STICKMORPH_OT_rebake_shape_keys)

_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    setattr(bpy.types.Object, KEY_FRAME_PROPERTY, IntProperty(
        name="Key Frame", default=0, min=0, options=set(),
        description="The frame at which Bake Key Poses shows this object as a key (0: automatic, evenly "
                    "spaced from the start frame); give every key one, or none"))


def unregister():
    delattr(bpy.types.Object, KEY_FRAME_PROPERTY)
    _unregister_classes()
