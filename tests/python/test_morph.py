"""Tests of the Python `morph` and `triangulate_figures` functions.

The engine verifies its own frames; these tests do not trust that. Every
frame is re-checked here in pure Python with exact rational arithmetic on the
returned doubles (fractions.Fraction): no two non-adjacent edges meet, no two
adjacent edges overlap, no two vertices coincide, the counter-clockwise order
of the neighbours around every vertex (sorted by exact angle comparison) is
the source's, and the same face is the unbounded one. The triangulation is
re-checked the same way: every triangle positive in both embeddings, the
enclosure convex in both, and the triangles tiling it.

The default method is rigid (issue 12): it factors out the best-fit
similarity between the figures, so its triangulation is in output space and
its target enclosure is the source's moved by that similarity (the paper's
section 6 "rotated enclosure"); the barycentric method's enclosure is the
same polygon in both figures, and triangulate_figures gives its
triangulation.
"""
import functools
import math
import re
import threading
from fractions import Fraction

import numpy as np
import pytest

import stickmorph
from rigid_stats import check_rigid_section

# --------------------------------------------------------------------------
# Figures

# A unit-free tree: a degree-4 junction at 0 and a degree-3 junction at 1.
TREE_SOURCE = [[0, 0], [3, 0], [0, 3], [-3, 0], [0, -3], [4, 1], [4, -1], [-1, 4]]
TREE_TARGET = [[1, 1], [5, 2], [0.5, 4], [-2, -0.5], [2, -3], [7, 4], [6, 0], [-1.5, 5]]
TREE_EDGES = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 5], [1, 6], [2, 7]]

# A letter A: apex 0, crossbar 1-2 closing the loop 0 1 2, legs 1-3 and 2-4.
A_SOURCE = [[2, 6], [1, 3], [3, 3], [0, 0], [4, 0]]
A_TARGET = [[3, 7], [1.5, 3.5], [4, 3], [0, 0], [5, -1]]
A_EDGES = [[0, 1], [0, 2], [1, 2], [1, 3], [2, 4]]

# A square with a dangling edge inside it, hanging from corner 1; in the
# target the square is skewed and the dangling vertex has swung across to
# the far corner, so the edge turns and stretches a long way.
DANGLING_SOURCE = [[0, 0], [4, 0], [4, 4], [0, 4], [3, 1]]
DANGLING_TARGET = [[0, 0], [5, 1], [4, 5], [-1, 3], [0.25, 3.25]]
DANGLING_EDGES = [[0, 1], [1, 2], [2, 3], [3, 0], [1, 4]]

# A small convex-to-non-convex hexagon, used to try every option.
HEXAGON_SOURCE = [[2, 0], [4, 0], [5, 2], [4, 4], [2, 4], [1, 2]]
HEXAGON_TARGET = [[0, 0], [6, 1], [4, 3], [6, 6], [1, 5], [2, 2.5]]
HEXAGON_EDGES = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0]]



def no_compatibility_steiner(result):
    """A rigid morph of one figure moved as a whole: the normalised pair is one figure, so no
    Steiner vertex is needed for compatibility; those there are compatible refinement's, for
    the triangles' angles (issue 30)."""
    return result["stats"]["steiner_vertices"] == result["stats"]["rigid"]["refinement_steiner_vertices"]

def paper_pair(data_dir):
    """The paper's Figure 8 S -> U polylines."""
    source = stickmorph.load_figure(data_dir / "paper" / "s_to_u.source.json")
    target = stickmorph.load_figure(data_dir / "paper" / "s_to_u.target.json")
    return source["vertices"], target["vertices"], source["edges"]


def named_pair(name, data_dir):
    if name == "tree_junction":
        return TREE_SOURCE, TREE_TARGET, TREE_EDGES
    if name == "letter_a":
        return A_SOURCE, A_TARGET, A_EDGES
    if name == "square_dangling_inside":
        return DANGLING_SOURCE, DANGLING_TARGET, DANGLING_EDGES
    if name == "s_to_u":
        return paper_pair(data_dir)
    raise AssertionError(name)


PAIRS = ["tree_junction", "letter_a", "square_dangling_inside", "s_to_u"]

# --------------------------------------------------------------------------
# Exact geometry on doubles


def exact_points(points):
    """Each coordinate as the Fraction equal to its double, exactly."""
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in np.asarray(points, dtype=float)]


def sign(value):
    return (value > 0) - (value < 0)


def orient(a, b, c):
    """+1 if a b c turn counter-clockwise, -1 clockwise, 0 collinear (exact)."""
    return sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def in_box(p, a, b):
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def closed_segments_meet(a, b, c, d):
    """True iff the closed segments ab and cd share a point."""
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return ((o1 == 0 and in_box(c, a, b)) or (o2 == 0 and in_box(d, a, b))
            or (o3 == 0 and in_box(a, c, d)) or (o4 == 0 and in_box(b, c, d)))


def direction_order(u, v):
    """Comparator of two direction vectors by angle in [0, 2 pi), exactly."""
    def half(d):
        return 0 if d[1] > 0 or (d[1] == 0 and d[0] > 0) else 1
    if half(u) != half(v):
        return half(u) - half(v)
    return -sign(u[0] * v[1] - u[1] * v[0])


def rotation(points, edges):
    """Neighbours of every vertex, counter-clockwise by exact angle."""
    neighbours = [[] for _ in points]
    for i, j in edges:
        neighbours[i].append(j)
        neighbours[j].append(i)
    result = []
    for v, around in enumerate(neighbours):
        def key(w, v=v):
            return (points[w][0] - points[v][0], points[w][1] - points[v][1])
        ordered = sorted(around, key=lambda w: functools.cmp_to_key(direction_order)(key(w)))
        result.append(ordered)
    return result


def canonical_cycle(sequence):
    """The rotation of a cyclic sequence of distinct items starting at its minimum."""
    if not sequence:
        return ()
    k = sequence.index(min(sequence))
    return tuple(sequence[k:] + sequence[:k])


def faces(points, rotation_system):
    """The faces as lists of darts (u, v), each face to the left of its darts,
    with their exact signed areas (interior faces positive)."""
    position = {(v, w): k for v, around in enumerate(rotation_system) for k, w in enumerate(around)}
    seen, result = set(), []
    for start in sorted(position):
        dart = start
        if dart in seen:
            continue
        walk, area = [], Fraction(0)
        while dart not in seen:
            seen.add(dart)
            walk.append(dart)
            u, v = dart
            area += points[u][0] * points[v][1] - points[v][0] * points[u][1]
            around = rotation_system[v]
            # The next edge clockwise from v-u around v bounds the left face.
            w = around[(position[(v, u)] - 1) % len(around)]
            dart = (v, w)
        result.append((walk, area / 2))
    return result


def exterior_face(points, rotation_system):
    """The darts of the one face that is not positively oriented, or None."""
    outer = [frozenset(walk) for walk, area in faces(points, rotation_system) if area <= 0]
    assert len(outer) <= 1, f"{len(outer)} faces are not positively oriented"
    return outer[0] if outer else None


class Topology:
    """What every frame must share with the source."""

    def __init__(self, points, edges):
        self.edges = [tuple(int(i) for i in e) for e in np.asarray(edges).reshape(-1, 2)]
        exact = exact_points(points)
        system = rotation(exact, self.edges)
        self.rotation = [canonical_cycle(around) for around in system]
        self.exterior = exterior_face(exact, system)


