"""The bake operator, object.stick_morph_bake, the pin operators,
mesh.stick_morph_pin_selected and object.stick_morph_clear_pins, and
scene.stick_morph_load_defaults.

All checks (selection, faces, vertex counts, edge sets, pins, planarity, the
engine's validation, matching and compatibility) and the morph itself run
before any data is created, so that an error leaves the scene exactly as it
was; building the result is wrapped so that a failure removes what it
created. The pin operators likewise check everything before they change a
vertex group.

execute depends only on the operator's properties and the file, never on
state kept from an earlier run, because Adjust Last Operation (and redo)
undoes the last run and calls execute again on the restored file.

From the GUI the pair bake and Bake Key Poses run modal (ModalBake, issue
29): the meshes are read at once, the engine runs in a worker thread
(bake_job.py) while the status bar shows its stage, Esc cancels with the
scene unchanged, and the result is built when the engine is done. execute
runs the same three steps in one go.

numpy and the native module are imported only inside execute, after
dependencies.check() found them: the add-on registers without them, and the
bake reports what is missing as an ERROR instead of failing with a raw
ImportError.
"""

import time

import bpy
from bpy.props import IntProperty, StringProperty

from .bake_job import BakeJob, StageTimer
from .common import BakeSettings, StickMorphError, is_pin_group, next_pin_name
# The helpers the panel shares with the operators are helpers.py's (so that
# ui.py need not import this module); dependency_status is re-exported for
# scripts and tests that ask the operators' module.
from .helpers import dependency_status, edited_meshes, resolve_pair  # noqa: F401
from .properties import (OPTION_NAMES, addon_preferences, bake_settings, drawing_properties, mesh_option_properties,
                         option_properties)

class Progress(StageTimer):
    """The window manager's progress indicator, one call per stage, and the
    stages' times (bake_job.StageTimer).

    Only with a window: in background mode (tests, render_demo.py) there is
    no cursor or status bar to show it, and 3.x prints nothing useful.
    `stages`: the stages a modal bake's worker already timed, continued."""

    def __init__(self, context, stages=None):
        super().__init__()
        wm = context.window_manager
        self.wm = wm if wm is not None and context.window is not None and not bpy.app.background else None
        if stages is not None:
            self.stages = list(stages.stages)
            self.percent = stages.percent

    def __enter__(self):
        if self.wm is not None:
            self.wm.progress_begin(0, 100)
        return self

    def update(self, percent):
        super().update(percent)
        if self.wm is not None:
            self.wm.progress_update(percent)

    def __exit__(self, *exc):
        if self.wm is not None:
            self.wm.progress_end()
        return False


# How long the result stays in the status bar (show_in_status_bar).
STATUS_SECONDS = 8.0


def show_in_status_bar(context, text):
    """Shows text in the status bar for STATUS_SECONDS.

    Blender 3.4 shows an operator's INFO report in the status bar only when
    its report timer has a window: WM_report_banner_show() attaches it to
    wm->winactive, which is not set in every session, so the result was seen
    only in the Info editor (reported by a user; measured under Xvfb: no
    banner, while this text shows). Newer versions fall back to the first
    window, but that could not be checked here (4.3's window reads back black
    under Xvfb), so every version gets the text; where the banner shows too,
    both say the same. The workspace's status text is drawn without a timer;
    an app timer clears it, as Blender's modal operators clear theirs."""
    global _clear_status
    if bpy.app.background:
        return
    workspace = getattr(context, "workspace", None)
    if workspace is None:
        return
    workspace.status_text_set(text)
    name = workspace.name

    def clear():
        space = bpy.data.workspaces.get(name)
        if space is not None:
            space.status_text_set(None)
        return None

    # A bake within STATUS_SECONDS of the last (a redo) restarts the clock.
    if _clear_status is not None and bpy.app.timers.is_registered(_clear_status):
        bpy.app.timers.unregister(_clear_status)
    _clear_status = clear
    bpy.app.timers.register(clear, first_interval=STATUS_SECONDS)


_clear_status = None


class BakeExecute:
    """What the bake operators share (the pair bake here, the key-pose ones
    in sequence_operators.py): the poll, and an execute that checks the
    dependencies, takes the preferences for the options the caller did not
    set (preference_options), runs self.run(context, progress) and reports a
    StickMorphError as an ERROR."""

    preference_options = OPTION_NAMES

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
        for name in self.preference_options:
            if not self.properties.is_property_set(name):
                setattr(self, name, getattr(prefs, name))

    def execute(self, context):
        status = dependency_status(refresh=True)
        if not status.ok:
            self.report({"ERROR"}, f"Stick Morph: {status.message()}")
            return {"CANCELLED"}
        self._apply_preferences(context)
        try:
            with Progress(context) as progress:
                return self.run(context, progress)
        except StickMorphError as error:
            self.report({"ERROR"}, f"Stick Morph: {error}")
            return {"CANCELLED"}


