"""stickmorph.edge_set_difference and stickmorph.check_pins, the engine's
edge-set comparison and pin rule for callers that word their own messages:
the add-on's compare_edge_sets and check_pins ask them instead of keeping
their own copies (issue 27)."""

import numpy as np
import pytest

import stickmorph
from test_addon_core import core


def test_edge_set_difference_is_the_engines_first_compatibility_test():
    only_source, only_target = stickmorph.edge_set_difference([[3, 1], [0, 1], [2, 1]], [[1, 0], [3, 0], [2, 3]])
    assert only_source.tolist() == [[1, 2], [1, 3]]
    assert only_target.tolist() == [[0, 3], [2, 3]]
    same = stickmorph.edge_set_difference(np.array([[0, 1], [1, 2]], dtype=np.int32), [[2, 1], [1, 0], [0, 1]])
    assert [part.tolist() for part in same] == [[], []]
    # The same answer as check_compatibility's on figures with these edges.
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    report = stickmorph.check_compatibility(square, square, [[0, 1], [1, 2], [2, 3]], [[0, 1], [1, 2], [3, 0]])
    assert report.kind == "edge_set_differs" and report.vertices == [2, 3]
    only_source, only_target = stickmorph.edge_set_difference([[0, 1], [1, 2], [2, 3]], [[0, 1], [1, 2], [3, 0]])
    assert only_source.tolist() == [[2, 3]] and only_target.tolist() == [[0, 3]]


def test_edge_set_difference_refuses_what_is_not_an_index():
    with pytest.raises(stickmorph.InvalidArgumentError, match="source_edges: edge 0 names vertex -1"):
        stickmorph.edge_set_difference([[0, -1]], [])
    with pytest.raises(stickmorph.InvalidArgumentError, match="shape"):
        stickmorph.edge_set_difference([0, 1, 2], [])


Y = (5, [[0, 1], [1, 2], [0, 3], [0, 4]])  # 0 a junction of degree 3, 1 inside the stem, 2 3 4 ends
LINE = (4, [[0, 1], [1, 2], [2, 3]])


def test_check_pins_is_the_rule_correspond_applies():
    assert stickmorph.check_pins(*Y, *LINE, [[2, 0], [1, 2], [3, 3]]) is None
    problem = stickmorph.check_pins(*Y, *LINE, [[2, 0], [0, 3]])
    assert problem == {"pin": 1, "defect": "kinds_differ", "source_degree": 3, "target_degree": 1,
                       "reason": problem["reason"]}
    # correspond refuses the same pins with the same reason.
    y_xy = [[0, 0], [0, -1], [0, -2], [-1, 1], [1, 1]]
    line_xy = [[0, 0], [1, 0], [2, 0], [3, 0]]
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.correspond(y_xy, line_xy, Y[1], target_edges=LINE[1], pins=[[2, 0], [0, 3]])
    assert str(error.value) == "correspond: " + problem["reason"]
    for pins, defect in (([[5, 0]], "missing_source_vertex"), ([[2, 4]], "missing_target_vertex"),
                         ([[2, 0], [2, 3]], "source_pinned_twice"), ([[2, 0], [3, 0]], "target_pinned_twice")):
        assert stickmorph.check_pins(*Y, *LINE, pins)["defect"] == defect


def test_check_pins_refuses_edges_outside_their_figure():
    with pytest.raises(stickmorph.InvalidArgumentError, match="target_edges: edge 0 names vertex 7, but there are 4"):
        stickmorph.check_pins(*Y, 4, [[0, 7]], [[0, 0]])


def test_the_addon_words_the_engines_answers_with_its_names():
    assert core.compare_edge_sets([[0, 1], [2, 1]], [[1, 0], [1, 2]]) is None
    message = core.compare_edge_sets([[0, 1], [1, 2]], [[1, 0], [2, 3]], "S", "T")
    assert message.endswith("edges only in 'S': 1-2; edges only in 'T': 2-3")
    with pytest.raises(core.StickMorphError, match="the pin 'p' joins vertex 0 of 'S', a junction of degree 3"):
        core.check_pins((core.Pin("p", 0, 3),), Y[1], LINE[1], 5, 4, "S", "T")
    with pytest.raises(core.StickMorphError, match="'S': edge 1 names vertex 9, but there are 3 vertices"):
        core.check_pins((core.Pin("p", 0, 1),), [[0, 1], [1, 9]], [[0, 1]], 3, 2, "S", "T")