def frame_problems(points, topology):
    """Every way `points` with the topology's edges fails to be a stick
    figure with the topology's rotations and exterior face; [] if none."""
    exact = exact_points(points)
    problems = []
    if len(set(exact)) != len(exact):
        problems.append("coincident vertices")
    edges = topology.edges
    for a in range(len(edges)):
        for b in range(a + 1, len(edges)):
            shared = set(edges[a]) & set(edges[b])
            if not shared:
                p, q = (exact[i] for i in edges[a])
                r, s = (exact[i] for i in edges[b])
                if closed_segments_meet(p, q, r, s):
                    problems.append(f"edges {edges[a]} and {edges[b]} meet")
            else:
                (c,) = shared
                (i,) = set(edges[a]) - shared
                (j,) = set(edges[b]) - shared
                u = (exact[i][0] - exact[c][0], exact[i][1] - exact[c][1])
                w = (exact[j][0] - exact[c][0], exact[j][1] - exact[c][1])
                if orient(exact[c], exact[i], exact[j]) == 0 and u[0] * w[0] + u[1] * w[1] > 0:
                    problems.append(f"edges {edges[a]} and {edges[b]} overlap")
    system = rotation(exact, edges)
    for v, around in enumerate(system):
        if canonical_cycle(around) != topology.rotation[v]:
            problems.append(f"vertex {v}: neighbours {around}, source {list(topology.rotation[v])}")
    if not problems and exterior_face(exact, system) != topology.exterior:
        problems.append("another face is the exterior one")
    return problems


# The checker itself must be able to say no, or the morph tests prove nothing.


def test_checker_accepts_the_source_and_rejects_broken_frames():
    topology = Topology(A_SOURCE, A_EDGES)
    assert frame_problems(A_SOURCE, topology) == []
    # Apex pulled below the crossbar: no crossing, but the loop 0 1 2 turns
    # over, which reverses the cyclic order of neighbours at 1 and 2.
    flipped = [[2, 1], [1, 3], [3, 3], [0, 0], [4, 0]]
    assert frame_problems(flipped, topology)
    # The right leg swung across the left one: a crossing.
    crossing = [[2, 6], [1, 3], [3, 3], [0, 0], [-1, 1]]
    assert any("meet" in p for p in frame_problems(crossing, topology))
    # The left leg's foot exactly on the right leg: a touching, no crossing.
    touching = [[2, 6], [1, 3], [3, 3], [3.5, 1.5], [4, 0]]
    assert any("meet" in p for p in frame_problems(touching, topology))
    # The left leg folded back onto the crossbar: adjacent edges overlap.
    overlapping = [[2, 6], [1, 3], [3, 3], [2, 3], [4, 0]]
    assert any("overlap" in p for p in frame_problems(overlapping, topology))
    # Two vertices at one point.
    coincident = [[2, 6], [1, 3], [3, 3], [0, 0], [0, 0]]
    assert "coincident vertices" in frame_problems(coincident, topology)


def test_checker_tells_exterior_faces_apart():
    # The same rotation at every vertex, but another face outside (the pair
    # of tests/data/pairs/incompatible/exterior_differs has the same trait).
    wheel = [[0.0, 0.0], [4.0, 0.0], [2.0, 4.0], [2.0, 1.0]]
    other = [[0.0, 0.0], [2.0, 4.0], [2.0, 1.0], [4.0, 0.0]]
    edges = [[0, 1], [1, 2], [2, 0], [0, 3], [1, 3], [2, 3]]
    topology = Topology(wheel, edges)
    assert Topology(other, edges).rotation == topology.rotation
    assert frame_problems(other, topology) == ["another face is the exterior one"]


def test_checker_sorts_by_exact_angle():
    # Directions one ulp apart, which floating-point angles may not tell
    # apart: the exact comparison puts them in order.
    tiny = np.nextafter(1.0, 2.0)
    points = [[0.0, 0.0], [1.0, 1.0], [1.0, tiny], [-1.0, 0.0]]
    assert rotation(exact_points(points), [(0, 1), (0, 2), (0, 3)])[0] == [1, 2, 3]
    points = [[0.0, 0.0], [1.0, 1.0], [tiny, 1.0], [-1.0, 0.0]]
    assert rotation(exact_points(points), [(0, 1), (0, 2), (0, 3)])[0] == [2, 1, 3]


# --------------------------------------------------------------------------
# Triangulation checks


def similarity_image(similarity, points):
    """`points` moved by a rigid morph's fitted similarity at t = 1."""
    angle = math.radians(similarity["angle_degrees"])
    scale = similarity["scale"]
    turn = scale * np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])
    return (np.asarray(points, float) - similarity["source_center"]) @ turn.T + similarity["target_center"]


def check_triangulation(tri, source, target, edges, similarity=None):
    """Everything FORMAT.md promises about a triangulation dict, exactly.

    Without `similarity` (the barycentric morph, triangulate_figures) the
    enclosure is the same polygon in both embeddings. With it (the rigid
    morph's stats["rigid"]["similarity"], when factored out) the target's
    enclosure is the source's moved by that similarity."""
    assert set(tri) == {"figure_vertices", "enclosure_vertices", "steiner_vertices", "source",
                        "target", "triangles", "stats"}
    n, k, s = tri["figure_vertices"], tri["enclosure_vertices"], tri["steiner_vertices"]
    for count in (n, k, s):
        assert type(count) is int
    source = np.asarray(source, dtype=float)
    target = np.asarray(target, dtype=float)
    assert n == len(source) and k >= 3 and s >= 0
    nodes = n + k + s
    for positions in (tri["source"], tri["target"]):
        assert isinstance(positions, np.ndarray)
        assert positions.dtype == np.float64 and positions.shape == (nodes, 2)
    # Figure vertices first, exactly as given.
    assert np.array_equal(tri["source"][:n], source)
    assert np.array_equal(tri["target"][:n], target)
    # The enclosure: identical in both (or moved by the similarity),
    # strictly convex and counter-clockwise in both.
    if similarity is None:
        assert np.array_equal(tri["source"][n:n + k], tri["target"][n:n + k])
    else:
        ring = tri["target"][n:n + k]
        np.testing.assert_allclose(ring, similarity_image(similarity, tri["source"][n:n + k]), rtol=0,
                                   atol=1e-12 * np.ptp(ring, axis=0).max())
    for embedding in (tri["source"], tri["target"]):
        ring = exact_points(embedding[n:n + k])
        for i in range(k):
            assert orient(ring[i], ring[(i + 1) % k], ring[(i + 2) % k]) > 0, i

    triangles = tri["triangles"]
    assert isinstance(triangles, np.ndarray)
    assert triangles.dtype == np.int64 and triangles.ndim == 2 and triangles.shape[1] == 3
    assert triangles.min() >= 0 and triangles.max() < nodes
    # A triangulated disk with k boundary nodes has 2 * nodes - k - 2 triangles.
    assert len(triangles) == 2 * nodes - k - 2
    # Positive in both embeddings, exactly; they tile the enclosure (each
    # interior edge in two triangles, in opposite directions, each enclosure
    # side in one) and cover exactly its area.
    darts = set()
    for embedding in (tri["source"], tri["target"]):
        exact = exact_points(embedding)
        ring = exact[n:n + k]
        area = Fraction(0)
        for a, b, c in triangles:
            assert orient(exact[a], exact[b], exact[c]) > 0, (a, b, c)
            area += ((exact[b][0] - exact[a][0]) * (exact[c][1] - exact[a][1])
                     - (exact[b][1] - exact[a][1]) * (exact[c][0] - exact[a][0])) / 2
        enclosure_area = sum(ring[i][0] * ring[(i + 1) % k][1] - ring[(i + 1) % k][0] * ring[i][1]
                             for i in range(k)) / 2
        assert area == enclosure_area
    for a, b, c in triangles.tolist():
        for dart in ((a, b), (b, c), (c, a)):
            assert dart not in darts, dart
            darts.add(dart)
    boundary = {(n + i, n + (i + 1) % k) for i in range(k)}
    for u, v in darts:
        assert ((v, u) in darts) != ((u, v) in boundary), (u, v)
    # Every figure edge is a triangulation edge.
    for i, j in np.asarray(edges).reshape(-1, 2).tolist():
        assert (i, j) in darts or (j, i) in darts, (i, j)

    stats = tri["stats"]
    assert set(stats) == {"interior_faces", "cut_bends", "interior_steiner", "min_angle", "parts", "bridges",
                          "bridge_bends"}
    assert stats["bridges"] == stats["parts"] - 1 and 0 <= stats["bridge_bends"]
    interior = [f for f in stickmorph.decompose(source, edges) if not f["exterior"]]
    assert stats["interior_faces"] == len(interior)
    assert 0 <= stats["cut_bends"] and 0 <= stats["interior_steiner"]
    assert stats["cut_bends"] + stats["interior_steiner"] <= s
    angles = []
    for embedding in (tri["source"], tri["target"]):
        for corner in range(3):
            p = embedding[triangles[:, corner]]
            q = embedding[triangles[:, (corner + 1) % 3]]
            r = embedding[triangles[:, (corner + 2) % 3]]
            u, w = q - p, r - p
            angles.append(np.arctan2(np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]),
                                     (u * w).sum(axis=1)))
    assert 0 < stats["min_angle"] < np.pi / 3 + 1e-12
    assert stats["min_angle"] == pytest.approx(np.concatenate(angles).min(), rel=1e-9)