# How often a modal bake looks at its worker (seconds).
TIMER_SECONDS = 0.1
# Events a running modal bake lets through: looking around. Everything else
# waits for the bake, so that the scene it read cannot change under it
# before it builds the result (and no second bake starts meanwhile).
PASS_THROUGH = {"MIDDLEMOUSE", "WHEELUPMOUSE", "WHEELDOWNMOUSE", "WHEELINMOUSE", "WHEELOUTMOUSE",
                "TRACKPADPAN", "TRACKPADZOOM", "MOUSEMOVE", "INBETWEEN_MOUSEMOVE", "NDOF_MOTION",
                "WINDOW_DEACTIVATE", "TIMER_REPORT", "TIMERREGION"}


class ModalBake(BakeExecute):
    """A bake that the GUI runs modal (issue 29): invoke reads the meshes
    (self.start, main thread), runs the engine's part in a worker thread
    (bake_job.BakeJob) with a progress indicator and a status-bar text,
    and builds the result (self.finish, main thread) when it is done. Esc or
    a right-click cancels: the engine stops at its next check (within a
    fraction of a second, also inside the triangulation), nothing is
    created, the scene stays as it was, and a report says so.

    execute (scripts, tests, redo, Adjust Last Operation) runs the same
    three steps in one go, as before: run() = start, its work, finish.
    Without a window (background mode) or with a module that has no
    stickmorph.Progress, invoke is execute.

    Subclasses define start(context, progress) -> work, where work(timer)
    is free of bpy (it runs in the worker) and returns what
    finish(context, progress, computed) builds from."""

    def run(self, context, progress):
        work = self.start(context, progress)
        return self.finish(context, progress, work(progress))

    def invoke(self, context, event):
        engine_progress = self._engine_progress()
        if bpy.app.background or context.window is None or engine_progress is None:
            return self.execute(context)
        status = dependency_status(refresh=True)
        if not status.ok:
            self.report({"ERROR"}, f"Stick Morph: {status.message()}")
            return {"CANCELLED"}
        self._apply_preferences(context)
        timer = StageTimer()
        try:
            work = self.start(context, timer)
        except StickMorphError as error:
            self.report({"ERROR"}, f"Stick Morph: {error}")
            return {"CANCELLED"}
        self._job = BakeJob(work, engine_progress, timer).start()
        wm = context.window_manager
        self._timer = wm.event_timer_add(TIMER_SECONDS, window=context.window)
        wm.modal_handler_add(self)
        wm.progress_begin(0, 100)
        self._show(context)
        return {"RUNNING_MODAL"}

    @staticmethod
    def _engine_progress():
        """A new stickmorph.Progress, or None when the module has none (or
        is missing: execute reports that)."""
        if not dependency_status().ok:
            return None
        from . import native
        progress_type = getattr(native.load_engine(), "Progress", None)
        return progress_type() if progress_type is not None else None

    def _show(self, context):
        context.window_manager.progress_update(self._job.percent())
        workspace = getattr(context, "workspace", None)
        if workspace is not None:
            workspace.status_text_set(self._job.status_text())

    def _end(self, context):
        wm = context.window_manager
        if getattr(self, "_timer", None) is not None:
            wm.event_timer_remove(self._timer)
            self._timer = None
        wm.progress_end()
        workspace = getattr(context, "workspace", None)
        if workspace is not None:
            workspace.status_text_set(None)

    def modal(self, context, event):
        job = self._job
        if event.type in {"ESC", "RIGHTMOUSE"} and event.value == "PRESS":
            job.cancel()
            self._show(context)
            return {"RUNNING_MODAL"}
        if event.type == "TIMER":
            if job.running:
                self._show(context)
                return {"RUNNING_MODAL"}
            return self._done(context)
        if event.type in PASS_THROUGH:
            return {"PASS_THROUGH"}
        return {"RUNNING_MODAL"}

    def _done(self, context):
        job = self._job
        self._end(context)
        if job.cancelled:
            self.report({"WARNING"}, f"Stick Morph: bake cancelled after {job.elapsed:.1f} s; nothing was changed")
            return {"CANCELLED"}
        if job.error is not None:
            if isinstance(job.error, StickMorphError):
                self.report({"ERROR"}, f"Stick Morph: {job.error}")
                return {"CANCELLED"}
            raise job.error  # a bug, raised as execute would have raised it
        try:
            with Progress(context, job.timer) as progress:
                return self.finish(context, progress, job.result)
        except StickMorphError as error:
            self.report({"ERROR"}, f"Stick Morph: {error}")
            return {"CANCELLED"}

    def cancel(self, context):
        # Blender ends a running modal operator (a file loaded, the window
        # closed): stop the worker before the data it read goes away.
        job = getattr(self, "_job", None)
        if job is not None:
            job.cancel()
            job.wait()
            self._end(context)


