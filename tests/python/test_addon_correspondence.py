"""The add-on's side of figures drawn separately (issue 13), outside Blender:
choosing by index or matched (core.choose_correspondence), pins from plain
vertex-group data (core.read_pins, core.check_pins, common's naming rule),
the heights of matched vertices (core.matched_heights) and prepare_pair /
compute_morph on meshes that differ in vertex count, numbering or edges.

The modules are loaded as tests/python/test_addon_core.py loads them (its
loader and its tree pair in a tilted plane are reused); the Blender side
(vertex groups, Pin Selected Vertices, the result object) is in
tests/blender/test_correspond.py.
"""
import dataclasses

import numpy as np
import pytest

from test_addon_core import (SOURCE_WORLD, TREE_EDGES, TREE_SOURCE, TREE_TARGET, TARGET_WORLD, _N, common, core,
                             in_space)

# The tree drawn again, separately: turned by 40 degrees and scaled, in a
# parallel plane, numbered otherwise (from the end of the arm along +x),
# with a vertex more on two of its arms (9 vertices, not 7: 1 and 6 halve
# the source's edges 1-2 and 0-5) and its edges listed in another order.
# Counter-clockwise the source's arms end at 2, 4, 6, the target's at 0, 5, 8.
_TURN = np.array([[np.cos(0.7), np.sin(0.7)], [-np.sin(0.7), np.cos(0.7)]])
DENSE_TARGET = 0.8 * np.array([[2, 0.2], [1.5, 0.1], [1, 0], [0, 0], [-0.5, 0.9], [-1, 1.8], [-0.25, -0.45],
                               [-0.5, -0.9], [-0.8, -1.9]]) @ _TURN
DENSE_EDGES = np.array([[3, 4], [0, 1], [7, 6], [2, 3], [4, 5], [1, 2], [3, 6], [7, 8]])
# The target vertex each source vertex is.
DENSE_OF_SOURCE = [3, 2, 0, 4, 5, 7, 8]
DENSE_WORLD = in_space(DENSE_TARGET, [4.0, 1.0, -0.5] + 0.7 * _N)


def prepare(target=DENSE_WORLD, target_edges=DENSE_EDGES, source=SOURCE_WORLD, source_edges=TREE_EDGES,
            source_groups=None, target_groups=None, **settings):
    return core.prepare_pair(source, source_edges, 0, "Arm", target, target_edges, 0, "Arm pose",
                             core.BakeSettings(**settings), source_groups, target_groups)


def prepare_and_morph(target=DENSE_WORLD, target_edges=DENSE_EDGES, source=SOURCE_WORLD, source_edges=TREE_EDGES,
                      source_groups=None, target_groups=None, **settings):
    """(pair, MorphResult) as a bake gets them: prepare_pair, then morph_pair,
    which for Automatic morphs by index and falls back on the matching."""
    settings = core.BakeSettings(**{"frame_count": 3, **settings})
    prepared = core.prepare_pair(source, source_edges, 0, "Arm", target, target_edges, 0, "Arm pose",
                                 settings, source_groups, target_groups)
    return core.morph_pair(prepared, settings)


def fails(**changes):
    with pytest.raises(core.StickMorphError) as error:
        prepare_and_morph(**changes)
    return str(error.value)


def on_edge(world, edges, vertex, edge, fraction):
    """Where each matched vertex is on one mesh, computed here: an original
    vertex's world position, a dummy's on its edge."""
    points = []
    for v, e, f in zip(vertex, edge, fraction):
        a, b = edges[e] if v < 0 else (v, v)
        points.append((1 - f) * world[a] + f * world[b] if v < 0 else world[v])
    return np.array(points)


# ------------------------------------------------------------- choosing ----

class Check:
    """compatible_by_index for choose_correspondence, counting its calls."""

    def __init__(self, answer):
        self.answer, self.calls = answer, 0

    def __call__(self):
        self.calls += 1
        return self.answer


