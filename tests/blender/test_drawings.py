"""Grease Pencil drawings and curves in Blender (issue 32).

A Grease Pencil drawing (legacy in 3.4, v3 in 4.3 and 5.2) or a curve is
read as strokes, cleaned into a stick figure by the engine (crossings and
touchings become junctions, ends that stop short snap on; the bake's report
says every change), matched and morphed as meshes are, and baked into a
Grease Pencil object with one drawing per frame (Output Auto for a Grease
Pencil source) or the mesh with shape keys (meshes and curves). Checked
here, in every tested Blender:

- the sample stick figure (blend_samples/drawings/stick_figure_gp.blend,
  made by blend_samples/make_drawings.py): one Grease Pencil drawing per
  frame, each equal to the engine's frame, each a valid stick figure
  (rebuilt from the strokes and checked by the engine), the first on the
  source drawing and the last on the target's, the materials and the
  pressure or radius kept;
- the letters D and O as curves (a hole each) and curves of every spline
  type: every frame of the mesh result valid;
- one Grease Pencil object holding both poses (two keyframes), Pin Selected
  Points, a mesh baked into Grease Pencil;
- bad drawings (an empty layer, a single-point stroke, strokes overlapping
  along a length, a missing layer or frame, a spline of one point): an
  ERROR report naming the stroke, layer and frame, and nothing in the file
  changed (objects, meshes, Grease Pencil data, curves, actions, settings);
- the Drawing sub-panel and the rows greyed out where they do not apply.

The bpy-free part (cleaning, the strokes' paths through the morph, the
thickness) is tests/python/test_addon_drawings.py.
"""

import os
import sys

import bpy
import numpy as np
import pytest

from conftest import ROOT, addon_import, make_mesh_object, select, snapshot

sys.path.insert(0, os.path.join(ROOT, "blend_samples"))
import make_drawings  # noqa: E402

LEGACY = bpy.app.version < (4, 3, 0)
SAMPLES = os.path.join(ROOT, "blend_samples", make_drawings.DRAWINGS_DIR)
STICK_SAMPLE = os.path.join(SAMPLES, f"{make_drawings.STICK_NAME}.blend")
LETTERS_SAMPLE = os.path.join(SAMPLES, f"{make_drawings.LETTERS_NAME}.blend")


# ---------------------------------------------------------------- reading ----
# Read here with each Blender's own stroke API (not the add-on's attribute
# arrays), so that a mistake in drawing_io shows.

def layer_named(obj, name):
    for layer in obj.data.layers:
        if (layer.info if LEGACY else layer.name) == name:
            return layer
    raise KeyError(name)


def gp_strokes(obj, frame_number, layer=None):
    """[(world points (P, 3), cyclic, material index, thickness (P,))] of
    the keyframe frame_number of a layer (the first one by default):
    thickness is pressure (legacy) or radius (v3)."""
    found = obj.data.layers[0] if layer is None else layer_named(obj, layer)
    keyframe = next(f for f in found.frames if f.frame_number == frame_number)
    matrix = np.array(obj.matrix_world)
    strokes = []
    for stroke in (keyframe.strokes if LEGACY else keyframe.drawing.strokes):
        if LEGACY:
            co = np.array([p.co[:] for p in stroke.points])
            thickness = np.array([p.pressure for p in stroke.points])
            cyclic = stroke.use_cyclic
        else:
            co = np.array([p.position[:] for p in stroke.points])
            thickness = np.array([p.radius for p in stroke.points])
            cyclic = stroke.cyclic
        world = co.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]
        strokes.append((world, bool(cyclic), stroke.material_index, thickness))
    return strokes


def keyframes(obj, layer=None):
    layers = list(obj.data.layers) if layer is None else [layer_named(obj, layer)]
    return sorted(f.frame_number for lay in layers for f in lay.frames)


