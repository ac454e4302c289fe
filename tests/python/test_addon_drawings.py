"""Drawings at the add-on (issue 32), outside Blender: drawings.py cleans
Grease Pencil strokes and curve splines into stick figures with the engine
(stickmorph.clean_drawing), reports every change, refuses a drawing that
cannot be cleaned naming the stroke, its layer and frame, matches and morphs
the cleaned figures as meshes, and turns the morph back into strokes
(output_strokes: each input stroke's path through the morph's figure, its
thickness interpolated at inserted points).

The modules are loaded as tests/python/test_addon_core.py loads them; the
Blender side (reading legacy and v3 Grease Pencil and curves, writing the
Grease Pencil result, the panel, the scene left unchanged on errors) is
tests/blender/test_drawings.py.
"""
import types

import numpy as np
import pytest

from test_addon_core import core, load_addon_module

drawings = load_addon_module("drawings")
engine = core.load_engine()

needs_cleaning = pytest.mark.skipif(not hasattr(engine, "clean_drawing"),
                                    reason="the stickmorph module has no clean_drawing yet")


def drawing(name, strokes, where="layer 'Lines', frame 1", object_type="GPENCIL", selected=()):
    """A Drawing in the XZ plane (y = 0) from [(points [(x, z)], cyclic)],
    each stroke with a pressure rising along it and material 1."""
    made = []
    for points, cyclic in strokes:
        points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        world = np.stack([points[:, 0], np.zeros(len(points)), points[:, 1]], axis=1)
        made.append(drawings.Stroke(world, cyclic, {"pressure": np.linspace(0.5, 1.0, len(points))},
                                    {"material_index": 1}))
    return drawings.Drawing(name, object_type, made, where, selected=list(selected))


# A line, a line crossing it, and a stroke whose end stops 0.04 short of the
# first (1% of the drawing's size is about 0.045: it snaps).
CROSS_A = [([[0, 0], [1, 0.1], [4, 0]], False), ([[2, -1], [2, 1]], False), ([[3, 1], [3, 0.04]], False)]
# The same strokes drawn again: more points, moved, the end 0.05 short.
CROSS_B = [([[0, 0.5], [1, 0.2], [2, 0.1], [4, 0.3]], False), ([[2.2, -1], [2.5, 1]], False),
           ([[3.5, 1], [3.3, 0.5], [3.2, 0.25]], False)]


# ------------------------------------------------------------- helpers ----

def test_output_kind_follows_the_source():
    assert drawings.output_kind("AUTO", "GPENCIL") == "GREASE_PENCIL"
    assert drawings.output_kind("AUTO", "GREASEPENCIL") == "GREASE_PENCIL"
    assert drawings.output_kind("AUTO", "MESH") == "MESH"
    assert drawings.output_kind("AUTO", "CURVE") == "MESH"
    assert drawings.output_kind("MESH", "GREASEPENCIL") == "MESH"
    assert drawings.output_kind("GREASE_PENCIL", "MESH") == "GREASE_PENCIL"
    with pytest.raises(core.StickMorphError, match="unknown output 'PAPER'"):
        drawings.output_kind("PAPER", "MESH")


def test_figure_chains_split_at_ends_and_junctions():
    # A junction 0 with three arms (0-1-2, 3-0, 0-8), a loop 4-5-6, a dot 7.
    edges = [[0, 1], [1, 2], [3, 0], [0, 8], [4, 5], [5, 6], [6, 4]]
    chains = drawings.figure_chains(9, edges)
    assert chains == [([0, 1, 2], False), ([3, 0], False), ([0, 8], False), ([4, 5, 6], True), ([7], False)]
    # A chain entered in its middle is still walked from an end.
    assert drawings.figure_chains(3, [[1, 2], [0, 1]]) == [([2, 1, 0], False)]
    # A loop hanging on a junction is one stroke from the junction back to it.
    chains = drawings.figure_chains(4, [[0, 1], [1, 2], [2, 0], [0, 3]])
    assert sorted(map(tuple, (c for c, _ in chains))) == [(0, 1, 2, 0), (0, 3)]
    used = sorted(tuple(sorted(p)) for c, _ in chains for p in zip(c, c[1:]))
    assert used == [(0, 1), (0, 2), (0, 3), (1, 2)]


def test_point_slots_follow_the_path_in_order():
    # Points 1 and 2 merged into vertex 5; a junction 9 inserted; the path
    # passes vertex 5 twice (a loop of the stroke) and the points find it in order.
    assert drawings.point_slots([4, 5, 9, 6], [4, 5, 5, 6]).tolist() == [0, 1, 1, 3]
    assert drawings.point_slots([4, 5, 9, 5, 7], [4, 5, 9, 5, 7]).tolist() == [0, 1, 2, 3, 4]
    with pytest.raises(core.StickMorphError, match="internal error"):
        drawings.point_slots([4, 5], [5, 4])