def check_morph(result, source, target, edges, frames):
    """Shapes and endpoints of a morph result, and every frame exactly valid."""
    source = np.asarray(source, dtype=float)
    target = np.asarray(target, dtype=float)
    times, out = result["times"], result["frames"]
    assert isinstance(times, np.ndarray) and times.dtype == np.float64 and times.shape == (frames,)
    assert np.array_equal(times, np.arange(frames) / (frames - 1))
    assert times[0] == 0.0 and times[-1] == 1.0
    assert isinstance(out, np.ndarray) and out.dtype == np.float64
    assert out.shape == (frames, len(source), 2)
    assert np.array_equal(out[0], source)
    assert np.array_equal(out[-1], target)
    topology = Topology(source, edges)
    for k, frame in enumerate(out):
        assert frame_problems(frame, topology) == [], f"frame {k} (t = {times[k]})"
    return topology


BARYCENTRIC_STATS = {"steiner_vertices", "triangles", "parts", "bridge_vertices", "milliseconds", "method", "steiner_method",
                     "enclosure_sides", "weights", "verified", "refined_frames", "factorizations"}


def check_rigid_stats(stats, source, target, frames, rotation="short", turns=0, easing="none"):
    """A rigid morph's stats: the barycentric ones plus stats["rigid"] (rigid_stats.py)."""
    assert stats["method"] == "rigid"
    assert set(stats) == BARYCENTRIC_STATS | {"rigid"}
    return check_rigid_section(stats, source, target, frames, rotation, turns, easing)


def morph_similarity(result):
    """The similarity a rigid morph's triangulation is moved by, or None."""
    rigid = result["stats"].get("rigid")
    return rigid["similarity"] if rigid and rigid["similarity_factored"] else None


def engine_accepts_every_frame(result, source, edges):
    """The module's own exact check: every frame compatible with the source."""
    for k, frame in enumerate(result["frames"]):
        report = stickmorph.check_compatibility(source, frame, edges)
        assert report, f"frame {k}: {report.reason}"


# --------------------------------------------------------------------------
# The rigid (default) and barycentric morphs


@pytest.mark.parametrize("method", [None, "barycentric"], ids=["default-rigid", "barycentric"])
@pytest.mark.parametrize("name", PAIRS)
def test_every_frame_is_a_compatible_stick_figure(name, data_dir, method):
    source, target, edges = named_pair(name, data_dir)
    result = stickmorph.morph(source, target, edges, **({} if method is None else {"method": method}))
    check_morph(result, source, target, edges, 50)
    engine_accepts_every_frame(result, source, edges)
    # The figure really moves between the endpoints, continuously.
    middle = result["frames"][25]
    assert not np.array_equal(middle, np.asarray(source, float))
    assert not np.array_equal(middle, np.asarray(target, float))

    tri = result["triangulation"]
    check_triangulation(tri, source, target, edges, morph_similarity(result))
    stats = result["stats"]
    assert stats["steiner_vertices"] == tri["steiner_vertices"]
    assert stats["triangles"] == len(tri["triangles"])
    assert set(stats["milliseconds"]) == {"triangulate", "morph", "factorize", "solve", "verify"}
    assert all(type(v) is float and v >= 0 for v in stats["milliseconds"].values())
    assert type(stats["refined_frames"]) is int and 0 <= stats["refined_frames"] <= 50
    assert type(stats["factorizations"]) is int and 0 <= stats["factorizations"] <= 50
    if method is None:
        check_rigid_stats(stats, source, target, 50)
    else:
        assert set(stats) == BARYCENTRIC_STATS
        assert stats["method"] == "barycentric"
    assert stats["verified"] is True
    assert stats["steiner_method"] == "improved" and stats["weights"] == "mvc"
    assert stats["enclosure_sides"] == 6 and tri["enclosure_vertices"] == 6
    assert "invalid_frames" not in stats


@pytest.mark.parametrize("name", PAIRS)
def test_triangulate_figures(name, data_dir):
    source, target, edges = named_pair(name, data_dir)
    tri = stickmorph.triangulate_figures(source, target, edges)
    check_triangulation(tri, source, target, edges)
    # The barycentric morph uses the same triangulation for the same options.
    used = stickmorph.morph(source, target, edges, frames=2, method="barycentric")["triangulation"]
    for key in ("figure_vertices", "enclosure_vertices", "steiner_vertices", "stats"):
        assert used[key] == tri[key]
    for key in ("source", "target", "triangles"):
        assert np.array_equal(used[key], tri[key])
    # The rigid morph's is its own: the pair with the similarity factored out,
    # in output space, its target enclosure moved with the figure.
    rigid = stickmorph.morph(source, target, edges, frames=2)
    check_triangulation(rigid["triangulation"], source, target, edges, morph_similarity(rigid))
    n, k = tri["figure_vertices"], tri["enclosure_vertices"]
    assert morph_similarity(rigid) is not None
    assert not np.array_equal(rigid["triangulation"]["target"][n:n + k], rigid["triangulation"]["source"][n:n + k])


@pytest.mark.parametrize("weights", ["mvc", "uniform", "floater"])
def test_each_weight_kind(weights):
    result = stickmorph.morph(HEXAGON_SOURCE, HEXAGON_TARGET, HEXAGON_EDGES, frames=9,
                              weights=weights)
    check_morph(result, HEXAGON_SOURCE, HEXAGON_TARGET, HEXAGON_EDGES, 9)
    assert result["stats"]["weights"] == weights


def test_weight_kinds_give_different_paths():
    middles = [stickmorph.morph(DANGLING_SOURCE, DANGLING_TARGET, DANGLING_EDGES, frames=3, method="barycentric",
                                weights=w)["frames"][1] for w in ("mvc", "uniform", "floater")]
    assert not np.array_equal(middles[0], middles[1])
    assert not np.array_equal(middles[0], middles[2])


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
@pytest.mark.parametrize("steiner", ["improved", "sg2001", "aronov"])
def test_each_steiner_method(steiner, method):
    # The zigzag-to-spiral polyline needs Steiner vertices in the annulus.
    source = [[0, 0], [1, 2], [2, 0], [3, 2], [4, 0]]
    target = [[0, 0], [4, 0], [4, 4], [1, 4], [1, 1.5]]
    edges = [[0, 1], [1, 2], [2, 3], [3, 4]]
    result = stickmorph.morph(source, target, edges, frames=9, steiner=steiner, method=method)
    check_morph(result, source, target, edges, 9)
    check_triangulation(result["triangulation"], source, target, edges, morph_similarity(result))
    assert result["stats"]["steiner_method"] == steiner
    if method == "barycentric":
        tri = stickmorph.triangulate_figures(source, target, edges, steiner=steiner)
        check_triangulation(tri, source, target, edges)
        assert tri["steiner_vertices"] == result["stats"]["steiner_vertices"]
    else:
        assert result["triangulation"]["steiner_vertices"] == result["stats"]["steiner_vertices"]


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
@pytest.mark.parametrize("sides", [3, 4, 11])
def test_enclosure_sides(sides, method):
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=5, enclosure_sides=sides, method=method)
    check_morph(result, A_SOURCE, A_TARGET, A_EDGES, 5)
    check_triangulation(result["triangulation"], A_SOURCE, A_TARGET, A_EDGES, morph_similarity(result))
    assert result["triangulation"]["enclosure_vertices"] == sides
    assert result["stats"]["enclosure_sides"] == sides
    tri = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES, enclosure_sides=sides)
    assert tri["enclosure_vertices"] == sides


