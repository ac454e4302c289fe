"""Tests of stickmorph.MorphSolver, the stateful morph solver for scrubbing.

The reference is stickmorph.morph(method="barycentric"), the paper's morph:
a MorphSolver made from the triangulation that morph used must give its
frames, bit for bit when the times are solved in morph()'s order (the same
engine solver, the same per-frame check and repair), and to the engine's
iteration tolerance (about ten digits) in any other order. The rigid morph
(the default) moves its enclosure with the figure, which a MorphSolver, a
morph inside one fixed enclosure, refuses.
"""
import random
import re
import threading

import numpy as np
import pytest

import stickmorph

# A tree with a degree-4 and a degree-3 junction, moved and stretched.
TREE_SOURCE = [[0, 0], [3, 0], [0, 3], [-3, 0], [0, -3], [4, 1], [4, -1], [-1, 4]]
TREE_TARGET = [[1, 1], [5, 2], [0.5, 4], [-2, -0.5], [2, -3], [7, 4], [6, 0], [-1.5, 5]]
TREE_EDGES = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 5], [1, 6], [2, 7]]

# A letter A: a closed loop 0 1 2 with two legs.
A_SOURCE = [[2, 6], [1, 3], [3, 3], [0, 0], [4, 0]]
A_TARGET = [[3, 7], [1.5, 3.5], [4, 3], [0, 0], [5, -1]]
A_EDGES = [[0, 1], [0, 2], [1, 2], [1, 3], [2, 4]]

FIGURES = {"tree": (TREE_SOURCE, TREE_TARGET, TREE_EDGES), "A": (A_SOURCE, A_TARGET, A_EDGES)}
WEIGHTS = ("mvc", "uniform", "floater")
FRAMES = 17

# The engine's iteration stops at a residual of 1e-10 relative to the
# right-hand side ("positions to about ten digits", morph_solver.h); on
# these small, well-conditioned systems that bounds the difference between
# two solves of one t well below 1e-8 of the figure's extent.
ORDER_TOLERANCE = 1e-8


def extent(points):
    points = np.asarray(points, dtype=float)
    return float(np.max(points.max(axis=0) - points.min(axis=0)))


@pytest.fixture(scope="module", params=[(f, w) for f in FIGURES for w in WEIGHTS], ids=lambda p: f"{p[0]}-{p[1]}")
def case(request):
    figure, weights = request.param
    source, target, edges = FIGURES[figure]
    result = stickmorph.morph(source, target, edges, frames=FRAMES, weights=weights, method="barycentric")
    return source, target, edges, weights, result


def test_endpoints_are_the_inputs_exactly(case):
    source, target, edges, weights, result = case
    solver = stickmorph.MorphSolver(result["triangulation"], edges, weights=weights)
    # Solve an interior time first so the endpoints do not come from a
    # fresh solver only.
    solver.solve(0.5)
    assert np.array_equal(solver.solve(0), np.asarray(source, dtype=float))
    assert np.array_equal(solver.solve(1.0), np.asarray(target, dtype=float))
    tri = result["triangulation"]
    assert np.array_equal(solver.solve(0, all_nodes=True), tri["source"])
    assert np.array_equal(solver.solve(1, all_nodes=True), tri["target"])


def test_in_morph_order_equals_the_morph_bit_for_bit(case):
    _, _, edges, weights, result = case
    solver = stickmorph.MorphSolver(result["triangulation"], edges, weights=weights)
    for f, t in enumerate(result["times"]):
        frame = solver.solve(t)
        assert frame.dtype == np.float64
        assert np.array_equal(frame, result["frames"][f]), f"frame {f} (t = {t})"


def test_any_order_gives_the_morph_frames(case):
    source, _, edges, weights, result = case
    solver = stickmorph.MorphSolver(result["triangulation"], edges, weights=weights)
    order = list(range(FRAMES)) * 2
    random.Random(11).shuffle(order)
    atol = ORDER_TOLERANCE * extent(source)
    for f in order:
        np.testing.assert_allclose(solver.solve(result["times"][f]), result["frames"][f], rtol=0, atol=atol,
                                   err_msg=f"frame {f}")