class STICKMORPH_OT_bake(ModalBake, bpy.types.Operator):
    """Bake a morph between two edge meshes, Grease Pencil drawings or curves (source, then target active) into a new object with shape keys (or Grease Pencil drawings), free of self-intersection unless Motion is Linear"""
    bl_idname = "object.stick_morph_bake"
    bl_label = "Bake Stick Morph"
    bl_options = {"REGISTER", "UNDO"}

    __annotations__ = {
        # SKIP_SAVE: a later call from the menu must use its own selection,
        # not the names a previous bake resolved (redo keeps them: it re-runs
        # this operator's own properties, not the remembered ones).
        "source": StringProperty(name="Source", options={"SKIP_SAVE"},
                                 description="Source object name (empty: the selected non-active mesh)"),
        "target": StringProperty(name="Target", options={"SKIP_SAVE"},
                                 description="Target object name (empty: the active object)"),
        "frame_start": IntProperty(name="Start", description="Frame showing the source",
                                   default=BakeSettings.frame_start, options=set()),
        **option_properties(),
        **mesh_option_properties(),
        # Grease Pencil layers and frames, Pin Selected Points (issue 32);
        # SKIP_SAVE as source and target: a call from the menu reads the
        # active layer at the current frame of its own selection.
        **drawing_properties({"SKIP_SAVE"}),
    }

    def draw(self, context):
        from . import ui
        ui.draw_operator(self.layout, self)

    def start(self, context, progress):
        from . import baking, core

        self._started = time.perf_counter()
        settings = bake_settings(self)
        source, target = resolve_pair(context, self.source.strip(), self.target.strip())
        # Redo re-runs with these names even if the selection changed meanwhile.
        self.source, self.target = source.name, target.name
        depsgraph = baking.evaluated_depsgraph(context)
        if core.is_drawing_type(source.type) or core.is_drawing_type(target.type):
            return self._start_drawings(context, progress, settings, source, target, depsgraph)
        source_world, source_edges, source_faces = baking.mesh_world_data(source, depsgraph)
        target_world, target_edges, target_faces = baking.mesh_world_data(target, depsgraph)
        # The pins: vertex groups named pin* (core.read_pins checks them).
        source_groups = baking.vertex_groups(source, is_pin_group)
        target_groups = baking.vertex_groups(target, is_pin_group)
        # Local timing (issue 31): the source's delay group, refused here if
        # it is missing or empty.
        source_delay = baking.delay_weights(source, len(source_world), settings.delay_group)
        progress.stage("read", 5)
        source_name, target_name = source.name, target.name

        def work(timer):  # free of bpy: the worker thread of a modal bake
            # Checks, then by index or matched (settings.correspondence).
            prepared = core.prepare_pair(source_world, source_edges, source_faces, source_name,
                                         target_world, target_edges, target_faces, target_name, settings,
                                         source_groups, target_groups, source_delay)
            timer.stage("check", 15)
            # By index, or matched if Automatic's morph by index finds the pair
            # incompatible that way (the bake's one compatibility check).
            prepared, morph = core.morph_pair(prepared, settings)
            timer.stage("morph", 60)
            return settings, prepared, morph, None

        return work

    def _start_drawings(self, context, progress, settings, source, target, depsgraph):
        """start() for a pair with a Grease Pencil drawing or a curve (issue
        32): the drawings are read here; the worker cleans them into stick
        figures (drawings.prepare_drawings) and morphs them."""
        from . import core, drawing_io

        source_figure, target_figure, pin_selected = drawing_io.read_pair(context, source, target, self, settings,
                                                                          depsgraph)
        progress.stage("read", 5)

        def work(timer):  # free of bpy: the worker thread of a modal bake
            prepared, cleaning = core.prepare_drawings(source_figure, target_figure, settings, pin_selected)
            timer.stage("check", 15)
            prepared, morph = core.morph_pair(prepared, settings)
            timer.stage("morph", 60)
            return settings, prepared, morph, (source_figure, cleaning)

        return work

    def finish(self, context, progress, computed):
        from . import baking, core

        settings, prepared, morph, drawn = computed
        started = self._started
        # By name: a modal bake's objects are looked up again after the
        # engine ran (the modal handler keeps the scene as it was meanwhile).
        source, target = resolve_pair(context, self.source, self.target)
        previous = baking.previous_results(source.name, target.name)
        count = settings.frame_count

        def frame_done(k):
            progress.update(60 + int(35 * k / max(count, 1)))

        make_result = None
        if core.output_kind(settings.output, source.type) == "GREASE_PENCIL":
            from . import drawing_io
            make_result = drawing_io.result_builder(context, source, prepared, morph, settings, drawn, frame_done)
        try:
            result, created = baking.build_result(context, source, target, prepared, morph, settings,
                                                  report_progress=frame_done, make_result=make_result)
        except Exception as error:  # build_result removed what it made
            raise StickMorphError(f"building the result failed: {error}") from error
        # With the previous result gone, the new one takes the plain names.
        baking.replace_previous(previous, created)
        if settings.set_frame_range:
            context.scene.frame_start = settings.frame_start
            context.scene.frame_end = settings.frame_start + count - 1
        baking.select_only(context, result)
        progress.stage("build", 100)
        milliseconds = (time.perf_counter() - started) * 1000.0
        steiner = int(morph.stats.get("steiner_vertices", 0))
        motion_short, motion_text = core.motion_summary(morph, settings.frame_start)
        match_short, match_text = core.correspondence_summary(prepared.matching, source.name, target.name)
        timing_text = core.local_timing_summary(morph, settings.delay_group)
        if timing_text:
            motion_text = f"{motion_text}; {timing_text}"
        if drawn is not None:
            # Every change the cleaning made to a drawing, said (issue 32).
            cleaned = [core.cleaning_summary(role, side) for role, side in
                       (("source", drawn[1].source), ("target", drawn[1].target))]
            match_text = "; ".join([match_text] + [text for text in cleaned if text])
        scene_settings = getattr(context.scene, "stick_morph", None)
        if scene_settings is not None:
            scene_settings.last_result = result.name
            scene_settings.last_vertices = len(prepared.source_xy)
            scene_settings.last_steiner = steiner
            scene_settings.last_frames = count
            scene_settings.last_milliseconds = milliseconds
            scene_settings.last_motion = motion_short
            scene_settings.last_correspondence = match_short
            # The engine's call is the part of "morph" spent in the module
            # (issue 29's split of a bake between the engine and Blender).
            scene_settings.last_stages = f"{progress.summary()}, engine {morph.engine_ms:.0f} ms"
        # Several parts (loose parts, dots) are said; one part is not.
        parts = core.parts_summary(core.figure_parts(len(prepared.source_xy), prepared.edges))
        text = (f"Stick Morph: '{result.name}': {len(prepared.source_xy)} vertices, "
                f"{parts + ', ' if parts else ''}{steiner} Steiner vertices, {count} frames, {milliseconds:.0f} ms; {match_text}; {motion_text}")
        if morph.invalid_frames:
            # LINEAR is the baseline, not guaranteed valid: the bake keeps
            # its frames and says which of them are not stick figures
            # compatible with the source (the engine checks every frame;
            # core.compute_morph maps them to output frames).
            frames = [settings.frame_start + k for k in morph.invalid_frames]
            self.report({"WARNING"},
                        f"Stick Morph: the Linear motion crosses or folds the figure in {len(frames)} of "
                        f"{count} frames: {core.frame_list(frames)} (Rigid and Barycentric never do)")
        self.report({"INFO"}, f"{text} ({progress.summary()})")
        show_in_status_bar(context, text)
        return {"FINISHED"}