@pytest.mark.parametrize("frames", [2, 3, 7, 101])
def test_frame_counts(frames):
    result = stickmorph.morph(TREE_SOURCE, TREE_TARGET, TREE_EDGES, frames=frames)
    check_morph(result, TREE_SOURCE, TREE_TARGET, TREE_EDGES, frames)


def test_frames_accepts_numpy_integers():
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=np.int16(4))
    assert result["frames"].shape == (4, 5, 2)


def test_without_verification_frames_are_still_valid_here():
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=11, verify=False)
    check_morph(result, A_SOURCE, A_TARGET, A_EDGES, 11)
    assert result["stats"]["verified"] is False


def test_target_edges_in_another_order_and_direction(data_dir):
    folder = data_dir / "pairs" / "compatible"
    source = stickmorph.load_figure(folder / "square_with_spikes.source.json")
    target = stickmorph.load_figure(folder / "square_with_spikes.target.json")
    assert not np.array_equal(source["edges"], target["edges"])
    result = stickmorph.morph(source["vertices"], target["vertices"], source["edges"], frames=12,
                              target_edges=target["edges"])
    check_morph(result, source["vertices"], target["vertices"], source["edges"], 12)
    tri = stickmorph.triangulate_figures(source["vertices"], target["vertices"], source["edges"],
                                         target_edges=target["edges"])
    check_triangulation(tri, source["vertices"], target["vertices"], source["edges"])


def test_identical_source_and_target_stay_put():
    result = stickmorph.morph(A_SOURCE, A_SOURCE, A_EDGES, frames=6)
    for frame in result["frames"]:
        np.testing.assert_allclose(frame, np.asarray(A_SOURCE, float), rtol=0, atol=1e-12)


def test_results_do_not_share_memory():
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=3)
    again = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=3)
    result["frames"][:] = 0
    result["triangulation"]["source"][:] = 0
    assert np.array_equal(again["frames"][0], np.asarray(A_SOURCE, float))
    assert result["frames"].flags.writeable and result["frames"].flags.c_contiguous


def test_morph_from_threads(data_dir):
    # The engine runs without the GIL; concurrent morphs must not interfere.
    source, target, edges = paper_pair(data_dir)
    expected = stickmorph.morph(source, target, edges, frames=20)["frames"]
    results, failures = [], []

    def work():
        try:
            for _ in range(10):
                results.append(stickmorph.morph(source, target, edges, frames=20)["frames"])
        except Exception as error:  # reported below
            failures.append(error)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert failures == []
    assert len(results) == 40 and all(np.array_equal(r, expected) for r in results)


# --------------------------------------------------------------------------
# The rigid morph: the similarity factored out, an as-rigid-as-possible
# guide followed where it is valid, even speed (issue 12)


def exact_centroid(points):
    """The vertices' centroid, which these tests need to be a double exactly."""
    points = exact_points(points)
    center = tuple(sum(p[i] for p in points) / len(points) for i in (0, 1))
    assert all(Fraction(float(c)) == c for c in center), center
    return np.array([float(c) for c in center])


def turned_half(points):
    """The figure turned by exactly 180 degrees about its centroid c: x -> 2c - x,
    exact in doubles for these figures."""
    points = np.asarray(points, dtype=float)
    center = exact_centroid(points)
    turned = 2 * center - points
    cx, cy = Fraction(center[0]), Fraction(center[1])
    assert exact_points(turned) == [(2 * cx - x, 2 * cy - y) for x, y in exact_points(points)]
    return turned


def turned_quarter_clockwise(points):
    """The figure turned by exactly -90 degrees and moved: (x, y) -> (y + 1, 2 - x)."""
    points = np.asarray(points, dtype=float)
    return np.stack([points[:, 1] + 1, 2 - points[:, 0]], axis=1)


def edge_angles(frames, edges):
    """Every edge's direction in every frame, degrees, unwrapped over the frames."""
    edges = np.asarray(edges).reshape(-1, 2)
    d = frames[:, edges[:, 1]] - frames[:, edges[:, 0]]
    return np.degrees(np.unwrap(np.arctan2(d[..., 1], d[..., 0]), axis=0))


def edge_lengths(frames, edges):
    edges = np.asarray(edges).reshape(-1, 2)
    return np.linalg.norm(frames[:, edges[:, 1]] - frames[:, edges[:, 0]], axis=2)


def steps(frames):
    """The RMS distance the vertices move from each frame to the next."""
    return np.sqrt((np.diff(frames, axis=0) ** 2).sum(axis=2).mean(axis=1))


def turning_figure(name, data_dir):
    """Figures whose centroid is a double exactly: a tree, a hexagon, the paper's S."""
    if name == "tree":
        return TREE_SOURCE, TREE_EDGES
    if name == "hexagon":
        return HEXAGON_SOURCE, HEXAGON_EDGES
    source, _, edges = paper_pair(data_dir)
    return source, edges


@pytest.mark.parametrize("frames", [3, 8, 30])
@pytest.mark.parametrize("name", ["tree", "hexagon", "paper_s"])
def test_half_turn_is_a_rotation(name, frames, data_dir):
    # A figure morphed into itself turned by 180 degrees simply turns: no
    # Steiner vertex for compatibility, every edge keeps its length, the centroid stays put and
    # the figure turns by 180 degrees * k / (N - 1) at frame k.
    source, edges = turning_figure(name, data_dir)
    target = turned_half(source)
    result = stickmorph.morph(source, target, edges, frames=frames)
    check_morph(result, source, target, edges, frames)
    engine_accepts_every_frame(result, source, edges)
    rigid = check_rigid_stats(result["stats"], source, target, frames)
    assert no_compatibility_steiner(result)
    assert rigid["similarity_factored"] is True
    check_triangulation(result["triangulation"], source, target, edges, rigid["similarity"])
    angle = rigid["similarity"]["angle_degrees"]
    assert abs(angle) == pytest.approx(180, abs=1e-9)
    assert rigid["similarity"]["scale"] == pytest.approx(1, abs=1e-12)

    out = result["frames"]
    lengths = edge_lengths(out, edges)
    np.testing.assert_allclose(lengths, np.broadcast_to(lengths[0], lengths.shape), rtol=1e-9, atol=0)
    size = np.ptp(np.asarray(source, float), axis=0).max()
    np.testing.assert_allclose(out.mean(axis=1), np.broadcast_to(exact_centroid(source), (frames, 2)), rtol=0,
                               atol=1e-9 * size)
    turned = edge_angles(out, edges)
    expected = angle * np.arange(frames) / (frames - 1)
    np.testing.assert_allclose(turned - turned[0], np.broadcast_to(expected[:, None], turned.shape), rtol=0,
                               atol=1e-7)