def figure_of(strokes):
    """The stick figure a frame's strokes draw: points at the same place
    (a junction, drawn by every stroke through it) are one vertex, every
    segment an edge. (V, 3) vertices and (E, 2) edges."""
    index, vertices, edges = {}, [], []
    for world, cyclic, *_ in strokes:
        ids = []
        for point in world:
            key = tuple(np.float32(point).tolist())
            if key not in index:
                index[key] = len(vertices)
                vertices.append(point)
            ids.append(index[key])
        edges += list(zip(ids, ids[1:])) + ([(ids[-1], ids[0])] if cyclic and len(ids) > 2 else [])
    return np.array(vertices), np.array(edges, dtype=np.int64).reshape(-1, 2)


def distance_to_strokes(points, strokes):
    """Each point's distance from the nearest segment (or point) of the strokes."""
    best = np.full(len(points), np.inf)
    for world, cyclic, *_ in strokes:
        a = world
        b = np.roll(world, -1, axis=0) if cyclic else np.vstack([world[1:], world[-1:]])
        ab = b - a
        for k in range(len(a)):
            length = ab[k] @ ab[k]
            t = np.clip(((points - a[k]) @ ab[k]) / length, 0, 1) if length > 0 else np.zeros(len(points))
            best = np.minimum(best, np.linalg.norm(points - (a[k] + t[:, None] * ab[k]), axis=1))
    return best


def size_of(*worlds):
    every = np.vstack(worlds)
    return float(np.linalg.norm(every.max(axis=0) - every.min(axis=0)))


def check_valid_frames(engine, frames_xy, edges):
    """Every frame a valid stick figure with the first frame's cyclic
    sequences: the engine's exact check of each against the first."""
    for k, xy in enumerate(frames_xy):
        try:
            engine.check_compatibility(frames_xy[0], xy, edges, edges)
        except Exception as error:  # say which frame
            raise AssertionError(f"frame {k} is not valid: {error}") from error


def full_snapshot():
    """conftest.snapshot() and the Grease Pencil and curve data it leaves
    out, and the scene's Stick Morph settings."""
    state = snapshot()
    pencils = []
    for obj in bpy.data.objects:
        if obj.type not in ("GPENCIL", "GREASEPENCIL"):
            continue
        for layer in obj.data.layers:
            for frame in layer.frames:
                strokes = gp_strokes(obj, frame.frame_number, layer.info if LEGACY else layer.name)
                pencils.append((obj.name, obj.data.name, frame.frame_number, len(strokes),
                                tuple(s[0].round(7).tobytes() for s in strokes)))
    state["grease_pencil"] = sorted(pencils)
    v3 = getattr(bpy.data, "grease_pencils_v3", None)  # 4.3; legacy (3.4) and v3 (5.x) are grease_pencils
    state["grease_pencil_data"] = sorted(d.name for d in (v3 if v3 is not None else bpy.data.grease_pencils))
    state["curves"] = sorted((c.name, tuple(len(s.points) + len(s.bezier_points) for s in c.splines),
                              getattr(c, "fill_mode", None)) for c in bpy.data.curves)
    settings = bpy.context.scene.stick_morph
    state["settings"] = {prop.identifier: str(getattr(settings, prop.identifier))
                         for prop in settings.bl_rna.properties if prop.identifier != "rna_type"}
    return state


def refused(**kwargs):
    """The pair bake expecting an ERROR report and no change at all; the message."""
    before = full_snapshot()
    with pytest.raises(RuntimeError) as error:
        bpy.ops.object.stick_morph_bake(**kwargs)
    assert full_snapshot() == before, "the file changed"
    message = str(error.value)
    assert message.startswith("Error:") and "Stick Morph" in message, message
    return message


def result_object():
    return bpy.data.objects[bpy.context.scene.stick_morph.last_result]


def open_sample(path):
    assert os.path.isfile(path), path
    assert bpy.ops.wm.open_mainfile(filepath=path, load_ui=False) == {"FINISHED"}
    settings = bpy.context.scene.stick_morph
    return settings.source, settings.target


# ------------------------------------------------------ the stick figure ----

