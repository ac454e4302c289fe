"""Figures of several parts (issue 14) at the add-on, outside Blender: a mesh
with loose parts, or with a vertex on no edge (a dot), bakes; its parts are
numbered as the engine numbers them (core.figure_parts); a part that lies in
another face of another part in the target than in the source is refused
with a message naming the objects and the part (kind nesting_differs).

The modules are loaded as tests/python/test_addon_core.py loads them (its
loader and its tilted plane are reused); the Blender side (meshes with loose
parts, the result object, its tubes) is tests/blender/test_parts.py.
"""
import numpy as np
import pytest

from test_addon_core import _N, core, in_space

# A dotted i: the stem, a polyline 0-1-2, and the dot 3 above it. The
# target bends the stem and moves the dot along.
I_SOURCE = np.array([[0.0, 0.0], [0.0, 1.0], [0.0, 2.0], [0.0, 3.0]])
I_TARGET = np.array([[0.0, 0.0], [0.4, 0.9], [0.6, 1.9], [1.1, 2.7]])
I_EDGES = np.array([[0, 1], [1, 2]])


def _ring(count, radius, turn=0.0, centre=(0.0, 0.0)):
    angles = turn + 2 * np.pi * np.arange(count) / count
    return np.stack([centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles)], axis=1)


def _inner(turn_degrees=0.0, centre=(0.0, 0.0)):
    """The inner ring: a quadrilateral without symmetry (so that a matching
    can pair it only one way), turned by turn_degrees about its centre."""
    angles = np.radians(np.array([0.0, 80.0, 170.0, 260.0]) + turn_degrees)
    radii = np.array([0.7, 0.5, 0.8, 0.6])
    return np.stack([centre[0] + radii * np.cos(angles), centre[1] + radii * np.sin(angles)], axis=1)


def _subdivided_hexagon(radius):
    """A hexagon with its edges 0-1 and 3-4 halved: 8 vertices, the corners
    at the hexagon's arc-length fractions k / 6."""
    corners = _ring(6, radius)
    points = [corners[0], (corners[0] + corners[1]) / 2, corners[1], corners[2], corners[3],
              (corners[3] + corners[4]) / 2, corners[4], corners[5]]
    return np.array(points)


def _cycle(first, count):
    return [[first + k, first + (k + 1) % count] for k in range(count)]


# A ring in a ring: a hexagon 0..5 around a quadrilateral 6..9. In the target the
# outer ring is a little larger and the inner one turned by 30 degrees.
RINGS_SOURCE = np.vstack([_ring(6, 2.0), _inner()])
RINGS_TARGET = np.vstack([_ring(6, 2.3), _inner(30.0)])
RINGS_EDGES = np.array(_cycle(0, 6) + _cycle(6, 4))
# The inner ring moved out of the outer one: its part changes face.
RINGS_OUTSIDE = np.vstack([_ring(6, 2.0), _inner(centre=(4.0, 0.0))])

SOURCE_OFFSET = np.array([1.0, -2.0, 0.5])
TARGET_OFFSET = np.array([4.0, 1.0, -0.5]) + 0.7 * _N


def prepare(source, target, edges, target_edges=None, names=("Ring", "Ring.001"), **settings):
    return core.prepare_pair(in_space(source, SOURCE_OFFSET), edges, 0, names[0],
                             in_space(target, TARGET_OFFSET), edges if target_edges is None else target_edges,
                             0, names[1], core.BakeSettings(**settings))