@pytest.mark.parametrize("sides", [3, 24])
def test_half_turn_does_not_depend_on_the_enclosure(sides):
    # The barycentric morph turned less and squashed more with more sides.
    target = turned_half(TREE_SOURCE)
    result = stickmorph.morph(TREE_SOURCE, target, TREE_EDGES, frames=9, enclosure_sides=sides)
    check_morph(result, TREE_SOURCE, target, TREE_EDGES, 9)
    assert no_compatibility_steiner(result) and result["triangulation"]["enclosure_vertices"] == sides
    lengths = edge_lengths(result["frames"], TREE_EDGES)
    np.testing.assert_allclose(lengths, np.broadcast_to(lengths[0], lengths.shape), rtol=1e-9, atol=0)
    turned = edge_angles(result["frames"], TREE_EDGES)
    assert np.abs(turned[-1] - turned[0]) == pytest.approx(180, abs=1e-7)


@pytest.mark.parametrize("rotation, turns, expected", [
    (None, None, -90), ("short", 0, -90), ("cw", None, -90), ("ccw", None, 270), ("ccw", 0, 270),
    (None, 1, 270), (None, -1, -450), ("ccw", 1, 630), ("cw", -1, -450), ("cw", 2, 630), ("short", -2, -810),
])
@pytest.mark.parametrize("name", ["tree_junction", "letter_a"])
def test_quarter_turn_direction_and_whole_turns(name, rotation, turns, expected, data_dir):
    # The pair is a clockwise quarter turn: the short way and "cw" turn by
    # -90 degrees, "ccw" the long way by +270, and each whole turn adds 360.
    source, _, edges = named_pair(name, data_dir)
    target = turned_quarter_clockwise(source)
    frames = 41
    options = {key: value for key, value in (("rotation", rotation), ("turns", turns)) if value is not None}
    result = stickmorph.morph(source, target, edges, frames=frames, **options)
    check_morph(result, source, target, edges, frames)
    rigid = check_rigid_stats(result["stats"], source, target, frames, rotation=rotation or "short",
                              turns=turns or 0)
    assert no_compatibility_steiner(result)
    assert rigid["similarity"]["angle_degrees"] == pytest.approx(expected, abs=1e-9)
    # Tracked edge by edge, unwrapped: a rigid turn at constant angular speed.
    turned = edge_angles(result["frames"], edges)
    progress = expected * np.arange(frames) / (frames - 1)
    np.testing.assert_allclose(turned - turned[0], np.broadcast_to(progress[:, None], turned.shape), rtol=0,
                               atol=1e-7)
    lengths = edge_lengths(result["frames"], edges)
    np.testing.assert_allclose(lengths, np.broadcast_to(lengths[0], lengths.shape), rtol=1e-9, atol=0)


@pytest.mark.parametrize("turns", [1, -1, 2])
@pytest.mark.parametrize("name", ["letter_a", "s_to_u"])
def test_whole_turns_add_360_degrees_to_any_pair(name, turns, data_dir):
    # A pair that is not a similarity: every edge still ends up turned by
    # 360 degrees per extra turn more than with the short way.
    source, target, edges = named_pair(name, data_dir)
    frames = 61
    short = stickmorph.morph(source, target, edges, frames=frames)
    more = stickmorph.morph(source, target, edges, frames=frames, turns=turns)
    check_morph(more, source, target, edges, frames)
    rigid = check_rigid_stats(more["stats"], source, target, frames, turns=turns)
    assert rigid["similarity"]["angle_degrees"] == pytest.approx(
        short["stats"]["rigid"]["similarity"]["angle_degrees"] + 360 * turns, abs=1e-9)
    a, b = edge_angles(short["frames"], edges), edge_angles(more["frames"], edges)
    np.testing.assert_allclose((b[-1] - b[0]) - (a[-1] - a[0]), 360 * turns, rtol=0, atol=1e-6)


def test_the_largest_number_of_turns():
    top = stickmorph.limits["max_turns"]
    for turns in (top, -top):
        result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=7, turns=turns)
        check_morph(result, A_SOURCE, A_TARGET, A_EDGES, 7)
        check_rigid_stats(result["stats"], A_SOURCE, A_TARGET, 7, turns=turns)


@pytest.mark.parametrize("name", PAIRS)
def test_even_speed_by_default(name, data_dir):
    # The vertices move about as far from each frame to the next, with no
    # snap out of the start pose or into the end pose and no pop in between
    # (the barycentric morph's first or last step is often several times its
    # mean): the rigid motion keeps its own time (issue 30) while its speed
    # stays within 1.3 times the mean (internal/motion_timing.h), and is
    # evened just enough beyond that.
    source, target, edges = named_pair(name, data_dir)
    step = steps(stickmorph.morph(source, target, edges, frames=30)["frames"])
    assert 0.75 * step.mean() <= step.min() and step.max() <= 1.3 * 1.01 * step.mean(), step / step.mean()


@pytest.mark.parametrize("name", ["tree_junction", "letter_a", "s_to_u", "quarter_turn"])
def test_easing_in_out_slows_the_start_and_the_end(name, data_dir):
    if name == "quarter_turn":
        source, edges = TREE_SOURCE, TREE_EDGES
        target = turned_quarter_clockwise(source)
    else:
        source, target, edges = named_pair(name, data_dir)
    frames = 21
    even = stickmorph.morph(source, target, edges, frames=frames)
    eased = stickmorph.morph(source, target, edges, frames=frames, easing="in-out")
    check_morph(eased, source, target, edges, frames)
    check_rigid_stats(eased["stats"], source, target, frames, easing="in-out")
    # The times stay k / (N - 1); the motion is what slows down.
    assert np.array_equal(eased["times"], even["times"])
    step = steps(eased["frames"])
    middle = step[len(step) // 3: 2 * len(step) // 3]
    assert step[0] < 0.5 * middle.min() and step[-1] < 0.5 * middle.min(), step
    assert step[0] < 0.5 * steps(even["frames"])[0] and step[-1] < 0.5 * steps(even["frames"])[-1]


@pytest.mark.parametrize("options", [{"rotation": "ccw"}, {"rotation": "cw", "turns": 1},
                                     {"turns": -1, "easing": "in-out"}, {"weights": "uniform", "steiner": "sg2001"},
                                     {"enclosure_sides": 3, "easing": "in-out"}],
                         ids=["ccw", "cw+1", "-1+in-out", "uniform-sg2001", "triangle-in-out"])
@pytest.mark.parametrize("name", PAIRS + ["half_turn"])
def test_every_rigid_frame_is_a_compatible_stick_figure(name, options, data_dir):
    # Whichever way and however often it turns: the exact checks here and
    # the module's own compatibility check accept every frame.
    if name == "half_turn":
        source, edges = HEXAGON_SOURCE, HEXAGON_EDGES
        target = turned_half(source)
    else:
        source, target, edges = named_pair(name, data_dir)
    frames = 16
    result = stickmorph.morph(source, target, edges, frames=frames, **options)
    check_morph(result, source, target, edges, frames)
    engine_accepts_every_frame(result, source, edges)
    rigid_options = {key: options[key] for key in ("rotation", "turns", "easing") if key in options}
    check_rigid_stats(result["stats"], source, target, frames, **rigid_options)
    check_triangulation(result["triangulation"], source, target, edges, morph_similarity(result))


def test_rigid_triangulation_is_in_output_space():
    # Source positions as given, target positions those of the target: its
    # figure nodes exactly the target's vertices, its enclosure the source's
    # moved by the fitted similarity; the triangulation of the pair with the
    # similarity factored out, not triangulate_figures'.
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=2)
    tri = result["triangulation"]
    similarity = morph_similarity(result)
    assert similarity is not None
    check_triangulation(tri, A_SOURCE, A_TARGET, A_EDGES, similarity)
    n, k = tri["figure_vertices"], tri["enclosure_vertices"]
    fixed = stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES)
    assert np.array_equal(fixed["source"][n:n + k], fixed["target"][n:n + k])
    assert not np.array_equal(tri["source"][n:n + k], tri["target"][n:n + k])
    # Moving every node of the target back by the similarity gives an
    # embedding of the same triangles, counter-clockwise too.
    back = {"angle_degrees": -similarity["angle_degrees"], "scale": 1 / similarity["scale"],
            "source_center": similarity["target_center"], "target_center": similarity["source_center"]}
    normalised = similarity_image(back, tri["target"])
    np.testing.assert_allclose(normalised[n:n + k], tri["source"][n:n + k], rtol=0,
                               atol=1e-12 * np.ptp(tri["source"], axis=0).max())
    assert np.all(np.cross(normalised[tri["triangles"][:, 1]] - normalised[tri["triangles"][:, 0]],
                           normalised[tri["triangles"][:, 2]] - normalised[tri["triangles"][:, 0]]) > 0)