def test_the_sample_drawing_bakes_into_one_grease_pencil_drawing_per_frame(addon, capfd):
    source, target = open_sample(STICK_SAMPLE)
    assert source.type == target.type == ("GPENCIL" if LEGACY else "GREASEPENCIL")
    count = 9
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(frame_count=count, frame_start=3) == {"FINISHED"}
    report = capfd.readouterr().out
    # Every change the cleaning made is said: the arms cross the torso, the
    # torso's ends stop short of the head and the legs.
    assert "cleaned the source: 1 junction made, 2 ends snapped" in report, report
    assert "cleaned the target: 1 junction made, 2 ends snapped" in report, report
    result = result_object()
    assert result.type == source.type and result.get("stick_morph_role") == "result"
    assert keyframes(result) == list(range(3, 3 + count))
    assert [m.name for m in result.data.materials] == ["Ink", "Head Red"]

    # Each drawing is the engine's frame: the add-on's own pipeline, run
    # again here without Blender (its reading, cleaning, matching, morph).
    core, drawing_io = addon_import("core"), addon_import("drawing_io")
    settings = core.BakeSettings(frame_count=count, frame_start=3)  # the bake's, the others default
    figures = [drawing_io.read_figure(obj, role, core.DrawingChoice(), 1, settings)
               for obj, role in ((source, "source"), (target, "target"))]
    prepared, pair = core.prepare_drawings(*figures, settings)
    prepared, morph = core.morph_pair(prepared, settings)
    out = core.output_strokes(prepared, core.source_strokes(pair.source))
    size = size_of(*(s[0] for s in gp_strokes(source, 1) + gp_strokes(target, 1)))
    engine = core.load_engine()
    for k in range(count):
        drawn = gp_strokes(result, 3 + k)
        assert len(drawn) == len(out) == 4
        for (world, cyclic, material, _), stroke in zip(drawn, out):
            assert cyclic == stroke.cyclic and material == stroke.stroke_values["material_index"]
            assert np.abs(world - morph.frames_world[k][stroke.vertices]).max() <= 1e-5 * size, k
    # Each frame is a valid stick figure (the engine's exact check of the
    # figure its strokes draw), with the first frame's cyclic sequences.
    figures = [figure_of(gp_strokes(result, 3 + k)) for k in range(count)]
    edges = figures[0][1]
    assert all(len(v) == len(figures[0][0]) and np.array_equal(e, edges) for v, e in figures)
    check_valid_frames(engine, [v[:, [0, 2]] for v, _ in figures], edges)
    # The first frame lies on the source drawing, the last on the target's
    # (up to the cleaning's snaps, within 1% of each drawing's size), and
    # every drawn point is still there.
    for frame, drawing in ((3, gp_strokes(source, 1)), (3 + count - 1, gp_strokes(target, 1))):
        points = np.vstack([s[0] for s in gp_strokes(result, frame)])
        reach = 0.011 * size_of(*(s[0] for s in drawing))
        assert distance_to_strokes(points, drawing).max() <= reach
        drawn_points = np.vstack([s[0] for s in drawing])
        assert distance_to_strokes(drawn_points, gp_strokes(result, frame)).max() <= reach
    # The thickness is the source's: each input point keeps its own, the
    # inserted points lie between.
    first = gp_strokes(result, 3)
    for (_, _, _, thickness), (world, _, _, own) in zip(first, gp_strokes(source, 1)):
        assert own.min() - 1e-6 <= thickness.min() and thickness.max() <= own.max() + 1e-6
        assert thickness[0] == pytest.approx(own[0], abs=1e-6)


def test_one_grease_pencil_object_holds_both_poses(scene, addon):
    shapes = {pose: make_drawings.stick_figure_strokes(pose) for pose in make_drawings.POSES}
    obj = make_drawings.add_grease_pencil("Poses", shapes["stick_pose_a"], frame=1)
    make_drawings.add_grease_pencil("Poses", shapes["stick_pose_b"], frame=20, obj=obj)
    bpy.context.view_layer.update()
    select(obj)
    # The same object twice, both at the current frame: the same drawing.
    message = refused(source="Poses", target="Poses", frame_count=4)
    assert "source and target are the same drawing of 'Poses' (layer 'Lines', frame 1)" in message
    assert bpy.ops.object.stick_morph_bake(source="Poses", target="Poses", source_frame=1, target_frame=25,
                                           frame_count=5, frame_start=30) == {"FINISHED"}
    result = result_object()
    assert keyframes(result) == [30, 31, 32, 33, 34]
    size = size_of(*(s[0] for s in gp_strokes(obj, 1)))
    last = np.vstack([s[0] for s in gp_strokes(result, 34)])
    assert distance_to_strokes(last, gp_strokes(obj, 20)).max() <= 0.011 * size
    # A frame before the first keyframe shows no drawing; a missing layer.
    message = refused(source="Poses", target="Poses", source_frame=1, target_frame=-5, frame_count=4)
    assert "the layer 'Lines' of 'Poses' shows no drawing at frame -5 (its keyframes: 1, 20)" in message
    message = refused(source="Poses", target="Poses", source_layer="Sketch", target_frame=20, frame_count=4)
    assert "'Poses' has no layer 'Sketch' (its layers: 'Lines')" in message