def test_shapes_and_all_nodes(case):
    source, _, edges, weights, result = case
    tri = result["triangulation"]
    solver = stickmorph.MorphSolver(tri, edges, weights=weights)
    n = len(source)
    nodes = tri["figure_vertices"] + tri["enclosure_vertices"] + tri["steiner_vertices"]
    assert solver.solve(0.3).shape == (n, 2)
    everything = solver.solve(0.3, all_nodes=True)
    assert everything.shape == (nodes, 2)
    np.testing.assert_allclose(everything[:n], solver.solve(0.3), rtol=0, atol=ORDER_TOLERANCE * extent(source))
    # The enclosure is fixed: the same nodes as in the source.
    k = tri["enclosure_vertices"]
    assert np.array_equal(everything[n:n + k], tri["source"][n:n + k])
    assert solver.weights == weights


def test_verify_false_skips_only_the_check(case):
    _, _, edges, weights, result = case
    checked = stickmorph.MorphSolver(result["triangulation"], edges, weights=weights)
    unchecked = stickmorph.MorphSolver(result["triangulation"], edges, weights=weights)
    atol = ORDER_TOLERANCE * extent(result["frames"][0])
    for t in result["times"]:
        # A frame the check repairs may differ in the last digits.
        np.testing.assert_allclose(unchecked.solve(t, verify=False), checked.solve(t), rtol=0, atol=atol)


# A path 0-1-2-3 whose last vertex swings from (0, 4) to (5, 2). Edge 3-0 is
# not in the triangulation: it closes a square in the source but crosses
# edge 1-2 in the target. The frame certificate needs every figure edge to
# be a triangulation edge, so the solver refuses it at once.
PATH_SOURCE = [[0, 0], [4, 0], [4, 4], [0, 4]]
PATH_TARGET = [[0, 0], [4, 0], [4, 4], [5, 2]]
PATH_EDGES = [[0, 1], [1, 2], [2, 3]]


def test_a_figure_edge_off_the_triangulation_is_refused():
    tri = stickmorph.triangulate_figures(PATH_SOURCE, PATH_TARGET, PATH_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError,
                       match=r"figure edge 3 \(3-0\) is not an edge of the triangulation"):
        stickmorph.MorphSolver(tri, PATH_EDGES + [[3, 0]])
    # With the figure's own edges the same triangulation morphs validly.
    valid = stickmorph.MorphSolver(tri, PATH_EDGES)
    for t in np.linspace(0, 1, 9):
        valid.solve(t)


@pytest.mark.parametrize("t, shown", [(-0.25, "-0.25"), (1.5, "1.5"), (float("nan"), "nan"),
                                      (float("inf"), "inf"), (-1e-300, "-1e-300")])
def test_time_out_of_range(t, shown):
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    solver = stickmorph.MorphSolver(tri, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"t must be in \[0, 1\], got " + shown):
        solver.solve(t)
    # The solver is still usable afterwards.
    assert solver.solve(0.5).shape == (len(A_SOURCE), 2)


@pytest.mark.parametrize("t", ["0.5", True, None, [0.5]])
def test_time_not_a_number(t):
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    solver = stickmorph.MorphSolver(tri, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"t must be a number in \[0, 1\]"):
        solver.solve(t)


def test_time_accepts_ints_and_numpy_scalars():
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    solver = stickmorph.MorphSolver(tri, A_EDGES)
    assert np.array_equal(solver.solve(np.float32(0.5)), solver.solve(0.5, verify=True))
    assert np.array_equal(solver.solve(np.int64(1)), np.asarray(A_TARGET, dtype=float))


