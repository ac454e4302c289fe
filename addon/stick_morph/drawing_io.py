"""Grease Pencil drawings and curves in Blender (issue 32): reading a layer's
drawing at a frame, or a curve's outline, into drawings.Drawing (world
space), and writing a morph as a Grease Pencil object with one drawing per
frame.

Two Grease Pencil APIs, checked in each tested Blender:
- legacy (3.4, object type GPENCIL, bpy.data.grease_pencils): a layer's
  name is `info`, its transform `matrix_layer`; frames hold `strokes`, each
  with `points` (co, pressure, strength, select), `line_width` (pixels),
  `material_index`, `use_cyclic`;
- v3 (4.3 as bpy.data.grease_pencils_v3, 5.2 as bpy.data.grease_pencils;
  object type GREASEPENCIL): a layer has `name`, `matrix_local`,
  `get_frame_at(frame)`; a frame's `drawing` keeps its strokes as curve
  attributes ("position", "radius", "opacity", ".selection" per point;
  "cyclic", "material_index", "curve_type" per stroke; `curve_offsets`).
  An attribute that was never set is absent and has Blender's default
  (radius 0.01, opacity 1, selected). 4.3 converts a legacy file's Grease
  Pencil on load (radius = line_width * pressure / 2000, measured).

Curves (CURVE, FONT) are read through Blender's own sampling: Object.to_mesh
of a temporary copy whose fill, extrusion and bevel are off, so that every
spline is a polyline at its own resolution_u (a Bezier segment with vector
handles stays one segment, NURBS as Blender evaluates them), one connected
part per spline, in spline order (measured in 3.4, 4.3 and 5.2). The copy is
removed before anything else happens, so the file is as it was.
"""

from __future__ import annotations

import bpy
import numpy as np

from . import baking, core, drawings
from .common import CURVE_TYPES, GREASE_PENCIL_TYPES, StickMorphError, is_pin_group

LEGACY_RADIUS_PER_PIXEL = 1.0 / 2000.0  # Blender's conversion of a legacy line width to a v3 radius
CURVE_TYPE_POLY = 1  # GPv3's curve_type of a poly stroke (CurveType::CURVE_TYPE_POLY)
RESULT_LAYER = "Stick Morph"
INK_ROLE = "ink"  # the ROLE tag of the material a Grease Pencil result of a mesh or curve gets


def is_legacy(obj) -> bool:
    return obj.type == "GPENCIL"


def _gp_collection():
    """bpy.data's collection of Grease Pencil data of the running Blender:
    legacy (3.x), grease_pencils_v3 (4.3), grease_pencils (5.x, v3)."""
    # Not `a or b`: an empty collection is false, and 4.3's grease_pencils
    # (its annotations' legacy type) would be taken for it.
    v3 = getattr(bpy.data, "grease_pencils_v3", None)
    return v3 if v3 is not None else bpy.data.grease_pencils


def _layer_name(layer) -> str:
    return layer.name if hasattr(layer, "name") else layer.info  # legacy layers are named by `info`


def drawing_choices(op):
    """(source, target) DrawingChoice and Pin Selected Points of an operator
    (or the scene settings): the layers and frames the bake reads."""
    return (drawings.DrawingChoice(op.source_layer.strip(), int(op.source_frame)),
            drawings.DrawingChoice(op.target_layer.strip(), int(op.target_frame)), bool(op.pin_selected))


# ------------------------------------------------------------------ read ----

def _pick_layer(obj, choice):
    layers = obj.data.layers
    names = [_layer_name(layer) for layer in layers]
    if choice.layer:
        layer = layers.get(choice.layer)
        if layer is None:
            listed = ", ".join(f"'{n}'" for n in names) or "none"
            raise StickMorphError(f"'{obj.name}' has no layer '{choice.layer}' (its layers: {listed})")
    else:
        layer = layers.active
        if layer is None:
            raise StickMorphError(f"'{obj.name}' has no active layer: choose a Layer in the Drawing panel"
                                  + ("" if names else " (it has no layers)"))
    if layer.parent is not None:
        raise StickMorphError(f"the layer '{_layer_name(layer)}' of '{obj.name}' is parented to "
                              f"'{layer.parent.name}': Stick Morph reads layers in their object's space; clear "
                              "the layer's parent")
    return layer