def crossing(flip=1.0, shift=0.0):
    """Three strokes: a line, a line crossing it, one stopping just short of the first."""
    ones = [1.0, 1.0, 1.0, 1.0]
    return [([(0.0, shift), (1.0, 0.1 * flip + shift), (2.0, 0.05), (4.0, shift)], False, 0, ones),
            ([(2.0 + shift, -1.0), (2.1, 0.0), (2.0, 1.0)], False, 0, ones[:3]),
            ([(3.0, 1.0), (3.0 + shift, 0.5), (3.0, 0.035 + shift / 4)], False, 0, ones[:3])]


def test_pin_selected_points_and_a_mesh_output(scene, addon, capfd):
    a = make_drawings.add_grease_pencil("A", crossing())
    b = make_drawings.add_grease_pencil("B", crossing(-1.0, 0.2), location=(5.0, 0.0, 0.0))
    bpy.context.view_layer.update()

    def select_point(obj, stroke, point):
        if LEGACY:
            # A legacy stroke's select selects all its points (measured in
            # 3.4): the stroke first, then only the one point.
            chosen = obj.data.layers[0].frames[0].strokes[stroke]
            chosen.select = True
            for other in chosen.points:
                other.select = False
            chosen.points[point].select = True
        else:
            obj.data.layers[0].frames[0].drawing.strokes[stroke].points[point].select = True

    select_point(a, 0, 0)
    select_point(b, 0, 0)
    select(a, b)
    assert bpy.ops.object.stick_morph_bake(frame_count=3, pin_selected=True, output="MESH") == {"FINISHED"}
    result = result_object()
    report = capfd.readouterr().out
    assert result.type == "MESH" and "matched (pins are given)" in report and ", 1 pin;" in report, report
    # The pinned ends meet: vertex 0 of the result (point 0 of stroke 0 of
    # A) ends on point 0 of stroke 0 of B.
    end = np.array(result.data.shape_keys.key_blocks[-1].data[0].co) + np.array(result.location)
    assert np.abs(end - gp_strokes(b, 1)[0][0][0]).max() < 1e-5
    # Two selected points in A, one in B: said.
    select_point(a, 1, 0)
    select(a, b)
    message = refused(frame_count=3, pin_selected=True)
    assert "'A' (layer 'Lines', frame 1) has 2 selected and 'B' (layer 'Lines', frame 1) 1" in message


def test_a_mesh_bakes_into_grease_pencil(scene, addon):
    xy = [[0, 0], [1, 0.2], [2, 0], [1, 1]]
    source = make_mesh_object("Tee", xy, [[0, 1], [1, 2], [1, 3]])
    target = make_mesh_object("Tee.moved", [[0, 0.5], [1, 0], [2, 0.5], [1.2, 1.2]], [[0, 1], [1, 2], [1, 3]])
    target.location.x = 4.0
    bpy.context.view_layer.update()
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(frame_count=4, output="GREASE_PENCIL") == {"FINISHED"}
    result = result_object()
    assert result.type == ("GPENCIL" if LEGACY else "GREASEPENCIL")
    assert keyframes(result) == [1, 2, 3, 4]
    # A stroke per chain (junction 1 to each end), black ink.
    strokes = gp_strokes(result, 4)
    assert len(strokes) == 3 and [m.name for m in result.data.materials] == ["Stick Morph Ink"]
    world = np.array([v.co[:] for v in target.data.vertices]) + np.array(target.location)
    ends = {tuple(np.round(point, 4)) for s in strokes for point in (s[0][0], s[0][-1])}
    assert ends == {tuple(np.round(point, 4)) for point in world}