@pytest.mark.parametrize("setting, same_count, same_edges, pinned, compatible, expected, calls", [
    ("INDEX", False, False, True, False, (False, ""), 0),  # prepare_pair refused what INDEX cannot take
    ("MATCH", True, True, False, True, (True, ""), 0),
    ("INDEX_OR_MATCH", True, True, False, True, (False, "compatible by index"), 1),
    ("INDEX_OR_MATCH", True, True, False, False, (True, "they are not compatible by index"), 1),
    ("INDEX_OR_MATCH", False, True, False, True, (True, "the vertex counts differ"), 0),
    ("INDEX_OR_MATCH", True, False, False, True, (True, "the edges differ"), 0),
    ("INDEX_OR_MATCH", True, True, True, True, (True, "pins are given"), 0),
])
def test_choose_correspondence(setting, same_count, same_edges, pinned, compatible, expected, calls):
    check = Check(compatible)
    assert core.choose_correspondence(setting, same_count, same_edges, pinned, check) == expected
    # The engine's check runs only when the answer depends on it.
    assert check.calls == calls
    with pytest.raises(core.StickMorphError, match="unknown correspondence 'SHAPE'"):
        core.choose_correspondence("SHAPE", True, True, False, check)


def test_the_default_is_automatic():
    assert core.BakeSettings().correspondence == "INDEX_OR_MATCH" == core.CORRESPONDENCES[0]
    assert set(core.CORRESPONDENCES) == {"INDEX_OR_MATCH", "INDEX", "MATCH"}
    assert "unknown correspondence 'index'" in fails(correspondence="index")


# ----------------------------------------------------------------- pins ----

def test_pin_names():
    assert [common.is_pin_group(n) for n in ("pin.001", "Pin_hand", "PIN", "pi", "spin", "")] == \
        [True, True, True, False, False, False]
    assert common.next_pin_name([], []) == "pin.001"
    assert common.next_pin_name(["pin.001", "Group"], ["pin.002"]) == "pin.003"
    assert common.next_pin_name(["pin.002"], []) == "pin.001"  # the first free number
    assert common.pin_names(["pin.002", "Group", "Pin.a", "pin.001"], ["pin.001", "PIN.x", "pin.002"]) == \
        (["pin.001", "pin.002"], ["Pin.a"], ["PIN.x"])


def test_read_pins():
    # Only pin groups count; any case; in order of name; weights do not matter.
    pins = core.read_pins({"pin.b": [4], "Group": [0, 1, 2], "PIN.a": [2]},
                          {"pin.b": [0], "PIN.a": [7], "Other": []}, "S", "T")
    assert pins == (core.Pin("PIN.a", 2, 7), core.Pin("pin.b", 4, 0))
    assert core.read_pins({}, {"Group": [1]}) == ()
    # A vertex listed twice in one group is one vertex.
    assert core.read_pins({"pin": [3, 3]}, {"pin": [1]}) == (core.Pin("pin", 3, 1),)


@pytest.mark.parametrize("source, target, fragments", [
    ({"pin.001": [1]}, {}, ["the pin group 'pin.001' is in 'S' but not in 'T'", "same name in both meshes"]),
    ({"pin.001": [1]}, {"Pin.001": [1]}, ["'pin.001' is in 'S' but not in 'T'"]),  # names are exact
    ({}, {"pin.x": [2]}, ["'pin.x' is in 'T' but not in 'S'"]),
    ({"pin.001": []}, {"pin.001": [1]}, ["the pin group 'pin.001' of 'S' holds no vertex",
                                         "exactly one vertex in each mesh"]),
    ({"pin.001": [0]}, {"pin.001": [5, 1, 3]}, ["the pin group 'pin.001' of 'T' holds 3 vertices (1, 3, 5)"]),
    ({"pin.a": [2], "pin.b": [2]}, {"pin.a": [0], "pin.b": [1]},
     ["vertex 2 of 'S' is in two pin groups, 'pin.a' and 'pin.b'", "pinned only once"]),
    ({"pin.a": [1], "pin.b": [2]}, {"pin.a": [4], "pin.b": [4]}, ["vertex 4 of 'T' is in two pin groups"]),
])
def test_bad_pin_groups_are_refused_by_name(source, target, fragments):
    with pytest.raises(core.StickMorphError) as error:
        core.read_pins(source, target, "S", "T")
    for fragment in fragments:
        assert fragment in str(error.value), (fragment, str(error.value))


