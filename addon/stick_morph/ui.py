"""The sidebar panel (View3D > Sidebar > Stick Morph) and its Pins, Local
Timing, Key Poses and Advanced sub-panels; the same layout draws the
operator's Adjust Last Operation panel (without the pins, which are mesh
data, not options).

Sized for the sidebar's default width in Blender 3.4 (220 px at scale 1): in
a property-split row the label column holds about 7 characters, so those rows
use labels of at most SPLIT_LABEL_CHARS characters and everything longer
(check boxes, the tube radius, the expert numbers) is drawn without the
split, where the label has the whole width. No row has a keyframe decorator
(use_property_decorate = False; the properties are not animatable either).
"""

import json
import textwrap

import bpy

from .common import GREASE_PENCIL_TYPES, StickMorphError, is_drawing_type, pin_names, property_applies
from .helpers import dependency_status, edited_meshes, resolve_pair
from .properties import DRAWING_OPTIONS, MESH_OPTIONS, OPTION_NAMES, REBAKE_OPTIONS, SEQUENCE_OPTIONS

# Longest label of a property-split row that 3.4's default sidebar shows in
# full: "Weights" and "Steiner" were, "Enclos…" (Enclosure Sides) was not
# (measured from a screenshot under Xvfb, tests/blender/test_ui.py checks it).
SPLIT_LABEL_CHARS = 7
# Longest value of a drop-down in such a row: "Barycentric" and "Ease In-Out"
# show in full, "Counterclockwise" was cut (measured the same way).
SPLIT_VALUE_CHARS = 11
# Longest text of a row without split (a check box or number field across
# the panel, about 180 px).
FULL_LABEL_CHARS = 22

# (property, label) of the rows: split rows in the main panel and in
# Advanced, then the full-width rows. Labels None use the property's name.
# Motion is the headline option: the first row under the pair. The
# correspondence is "Match" (Correspondence is too long for the label
# column); its values read after it: Match Automatic, By Index, By Shape.
MAIN_SPLIT = (("motion", "Motion"), ("correspondence", "Match"), ("frame_start", "Start"),
              ("frame_count", "Frames"), ("plane", "Plane"), ("easing", "Easing"))
# Output (issue 32) is a full row: "Grease Pencil" is too long for a
# split row's value column.
MAIN_FULL = (("output", "Output"), ("renderable", None), ("tube_radius", None), ("show_triangulation", None),
             ("set_frame_range", None), ("clean_tolerance", None))
# "Rotation" (8) and "Extra Turns" are too long for a split row.
ADVANCED_SPLIT = (("rotation", "Rotate"), ("turns", "Turns"), ("steiner", "Steiner"), ("weights", "Weights"))
ADVANCED_FULL = (("enclosure_sides", None),)
# Too long for any row: a label line above a field without text.
ADVANCED_LABELLED = (("planarity_tolerance", "Planarity tolerance:"),)
ADVANCED = tuple(name for name, _ in ADVANCED_SPLIT + ADVANCED_FULL + ADVANCED_LABELLED)
# Local timing (issue 31): the delay group, a search over the source mesh's
# vertex groups (draw_local_timing), and the overlap slider, full width.
LOCAL_TIMING = (("delay_group", "Delay Group"), ("overlap", None))

# Options that only some motions use are drawn greyed out (row.active =
# False, still editable, as Blender greys out settings that have no effect)
# when the data's motion is not one of them, by the engine's own rule of
# which option applies to which method (native.option_methods).
def pair_objects(data):
    """The source and target objects a bake with data (the scene settings or
    an operator's properties) would use, or None where they cannot be told."""
    def named(value):
        return value if not isinstance(value, str) else bpy.data.objects.get(value) if value else None

    try:
        source, target = named(getattr(data, "source", None)), named(getattr(data, "target", None))
        return resolve_pair(bpy.context, source.name if source else "", target.name if target else "")
    except (StickMorphError, AttributeError):
        return None


def row_active(data, name):
    """Whether the option `name` has an effect with the other options of data."""
    if name == "tube_radius":
        return bool(getattr(data, "renderable", True))
    if name == "clean_tolerance":
        # Only drawings are cleaned; where the pair is not known yet it may be.
        pair = pair_objects(data)
        return pair is None or any(is_drawing_type(obj.type) for obj in pair)
    if name == "overlap" and not getattr(data, "delay_group", ""):
        return False  # no delay group: nothing lags
    return property_applies(name, getattr(data, "motion", "RIGID"), _option_methods())