def test_pure_translation_and_scale_morph_rigidly():
    # No rotation to factor out: the figure only grows and moves, every frame
    # similar to the source, the edge lengths growing geometrically.
    source = np.asarray(A_SOURCE, dtype=float)
    target = 2 * source + [3, -1]
    frames = 9
    result = stickmorph.morph(source, target, A_EDGES, frames=frames)
    check_morph(result, source, target, A_EDGES, frames)
    rigid = check_rigid_stats(result["stats"], source, target, frames)
    assert rigid["similarity"]["angle_degrees"] == pytest.approx(0, abs=1e-12)
    assert rigid["similarity"]["scale"] == pytest.approx(2, rel=1e-12)
    assert no_compatibility_steiner(result)
    lengths = edge_lengths(result["frames"], A_EDGES)
    ratio = lengths / lengths[0]
    np.testing.assert_allclose(ratio, np.broadcast_to(ratio[:, :1], ratio.shape), rtol=1e-9, atol=0)
    assert np.all(np.diff(ratio[:, 0]) > 0)
    turned = edge_angles(result["frames"], A_EDGES)
    np.testing.assert_allclose(turned, np.broadcast_to(turned[0], turned.shape), rtol=0, atol=1e-7)


def test_rigid_morph_is_deterministic():
    first = stickmorph.morph(DANGLING_SOURCE, DANGLING_TARGET, DANGLING_EDGES, frames=12, rotation="ccw")
    again = stickmorph.morph(DANGLING_SOURCE, DANGLING_TARGET, DANGLING_EDGES, frames=12, rotation="ccw")
    assert np.array_equal(first["frames"], again["frames"])
    assert first["stats"]["rigid"] == again["stats"]["rigid"]


# The rigid method's options, refused where they would mean nothing.

RIGID_ONLY = [("rotation", "short"), ("rotation", "cw"), ("turns", 0), ("turns", 2), ("easing", "none"),
              ("easing", "in-out")]


@pytest.mark.parametrize("method", ["barycentric", "linear"])
@pytest.mark.parametrize("keyword, value", RIGID_ONLY)
def test_rigid_options_refused_with_other_methods(keyword, value, method):
    # As `stickmorph morph --method barycentric --turns ...` does: even the
    # default value, once given, would silently mean nothing.
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, method=method, **{keyword: value})
    assert isinstance(error.value, ValueError)
    assert str(error.value) == (f"{keyword} has no effect with method='{method}' "
                                "(only the rigid method factors out a rotation and follows a guide)")


def test_rigid_options_are_refused_before_the_figures_are_checked():
    with pytest.raises(stickmorph.InvalidArgumentError, match="turns has no effect"):
        stickmorph.morph(CROSSING, CROSSING, CROSSING_EDGES, method="barycentric", turns=1)


@pytest.mark.parametrize("keyword, value", RIGID_ONLY)
@pytest.mark.parametrize("method", [None, "rigid"], ids=["default", "rigid"])
def test_rigid_takes_its_options(keyword, value, method):
    arguments = {keyword: value} if method is None else {keyword: value, "method": method}
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=4, **arguments)
    assert result["stats"]["rigid"][keyword] == value


@pytest.mark.parametrize("turns", [101, -101, 10**30, -10**30])
def test_turns_out_of_range(turns):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, turns=turns)
    bound = "at least -100" if turns < 0 else "at most 100"
    assert str(error.value) == f"turns must be {bound}, got {turns}"
    assert isinstance(error.value, ValueError)


@pytest.mark.parametrize("turns, shown", [(1.0, "float"), ("1", "str"), (True, "bool"), ([1], "list")])
def test_turns_not_an_integer(turns, shown):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, turns=turns)
    assert str(error.value) == f"turns must be an integer, got {shown}"


def test_turns_accepts_numpy_integers():
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=3, turns=np.int8(-3))
    assert result["stats"]["rigid"]["turns"] == -3 and type(result["stats"]["rigid"]["turns"]) is int


@pytest.mark.parametrize("keyword, value, message", [
    ("rotation", "left", "unknown rotation direction 'left' (choose short, ccw or cw)"),
    ("rotation", "CCW", "unknown rotation direction 'CCW' (choose short, ccw or cw)"),
    ("rotation", "", "unknown rotation direction '' (choose short, ccw or cw)"),
    ("easing", "smooth", "unknown easing 'smooth' (choose none or in-out)"),
    ("easing", "in_out", "unknown easing 'in_out' (choose none or in-out)"),
    ("rotation", 1, "rotation must be a str, got int"),
    ("easing", ["none"], "easing must be a str, got list"),
])
def test_unknown_rotation_and_easing(keyword, value, message):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, **{keyword: value})
    assert str(error.value) == message
    assert isinstance(error.value, ValueError)


def test_rigid_names_are_the_accepted_ones():
    for rotation in stickmorph.ROTATION_NAMES:
        assert stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=2, rotation=rotation)["stats"]["rigid"][
            "rotation"] == rotation
    for easing in stickmorph.EASING_NAMES:
        assert stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=2, easing=easing)["stats"]["rigid"][
            "easing"] == easing
    for method in stickmorph.METHOD_NAMES:
        assert stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=2, method=method)["stats"]["method"] == method


# --------------------------------------------------------------------------
# The linear baseline


def test_linear_s_to_u_self_intersects(data_dir):
    source, target, edges = paper_pair(data_dir)
    frames = 50
    result = stickmorph.morph(source, target, edges, frames=frames, method="linear")
    assert result["triangulation"] is None
    times, out = result["times"], result["frames"]
    assert np.array_equal(times, np.arange(frames) / (frames - 1))
    assert out.shape == (frames, len(source), 2) and out.dtype == np.float64
    assert np.array_equal(out[0], source) and np.array_equal(out[-1], target)
    # Straight lines: vertex v at time t is (1 - t) source + t target.
    straight = (1 - times)[:, None, None] * source[None] + times[:, None, None] * target[None]
    np.testing.assert_allclose(out, straight, rtol=0, atol=1e-14)

    stats = result["stats"]
    invalid = stats["invalid_frames"]
    assert isinstance(invalid, list) and all(type(f) is int for f in invalid)
    assert invalid, "the paper's Figure 8d: the S self-intersects on its way to the U"
    assert invalid == sorted(invalid)
    # The engine's verdict agrees with the exact check here, frame by frame.
    topology = Topology(source, edges)
    assert invalid == [k for k, frame in enumerate(out) if frame_problems(frame, topology)]
    assert 0 not in invalid and frames - 1 not in invalid
    assert stats["method"] == "linear"
    assert stats["steiner_vertices"] == 0 and stats["triangles"] == 0
    assert stats["refined_frames"] == 0 and stats["factorizations"] == 0
    assert set(stats) == {"steiner_vertices", "triangles", "parts", "bridge_vertices", "milliseconds", "method",
                          "refined_frames", "factorizations", "invalid_frames"}
    assert set(stats["milliseconds"]) == {"triangulate", "morph", "factorize", "solve", "verify"}
    assert stats["milliseconds"]["triangulate"] == 0.0 and stats["milliseconds"]["factorize"] == 0.0

    # The barycentric and rigid morphs of the same pair have no invalid frame.
    for method in ("barycentric", "rigid"):
        check_morph(stickmorph.morph(source, target, edges, frames=frames, method=method), source, target, edges,
                    frames)