def test_check_pins_names_the_pin_that_joins_unlike_vertices():
    # The tree: 0 a junction of degree 3, 1 inside an arm, 2 an end; in the
    # target 3, 1 and 0.
    core.check_pins((core.Pin("pin.1", 0, 3), core.Pin("pin.2", 2, 0), core.Pin("pin.3", 1, 1)), TREE_EDGES,
                    DENSE_EDGES, 7, 9)
    with pytest.raises(core.StickMorphError) as error:
        core.check_pins((core.Pin("pin.1", 0, 3), core.Pin("hand", 2, 1)), TREE_EDGES, DENSE_EDGES, 7, 9, "S", "T")
    assert str(error.value) == ("the pin 'hand' joins vertex 2 of 'S', an end, to vertex 1 of 'T', inside a "
                                "stroke: a pin joins two ends, two junctions of the same degree or two vertices "
                                "inside strokes")
    with pytest.raises(core.StickMorphError, match="vertex 0 of 'S', a junction of degree 3, to vertex 0 of 'T', an end"):
        core.check_pins((core.Pin("p", 0, 0),), TREE_EDGES, DENSE_EDGES, 7, 9, "S", "T")
    with pytest.raises(core.StickMorphError, match="'p' names vertex 9 of 'T', which has 9 vertices"):
        core.check_pins((core.Pin("p", 0, 9),), TREE_EDGES, DENSE_EDGES, 7, 9, "S", "T")


def test_pins_by_index_are_an_error():
    # Pins only steer a matching: by index they would do nothing, silently.
    message = fails(target=TARGET_WORLD, target_edges=TREE_EDGES, correspondence="INDEX",
                    source_groups={"pin.001": [0], "Group": [1]}, target_groups={"pin.001": [0], "pin.002": [1]})
    assert message.startswith("pins need Correspondence (Match) Automatic or By Shape")
    assert "'pin.001', 'pin.002'" in message and "Clear Pins" in message
    # Other vertex groups are no pins.
    assert not prepare(target=TARGET_WORLD, target_edges=TREE_EDGES, correspondence="INDEX",
                       source_groups={"Group": [1]}).matching.matched


# -------------------------------------------------------------- heights ----

def test_matched_heights_interpolate_along_the_edge():
    heights = np.array([0.0, 1.0, 3.0])
    edges = np.array([[0, 1], [2, 1]])
    got = core.matched_heights(heights, edges, vertex=[2, -1, 0, -1], edge=[-1, 0, -1, 1],
                               fraction=[0.0, 0.25, 0.0, 0.5])
    assert np.array_equal(got, [3.0, 0.25, 0.0, 2.0])
    with pytest.raises(core.StickMorphError, match="internal error"):
        core.matched_heights(heights, edges, vertex=[-1], edge=[-1], fraction=[0.0])


# ------------------------------------------------------- matched pairs ----