def _option_methods():
    """The engine's rule, or None where the module does not load (the panel
    says so; nothing is greyed out on a guess). Loaded only after the cached
    dependency check passed, so a redraw never retries a failing import."""
    if not dependency_status().ok:
        return None
    from .native import option_methods  # needs NumPy and the module: only when they load
    return option_methods()


def _wrap(context, text):
    """Lines of text that fit the region (labels are cut, not wrapped)."""
    region = getattr(context, "region", None)
    # ui_scale is 0 in background mode (no window).
    scale = (context.preferences.system.ui_scale if context.preferences else 0.0) or 1.0
    width = region.width if region is not None and region.width > 1 else 220
    # About 7 px per character of the UI font at scale 1, less the margins,
    # a box and an icon (measured on 3.4's sidebar: 24 characters fit in 220 px).
    chars = max(16, int((width - 50) / (7.0 * scale)))
    return textwrap.wrap(text, chars) or [""]


def _label_lines(layout, context, text, icon="NONE"):
    column = layout.column(align=True)
    for k, line in enumerate(_wrap(context, text)):
        column.label(text=line, icon=icon if k == 0 else "BLANK1" if icon != "NONE" else "NONE")


def draw_dependency_box(layout, context):
    """A box saying what is missing when numpy or the native module do not
    load (dependencies.check at enable time); nothing otherwise."""
    status = dependency_status()
    if status.ok:
        return False
    box = layout.box()
    box.alert = True
    lines = status.lines()
    box.label(text=lines[0], icon="ERROR")
    for line in lines[1:]:
        _label_lines(box, context, line)
    return True


def pair_preview(context, settings):
    """(ok, text lines) saying which object a bake would use as the source and
    which as the target, resolved exactly as the operator does, or why it
    cannot."""
    source_name = settings.source.name if settings.source else ""
    target_name = settings.target.name if settings.target else ""
    try:
        source, target = resolve_pair(context, source_name, target_name)
    except StickMorphError as error:
        return False, [f"To bake: {error}" if not (source_name or target_name) else f"Cannot bake: {error}"]
    # Two lines: one line holds about 24 characters at the default width.
    return True, [f"Source: {source.name}  \u2192", f"Target: {target.name}"]


def pin_preview(context, settings):
    """(count, text, problems): the pins of the two meshes a bake would use
    (or, in Edit Mode, of the two meshes being edited), from their vertex
    group names only (the panel redraws often; the bake reads and checks
    the groups' vertices, core.read_pins): how many, a line saying so, and
    what a bake would refuse."""
    objects = edited_meshes(context)
    if len(objects) != 2:
        try:
            objects = resolve_pair(context, settings.source.name if settings.source else "",
                                   settings.target.name if settings.target else "")
        except StickMorphError:
            return 0, "Pins join vertices of two meshes", []
    a, b = objects
    both, only_a, only_b = pin_names([g.name for g in a.vertex_groups], [g.name for g in b.vertex_groups])
    text = f"{len(both)} pin{'s' if len(both) != 1 else ''}: {', '.join(both)}" if both else "No pins"
    problems = [f"'{name}' is in '{present.name}', not in '{missing.name}'"
                for names, present, missing in ((only_a, a, b), (only_b, b, a)) for name in names]
    if (both or problems) and settings.correspondence == "INDEX":
        problems.append("Pins need Match Automatic or By Shape")
    return len(both), text, problems


def delay_group_owner(context, settings):
    """The mesh whose vertex groups the sidebar's Delay Group lists: the
    source of the pair a bake would use (resolve_pair), else the active mesh
    (the first key or the mesh of Rebake Shape Keys, say); None if neither."""
    try:
        source, _ = resolve_pair(context, settings.source.name if settings.source else "",
                                 settings.target.name if settings.target else "")
        return source
    except StickMorphError:
        obj = context.active_object
        return obj if obj is not None and obj.type == "MESH" else None