# -------------------------------------------------------------- curves ----

def check_mesh_result_valid(result, count):
    engine = addon_import("core").load_engine()
    edges = np.array([e.vertices[:] for e in result.data.edges], dtype=np.int64)
    frames = [np.array([p.co[:] for p in block.data]) for block in result.data.shape_keys.key_blocks]
    assert len(frames) == count
    check_valid_frames(engine, [f[:, :2] for f in frames], edges)
    return frames


def test_letters_as_curves_with_holes_morph_validly(addon, capfd):
    source, target = open_sample(LETTERS_SAMPLE)
    assert source.type == target.type == "CURVE"
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(frame_count=8) == {"FINISHED"}
    assert "cleaned the source: no changes; cleaned the target: no changes" in capfd.readouterr().out
    result = result_object()
    assert result.type == "MESH"
    frames = check_mesh_result_valid(result, 8)
    parts = addon_import("core").figure_parts(len(frames[0]), [e.vertices[:] for e in result.data.edges])
    assert len(parts) == 2  # the outline and the hole
    # The ends lie on the letters' own sampled outlines.
    drawing_io = addon_import("drawing_io")
    for frame, letter in ((frames[0], source), (frames[-1], target)):
        outline = [(s.world, s.cyclic) for s in drawing_io.read_curve(letter).strokes]
        world = frame + np.array(result.location)
        assert distance_to_strokes(world, outline).max() < 1e-5


def add_curve(name, splines, location=(0.0, 0.0, 0.0)):
    """A 2D curve object of splines [(type, points [(x, y)], cyclic)]."""
    data = bpy.data.curves.new(name, "CURVE")
    data.dimensions = "2D"
    for kind, points, cyclic in splines:
        spline = data.splines.new(kind)
        if kind == "BEZIER":
            spline.bezier_points.add(len(points) - 1)
            for point, (x, y) in zip(spline.bezier_points, points):
                point.co = (x, y, 0.0)
                point.handle_left_type = point.handle_right_type = "AUTO"
        else:
            spline.points.add(len(points) - 1)
            for point, (x, y) in zip(spline.points, points):
                point.co = (x, y, 0.0, 1.0)
            if kind == "NURBS":
                spline.order_u = 3
        spline.use_cyclic_u = cyclic
    obj = bpy.data.objects.new(name, data)
    obj.location = location
    bpy.context.scene.collection.objects.link(obj)
    return obj


SQUARE = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
INNER = [(-0.4, -0.3), (0.4, -0.3), (0.3, 0.4), (-0.3, 0.35)]


def test_poly_bezier_and_nurbs_splines_are_sampled_and_morph(scene, addon):
    source = add_curve("Frame", [("POLY", SQUARE, True), ("NURBS", INNER, True)])
    target = add_curve("Ring", [("BEZIER", SQUARE, True), ("POLY", [(x * 0.8, y) for x, y in INNER], True)],
                       (4.0, 0.0, 0.0))
    target.data.resolution_u = 5
    bpy.context.view_layer.update()
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(frame_count=6) == {"FINISHED"}
    result = result_object()
    check_mesh_result_valid(result, 6)
    # The Bezier square is sampled at its resolution: 4 segments of 5.
    strokes = addon_import("drawing_io").read_curve(target).strokes
    assert [len(s.world) for s in strokes] == [20, 4] and all(s.cyclic for s in strokes)
    # And into Grease Pencil: one stroke per spline, cyclic.
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(frame_count=3, output="GREASE_PENCIL") == {"FINISHED"}
    pencil = result_object()
    assert [s[1] for s in gp_strokes(pencil, 1)] == [True, True]


# ------------------------------------------------------ bad drawings ----