def test_meshes_with_different_vertex_counts_are_matched_and_keep_every_vertex():
    prepared = prepare()
    matching = prepared.matching
    assert matching.matched and matching.why == "the vertex counts differ"
    assert (matching.source_count, matching.target_count) == (7, 9)
    m = len(prepared.source_xy)
    assert prepared.target_xy.shape == (m, 2) and prepared.source_h.shape == prepared.target_h.shape == (m,)
    # Rows 0..6 are the source's own vertices; every vertex of both meshes is there once.
    assert np.array_equal(matching.source_vertex[:7], np.arange(7))
    assert sorted(v for v in matching.source_vertex if v >= 0) == list(range(7))
    assert sorted(v for v in matching.target_vertex if v >= 0) == list(range(9))
    assert matching.target_vertex[:7].tolist() == DENSE_OF_SOURCE
    stats = matching.stats
    assert m == 7 + stats["source_dummies"] == 9 + stats["target_dummies"] == stats["matched_vertices"]
    # The target's two extra vertices are dummies halfway along the source's edges.
    assert (stats["source_dummies"], stats["target_dummies"]) == (2, 0)
    # The matched figure's edges join its m vertices.
    assert prepared.edges.max() == m - 1 and len(prepared.edges) == m - 1  # a tree

    # The engine's correspondence, asked here directly.
    engine = core.load_engine()
    source_xy, _ = core.project(SOURCE_WORLD, prepared.plane)
    target_xy, _ = core.project(DENSE_WORLD, prepared.plane)
    c = engine.correspond(source_xy, target_xy, TREE_EDGES, target_edges=DENSE_EDGES)["correspondence"]
    assert np.array_equal(c["source"], matching.source_vertex) and np.array_equal(c["target"], matching.target_vertex)

    # In world space the first frame is the source drawing (dummies on its
    # edges) and the last the target drawing, both in their own planes.
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=5, show_triangulation=True))
    assert morph.frames_world.shape == (5, m, 3)
    size = prepared.size
    source_places = on_edge(SOURCE_WORLD, TREE_EDGES, c["source"], c["source_edge"], c["source_fraction"])
    target_places = on_edge(DENSE_WORLD, DENSE_EDGES, c["target"], c["target_edge"], c["target_fraction"])
    assert np.abs(morph.frames_world[0] - source_places).max() <= 1e-9 * size
    assert np.abs(morph.frames_world[-1] - target_places).max() <= 1e-9 * size
    # (The dummies' heights matter: the planes are parallel, but apart.)
    assert np.ptp(prepared.source_h) <= 1e-9 * size and np.ptp(prepared.target_h) <= 1e-9 * size
    assert abs(prepared.target_h[0] - prepared.source_h[0]) > 0.1 * size
    # Each frame a valid figure compatible with the matched source.
    for frame in morph.frames_world:
        xy, _ = core.project(frame, prepared.plane)
        assert engine.check_compatibility(prepared.source_xy, xy, prepared.edges)
    # The triangulation helper's figure vertices are the matched figure's.
    source_nodes, target_nodes, _ = core.triangulation_world(morph.triangulation, prepared)
    assert np.abs(source_nodes[:m] - source_places).max() <= 1e-9 * size
    assert np.abs(target_nodes[:m] - target_places).max() <= 1e-9 * size


def test_automatic_takes_a_compatible_pair_by_index_after_one_check(monkeypatch):
    # The one check is the morph's own (issue 27): no check_compatibility,
    # no matching, one morph.
    engine = core.load_engine()
    calls = []
    check, correspond, morph = engine.check_compatibility, engine.correspond, engine.morph
    monkeypatch.setattr(engine, "check_compatibility", lambda *a, **k: calls.append("check") or check(*a, **k))
    monkeypatch.setattr(engine, "correspond", lambda *a, **k: calls.append("correspond") or correspond(*a, **k))
    monkeypatch.setattr(engine, "morph", lambda *a, **k: calls.append("morph") or morph(*a, **k))
    # The same edges, listed otherwise.
    prepared, _ = prepare_and_morph(target=TARGET_WORLD, target_edges=TREE_EDGES[::-1, ::-1])
    assert not prepared.matching.matched and prepared.matching.why == "compatible by index"
    assert calls == ["morph"]
    assert np.array_equal(prepared.matching.source_vertex, np.arange(7))
    assert np.array_equal(prepared.edges, TREE_EDGES)  # the source's edges, as before issue 13
    assert core.correspondence_summary(prepared.matching) == ("By index", "by index")
    # By index: no check of its own (the morph checks as it starts).
    calls.clear()
    assert not prepare(target=TARGET_WORLD, target_edges=TREE_EDGES, correspondence="INDEX").matching.matched
    assert calls == []