def test_bad_weights():
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match="unknown weight kind 'cotan'"):
        stickmorph.MorphSolver(tri, A_EDGES, weights="cotan")
    with pytest.raises(stickmorph.InvalidArgumentError, match="weights must be a str"):
        stickmorph.MorphSolver(tri, A_EDGES, weights=1)


def test_bad_flags():
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    solver = stickmorph.MorphSolver(tri, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match="verify must be True or False"):
        solver.solve(0.5, verify="no")
    with pytest.raises(stickmorph.InvalidArgumentError, match="all_nodes must be True or False"):
        solver.solve(0.5, all_nodes=1)


def test_bad_triangulations():
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match="must be the dict triangulate_figures returns"):
        stickmorph.MorphSolver([1, 2], A_EDGES)
    missing = {key: value for key, value in tri.items() if key != "triangles"}
    with pytest.raises(stickmorph.InvalidArgumentError, match="no 'triangles' entry"):
        stickmorph.MorphSolver(missing, A_EDGES)
    out_of_range = dict(tri, triangles=np.where(tri["triangles"] == 0, 10**12, tri["triangles"]))
    with pytest.raises(stickmorph.InvalidArgumentError, match="refers to a node out of range"):
        stickmorph.MorphSolver(out_of_range, A_EDGES)
    flipped = dict(tri, triangles=tri["triangles"][:, ::-1])
    with pytest.raises(stickmorph.InvalidArgumentError, match="invalid triangulation for the morph"):
        stickmorph.MorphSolver(flipped, A_EDGES)
    negative = dict(tri, steiner_vertices=-1)
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"triangulation\['steiner_vertices'\]"):
        stickmorph.MorphSolver(negative, A_EDGES)


def test_threads_share_one_solver():
    result = stickmorph.morph(TREE_SOURCE, TREE_TARGET, TREE_EDGES, frames=FRAMES, method="barycentric")
    solver = stickmorph.MorphSolver(result["triangulation"], TREE_EDGES)
    atol = ORDER_TOLERANCE * extent(TREE_SOURCE)
    failures = []

    def scrub(seed):
        rng = random.Random(seed)
        for _ in range(40):
            f = rng.randrange(FRAMES)
            frame = solver.solve(result["times"][f])
            if not np.allclose(frame, result["frames"][f], rtol=0, atol=atol):
                failures.append(f)

    threads = [threading.Thread(target=scrub, args=(seed,)) for seed in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert failures == []


@pytest.mark.parametrize("figure", FIGURES)
def test_the_rigid_morphs_moving_enclosure_is_refused(figure):
    # The default morph's triangulation is in output space: its target
    # enclosure is the source's turned, scaled and moved, so it is no
    # triangulation of one fixed enclosure.
    source, target, edges = FIGURES[figure]
    result = stickmorph.morph(source, target, edges, frames=3)
    assert result["stats"]["method"] == "rigid" and result["stats"]["rigid"]["similarity_factored"]
    n = result["triangulation"]["figure_vertices"]
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.MorphSolver(result["triangulation"], edges)
    assert re.fullmatch(r"invalid triangulation for the morph: node (\d+) \(enclosure vertex (\d+)\) moves: "
                        r"the enclosure must be the same in source and target", str(error.value)), str(error.value)
    node, corner = map(int, re.fullmatch(r".*node (\d+) \(enclosure vertex (\d+)\).*", str(error.value)).groups())
    assert node == n + corner
    assert isinstance(error.value, ValueError)
    # triangulate_figures' triangulation of the same pair, whose enclosure
    # is fixed, is accepted.
    tri = stickmorph.triangulate_figures(source, target, edges)
    stickmorph.MorphSolver(tri, edges).solve(0.5)


def test_docstrings():
    assert "#n by 2" in stickmorph.MorphSolver.solve.__doc__
    assert "verify" in stickmorph.MorphSolver.solve.__doc__
    assert "triangulate_figures" in stickmorph.MorphSolver.__doc__