BAD = {
    "an empty layer": ([], ["the drawing has no strokes", "'Bad' (layer 'Lines', frame 1)"]),
    "a single point": ([([(0.0, 0.0), (1.0, 0.0)], False, 0, [1, 1]), ([(2.0, 2.0)], False, 0, [1])],
                       ["stroke 1 has a single point", "'Bad' (layer 'Lines', frame 1)",
                        "stroke 1 starts at (2, 0, 2) in world space"]),
    "an overlap": ([([(0.0, 0.0), (2.0, 0.0)], False, 0, [1, 1]), ([(1.0, 0.0), (3.0, 0.0)], False, 0, [1, 1])],
                   ["strokes 0 and 1 overlap along a length", "'Bad' (layer 'Lines', frame 1)"]),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_a_bad_drawing_is_refused_naming_the_stroke_with_the_file_unchanged(scene, addon, case):
    strokes, fragments = BAD[case]
    good = make_drawings.add_grease_pencil("Good", crossing(), location=(6.0, 0.0, 0.0))
    bad = make_drawings.add_grease_pencil("Bad", strokes)
    bpy.context.view_layer.update()
    select(bad, good)
    message = refused(frame_count=3)
    assert "cannot use the source 'Bad' (layer 'Lines', frame 1) as a stick figure" in message, message
    for fragment in fragments:
        assert fragment in message, message
    # As the target too, after a bake that succeeded: its result stays.
    select(good, make_drawings.add_grease_pencil("Fine", crossing(-1.0, 0.2), location=(12.0, 0.0, 0.0)))
    assert bpy.ops.object.stick_morph_bake(frame_count=3) == {"FINISHED"}
    select(good, bad)
    assert "cannot use the target 'Bad'" in refused(frame_count=3)


def test_a_spline_of_one_point_is_refused_naming_it(scene, addon):
    source = add_curve("Lines", [("POLY", [(0, 0), (2, 0)], False), ("POLY", [(1, 1)], False)])
    target = add_curve("Other", [("POLY", [(0, 0), (2, 1)], False), ("POLY", [(1, 2), (1, 3)], False)], (4, 0, 0))
    bpy.context.view_layer.update()
    select(source, target)
    message = refused(frame_count=3)
    assert "cannot use the source 'Lines' as a stick figure: stroke 1 has a single point" in message
    assert "stroke i is spline i of the curve" in message


# ----------------------------------------------------------------- panel ----

def test_the_drawing_panel_and_the_greyed_rows(scene, addon):
    from test_ui import FakeLayout, active_rows, draw  # the recording layout of the panel tests

    ui = addon_import("ui")
    a = make_drawings.add_grease_pencil("A", crossing())
    mesh = make_mesh_object("M", [[0, 0], [1, 0]], [[0, 1]])
    bpy.context.view_layer.update()
    select(mesh, a)
    record = draw(bpy.types.VIEW3D_PT_stick_morph_drawing, bpy.context)
    active = active_rows(record)
    # The source is a mesh: its layer and frame do not apply, nor do pins.
    assert active == {"source_layer": False, "source_frame": False, "target_layer": True, "target_frame": True,
                      "pin_selected": False}
    assert ("search", "target_layer", "A", "layers") in record
    # Clean Tolerance applies to a pair with a drawing, not to two meshes.
    assert active_rows(draw(bpy.types.VIEW3D_PT_stick_morph, bpy.context))["clean_tolerance"]
    other = make_mesh_object("N", [[0, 0], [1, 1]], [[0, 1]])
    select(mesh, other)
    assert not active_rows(draw(bpy.types.VIEW3D_PT_stick_morph, bpy.context))["clean_tolerance"]
    # The redo panel shows the Drawing rows for a pair with a drawing only.
    op = bpy.context.window_manager.operator_properties_last("object.stick_morph_bake")
    saved = op.source, op.target
    try:
        op.source, op.target = "M", "A"
        record = []
        ui.draw_operator(FakeLayout(record), op)
        assert {"source_layer", "target_frame", "pin_selected"} <= {r[1] for r in record if r[0] == "prop"}
        op.source, op.target = "M", "N"
        record = []
        ui.draw_operator(FakeLayout(record), op)
        assert "source_layer" not in {r[1] for r in record if r[0] == "prop"}
    finally:
        op.source, op.target = saved
    # The Source and Target pickers take Grease Pencil objects and curves.
    settings = scene.stick_morph
    settings.source, settings.target = a, mesh
    assert (settings.source, settings.target) == (a, mesh)