def test_automatic_matches_a_pair_that_is_not_compatible_by_index():
    # The tree's target mirrored: by index the junction's arms run the other
    # way round, but pairing two arms the other way makes it compatible.
    mirrored = in_space(TREE_TARGET * [-1.0, 1.0], [4.0, 1.0, -0.5])
    prepared, morph = prepare_and_morph(target=mirrored, target_edges=TREE_EDGES)
    assert prepared.matching.matched and prepared.matching.why == "they are not compatible by index"
    assert len(morph.frames_world) == 3
    assert not np.array_equal(prepared.matching.target_vertex, np.arange(7))
    assert prepared.matching.stats["source_dummies"] == prepared.matching.stats["target_dummies"] == 0
    assert core.correspondence_summary(prepared.matching, "Arm", "Arm pose") == (
        "Matched: 7 (0 dummies)", "matched (they are not compatible by index): 7 vertices, 0 dummies")
    # By index it is refused by the morph's own check.
    by_index = prepare(target=mirrored, target_edges=TREE_EDGES, correspondence="INDEX")
    with pytest.raises(core.StickMorphError, match="'Arm pose' is a mirror image of 'Arm'"):
        core.compute_morph(by_index, core.BakeSettings(frame_count=3))


def test_match_finds_a_shuffled_numbering():
    # The source figure turned, scaled and numbered otherwise: Match pairs
    # every vertex with the one it was before the shuffle.
    order = np.array([3, 6, 0, 5, 1, 4, 2])  # new vertex k is old vertex order[k]
    new_of_old = np.argsort(order)
    turned = in_space(0.8 * TREE_SOURCE @ _TURN, [4.0, 1.0, -0.5])
    shuffled = turned[order]
    edges = new_of_old[TREE_EDGES]
    prepared = prepare(target=shuffled, target_edges=edges, correspondence="MATCH")
    matching = prepared.matching
    assert matching.matched and matching.why == ""
    assert np.array_equal(matching.target_vertex, new_of_old)
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=3))
    assert np.abs(morph.frames_world[-1] - turned).max() <= 1e-9 * prepared.size
    short, text = core.correspondence_summary(matching, "Arm", "Arm pose")
    assert (short, text) == ("Matched: 7 (0 dummies)", "matched: 7 vertices, 0 dummies")


def test_pins_steer_the_matching():
    # Unpinned, the arms pair as drawn: ends 2, 4, 6 go to 0, 5, 8. Pinned
    # 2 -> 5 and 6 -> 0, the arms pair turned by one: 4 goes to 8.
    free = prepare().matching
    where = dict(zip(free.source_vertex.tolist(), free.target_vertex.tolist()))
    assert (where[0], where[2], where[4], where[6]) == (3, 0, 5, 8)
    pins = ({"pin.001": [2], "pin.002": [6]}, {"pin.001": [5], "pin.002": [0]})
    prepared = prepare(source_groups=pins[0], target_groups=pins[1])
    matching = prepared.matching
    assert matching.pins == (core.Pin("pin.001", 2, 5), core.Pin("pin.002", 6, 0))
    where = dict(zip(matching.source_vertex.tolist(), matching.target_vertex.tolist()))
    assert (where[0], where[2], where[4], where[6]) == (3, 5, 8, 0)
    # The pinned source vertex ends on its pinned target vertex.
    morph = core.compute_morph(prepared, core.BakeSettings(frame_count=3))
    assert np.abs(morph.frames_world[-1][2] - DENSE_WORLD[5]).max() <= 1e-9 * prepared.size
    assert np.abs(morph.frames_world[-1][6] - DENSE_WORLD[0]).max() <= 1e-9 * prepared.size
    assert core.correspondence_summary(matching, "Arm", "Arm pose")[1].endswith(", 2 pins")
    # Automatic matches whenever there are pins, even a pair compatible by index.
    pinned = prepare(target=TARGET_WORLD, target_edges=TREE_EDGES, source_groups={"pin": [2]},
                     target_groups={"pin": [2]})
    assert pinned.matching.matched and pinned.matching.why == "pins are given"