def test_path_values_interpolate_at_inserted_points():
    positions = np.array([0.0, 1.0, 3.0, 4.0])
    # Points at path vertices 0, 1 (two merged: their mean) and 3; vertex 2
    # inserted, two thirds of the way from vertex 1 (3) to vertex 3 (5).
    values = drawings.path_values([1.0, 2.0, 4.0, 5.0], [0, 1, 1, 3], positions, 4.0, False)
    assert values.tolist() == pytest.approx([1.0, 3.0, 13.0 / 3.0, 5.0])
    # Around a cyclic stroke the closing segment counts: vertex 3 lies
    # between vertex 2 (value 3) and vertex 0 again (value 1) at length 6.
    values = drawings.path_values([1.0, 3.0], [0, 2], np.array([0.0, 1.0, 2.0, 4.0]), 6.0, True)
    assert values.tolist() == pytest.approx([1.0, 2.0, 3.0, 2.0])


def test_vertex_heights_of_merged_points_and_junctions():
    cleaned = types.SimpleNamespace(
        point_vertex=[np.array([0, 1, 1, 2]), np.array([3, 4])],
        stroke_vertices=[np.array([0, 1, 5, 2]), np.array([3, 5, 4])],
        cyclic=[False, False])
    xy = np.array([[0, 0], [1, 0], [3, 0], [2, -1], [2, 1], [2, 0]], dtype=float)
    heights = drawings.vertex_heights(cleaned, [np.array([0.0, 1.0, 3.0, 2.0]), np.array([5.0, 7.0])], xy)
    # Vertex 1 is two points (1 and 3: 2); junction 5 is first on stroke 0,
    # half way from vertex 1 (2) to vertex 2 (2).
    assert heights.tolist() == [0.0, 2.0, 2.0, 5.0, 7.0, 2.0]


def fake_pair(source_xy, edges, source_vertex):
    matching = core.Matching(bool((np.asarray(source_vertex) < 0).any()), "", np.asarray(source_vertex),
                             np.arange(len(source_vertex)), int((np.asarray(source_vertex) >= 0).sum()),
                             len(source_vertex))
    return types.SimpleNamespace(source_xy=np.asarray(source_xy, dtype=float), edges=np.asarray(edges),
                                 matching=matching)


def test_output_strokes_walk_through_the_dummies():
    # The source figure: stroke 0-1-2 and stroke 3-1. Matched: dummies 4
    # (on 0-1) and 5, 6 (on 1-3, in the order 1 5 6 3).
    xy = [[0, 0], [2, 0], [4, 0], [2, 3], [1, 0], [2, 1], [2, 2]]
    edges = [[0, 4], [4, 1], [1, 2], [1, 5], [5, 6], [6, 3]]
    pair = fake_pair(xy, edges, [0, 1, 2, 3, -1, -1, -1])
    strokes = [([0, 1, 2], False, np.array([0, 1, 2]), {"radius": np.array([1.0, 2.0, 3.0])}, {"material_index": 2}),
               ([3, 1], False, np.array([0, 1]), {"radius": np.array([0.0, 3.0])}, {})]
    out = drawings.output_strokes(pair, strokes)
    assert out[0].vertices.tolist() == [0, 4, 1, 2]
    assert out[0].point_values["radius"].tolist() == pytest.approx([1.0, 1.5, 2.0, 3.0])
    assert out[0].stroke_values == {"material_index": 2}
    assert out[1].vertices.tolist() == [3, 6, 5, 1]
    assert out[1].point_values["radius"].tolist() == pytest.approx([0.0, 1.0, 2.0, 3.0])


def test_output_strokes_close_a_cyclic_stroke_and_use_every_edge():
    # A square 0-1-2-3 with a dummy 4 on its closing edge 3-0.
    xy = [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0.5]]
    edges = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]]
    pair = fake_pair(xy, edges, [0, 1, 2, 3, -1])
    out = drawings.output_strokes(pair, [([0, 1, 2, 3], True, np.arange(4), {}, {})])
    assert out[0].vertices.tolist() == [0, 1, 2, 3, 4] and out[0].cyclic
    # An edge on no stroke is a bug, said.
    with pytest.raises(core.StickMorphError, match="internal error: 3 edges"):
        drawings.output_strokes(pair, [([0, 1, 2], False, np.arange(3), {}, {})])


# ------------------------------------------------------- with the engine ----