def operator_delay_owner(op):
    """The mesh whose vertex groups an operator's Delay Group names, for
    its Adjust Last Operation panel: the pair bake's source, the first key,
    or the rebaked mesh (None when the name is not known yet)."""
    def text(prop):  # a string property of op, "" if it has none (op.keys() is a method of every op)
        return getattr(op, prop) if prop in op.bl_rna.properties else ""

    name = text("source") or text("object")
    if not name and text("keys"):
        try:
            keys = json.loads(op.keys)
            name = keys[0] if isinstance(keys, list) and keys and isinstance(keys[0], str) else ""
        except ValueError:
            name = ""
    obj = bpy.data.objects.get(name) if name else None
    return obj if obj is not None and obj.type == "MESH" else None


def draw_local_timing(layout, data, owner):
    """The delay group (a search over owner's vertex groups; a text field
    when there is no owner) and the overlap slider, greyed out where they
    have no effect (row_active)."""
    column = layout.column()
    column.use_property_split = False
    column.use_property_decorate = False
    row = column.row()
    row.active = row_active(data, "delay_group")
    if owner is not None:
        row.prop_search(data, "delay_group", owner, "vertex_groups", text="Delay Group", icon="GROUP_VERTEX")
    else:
        row.prop(data, "delay_group", text="Delay Group", icon="GROUP_VERTEX")
    row = column.row()
    row.active = row_active(data, "overlap")
    row.prop(data, "overlap", slider=True)


def delay_group_problem(owner, name):
    """What a bake would refuse of the delay group, from the names only (the
    panel redraws often; the bake also refuses an empty group), or None."""
    if not name or owner is None:
        return None
    if owner.vertex_groups.get(name) is None:
        return f"'{name}' is not a vertex group of '{owner.name}'"
    return None


# The Drawing sub-panel (issue 32): which layer and frame of a Grease Pencil
# source and target, and its pins. (property, label) rows, full width.
DRAWING_ROWS = (("source_layer", "Layer"), ("source_frame", "Frame"), ("target_layer", "Layer"),
                ("target_frame", "Frame"), ("pin_selected", None))


def draw_drawing_rows(layout, data, pair):
    """The Drawing rows of data (scene settings or the operator) for the
    pair (source, target) or None: a role's layer (a search over its Grease
    Pencil layers) and frame greyed out unless it is a Grease Pencil object,
    Pin Selected Points unless both are."""
    column = layout.column()
    column.use_property_split = False
    column.use_property_decorate = False
    pencils = [obj if obj is not None and obj.type in GREASE_PENCIL_TYPES else None for obj in (pair or (None, None))]
    for role, obj in zip(("source", "target"), pencils):
        column.label(text=f"{role.title()}: '{obj.name}'" if obj is not None else f"{role.title()}: not Grease Pencil")
        row = column.row()
        row.active = obj is not None or pair is None
        if obj is not None:
            row.prop_search(data, f"{role}_layer", obj.data, "layers", text="Layer")
        else:
            row.prop(data, f"{role}_layer", text="Layer")
        row = column.row()
        row.active = obj is not None or pair is None
        row.prop(data, f"{role}_frame", text="Frame")
    row = column.row()
    row.active = pair is None or all(obj is not None for obj in pencils)
    row.prop(data, "pin_selected")


def draw_rows(layout, data, split_rows, full_rows, labelled_rows=()):
    column = layout.column()
    column.use_property_split = True
    column.use_property_decorate = False
    for name, label in split_rows:
        row = column.row()
        row.active = row_active(data, name)
        row.prop(data, name, text=label)
    column = layout.column()
    column.use_property_split = False
    column.use_property_decorate = False
    for name, label in full_rows:
        row = column.row()
        row.active = row_active(data, name)
        row.prop(data, name, **({} if label is None else {"text": label}))
    for name, label in labelled_rows:
        column.label(text=label)
        column.prop(data, name, text="")