def _pick_frame(obj, layer, choice, scene_frame: int):
    """The layer's keyframe shown at the chosen scene frame (the current one
    for frame 0): the last keyframe at or before it."""
    at = choice.frame or scene_frame
    if is_legacy(obj):
        shown = [f for f in layer.frames if f.frame_number <= at]
        frame = max(shown, key=lambda f: f.frame_number) if shown else None
    else:
        frame = layer.get_frame_at(at)
    if frame is None:
        keys = sorted(f.frame_number for f in layer.frames)
        listed = ", ".join(str(k) for k in keys[:12]) + (" ..." if len(keys) > 12 else "")
        raise StickMorphError(
            f"the layer '{_layer_name(layer)}' of '{obj.name}' shows no drawing at frame {at} "
            f"({'its keyframes: ' + listed if keys else 'it has no keyframes'})"
            + ("" if choice.frame else "; the Frame 0 means the current frame"))
    return frame


def _uniform_scale(matrix) -> float:
    """The mean scale of a 4x4 transform (the cube root of its 3x3
    determinant), by which a stroke's thickness grows in world space."""
    determinant = abs(float(np.linalg.det(np.asarray(matrix, dtype=np.float64)[:3, :3])))
    return determinant ** (1.0 / 3.0) if determinant > 0 else 1.0


def _legacy_strokes(frame, matrix, scale):
    strokes, selected = [], []
    for i, stroke in enumerate(frame.strokes):
        points = stroke.points
        count = len(points)
        co = np.empty(count * 3, dtype=np.float32)
        pressure = np.empty(count, dtype=np.float32)
        strength = np.empty(count, dtype=np.float32)
        select = np.zeros(count, dtype=bool)
        points.foreach_get("co", co)
        points.foreach_get("pressure", pressure)
        points.foreach_get("strength", strength)
        points.foreach_get("select", select)
        local = co.reshape(-1, 3).astype(np.float64)
        strokes.append(drawings.Stroke(
            local @ matrix[:3, :3].T + matrix[:3, 3], bool(stroke.use_cyclic),
            {"pressure": pressure.astype(np.float64), "strength": strength.astype(np.float64)},
            {"material_index": int(stroke.material_index),
             "line_width": max(1, int(round(stroke.line_width * scale)))}))
        # A point counts as selected where its stroke is (4.3's conversion
        # of a legacy file keeps the same rule).
        if stroke.select:
            selected.extend((i, int(j)) for j in np.flatnonzero(select))
    return strokes, selected


def _attribute(drawing, name, count, default, width=1, dtype=np.float32):
    """An attribute of a v3 drawing as an array, Blender's default where it
    was never set (absent)."""
    attribute = drawing.attributes.get(name)
    if attribute is None:
        return np.full(count * width, default, dtype=dtype).reshape(-1, width) if width > 1 else \
            np.full(count, default, dtype=dtype)
    values = np.empty(count * width, dtype=dtype)
    attribute.data.foreach_get("vector" if width > 1 else "value", values)
    return values.reshape(-1, width) if width > 1 else values


def _v3_strokes(obj, drawing, matrix, scale, where):
    # A drawing of no strokes: 4.3's curve_offsets has length 1 but no item
    # to get (foreach_get: "given 1, needed 0"); one of n strokes has n + 1.
    offsets = np.zeros(0, dtype=np.int32)
    if len(drawing.curve_offsets) > 1:
        offsets = np.empty(len(drawing.curve_offsets), dtype=np.int32)
        drawing.curve_offsets.foreach_get("value", offsets)
    stroke_count = max(len(offsets) - 1, 0)
    point_count = int(offsets[-1]) if len(offsets) else 0
    position = _attribute(drawing, "position", point_count, 0.0, 3).astype(np.float64)
    radius = _attribute(drawing, "radius", point_count, 0.01).astype(np.float64) * scale
    opacity = _attribute(drawing, "opacity", point_count, 1.0).astype(np.float64)
    selection = _attribute(drawing, ".selection", point_count, True, dtype=bool)
    cyclic = _attribute(drawing, "cyclic", stroke_count, False, dtype=bool)
    material = _attribute(drawing, "material_index", stroke_count, 0, dtype=np.int32)
    curve_type = _attribute(drawing, "curve_type", stroke_count, CURVE_TYPE_POLY, dtype=np.int8)
    world = position @ matrix[:3, :3].T + matrix[:3, 3]
    strokes, selected = [], []
    for i in range(stroke_count):
        if int(curve_type[i]) != CURVE_TYPE_POLY:
            raise StickMorphError(
                f"'{obj.name}' ({where}): stroke {i} is not a poly stroke (a Bezier, NURBS or Catmull-Rom "
                "curve, whose points are control points): Stick Morph reads poly strokes; set its type to Poly "
                "(Edit Mode: Stroke > Set Curve Type)")
        a, b = int(offsets[i]), int(offsets[i + 1])
        strokes.append(drawings.Stroke(world[a:b], bool(cyclic[i]),
                                       {"radius": radius[a:b], "opacity": opacity[a:b]},
                                       {"material_index": int(material[i])}))
        selected.extend((i, int(j)) for j in np.flatnonzero(selection[a:b]))
    return strokes, selected