@needs_cleaning
def test_crossing_and_short_strokes_are_cleaned_and_said():
    settings = core.BakeSettings(frame_count=5)
    prepared, pair = drawings.prepare_drawings(drawing("A", CROSS_A), drawing("B", CROSS_B), settings)
    for side in (pair.source, pair.target):
        assert side.cleaned.junctions_made == 1 and side.cleaned.ends_snapped == 1
    assert drawings.cleaning_summary("source", pair.source) == "cleaned the source: 1 junction made, 1 end snapped"
    assert drawings.cleaning_summary("target", None) == ""
    # The counts differ (3 + 2 + 2 points against 4 + 2 + 3): matched.
    assert prepared.matching.matched and prepared.matching.why == "the vertex counts differ"
    prepared, morph = core.morph_pair(prepared, settings)
    # The morph starts on the cleaned drawing: the source's vertices first, in place.
    count = len(pair.source.xy)
    assert np.array_equal(prepared.source_xy[:count], pair.source.xy)
    first = core.unproject(prepared.source_xy, prepared.source_h, prepared.plane)
    assert np.abs(morph.frames_world[0] - first).max() < 1e-9
    assert np.abs(morph.frames_world[0][:, 1]).max() < 1e-12  # in the drawing's plane y = 0
    out = drawings.output_strokes(prepared, drawings.source_strokes(pair.source))
    assert [o.stroke_values["material_index"] for o in out] == [1, 1, 1]
    # Every input point is on its stroke, in order, with its own pressure.
    for o, stroke, cleaned_path in zip(out, pair.source.drawing.strokes, pair.source.cleaned.stroke_vertices):
        assert o.vertices[0] == cleaned_path[0] and o.vertices[-1] == cleaned_path[-1]
        assert o.point_values["pressure"][0] == pytest.approx(stroke.point_values["pressure"][0])
        assert o.point_values["pressure"][-1] == pytest.approx(stroke.point_values["pressure"][-1])
        assert np.all(np.diff(o.point_values["pressure"]) >= -1e-12)  # rising along the stroke, as drawn


@needs_cleaning
def test_a_larger_tolerance_snaps_a_farther_end():
    far = [([[0, 0], [4, 0]], False), ([[2, 1], [2, 0.3]], False)]  # 0.3 short: beyond 1% of 4.1
    target = [([[0, 0], [4, 0.2]], False), ([[2.5, 1], [2.5, 0.4]], False)]
    settings = core.BakeSettings(frame_count=3)
    prepared, pair = drawings.prepare_drawings(drawing("A", far), drawing("B", target), settings)
    assert pair.source.cleaned.ends_snapped == 0 and len(core.figure_parts(len(pair.source.xy),
                                                                           pair.source.edges)) == 2
    settings = core.BakeSettings(frame_count=3, clean_tolerance=0.1)
    prepared, pair = drawings.prepare_drawings(drawing("A", far), drawing("B", target), settings)
    assert pair.source.cleaned.ends_snapped == 1 and pair.target.cleaned.ends_snapped == 1
    assert pair.source.cleaned.tolerance == pytest.approx(0.1 * np.hypot(4.0, 1.0))


@needs_cleaning
@pytest.mark.parametrize("strokes, fragments", [
    ([], ["the drawing has no strokes"]),
    ([([[0, 0], [1, 0]], False), ([[2, 2]], False)],
     ["stroke 1 has a single point", "stroke 1 starts at (2, 0, 2) in world space"]),
    ([([[0, 0], [2, 0]], False), ([[1, 0], [3, 0]], False)], ["strokes 0 and 1 overlap along a length"]),
])
def test_a_bad_drawing_is_refused_naming_the_stroke_layer_and_frame(strokes, fragments):
    good = drawing("B", CROSS_B)
    with pytest.raises(core.StickMorphError) as error:
        drawings.prepare_drawings(drawing("Sketch", strokes, "layer 'Ink', frame 7"), good, core.BakeSettings())
    message = str(error.value)
    assert message.startswith("cannot use the source 'Sketch' (layer 'Ink', frame 7) as a stick figure: "), message
    for fragment in fragments:
        assert fragment in message, message