class VIEW3D_PT_stick_morph(bpy.types.Panel):
    bl_label = "Stick Morph"
    bl_idname = "VIEW3D_PT_stick_morph"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"

    def draw(self, context):
        layout = self.layout
        layout.use_property_decorate = False
        draw_dependency_box(layout, context)
        settings = context.scene.stick_morph
        column = layout.column(align=True)
        column.prop(settings, "source")
        column.prop(settings, "target")
        ok, lines = pair_preview(context, settings)
        if not ok or (settings.source is None and settings.target is None):
            box = layout.box()
            column = box.column(align=True)
            for k, line in enumerate(lines):
                # Only a wrong pick is an error; an unusable selection is a hint.
                icon = "ERROR" if not ok and (settings.source or settings.target) else "INFO"
                _label_lines(column, context, line, icon=icon if k == 0 else "BLANK1")

        draw_rows(layout, settings, MAIN_SPLIT, MAIN_FULL)
        row = layout.row(align=True)
        row.operator("scene.stick_morph_load_defaults", icon="LOOP_BACK")

        op = layout.operator("object.stick_morph_bake", icon="MOD_SIMPLEDEFORM")
        op.source = settings.source.name if settings.source else ""
        op.target = settings.target.name if settings.target else ""
        op.frame_start = settings.frame_start
        for name in OPTION_NAMES + MESH_OPTIONS + DRAWING_OPTIONS:
            setattr(op, name, getattr(settings, name))
        draw_sequence_buttons(layout.column(align=True), settings)

        if settings.last_result:
            box = layout.box()
            column = box.column(align=True)
            column.label(text=f"Last: {settings.last_result}")
            column.label(text=f"{settings.last_vertices} vertices, {settings.last_steiner} Steiner")
            column.label(text=f"{settings.last_frames} frames, {settings.last_milliseconds:.0f} ms")
            if settings.last_correspondence:
                column.label(text=settings.last_correspondence)
            if settings.last_motion:
                column.label(text=settings.last_motion)


class VIEW3D_PT_stick_morph_pins(bpy.types.Panel):
    """Pins: vertex groups pin.* in both meshes that a matched bake pairs"""
    bl_label = "Pins"
    bl_idname = "VIEW3D_PT_stick_morph_pins"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"
    bl_parent_id = "VIEW3D_PT_stick_morph"

    def draw(self, context):
        layout = self.layout
        _, text, problems = pin_preview(context, context.scene.stick_morph)
        _label_lines(layout, context, text, icon="PINNED")
        if problems:
            column = layout.column(align=True)
            column.alert = True
            for problem in problems:
                _label_lines(column, context, problem, icon="ERROR")
        column = layout.column(align=True)
        column.operator("mesh.stick_morph_pin_selected", icon="PINNED")
        column.operator("object.stick_morph_clear_pins", icon="UNPINNED")


class VIEW3D_PT_stick_morph_local_timing(bpy.types.Panel):
    """Local timing: a vertex group of the source whose weights say which parts lag, and by how much"""
    bl_label = "Local Timing"
    bl_idname = "VIEW3D_PT_stick_morph_local_timing"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"
    bl_parent_id = "VIEW3D_PT_stick_morph"

    def draw(self, context):
        layout = self.layout
        layout.use_property_decorate = False
        settings = context.scene.stick_morph
        owner = delay_group_owner(context, settings)
        _label_lines(layout, context, f"Groups of '{owner.name}':" if owner is not None else
                     "Delay Group of the source mesh:")
        draw_local_timing(layout, settings, owner)
        problem = delay_group_problem(owner, settings.delay_group)
        if problem:
            column = layout.column(align=True)
            column.alert = True
            _label_lines(column, context, problem, icon="ERROR")
        elif settings.delay_group and not row_active(settings, "delay_group"):
            _label_lines(layout, context, "Local timing needs Motion Rigid", icon="INFO")
        else:
            _label_lines(layout, context, "Weight 0 leads, weight 1 lags by Overlap (Weight Paint mode)")


class VIEW3D_PT_stick_morph_drawing(bpy.types.Panel):
    """Grease Pencil source and target: which layer and frame, and pins from selected points"""
    bl_label = "Drawing"
    bl_idname = "VIEW3D_PT_stick_morph_drawing"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"
    bl_parent_id = "VIEW3D_PT_stick_morph"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        layout = self.layout
        layout.use_property_decorate = False
        settings = context.scene.stick_morph
        draw_drawing_rows(layout, settings, pair_objects(settings))
        _label_lines(layout, context, "Layer empty: the active one; Frame 0: the drawing shown now")


class VIEW3D_PT_stick_morph_advanced(bpy.types.Panel):
    """Expert options: how the compatible triangulation and the morph are built"""
    bl_label = "Advanced"
    bl_idname = "VIEW3D_PT_stick_morph_advanced"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"
    bl_parent_id = "VIEW3D_PT_stick_morph"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        layout = self.layout
        layout.use_property_decorate = False
        draw_rows(layout, context.scene.stick_morph, ADVANCED_SPLIT, ADVANCED_FULL, ADVANCED_LABELLED)