def read_grease_pencil(obj, choice, scene_frame: int, depsgraph=None) -> drawings.Drawing:
    """The drawing of obj's chosen layer at the chosen frame (DrawingChoice:
    the active layer, the current frame by default), in world space: the
    object's evaluated world matrix and the layer's own transform."""
    layer = _pick_layer(obj, choice)
    frame = _pick_frame(obj, layer, choice, scene_frame)
    name = _layer_name(layer)
    where = f"layer '{name}', frame {frame.frame_number}"
    if is_legacy(obj):
        layer_matrix = np.array(layer.matrix_layer, dtype=np.float64)
    else:
        layer_matrix = np.array(layer.matrix_local, dtype=np.float64)
    matrix = baking.world_matrix(obj, depsgraph) @ layer_matrix
    scale = _uniform_scale(matrix)
    if is_legacy(obj):
        strokes, selected = _legacy_strokes(frame, matrix, scale)
    else:
        if frame.drawing is None:
            raise StickMorphError(f"'{obj.name}' ({where}) holds no drawing of its own (a reference to other "
                                  "Grease Pencil data)")
        strokes, selected = _v3_strokes(obj, frame.drawing, matrix, scale, where)
    return drawings.Drawing(obj.name, obj.type, strokes, where, "strokes count from 0 in the layer's drawing order",
                            selected, name)


def _curve_paths(vertex_count, edges):
    """The connected parts of a sampled curve's wire mesh in order of their
    first vertex (one per spline, in spline order), each as (vertices in
    order, cyclic). Blender numbers a spline's samples along it, so a loop
    is walked from its first vertex towards the next number."""
    neighbours = [[] for _ in range(vertex_count)]
    for a, b in edges.tolist():
        neighbours[a].append(b)
        neighbours[b].append(a)
    if any(len(n) > 2 for n in neighbours):
        raise StickMorphError("internal error: a sampled curve has a vertex on three segments")
    part = np.full(vertex_count, -1, dtype=np.int64)
    parts = []
    for first in range(vertex_count):
        if part[first] >= 0:
            continue
        members, stack = [], [first]
        part[first] = len(parts)
        while stack:
            vertex = stack.pop()
            members.append(vertex)
            for other in neighbours[vertex]:
                if part[other] < 0:
                    part[other] = len(parts)
                    stack.append(other)
        parts.append(sorted(members))
    paths = []
    for members in parts:
        ends = [v for v in members if len(neighbours[v]) < 2]
        cyclic = not ends
        start = members[0] if cyclic else ends[0]
        path, previous = [start], -1
        vertex = start
        while True:
            step = [n for n in neighbours[vertex] if n != previous and n != start]
            if not step:
                break
            previous, vertex = vertex, (start + 1 if vertex == start and start + 1 in step else min(step))
            path.append(vertex)
        paths.append((path, cyclic))
    return paths