@needs_cleaning
def test_a_drawing_and_a_mesh_pair_up():
    # The target is the source's cleaned figure as a mesh, moved: by index
    # when the numbering agrees (Automatic), matched with By Shape.
    settings = core.BakeSettings(frame_count=3)
    prepared, pair = drawings.prepare_drawings(drawing("A", CROSS_A), drawing("B", CROSS_A), settings)
    xy, edges = pair.source.xy, pair.source.edges
    mesh = drawings.MeshFigure("Mesh", np.stack([xy[:, 0] + 5, np.zeros(len(xy)), xy[:, 1]], axis=1), edges)
    prepared, pair = drawings.prepare_drawings(drawing("A", CROSS_A), mesh, settings)
    assert pair.target is None and not prepared.matching.matched
    prepared, _ = drawings.prepare_drawings(drawing("A", CROSS_A), mesh, core.BakeSettings(correspondence="MATCH"))
    assert prepared.matching.matched
    # A mesh's pin groups cannot pin a drawing; a mesh with faces is refused as always.
    mesh.pin_groups = ("pin.001",)
    with pytest.raises(core.StickMorphError, match="'Mesh' has pin groups \\('pin.001'\\), but the other figure"):
        drawings.prepare_drawings(drawing("A", CROSS_A), mesh, settings)
    mesh.pin_groups, mesh.faces = (), 2
    with pytest.raises(core.StickMorphError, match="'Mesh' has 2 faces"):
        drawings.prepare_drawings(drawing("A", CROSS_A), mesh, settings)


@needs_cleaning
def test_by_index_needs_the_same_cleaned_figure():
    with pytest.raises(core.StickMorphError) as error:
        drawings.prepare_drawings(drawing("A", CROSS_A), drawing("B", CROSS_B),
                                  core.BakeSettings(correspondence="INDEX"))
    assert "different vertex counts: 'A' (layer 'Lines', frame 1), cleaned, has 8 vertices, 'B' (layer 'Lines', " \
           "frame 1), cleaned, has 10" in str(error.value)
    assert "By Index" in str(error.value)


@needs_cleaning
def test_selected_points_pin_in_drawing_order():
    source = drawing("A", CROSS_A, selected=[(0, 0)])
    target = drawing("B", CROSS_B, selected=[(0, 0)])
    prepared, pair = drawings.prepare_drawings(source, target, core.BakeSettings(frame_count=3), pin_selected=True)
    assert prepared.matching.matched and len(prepared.matching.pins) == 1
    pin = prepared.matching.pins[0]
    assert pin.source == pair.source.cleaned.point_vertex[0][0]
    assert pin.target == pair.target.cleaned.point_vertex[0][0]
    assert "point 0 of stroke 0 to point 0 of stroke 0" in pin.name
    # A pin the matching cannot keep (the line's start to its other end) is said, named.
    with pytest.raises(core.StickMorphError, match="the pins cannot all hold: .* 'selected point 1 \\(point 0 of "
                                                   "stroke 0 to point 3 of stroke 0\\)'"):
        drawings.prepare_drawings(source, drawing("B", CROSS_B, selected=[(0, 3)]), core.BakeSettings(),
                                  pin_selected=True)
    # Counts that differ, or none selected, are said.
    with pytest.raises(core.StickMorphError, match="has 1 selected and 'B' .* 2"):
        drawings.prepare_drawings(source, drawing("B", CROSS_B, selected=[(0, 0), (1, 1)]),
                                  core.BakeSettings(), pin_selected=True)
    with pytest.raises(core.StickMorphError, match="no point of 'B' \\(layer 'Lines', frame 1\\) is selected"):
        drawings.prepare_drawings(source, drawing("B", CROSS_B), core.BakeSettings(), pin_selected=True)
    # Curves cannot be pinned; By Index would ignore pins.
    curve = drawing("C", CROSS_B, where="", object_type="CURVE", selected=[(0, 0)])
    with pytest.raises(core.StickMorphError, match="Pin Selected Points pins two Grease Pencil drawings"):
        drawings.prepare_drawings(source, curve, core.BakeSettings(), pin_selected=True)
    with pytest.raises(core.StickMorphError, match="pins need Correspondence"):
        drawings.prepare_drawings(source, target, core.BakeSettings(correspondence="INDEX"), pin_selected=True)


@needs_cleaning
def test_a_drawing_off_its_plane_is_refused_naming_the_point():
    bent = drawing("A", CROSS_A)
    bent.strokes[1].world[1, 1] = 0.5  # point 1 of stroke 1 half a unit off the XZ plane
    with pytest.raises(core.StickMorphError) as error:
        drawings.prepare_drawings(bent, drawing("B", CROSS_B), core.BakeSettings(plane="XZ"))
    assert "point 1 of stroke 1 of 'A' (layer 'Lines', frame 1) is" in str(error.value)
    # A delay group needs a mesh source.
    with pytest.raises(core.StickMorphError, match="Delay Group 'lag' .* is not a mesh"):
        drawings.prepare_drawings(drawing("A", CROSS_A), drawing("B", CROSS_B), core.BakeSettings(delay_group="lag"))