def test_unsatisfiable_pins_name_the_groups():
    # The arms ending at 2, 4, 6 (counter-clockwise) can go to those ending
    # at 0, 5, 8 turned, never reversed: 2 -> 0 with 4 -> 8 is a reversal.
    message = fails(source_groups={"pin.a": [2], "pin.b": [4]}, target_groups={"pin.a": [0], "pin.b": [8]})
    assert message.startswith("the pins cannot all hold: no matching respects every pin")
    assert "'pin.a': vertex 2 of 'Arm' to vertex 0 of 'Arm pose'; 'pin.b': vertex 4 of 'Arm' to vertex 8" in message
    assert "correspond:" not in message


# CHIRAL: a junction (0) with an end (1), a junction of degree 3 (2) and one
# of degree 4 (3): its mirror image cannot be matched however the arms pair.
CHIRAL = np.array([[0, 0], [1, 0], [-0.5, 0.9], [-0.5, -0.9], [-0.6, 1.9], [-1.4, 1.2], [-1.5, -1.0],
                   [-0.9, -1.9], [0.2, -1.8]])
CHIRAL_EDGES = np.array([[0, 1], [0, 2], [0, 3], [2, 4], [2, 5], [3, 6], [3, 7], [3, 8]])


@pytest.mark.parametrize("case", ["topology", "mirror", "exterior", "invalid"])
def test_unmatchable_pairs_say_what_differs(case):
    if case == "topology":  # a polyline is not a tree
        message = fails(target=in_space([[0, 0], [1, 0], [2, 1]], [0, 0, 0]), target_edges=[[0, 1], [1, 2]])
        assert message == ("cannot match 'Arm' and 'Arm pose': the figures' topologies cannot be matched: the "
                           "source has 3 ends and a junction of degree 3, the target 2 ends and no junction")
    elif case == "mirror":
        message = fails(source=in_space(CHIRAL, [0, 0, 0]), source_edges=CHIRAL_EDGES,
                        target=in_space(CHIRAL * [-1.0, 1.0], [0, 0, 0]), target_edges=CHIRAL_EDGES,
                        correspondence="MATCH")
        assert message.startswith("cannot match 'Arm' and 'Arm pose': 'Arm pose' is a mirror image of 'Arm': ")
        assert "a morph cannot reflect" in message and "by index" not in message
    elif case == "exterior":
        # A triangle with a stalk outside it, and with the stalk inside: the
        # same counts and edges, compatible neither by index nor matched;
        # Automatic tried both and says so.
        triangle = [[0, 0], [2, 0], [1, 1.5]]
        outside = in_space(triangle + [[-1, -0.5]], [0, 0, 0])
        inside = in_space(triangle + [[1, 0.5]], [0, 0, 0])
        edges = [[0, 1], [1, 2], [2, 0], [0, 3]]
        message = fails(source=outside, source_edges=edges, target=inside, target_edges=edges)
        assert message.startswith("cannot match 'Arm' and 'Arm pose': the figures match only with another "
                                  "face outside")
        assert "(nor are they compatible by index: the cyclic order of edges around vertex 0 differs" in message
    else:  # an invalid figure is reported as it is by index, naming the object
        crossing = TREE_TARGET.copy()
        crossing[2], crossing[6] = [-1.0, -1.0], [1.0, 1.0]
        message = fails(target=in_space(np.vstack([crossing, [[-2.0, -1.5]]]), [0, 0, 0]),
                        target_edges=np.vstack([TREE_EDGES, [[2, 7]]]))
        assert message.startswith("crossing edges: 'Arm pose': edges ")


def test_settings_are_not_changed_by_matching():
    settings = core.BakeSettings(correspondence="MATCH")
    prepared = core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "A", DENSE_WORLD, DENSE_EDGES, 0, "B", settings)
    assert dataclasses.asdict(settings) == dataclasses.asdict(core.BakeSettings(correspondence="MATCH"))
    assert prepared.matching.matched