def test_linear_valid_morph_reports_nothing():
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=10, method="linear")
    assert result["stats"]["invalid_frames"] == []
    check_morph(result, A_SOURCE, A_TARGET, A_EDGES, 10)


def test_linear_accepts_the_largest_frame_count():
    result = stickmorph.morph([[0, 0], [1, 0]], [[0, 1], [2, 2]], [[0, 1]], method="linear",
                              frames=100000)
    assert result["frames"].shape == (100000, 2, 2)
    assert result["times"][-1] == 1.0 and result["stats"]["invalid_frames"] == []


# --------------------------------------------------------------------------
# Errors


def test_defaults_are_documented():
    doc = stickmorph.morph.__doc__
    # The triangulation options and the rigid-only ones default to None (not
    # given), so that the methods that would ignore them can refuse them;
    # their effective defaults are in the text.
    for default in (r"frames: \w+ = 50", r"steiner: \w+ = None", r"weights: \w+ = None",
                    r"enclosure_sides: \w+ = None", r"method: \w+ = 'rigid'",
                    r"verify: \w+ = None", r"target_edges: \w+ = None", r"rotation: \w+ = None",
                    r"turns: \w+ = None", r"easing: \w+ = None"):
        assert re.search(default, doc), default
    for text in ('"improved" (default)', '"mvc" (mean value coordinates, default)', "(default 6)",
                 "(default True)", '"rigid" (default)', '"short" (default)', "(default 0)",
                 '"none" (default, even speed)'):
        assert text in doc, text
    assert "(N, #V, 2)" in doc and "(N,) float64" in doc
    doc = stickmorph.triangulate_figures.__doc__
    for default in (r"steiner: \w+ = 'improved'", r"enclosure_sides: \w+ = 6",
                    r"target_edges: \w+ = None"):
        assert re.search(default, doc), default
    assert "#T by 3 int64" in doc


@pytest.mark.parametrize("keyword, value, message", [
    ("method", "spline", "unknown morph method 'spline' (choose rigid, barycentric or linear)"),
    ("weights", "cotan", "unknown weight kind 'cotan' (choose mvc, uniform or floater)"),
    ("steiner", "delaunay", "unknown Steiner method 'delaunay' (choose aronov, sg2001 or improved)"),
])
@pytest.mark.parametrize("method", ["rigid", "barycentric", "linear"])
def test_unknown_names(keyword, value, message, method):
    arguments = {"method": method, keyword: value}
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, **arguments)
    assert str(error.value) == message


def test_unknown_steiner_name_in_triangulate_figures():
    with pytest.raises(stickmorph.InvalidArgumentError, match="unknown Steiner method 'x'"):
        stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES, steiner="x")


@pytest.mark.parametrize("frames", [1, 0, -3, 100001, 10**30, -10**30])
@pytest.mark.parametrize("method", ["rigid", "barycentric", "linear"])
def test_frames_out_of_range(frames, method):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=frames, method=method)
    bound = "at least 2" if frames < 2 else "at most 100000"
    assert str(error.value) == f"frames must be {bound}, got {frames}"


@pytest.mark.parametrize("frames", [2.0, 7.5, "7", True, None])
def test_frames_not_an_integer(frames):
    with pytest.raises(stickmorph.InvalidArgumentError, match="frames must be an integer"):
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=frames)


@pytest.mark.parametrize("sides, message", [
    (2, "enclosure_sides must be at least 3, got 2"),
    (0, "enclosure_sides must be at least 3, got 0"),
    (-10**20, "enclosure_sides must be at least 3, got -100000000000000000000"),
    (1001, "enclosure_sides must be at most 1000, got 1001"),
    (2**31, "enclosure_sides must be at most 1000, got 2147483648"),
])
def test_enclosure_sides_out_of_range(sides, message):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, enclosure_sides=sides)
    assert str(error.value) == message
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES, enclosure_sides=sides)
    assert str(error.value) == message


LINEAR_IGNORES = [("steiner", "aronov"), ("steiner", "improved"), ("weights", "uniform"),
                  ("enclosure_sides", 6), ("enclosure_sides", 2), ("verify", True), ("verify", False)]


@pytest.mark.parametrize("keyword, value", LINEAR_IGNORES)
def test_linear_refuses_what_it_would_ignore(keyword, value):
    # As `stickmorph morph --method linear --steiner ...` does: even a default
    # value, once asked for, would silently mean nothing.
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, method="linear", **{keyword: value})
    assert str(error.value) == (f"{keyword} has no effect with method='linear' "
                                "(the straight-line morph uses no triangulation)")


@pytest.mark.parametrize("method", [None, "rigid", "barycentric"], ids=["default", "rigid", "barycentric"])
@pytest.mark.parametrize("keyword, value", [("steiner", "sg2001"), ("weights", "uniform"),
                                            ("enclosure_sides", 7), ("verify", False)])
def test_barycentric_takes_what_linear_refuses(keyword, value, method):
    arguments = {keyword: value} if method is None else {keyword: value, "method": method}
    result = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=3, **arguments)
    assert result["frames"].shape == (3, len(A_SOURCE), 2)
    assert result["stats"]["method"] == (method or "rigid")
    stat = {"steiner": "steiner_method", "verify": "verified"}.get(keyword, keyword)
    assert result["stats"][stat] == value


def test_none_means_not_given():
    given = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=4, steiner="improved", weights="mvc",
                             enclosure_sides=6, verify=True, method="rigid", rotation="short", turns=0,
                             easing="none")
    defaults = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=4, steiner=None, weights=None,
                                enclosure_sides=None, verify=None, rotation=None, turns=None, easing=None)
    assert np.array_equal(given["frames"], defaults["frames"])
    assert {k: defaults["stats"][k] for k in ("steiner_method", "enclosure_sides", "weights", "verified")} == \
        {"steiner_method": "improved", "enclosure_sides": 6, "weights": "mvc", "verified": True}
    assert {k: defaults["stats"]["rigid"][k] for k in ("rotation", "turns", "easing")} == \
        {"rotation": "short", "turns": 0, "easing": "none"}
    barycentric = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=4, method="barycentric", rotation=None,
                                   turns=None, easing=None)
    assert barycentric["stats"]["method"] == "barycentric" and "rigid" not in barycentric["stats"]
    linear = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=4, method="linear", steiner=None,
                              weights=None, enclosure_sides=None, verify=None, rotation=None, turns=None,
                              easing=None)
    assert linear["triangulation"] is None


