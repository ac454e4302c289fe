"""stickmorph.figure_parts, the binding of the engine's figure_parts
(native/stickmorph/figure_parts.h) that the add-on's report uses instead of
its own union-find (issue 27)."""

import numpy as np
import pytest

import stickmorph


def test_parts_are_numbered_by_their_smallest_vertex():
    assert stickmorph.figure_parts(7, [[5, 2], [6, 4], [2, 0]]) == [[0, 2, 5], [1], [3], [4, 6]]
    assert stickmorph.figure_parts(4, np.array([[2, 3], [0, 1], [3, 0]], dtype=np.int32)) == [[0, 1, 2, 3]]
    assert stickmorph.figure_parts(1, []) == [[0]]
    assert stickmorph.figure_parts(0, []) == []


def test_the_numbering_is_the_engines_messages():
    # Two rings, the second in the first's face: the morph's refusal names
    # "part 1", which figure_parts says is vertices 4 to 7.
    assert stickmorph.figure_parts(8, [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]) == [
        [0, 1, 2, 3], [4, 5, 6, 7]]


@pytest.mark.parametrize("vertex_count, edges, text", [
    (-1, [], "vertex_count must be from 0"),
    (2, [[0, 5]], "edge 0 names vertex 5, but there are 2 vertices"),
    (3, [[0, 1], [-1, 2]], "edge 1 names vertex -1"),
    (3, [[0, 1, 2]], "edges must have shape (#E, 2)"),
])
def test_bad_arguments_are_refused(vertex_count, edges, text):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.figure_parts(vertex_count, edges)
    assert text in str(error.value)


def test_it_has_a_docstring():
    assert "parts (connected components)" in stickmorph.figure_parts.__doc__