def draw_operator(layout, op):
    """The Adjust Last Operation panel of the bake: the same rows, the expert
    ones under a heading (operator panels have no sub-panels)."""
    layout.use_property_decorate = False
    column = layout.column(align=True)
    column.use_property_split = True
    column.prop(op, "source")
    column.prop(op, "target")
    draw_rows(layout, op, MAIN_SPLIT, MAIN_FULL)
    # The Drawing rows only for a pair with a Grease Pencil drawing or a
    # curve: a pair of meshes has no layers or frames to choose.
    pair = pair_objects(op)
    if pair is not None and any(is_drawing_type(obj.type) for obj in pair):
        layout.label(text="Drawing")
        draw_drawing_rows(layout, op, pair)
    layout.label(text="Local Timing")
    draw_local_timing(layout, op, operator_delay_owner(op))
    layout.label(text="Advanced")
    draw_rows(layout, op, ADVANCED_SPLIT, ADVANCED_FULL, ADVANCED_LABELLED)


# ------------------------------------------------------------ key poses ----


def draw_sequence_buttons(layout, settings):
    """Bake Key Poses and Rebake Shape Keys, next to the Bake button, with
    the scene's options (the Key Poses sub-panel holds their own)."""
    op = layout.operator("object.stick_morph_bake_sequence", icon="ANIM")
    op.collection = settings.key_collection.name if settings.key_collection else ""
    op.frame_step = settings.frame_step
    op.loop = settings.loop
    op.hold = settings.hold
    for name in SEQUENCE_OPTIONS + MESH_OPTIONS:
        setattr(op, name, getattr(settings, name))
    op = layout.operator("object.stick_morph_rebake_shape_keys", icon="SHAPEKEY_DATA")
    op.hold = settings.hold
    for name in REBAKE_OPTIONS + MESH_OPTIONS:
        setattr(op, name, getattr(settings, name))


class VIEW3D_PT_stick_morph_key_poses(bpy.types.Panel):
    """Key poses: one morph through several edge meshes, or through a mesh's pose-to-pose shape keys"""
    bl_label = "Key Poses"
    bl_idname = "VIEW3D_PT_stick_morph_key_poses"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Stick Morph"
    bl_parent_id = "VIEW3D_PT_stick_morph"

    def draw(self, context):
        layout = self.layout
        layout.use_property_decorate = False
        settings = context.scene.stick_morph
        layout.label(text="Keys (empty: selection by name):")
        layout.prop(settings, "key_collection", text="")
        column = layout.column()
        column.prop(settings, "frame_step")
        column.prop(settings, "loop")
        column.prop(settings, "hold")
        obj = context.active_object
        if obj is not None and obj.type == "MESH":
            layout.label(text=f"Key frame of '{obj.name}' (0: auto):")
            layout.prop(obj, "stick_morph_key_frame", text="")
        draw_sequence_buttons(layout.column(align=True), settings)


def draw_key_pose_operator(layout, op, fields, toggles, options):
    """The Adjust Last Operation panel of a key-pose operator: its own
    fields and toggles, then the bake's rows it takes (options)."""
    layout.use_property_decorate = False
    column = layout.column()
    column.use_property_split = True
    for name in fields:
        column.prop(op, name)
    for name in toggles:
        layout.prop(op, name)
    draw_rows(layout, op, tuple(r for r in MAIN_SPLIT if r[0] in options),
              tuple(r for r in MAIN_FULL if r[0] in options))
    layout.label(text="Local Timing")
    draw_local_timing(layout, op, operator_delay_owner(op))
    layout.label(text="Advanced")
    draw_rows(layout, op, ADVANCED_SPLIT, ADVANCED_FULL, ADVANCED_LABELLED)


classes = (VIEW3D_PT_stick_morph, VIEW3D_PT_stick_morph_drawing, VIEW3D_PT_stick_morph_pins,
           VIEW3D_PT_stick_morph_local_timing, VIEW3D_PT_stick_morph_key_poses, VIEW3D_PT_stick_morph_advanced)


register, unregister = bpy.utils.register_classes_factory(classes)