# ------------------------------------------------------------------ pins ----

def _listing(objects):
    return ", ".join(f"'{obj.name}'" for obj in objects)


class STICKMORPH_OT_pin_selected(bpy.types.Operator):
    """Pin the selected vertex of one mesh to the selected vertex of the other: a new vertex group pin.NNN in both holds it, and a matched bake pairs the two (Edit Mode with both meshes, one vertex selected in each)"""
    bl_idname = "mesh.stick_morph_pin_selected"
    bl_label = "Pin Selected Vertices"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if context.mode != "EDIT_MESH":
            cls.poll_message_set("Edit both meshes together (select both, Tab) and select one vertex in each")
            return False
        return True

    def execute(self, context):
        try:
            text = self._pin(context)
        except StickMorphError as error:
            self.report({"ERROR"}, f"Stick Morph: {error}")
            return {"CANCELLED"}
        self.report({"INFO"}, f"Stick Morph: {text}")
        return {"FINISHED"}

    @staticmethod
    def _pin(context):
        import bmesh

        objects = edited_meshes(context)
        if len(objects) != 2:
            raise StickMorphError(
                "Pin Selected Vertices needs exactly two meshes in Edit Mode (select both, then Tab); "
                + (f"{len(objects)} are: {_listing(objects)}" if len(objects) > 1 else
                   f"only {_listing(objects)} is" if objects else "none is"))
        if objects[0].data == objects[1].data:
            raise StickMorphError(f"{_listing(objects)} share the mesh '{objects[0].data.name}': a pin "
                                  "joins vertices of two different meshes")
        # Everything is checked before anything changes.
        chosen = []
        for obj in objects:
            mesh = bmesh.from_edit_mesh(obj.data)
            mesh.verts.index_update()  # the numbers the report and the bake use
            selected = [vertex for vertex in mesh.verts if vertex.select]
            if len(selected) != 1:
                raise StickMorphError(f"select exactly one vertex in each mesh: '{obj.name}' has "
                                      f"{len(selected)} selected")
            vertex = selected[0]
            deform = mesh.verts.layers.deform.active
            if deform is not None:
                for index in vertex[deform].keys():
                    if index < len(obj.vertex_groups) and is_pin_group(obj.vertex_groups[index].name):
                        raise StickMorphError(
                            f"vertex {vertex.index} of '{obj.name}' is already pinned by "
                            f"'{obj.vertex_groups[index].name}' (Clear Pins removes the pins)")
            chosen.append((obj, vertex.index))
        # One name free in both meshes: the pin is the name they share.
        name = next_pin_name(*([group.name for group in obj.vertex_groups] for obj in objects))
        for obj, index in chosen:
            group = obj.vertex_groups.new(name=name)
            mesh = bmesh.from_edit_mesh(obj.data)
            deform = mesh.verts.layers.deform.verify()
            # Adding the deform layer (to a mesh without vertex groups)
            # reallocates the vertices: a BMVert taken before is gone
            # (measured in 3.4: "BMesh data of type BMVert has been
            # removed"), so the vertex is looked up by index after it.
            mesh.verts.ensure_lookup_table()
            mesh.verts[index][deform][group.index] = 1.0
            bmesh.update_edit_mesh(obj.data)
        (a, va), (b, vb) = chosen
        return f"pinned vertex {va} of '{a.name}' to vertex {vb} of '{b.name}' as '{name}'"