def check_ends_and_parts(prepared, morph, source_world, target_world, parts):
    """Frame 0 is the source, the last frame the target (world space), and
    every part moves in between."""
    size = prepared.size
    frames = morph.frames_world
    assert np.abs(frames[0] - source_world).max() <= 1e-9 * size
    assert np.abs(frames[-1] - target_world).max() <= 1e-9 * size
    middle = frames[len(frames) // 2]
    for part in parts:
        assert np.linalg.norm(middle[part] - frames[0][part], axis=1).max() > 1e-3 * size, part
        assert np.linalg.norm(frames[-1][part] - frames[0][part], axis=1).max() > 1e-2 * size, part


# ----------------------------------------------------------------- parts ----

def test_figure_parts_are_numbered_by_their_smallest_vertex():
    assert core.figure_parts(4, I_EDGES) == [[0, 1, 2], [3]]
    assert core.figure_parts(10, RINGS_EDGES) == [list(range(6)), list(range(6, 10))]
    # Numbered by the smallest vertex, whatever the edge order; dots are parts.
    assert core.figure_parts(7, [[5, 2], [6, 4], [2, 0]]) == [[0, 2, 5], [1], [3], [4, 6]]
    assert core.figure_parts(1, []) == [[0]]
    assert core.figure_parts(0, []) == []
    # One part, joined late (the union of two runs).
    assert core.figure_parts(4, [[2, 3], [0, 1], [3, 0]]) == [[0, 1, 2, 3]]
    # An edge to a missing vertex is the engine's error; it joins nothing here.
    assert core.figure_parts(2, [[0, 5]]) == [[0], [1]]


def test_parts_summary():
    assert core.parts_summary([[0, 1, 2]]) == ""
    assert core.parts_summary([]) == ""
    assert core.parts_summary([[0, 1, 2], [3]]) == "2 parts (1 dot)"
    assert core.parts_summary([[0], [1], [2, 3]]) == "3 parts (2 dots)"
    assert core.parts_summary(core.figure_parts(10, RINGS_EDGES)) == "2 parts"


# ----------------------------------------------------------------- bakes ----

@pytest.mark.parametrize("motion", ["RIGID", "BARYCENTRIC"])
def test_a_dotted_i_bakes_by_index(motion):
    prepared = prepare(I_SOURCE, I_TARGET, I_EDGES, names=("i", "i.001"))
    assert not prepared.matching.matched and prepared.matching.why == "compatible by index"
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=9, motion=motion))
    assert morph.frames_world.shape == (9, 4, 3)
    check_ends_and_parts(prepared, morph, in_space(I_SOURCE, SOURCE_OFFSET), in_space(I_TARGET, TARGET_OFFSET),
                         core.figure_parts(4, I_EDGES))
    # Every frame is a figure compatible with the source: the dot never
    # touches the stem.
    engine = core.load_engine()
    for frame in morph.frames_world:
        xy, _ = core.project(frame, prepared.plane)
        assert engine.check_compatibility(prepared.source_xy, xy, prepared.edges)


@pytest.mark.parametrize("correspondence", ["INDEX_OR_MATCH", "MATCH"])
def test_dots_alone_bake(correspondence):
    # Three vertices and no edge: three parts, each a dot.
    source = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 1.6]])
    target = np.array([[0.0, 0.3], [2.4, 0.0], [1.5, 2.0]])
    prepared = prepare(source, target, np.zeros((0, 2), dtype=np.int64), correspondence=correspondence)
    assert prepared.edges.shape == (0, 2)
    assert core.parts_summary(core.figure_parts(3, prepared.edges)) == "3 parts (3 dots)"
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=5))
    check_ends_and_parts(prepared, morph, in_space(source, SOURCE_OFFSET), in_space(target, TARGET_OFFSET),
                         [[0], [1], [2]])