def test_limits_and_option_names_are_exported():
    assert stickmorph.limits["min_frames"] == 2 and stickmorph.limits["max_frames"] == 100000
    assert stickmorph.limits["max_enclosure_sides"] == 1000
    assert stickmorph.limits["min_enclosure_sides"] == 3
    assert stickmorph.limits["default_frames"] == 50 and stickmorph.limits["default_enclosure_sides"] == 6
    assert stickmorph.limits["max_smoothing_rounds"] == 1000
    assert stickmorph.OPTION_NAMES["enclosure_sides"] == "--enclosure-sides"
    assert stickmorph.OPTION_NAMES["verify"] == "--no-verify"
    assert stickmorph.OPTION_NAMES["smoothing_rounds"] == ""
    assert stickmorph.METHOD_NAMES == ("rigid", "barycentric", "linear")
    assert stickmorph.ROTATION_NAMES == ("short", "ccw", "cw")
    assert stickmorph.EASING_NAMES == ("none", "in-out")
    assert stickmorph.limits["max_turns"] == 100
    assert {k: stickmorph.OPTION_NAMES[k] for k in ("rotation", "turns", "easing")} == \
        {"rotation": "--rotation", "turns": "--turns", "easing": "--easing"}
    top_turns = stickmorph.limits["max_turns"]
    assert re.search(rf"-{top_turns} to\s+{top_turns} \(default 0\)", stickmorph.morph.__doc__)
    # The docstrings quote them from the same table.
    limits = stickmorph.limits
    assert f"{limits['min_frames']} to {limits['max_frames']}" in stickmorph.morph.__doc__
    for function in (stickmorph.morph, stickmorph.triangulate_figures):
        assert f"{limits['min_enclosure_sides']} to {limits['max_enclosure_sides']}" in function.__doc__
    assert f"({limits['min_smoothing_rounds']} to {limits['max_smoothing_rounds']})" in \
        stickmorph.compatible_triangulation.__doc__
    for function in (stickmorph.morph, stickmorph.triangulate_figures, stickmorph.compatible_triangulation):
        assert "{min_" not in function.__doc__ and "{max_" not in function.__doc__
    # The limits are the ones enforced.
    top = stickmorph.limits["max_enclosure_sides"]
    with pytest.raises(stickmorph.InvalidArgumentError, match=f"at most {top}"):
        stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES, enclosure_sides=top + 1)


def test_enclosure_sides_not_an_integer():
    with pytest.raises(stickmorph.InvalidArgumentError, match="enclosure_sides must be an integer"):
        stickmorph.triangulate_figures(A_SOURCE, A_TARGET, A_EDGES, enclosure_sides=6.0)


INCOMPATIBLE = ["junction_rotation", "mirror_image", "exterior_differs", "polygon_reversed",
                "edge_set_differs", "vertex_count_differs", "nesting_differs"]


def test_every_incompatible_pair_is_listed(data_dir):
    on_disk = {p.name.rsplit(".", 2)[0] for p in (data_dir / "pairs" / "incompatible").glob("*.json")}
    assert on_disk == set(INCOMPATIBLE)


@pytest.mark.parametrize("name", INCOMPATIBLE)
def test_incompatible_figures(name, data_dir):
    folder = data_dir / "pairs" / "incompatible"
    source = stickmorph.load_figure(folder / f"{name}.source.json")
    target = stickmorph.load_figure(folder / f"{name}.target.json")
    arguments = (source["vertices"], target["vertices"], source["edges"])
    report = stickmorph.check_compatibility(*arguments, target_edges=target["edges"])
    for method in ("rigid", "barycentric", "linear"):
        with pytest.raises(stickmorph.IncompatibleFiguresError) as error:
            stickmorph.morph(*arguments, target_edges=target["edges"], method=method)
        # The report travels with the exception: no message parsing needed.
        assert str(error.value) == f"incompatible figures: {report.reason}"
        assert error.value.kind == report.kind != "none"
        assert error.value.vertices == report.vertices
    with pytest.raises(stickmorph.IncompatibleFiguresError) as error:
        stickmorph.triangulate_figures(*arguments, target_edges=target["edges"])
    assert (error.value.kind, error.value.vertices) == (report.kind, report.vertices)


def test_incompatible_is_not_invalid():
    with pytest.raises(stickmorph.IncompatibleFiguresError) as error:
        stickmorph.morph(A_SOURCE, [[-x, y] for x, y in A_SOURCE], A_EDGES)
    assert not isinstance(error.value, stickmorph.InvalidFigureError)
    assert isinstance(error.value, stickmorph.StickMorphError)


CROSSING = [[0, 0], [1, 1], [1, 0], [0, 1]]  # edges 0-1 and 2-3 cross
CROSSING_EDGES = [[0, 1], [2, 3], [1, 2]]


@pytest.mark.parametrize("function", ["morph", "triangulate_figures"])
def test_invalid_source_or_target(function):
    call = getattr(stickmorph, function)
    valid = [[0, 0], [1, 0], [1, 1], [0, 1]]
    with pytest.raises(stickmorph.InvalidFigureError) as error:
        call(CROSSING, valid, CROSSING_EDGES)
    assert str(error.value).startswith("source: ")
    assert error.value.defect == "crossing_edges" and error.value.edges == [0, 1]
    assert error.value.role == "source"
    with pytest.raises(stickmorph.InvalidFigureError) as error:
        call(valid, CROSSING, CROSSING_EDGES)
    assert str(error.value).startswith("target: ")
    assert error.value.defect == "crossing_edges"
    assert error.value.role == "target"
    # Both bad: the source is named.
    with pytest.raises(stickmorph.InvalidFigureError, match="^source: "):
        call(CROSSING, CROSSING, CROSSING_EDGES)
    # A bad target edge list is the target's defect.
    with pytest.raises(stickmorph.InvalidFigureError, match="^target: ") as error:
        call(valid, valid, [[0, 1], [1, 2], [2, 3]], target_edges=[[0, 1], [1, 2], [2, 2]])
    assert error.value.defect == "self_loop"


def test_error_attributes_are_none_on_the_classes():
    for attribute in ("defect", "vertices", "edges", "role"):
        assert getattr(stickmorph.InvalidFigureError, attribute) is None
    for attribute in ("kind", "vertices"):
        assert getattr(stickmorph.IncompatibleFiguresError, attribute) is None


def test_a_figure_on_its_own_has_no_role():
    with pytest.raises(stickmorph.InvalidFigureError) as error:
        stickmorph.validate(CROSSING, CROSSING_EDGES)
    assert error.value.role is None


def test_invalid_source_with_linear_method():
    with pytest.raises(stickmorph.InvalidFigureError, match="^source: "):
        stickmorph.morph([[0, 0], [0, 0]], [[0, 0], [1, 0]], [[0, 1]], method="linear")


@pytest.mark.parametrize("function", ["morph", "triangulate_figures"])
def test_arrays_of_the_wrong_shape(function):
    call = getattr(stickmorph, function)
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"must have shape \(#V, 2\), got \(5, 3\)"):
        call(np.zeros((5, 3)), A_TARGET, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"must have shape \(#E, 2\)"):
        call(A_SOURCE, A_TARGET, [0, 1, 2])
    with pytest.raises(stickmorph.InvalidArgumentError, match="must hold real numbers"):
        call(A_SOURCE, [["a", "b"]] * 5, A_EDGES)
    with pytest.raises(stickmorph.InvalidArgumentError, match="edge 0: index 0.5 is not an integer"):
        call(A_SOURCE, A_TARGET, [[0.5, 1]] + A_EDGES[1:])


def test_argument_checks_come_before_figure_checks():
    # As in the CLI: a bad option is reported even when the figures are bad too.
    with pytest.raises(stickmorph.InvalidArgumentError):
        stickmorph.morph(CROSSING, CROSSING, CROSSING_EDGES, weights="x")


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
def test_frame_check_full_agrees_with_the_certificate(method):
    # The certificate (default) proves each frame valid; the full check
    # rebuilds each frame's figure as well. Both accept the same frames.
    certified = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=11, method=method)
    full = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=11, method=method, frame_check="full")
    np.testing.assert_array_equal(certified["frames"], full["frames"])
    explicit = stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=11, method=method, frame_check="certificate")
    np.testing.assert_array_equal(certified["frames"], explicit["frames"])


@pytest.mark.parametrize("keywords, message", [
    ({"frame_check": "full", "verify": False}, "frame_check has no effect with verify=False (no frame is checked)"),
    ({"frame_check": "full", "method": "linear"},
     "frame_check has no effect with method='linear' (the straight-line morph uses no triangulation)"),
    ({"frame_check": "quick"}, "unknown frame check 'quick' (choose certificate or full)"),
])
def test_frame_check_refusals(keywords, message):
    with pytest.raises(stickmorph.InvalidArgumentError) as error:
        stickmorph.morph(A_SOURCE, A_TARGET, A_EDGES, frames=5, **keywords)
    assert str(error.value) == message