def read_curve(obj, depsgraph=None) -> drawings.Drawing:
    """A curve's (or a text's) splines as strokes: each spline sampled at
    its own resolution_u by Blender (see the module's docstring), in world
    space. The object's modifiers are not applied, as for meshes."""
    data = obj.data.copy()
    try:
        # Only the line: no fill (which would join a letter's outlines into
        # one surface), no extrusion or bevel (a surface around the line).
        data.fill_mode = "NONE" if data.dimensions == "2D" else "FULL"
        data.extrude = 0.0
        data.bevel_depth = 0.0
        data.bevel_object = None
        data.render_resolution_u = 0  # the viewport's resolution_u, the one the user sees
        temporary = bpy.data.objects.new(f"{obj.name} (sampling)", data)
        try:
            mesh = temporary.to_mesh()
            co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
            mesh.vertices.foreach_get("co", co)
            edges = np.empty(len(mesh.edges) * 2, dtype=np.int32)
            mesh.edges.foreach_get("vertices", edges)
            temporary.to_mesh_clear()
        finally:
            bpy.data.objects.remove(temporary)
    finally:
        bpy.data.curves.remove(data)
    matrix = baking.world_matrix(obj, depsgraph)
    world = co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]
    paths = _curve_paths(len(world), edges.reshape(-1, 2).astype(np.int64))
    strokes = [drawings.Stroke(world[path], cyclic) for path, cyclic in paths]
    if obj.type == "CURVE" and len(paths) == len(obj.data.splines):
        numbering = "stroke i is spline i of the curve, counting from 0"
    elif obj.type == "CURVE":
        numbering = "strokes are the curve's splines that have points, in order, counting from 0"
    else:
        numbering = "strokes are the text's outlines in order, counting from 0"
    return drawings.Drawing(obj.name, obj.type, strokes, "", numbering)


def read_figure(obj, role, choice, scene_frame, settings, depsgraph=None):
    """A MeshFigure, or a Drawing of a Grease Pencil object or a curve."""
    if obj.type == "MESH":
        world, edges, faces = baking.mesh_world_data(obj, depsgraph)
        pins = tuple(sorted(baking.vertex_groups(obj, is_pin_group)))
        delay = baking.delay_weights(obj, len(world), settings.delay_group) if role == "source" else None
        return drawings.MeshFigure(obj.name, world, edges, faces, pins, delay)
    if obj.type in GREASE_PENCIL_TYPES:
        return read_grease_pencil(obj, choice, scene_frame, depsgraph)
    if obj.type in CURVE_TYPES:
        return read_curve(obj, depsgraph)
    raise StickMorphError(f"the {role} '{obj.name}' is a {obj.type.lower()}, not a mesh, Grease Pencil or curve")


def read_pair(context, source, target, op, settings, depsgraph):
    """(source figure, target figure, pin_selected) for a pair of which one
    side at least is a drawing; the same Grease Pencil object may be both
    with two different drawings (two layers, or two frames of a layer)."""
    source_choice, target_choice, pin_selected = drawing_choices(op)
    scene_frame = context.scene.frame_current
    source_figure = read_figure(source, "source", source_choice, scene_frame, settings, depsgraph)
    target_figure = read_figure(target, "target", target_choice, scene_frame, settings, depsgraph)
    if source == target and source_figure.where == target_figure.where:
        raise StickMorphError(
            f"source and target are the same drawing of '{source.name}' ({source_figure.where}): choose another "
            "Layer or Frame for the source or the target in the Drawing panel")
    return source_figure, target_figure, pin_selected


# ----------------------------------------------------------------- write ----

def _ink_material(created):
    """The material of a Grease Pencil result made from a mesh or a curve:
    one black stroke material, made once per file (tagged) and reused."""
    for material in bpy.data.materials:
        if material.get(baking.ROLE) == INK_ROLE and material.is_grease_pencil:
            return material
    material = bpy.data.materials.new("Stick Morph Ink")
    bpy.data.materials.create_gpencil_data(material)
    material.grease_pencil.color = (0.0, 0.0, 0.0, 1.0)
    material[baking.ROLE] = INK_ROLE
    created.material = material
    return material


def _write_legacy_frame(frame, strokes, positions, defaults):
    for stroke, points in zip(strokes, positions):
        new = frame.strokes.new()
        new.display_mode = "3DSPACE"
        new.line_width = int(stroke.stroke_values.get("line_width", defaults["line_width"]))
        new.material_index = int(stroke.stroke_values.get("material_index", 0))
        new.use_cyclic = stroke.cyclic
        new.points.add(len(points))
        new.points.foreach_set("co", points.astype(np.float32).ravel())
        for name in ("pressure", "strength"):
            values = stroke.point_values.get(name)
            if values is None:
                values = np.full(len(points), defaults[name])
            new.points.foreach_set(name, np.asarray(values, dtype=np.float32))