def test_a_ring_in_a_ring_bakes_and_its_inner_ring_turns():
    prepared = prepare(RINGS_SOURCE, RINGS_TARGET, RINGS_EDGES)
    assert not prepared.matching.matched
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=7))
    assert morph.frames_world.shape == (7, 10, 3)
    check_ends_and_parts(prepared, morph, in_space(RINGS_SOURCE, SOURCE_OFFSET),
                         in_space(RINGS_TARGET, TARGET_OFFSET), core.figure_parts(10, RINGS_EDGES))
    # The inner ring stays inside the outer one in every frame.
    for frame in morph.frames_world:
        xy, _ = core.project(frame, prepared.plane)
        centre = xy[:6].mean(axis=0)
        assert np.linalg.norm(xy[6:] - centre, axis=1).max() < np.linalg.norm(xy[:6] - centre, axis=1).min()
    # One triangulation holds both rings (bridged): the helper's figure
    # vertices are the rings' in the source and in the target.
    assert morph.stats["parts"] == 2
    source_nodes, target_nodes, triangles = core.triangulation_world(morph.triangulation, prepared)
    assert np.abs(source_nodes[:10] - morph.frames_world[0]).max() <= 1e-9 * prepared.size
    assert np.abs(target_nodes[:10] - morph.frames_world[-1]).max() <= 1e-9 * prepared.size
    assert triangles.max() == len(source_nodes) - 1


def test_parts_drawn_separately_are_matched_part_to_part():
    # The target drawn again: the inner ring first (0..3), then the outer
    # ring with two more vertices (4..11), its edges listed backwards.
    # Automatic matches it (the vertex counts differ) and pairs the rings.
    outer = _subdivided_hexagon(2.3)
    target = np.vstack([_inner(30.0), outer])
    target_edges = np.array((_cycle(0, 4) + _cycle(4, 8))[::-1])
    prepared = prepare(RINGS_SOURCE, target, RINGS_EDGES, target_edges)
    matching = prepared.matching
    assert matching.matched and matching.why == "the vertex counts differ"
    m = len(prepared.source_xy)
    assert m == 12 and matching.stats["source_dummies"] == 2 and matching.stats["target_dummies"] == 0
    # The source's outer ring (0..5) goes to the target's outer ring, its
    # inner ring (6..9) to the target's inner ring, the dummies (on source
    # edges) to target vertices of the outer ring.
    assert set(matching.target_vertex[:6].tolist()) <= set(range(4, 12))
    assert set(matching.target_vertex[6:10].tolist()) == set(range(4))
    assert set(matching.target_vertex[10:].tolist()) <= set(range(4, 12))
    assert core.figure_parts(m, prepared.edges) == [[0, 1, 2, 3, 4, 5, 10, 11], [6, 7, 8, 9]]
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=5))
    assert morph.frames_world.shape == (5, m, 3)
    target_world = in_space(target, TARGET_OFFSET)
    assert np.abs(morph.frames_world[-1][:10] - target_world[matching.target_vertex[:10]]).max() \
        <= 1e-9 * prepared.size


# ----------------------------------------------------------------- nesting ----

def test_a_part_that_changes_face_is_refused_naming_the_objects_and_the_part():
    engine = core.load_engine()
    report = engine.check_compatibility(RINGS_SOURCE, RINGS_OUTSIDE, RINGS_EDGES)
    assert not report and report.kind == "nesting_differs" and "part 1" in report.reason
    # By index: the morph's own check refuses it.
    prepared = prepare(RINGS_SOURCE, RINGS_OUTSIDE, RINGS_EDGES, correspondence="INDEX")
    with pytest.raises(core.StickMorphError) as error:
        core.compute_morph(prepared, core.BakeSettings(frame_count=3))
    message = str(error.value)
    assert message.startswith("'Ring' and 'Ring.001': a part changes face: "), message
    assert "part 1" in message and "incompatible figures: incompatible" not in message
    # Automatic morphs by index, then tries to match, which cannot help: the
    # refusal by index (in the meshes' vertex numbers) first, then the
    # matching's, or only that it fails the same way.
    engine = core.load_engine()
    with pytest.raises(engine.IncompatibleFiguresError) as refusal:
        engine.correspond(RINGS_SOURCE, RINGS_OUTSIDE, RINGS_EDGES)
    match_kind, match_reason = refusal.value.kind, refusal.value.reason.removeprefix("correspond: ")
    assert "part" in match_reason
    with pytest.raises(core.StickMorphError) as error:
        core.morph_pair(prepare(RINGS_SOURCE, RINGS_OUTSIDE, RINGS_EDGES), core.BakeSettings(frame_count=3))
    by_index = f"'Ring' and 'Ring.001': a part changes face: {report.reason}"
    if match_kind == "nesting_differs":
        assert str(error.value) == by_index + " (matched by shape, the parts nest differently too)"
    else:
        assert str(error.value) == by_index + f" (nor can they be matched by shape: {match_reason})"
    # By Shape: the matching's own refusal.
    with pytest.raises(core.StickMorphError) as error:
        prepare(RINGS_SOURCE, RINGS_OUTSIDE, RINGS_EDGES, correspondence="MATCH")
    if match_kind == "nesting_differs":
        assert str(error.value) == f"'Ring' and 'Ring.001': a part changes face: {match_reason}"
    else:
        assert str(error.value) == f"cannot match 'Ring' and 'Ring.001': {match_reason}"