def pin_meshes(context):
    """The meshes Clear Pins works on: the selected mesh objects and those in
    Edit Mode, each once."""
    objects = []
    for obj in list(context.selected_objects) + edited_meshes(context):
        if obj.type == "MESH" and obj not in objects:
            objects.append(obj)
    return objects


class STICKMORPH_OT_clear_pins(bpy.types.Operator):
    """Remove the pins, the vertex groups named pin*, from the selected meshes"""
    bl_idname = "object.stick_morph_clear_pins"
    bl_label = "Clear Pins"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not pin_meshes(context):
            cls.poll_message_set("Select the meshes whose pins to remove")
            return False
        return True

    def execute(self, context):
        objects = pin_meshes(context)
        removed = 0
        for obj in objects:
            for group in [group for group in obj.vertex_groups if is_pin_group(group.name)]:
                obj.vertex_groups.remove(group)
                removed += 1
        if not removed:
            self.report({"WARNING"}, f"Stick Morph: no pins in {_listing(objects)}")
            return {"CANCELLED"}
        self.report({"INFO"}, f"Stick Morph: removed {removed} pin group{'s' if removed != 1 else ''} "
                              f"from {_listing(objects)}")
        return {"FINISHED"}


class STICKMORPH_OT_load_defaults(bpy.types.Operator):
    """Copy the add-on preferences' defaults into this scene's Stick Morph options"""
    bl_idname = "scene.stick_morph_load_defaults"
    bl_label = "Load Defaults"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        prefs = addon_preferences(context)
        if prefs is None:
            self.report({"ERROR"}, "Stick Morph preferences are not available")
            return {"CANCELLED"}
        settings = context.scene.stick_morph
        for name in OPTION_NAMES:
            setattr(settings, name, getattr(prefs, name))
        return {"FINISHED"}



classes = (STICKMORPH_OT_bake, STICKMORPH_OT_pin_selected, STICKMORPH_OT_clear_pins,
           STICKMORPH_OT_load_defaults)


register, unregister = bpy.utils.register_classes_factory(classes)