def _set_attribute(drawing, name, data_type, domain, values, key="value"):
    attribute = drawing.attributes.get(name)
    if attribute is None:
        attribute = drawing.attributes.new(name, data_type, domain)
    attribute.data.foreach_set(key, values)


def _write_v3_frame(frame, strokes, positions, defaults):
    drawing = frame.drawing
    drawing.add_strokes([len(points) for points in positions])
    every = np.vstack(positions) if positions else np.zeros((0, 3))
    _set_attribute(drawing, "position", "FLOAT_VECTOR", "POINT", every.astype(np.float32).ravel(), "vector")
    for name in ("radius", "opacity"):
        values = [np.asarray(s.point_values.get(name, np.full(len(p), defaults[name])), dtype=np.float32)
                  for s, p in zip(strokes, positions)]
        _set_attribute(drawing, name, "FLOAT", "POINT", np.concatenate(values) if values else np.zeros(0, np.float32))
    _set_attribute(drawing, "cyclic", "BOOLEAN", "CURVE", np.array([s.cyclic for s in strokes], dtype=bool))
    _set_attribute(drawing, "material_index", "INT", "CURVE",
                   np.array([int(s.stroke_values.get("material_index", 0)) for s in strokes], dtype=np.int32))
    drawing.tag_positions_changed()


def build_grease_pencil_result(context, created, name, out_strokes, frames_world, origin, frame_start, source,
                               size, settings, layer_name, tags, report_progress=None):
    """A new Grease Pencil object `name` (recorded in created) located at
    origin, with one layer and one drawing (keyframe) per frame of the
    morph, frame_start on: each stroke's points are the morph's vertices it
    runs through in that frame. Materials: the source's (a Grease Pencil
    source), else one black ink. Thickness: the source's per point values,
    else the tube radius (settings.tube_radius of size)."""
    data = _gp_collection().new(name)
    obj = baking.new_result_object(context, created, name, data, origin, tags)
    if source.type in GREASE_PENCIL_TYPES:
        for slot in source.material_slots:
            data.materials.append(slot.material)
    else:
        data.materials.append(_ink_material(created))
    radius = core.tube_radius(size, settings.tube_radius)
    defaults = {"radius": radius, "opacity": 1.0, "pressure": 1.0, "strength": 1.0,
                "line_width": max(1, int(round(radius / LEGACY_RADIUS_PER_PIXEL)))}
    layer = data.layers.new(layer_name or RESULT_LAYER)
    legacy = obj.type == "GPENCIL"
    for k, frame_world in enumerate(frames_world):
        local = np.asarray(frame_world, dtype=np.float64) - origin
        positions = [local[stroke.vertices] for stroke in out_strokes]
        frame = layer.frames.new(frame_start + k)
        if legacy:
            _write_legacy_frame(frame, out_strokes, positions, defaults)
        else:
            _write_v3_frame(frame, out_strokes, positions, defaults)
        if report_progress and k % 16 == 0:
            report_progress(k)
    return obj


def result_builder(context, source, prepared, morph, settings, drawn, report_progress=None):
    """The make_result of baking.build_result for a Grease Pencil result.
    drawn: (source figure, drawings.DrawingPair) of a pair with a drawing,
    None for two meshes. The strokes are worked out here, before anything
    is created: a drawing's own strokes through the morph's figure, a
    mesh's chains (drawings.figure_chains)."""
    if drawn is not None and drawn[1].source is not None:
        strokes = drawings.source_strokes(drawn[1].source)
        layer_name = drawn[0].layer
    else:
        edges = drawn[0].edges if drawn is not None else baking.mesh_world_data(source)[1]
        strokes = drawings.source_strokes(None, prepared.matching.source_count, edges)
        layer_name = ""
    out = drawings.output_strokes(prepared, strokes)

    def make(created, name, origin, tags):
        return build_grease_pencil_result(context, created, name, out, morph.frames_world, origin,
                                          settings.frame_start, source, prepared.size, settings, layer_name, tags,
                                          report_progress)

    return make