def test_a_dot_that_leaves_its_ring_is_refused():
    # A dot (vertex 6) inside a hexagon, then outside it.
    source = np.vstack([_ring(6, 2.0), [[0.3, 0.2]]])
    target = np.vstack([_ring(6, 2.0), [[3.0, 0.2]]])
    prepared = prepare(source, target, np.array(_cycle(0, 6)), correspondence="INDEX")
    with pytest.raises(core.StickMorphError, match=r"^'Ring' and 'Ring.001': a part changes face: .*part 1"):
        core.compute_morph(prepared, core.BakeSettings(frame_count=3))


@pytest.mark.parametrize("prefix", ["incompatible figures: ", "correspond: ", ""])
def test_the_nesting_message_from_the_exceptions_attributes(prefix):
    # engine_error_message and match_error_message read kind and reason
    # (set on the exception by the module), not the text.
    engine = core.load_engine()
    reason = "part 1 (vertices 6-9) lies in face 0 of part 0 in the source, outside it in the target"
    error = engine.IncompatibleFiguresError(f"incompatible figures: {reason}")
    error.kind, error.vertices, error.reason = "nesting_differs", [6], prefix + reason
    expected = f"'Ring' and 'Ring.001': a part changes face: {reason}"
    assert core.engine_error_message(error, "Ring", "Ring.001") == expected
    assert core.match_error_message(error, "Ring", "Ring.001") == expected
    # After a check by index that failed otherwise, that is said too.
    index_report = Failed("rotation_differs", "vertex 2 sees its edges in another order")
    assert core.match_error_message(error, "Ring", "Ring.001", index_report=index_report) == \
        expected + " (nor are they compatible by index: vertex 2 sees its edges in another order)"
    # By index a part changes face, and matched too: said once, by index.
    index_report = Failed("nesting_differs", "the parts nest differently: part 1 (vertices 6, 7, 8, 9) lies ...")
    assert core.match_error_message(error, "Ring", "Ring.001", index_report=index_report) == \
        "'Ring' and 'Ring.001': a part changes face: the parts nest differently: part 1 (vertices 6, 7, 8, 9) " \
        "lies ... (matched by shape, the parts nest differently too)"


class Failed:
    """A failed CompatibilityReport's stand-in (false, with kind and reason)."""

    def __init__(self, kind, reason):
        self.kind, self.reason = kind, reason

    def __bool__(self):
        return False


def test_a_pin_joins_a_dot_only_to_a_dot():
    # Vertex 3 of the i is a dot (degree 0): pinned to the target's dot it
    # passes, to an end it is refused by name.
    core.check_pins((core.Pin("pin.dot", 3, 3),), I_EDGES, I_EDGES, 4, 4)
    with pytest.raises(core.StickMorphError) as error:
        core.check_pins((core.Pin("pin.dot", 3, 2),), I_EDGES, I_EDGES, 4, 4, "i", "i.001")
    assert "the pin 'pin.dot' joins vertex 3 of 'i', a lone vertex, to vertex 2 of 'i.001', an end" \
        in str(error.value)
