"""Tests of stickmorph.compatible_triangulation (native/python/module.cpp).

Every result is re-checked here independently of the engine's own verifier:
each triangle is positively oriented in both polygons (exact rational
arithmetic on the returned doubles), the triangles' areas add up to the
polygon's area in each, and the triangles' boundary is exactly the polygon's
edges, each walked once in the polygon's direction.
"""
import math
import threading
from fractions import Fraction

import numpy as np
import pytest

import stickmorph

METHODS = ["aronov", "sg2001", "improved"]


# --------------------------------------------------------------------------
# Test polygons, counter-clockwise and simple (checked by check_simple_ccw).


def rotate(points, degrees, center=(0.0, 0.0)):
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    cx, cy = center
    return [[cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy)]
            for x, y in points]


SQUARE = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]
ROTATED_SQUARE = rotate(SQUARE, 30.0, center=(2.0, 2.0))
# The same square with every vertex moved one corner on: vertex i of the
# target sits where vertex i+1 of the source is.
SHIFTED_SQUARE = SQUARE[1:] + SQUARE[:1]

# A six-pointed star: 12 corners alternating between radius 10 and radius 4,
# at increasing angles, so it is star-shaped around the origin.
STAR = [[r * math.cos(math.pi * k / 6), r * math.sin(math.pi * k / 6)]
        for k, r in zip(range(12), [10.0, 4.0] * 6)]
# A comb: a bar along the bottom and three teeth pointing up.
COMB = [[0.0, 0.0], [10.0, 0.0], [10.0, 6.0], [8.0, 6.0], [8.0, 2.0], [6.0, 2.0],
        [6.0, 6.0], [4.0, 6.0], [4.0, 2.0], [2.0, 2.0], [2.0, 6.0], [0.0, 6.0]]
# A convex 12-gon (an ellipse).
OVAL = [[7.0 * math.cos(math.pi * k / 6), 3.0 * math.sin(math.pi * k / 6)] for k in range(12)]


def shift(points, k):
    return points[k:] + points[:k]


PAIRS = {
    "square_rotated": (SQUARE, ROTATED_SQUARE),
    "square_shifted": (SQUARE, SHIFTED_SQUARE),
    "star_comb": (STAR, COMB),
    "comb_star": (COMB, STAR),
    "star_shifted_comb": (STAR, shift(COMB, 5)),
    "comb_oval": (COMB, shift(OVAL, 3)),
}

# A square face with a dangling edge from vertex 1 to vertex 4, walked on both
# sides: the corner sequence repeats vertex 1.
DANGLING_SOURCE = SQUARE + [[1.0, 3.0]]
DANGLING_TARGET = SQUARE + [[3.5, 3.5]]
DANGLING_CORNERS = [1, 4, 1, 2, 3, 0]


# --------------------------------------------------------------------------
# Independent checks (Python, no engine code)


def exact(point):
    return Fraction(point[0]), Fraction(point[1])


def cross(o, a, b):
    """Twice the signed area of triangle o a b, exactly (Fraction is exact on floats)."""
    ox, oy = exact(o)
    ax, ay = exact(a)
    bx, by = exact(b)
    return (ax - ox) * (by - oy) - (ay - oy) * (bx - ox)


def shoelace(points):
    """Signed area of the closed polygon through `points`, exactly."""
    total = Fraction(0)
    for k in range(len(points)):
        x0, y0 = exact(points[k])
        x1, y1 = exact(points[(k + 1) % len(points)])
        total += x0 * y1 - x1 * y0
    return total / 2


def on_segment(p, a, b):
    """p lies on the closed segment a b (p, a, b collinear assumed)."""
    (px, py), (ax, ay), (bx, by) = exact(p), exact(a), exact(b)
    return min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by)


def segments_meet(a, b, c, d):
    """The closed segments a b and c d share at least one point."""
    d1, d2 = cross(c, d, a), cross(c, d, b)
    d3, d4 = cross(a, b, c), cross(a, b, d)
    if ((d1 > 0) != (d2 > 0)) and d1 != 0 and d2 != 0 and \
            ((d3 > 0) != (d4 > 0)) and d3 != 0 and d4 != 0:
        return True
    return ((d1 == 0 and on_segment(a, c, d)) or (d2 == 0 and on_segment(b, c, d)) or
            (d3 == 0 and on_segment(c, a, b)) or (d4 == 0 and on_segment(d, a, b)))


def is_simple_ccw(points):
    """Brute force: positive area, and edges meet only where consecutive edges share a corner."""
    n = len(points)
    if n < 3 or shoelace(points) <= 0:
        return False
    if len({tuple(p) for p in points}) != n:
        return False
    for i in range(n):
        a, b = points[i], points[(i + 1) % n]
        for j in range(i + 1, n):
            c, d = points[j], points[(j + 1) % n]
            if j == i + 1 or (i == 0 and j == n - 1):
                # Consecutive edges share one corner; they must not fold back
                # onto each other (the far endpoint must not lie on the other).
                shared, p, q = (b, a, d) if j == i + 1 else (a, b, c)
                if cross(shared, p, q) == 0 and (on_segment(p, shared, q) or on_segment(q, shared, p)):
                    return False
            elif segments_meet(a, b, c, d):
                return False
    return True


def node_positions(vertices, corners, steiner):
    corner_points = np.asarray(vertices, dtype=np.float64)[np.asarray(corners)]
    return np.vstack([corner_points, np.asarray(steiner, dtype=np.float64).reshape(-1, 2)])


def check_triangulation(result, source, target, corners=None):
    """Re-checks a compatible triangulation; returns the number of Steiner vertices."""
    n = len(source)
    if corners is None:
        corners = list(range(n))
    triangles = result["triangles"]
    c = len(corners)
    s = len(result["source_steiner"])

    assert triangles.dtype == np.int64 and triangles.ndim == 2 and triangles.shape[1] == 3
    assert result["corners"].dtype == np.int64
    assert result["corners"].tolist() == list(corners)
    for key in ("source_steiner", "target_steiner"):
        assert result[key].dtype == np.float64 and result[key].shape == (s, 2)
        assert np.all(np.isfinite(result[key]))
    assert result["stats"]["steiner_vertices"] == s
    assert result["stats"]["spiderweb_steiner_vertices"] >= s
    assert triangles.size == 0 or (triangles.min() >= 0 and triangles.max() < c + s)
    # A triangulated disk with c boundary nodes and s interior ones.
    assert len(triangles) == c - 2 + 2 * s
    for t in triangles:
        assert len(set(t.tolist())) == 3

    for name, vertices, steiner in (("source", source, result["source_steiner"]),
                                    ("target", target, result["target_steiner"])):
        nodes = node_positions(vertices, corners, steiner)
        polygon_area = shoelace(nodes[:c].tolist())
        assert polygon_area > 0
        total = Fraction(0)
        for t, (a, b, d) in enumerate(triangles.tolist()):
            area = cross(nodes[a], nodes[b], nodes[d]) / 2
            assert area > 0, f"triangle {t} {a, b, d} is not positive in the {name}"
            total += area
        assert abs(float(total - polygon_area)) <= 1e-9 * float(polygon_area), name

    sides = {}
    for a, b, d in triangles.tolist():
        for side in ((a, b), (b, d), (d, a)):
            sides[side] = sides.get(side, 0) + 1
    boundary = {(k, (k + 1) % c) for k in range(c)}
    for side in boundary:
        assert sides.get(side, 0) == 1, f"polygon edge {side} is covered {sides.get(side, 0)} times"
        assert (side[1], side[0]) not in sides, f"polygon edge {side} is walked backwards"
    for side, count in sides.items():
        assert count == 1, f"side {side} appears {count} times"
        if side not in boundary:
            assert (side[1], side[0]) in sides, f"interior side {side} has no twin"
    return s


def min_triangle_angle(result, source, target, corners):
    smallest = math.pi
    for vertices, steiner in ((source, result["source_steiner"]),
                              (target, result["target_steiner"])):
        nodes = node_positions(vertices, corners, steiner)
        for tri in result["triangles"].tolist():
            for j in range(3):
                p, q, r = (nodes[tri[j]], nodes[tri[(j + 1) % 3]], nodes[tri[(j + 2) % 3]])
                u, v = q - p, r - p
                smallest = min(smallest, math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u @ v))
    return smallest


# --------------------------------------------------------------------------
# The helpers themselves


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_test_polygons_are_simple_and_counter_clockwise(name):
    source, target = PAIRS[name]
    assert len(source) == len(target)
    assert is_simple_ccw(source)
    assert is_simple_ccw(target)


def test_simplicity_helper_rejects_bad_polygons():
    assert not is_simple_ccw(SQUARE[::-1])                                   # clockwise
    assert not is_simple_ccw([[0, 0], [4, 4], [4, 0], [0, 4]])               # bow tie
    assert not is_simple_ccw([[0, 0], [4, 0], [2, 0], [2, 3]])               # folds back
    assert not is_simple_ccw([[0, 0], [4, 0], [4, 4], [2, 0], [0, 4]])       # touches an edge
    assert not is_simple_ccw(COMB[:5] + [[9.0, -1.0]] + COMB[6:])            # crosses the bar


def test_triangulation_checker_rejects_bad_results():
    good = stickmorph.compatible_triangulation(SQUARE, SQUARE)
    check_triangulation(good, SQUARE, SQUARE)

    flipped = dict(good, triangles=good["triangles"][:, ::-1].copy())
    with pytest.raises(AssertionError):
        check_triangulation(flipped, SQUARE, SQUARE)
    # Both diagonals' triangles: positive, but twice the area.
    overlapping = dict(good, triangles=np.array([[0, 1, 2], [0, 2, 3], [0, 1, 3]], dtype=np.int64))
    with pytest.raises(AssertionError):
        check_triangulation(overlapping, SQUARE, SQUARE)
    # Right count, positive, but one triangle twice: edges 1 -> 2, 2 -> 3 missing.
    doubled = dict(good, triangles=np.array([[0, 1, 3], [0, 1, 3]], dtype=np.int64))
    with pytest.raises(AssertionError):
        check_triangulation(doubled, SQUARE, SQUARE)
    # A Steiner vertex outside the target: a triangle turns negative there.
    steiner = dict(stickmorph.compatible_triangulation(SQUARE, ROTATED_SQUARE, steiner="aronov"))
    check_triangulation(steiner, SQUARE, ROTATED_SQUARE)
    steiner["target_steiner"] = steiner["target_steiner"] + 100.0
    with pytest.raises(AssertionError):
        check_triangulation(steiner, SQUARE, ROTATED_SQUARE)


# --------------------------------------------------------------------------
# Results


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("name", sorted(PAIRS))
def test_result_is_a_compatible_triangulation(name, method):
    source, target = PAIRS[name]
    result = stickmorph.compatible_triangulation(source, target, steiner=method)
    check_triangulation(result, source, target)


@pytest.mark.parametrize("method", METHODS)
def test_stats_min_angles(method):
    source, target = PAIRS["star_comb"]
    corners = list(range(len(source)))
    result = stickmorph.compatible_triangulation(source, target, steiner=method)
    stats = result["stats"]
    assert 0 < stats["min_angle_before_smoothing"] <= stats["min_angle_after_smoothing"] <= math.pi / 3
    assert stats["min_angle_after_smoothing"] == pytest.approx(
        min_triangle_angle(result, source, target, corners), rel=1e-9, abs=1e-12)


def test_without_smoothing_angles_do_not_change():
    source, target = PAIRS["star_comb"]
    result = stickmorph.compatible_triangulation(source, target, steiner="sg2001",
                                                 smoothing_rounds=0)
    check_triangulation(result, source, target)
    stats = result["stats"]
    assert stats["min_angle_after_smoothing"] == stats["min_angle_before_smoothing"]


def test_default_method_is_improved():
    source, target = PAIRS["star_shifted_comb"]
    default = stickmorph.compatible_triangulation(source, target)
    improved = stickmorph.compatible_triangulation(source, target, steiner="improved")
    assert default["stats"] == improved["stats"]
    assert np.array_equal(default["triangles"], improved["triangles"])


@pytest.mark.parametrize("polygon", [SQUARE, STAR, COMB, OVAL], ids=["square", "star", "comb", "oval"])
def test_identical_polygons_need_no_steiner_vertices(polygon):
    result = stickmorph.compatible_triangulation(polygon, polygon, steiner="improved")
    assert check_triangulation(result, polygon, polygon) == 0
    assert result["stats"]["steiner_vertices"] == 0
    assert len(result["triangles"]) == len(polygon) - 2


def test_steiner_totals_are_ordered():
    totals = {}
    for method in METHODS:
        totals[method] = 0
        for source, target in PAIRS.values():
            result = stickmorph.compatible_triangulation(source, target, steiner=method)
            totals[method] += check_triangulation(result, source, target)
    assert totals["improved"] <= totals["sg2001"] <= totals["aronov"], totals
    assert totals["improved"] < totals["aronov"], totals


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_improved_removes_from_the_reduced_spiderweb(name):
    source, target = PAIRS[name]
    sg2001 = stickmorph.compatible_triangulation(source, target, steiner="sg2001")["stats"]
    improved = stickmorph.compatible_triangulation(source, target, steiner="improved")["stats"]
    assert sg2001["spiderweb_steiner_vertices"] == sg2001["steiner_vertices"]
    assert improved["steiner_vertices"] <= sg2001["steiner_vertices"]


@pytest.mark.parametrize("method", METHODS)
def test_face_with_a_dangling_edge(method):
    assert shoelace([DANGLING_SOURCE[i] for i in DANGLING_CORNERS]) == 16
    assert shoelace([DANGLING_TARGET[i] for i in DANGLING_CORNERS]) == 16
    result = stickmorph.compatible_triangulation(DANGLING_SOURCE, DANGLING_TARGET, steiner=method,
                                                 corners=DANGLING_CORNERS)
    check_triangulation(result, DANGLING_SOURCE, DANGLING_TARGET, DANGLING_CORNERS)
    # The dangling edge is walked both ways: corner 0 -> 1 and corner 1 -> 2.
    assert result["corners"].tolist() == DANGLING_CORNERS


def test_corners_select_and_order_vertices():
    # The comb's vertices stored in another order, plus an unused vertex.
    order = [5, 0, 11, 3, 8, 1, 10, 6, 2, 9, 4, 7]
    source = [None] * 12
    target = [None] * 12
    for position, k in enumerate(order):
        source[position] = COMB[k]
        target[position] = STAR[k]
    source.append([100.0, 100.0])
    target.append([-100.0, 100.0])
    corners = [order.index(k) for k in range(12)]
    for method in METHODS:
        result = stickmorph.compatible_triangulation(source, target, steiner=method, corners=corners)
        check_triangulation(result, source, target, corners)
        direct = stickmorph.compatible_triangulation(COMB, STAR, steiner=method)
        assert result["stats"]["steiner_vertices"] == direct["stats"]["steiner_vertices"]


@pytest.mark.parametrize("convert", [
    lambda c: np.array(c, dtype=np.int32),
    lambda c: np.array(c, dtype=np.uint8),
    lambda c: np.array(c, dtype=np.float64),
    tuple,
], ids=["int32", "uint8", "float64", "tuple"])
def test_corner_array_likes(convert):
    result = stickmorph.compatible_triangulation(DANGLING_SOURCE, DANGLING_TARGET,
                                                 corners=convert(DANGLING_CORNERS))
    check_triangulation(result, DANGLING_SOURCE, DANGLING_TARGET, DANGLING_CORNERS)


def test_vertex_array_likes():
    source, target = PAIRS["star_comb"]
    # Float32 would move the vertices; int and non-contiguous float64 do not.
    wide = np.zeros((12, 4))
    wide[:, ::2] = source
    result = stickmorph.compatible_triangulation(wide[:, ::2], np.asarray(target).T.copy().T)
    check_triangulation(result, source, target)
    integers = np.asarray(COMB, dtype=np.int64)
    result = stickmorph.compatible_triangulation(integers, tuple(map(tuple, STAR)))
    check_triangulation(result, COMB, STAR)


def test_from_threads():
    source, target = PAIRS["star_shifted_comb"]
    expected = stickmorph.compatible_triangulation(source, target, steiner="aronov")
    results = [None] * 4

    def work(i):
        results[i] = stickmorph.compatible_triangulation(source, target, steiner="aronov")

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(results))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for result in results:
        assert np.array_equal(result["triangles"], expected["triangles"])
        assert np.array_equal(result["source_steiner"], expected["source_steiner"])
        assert np.array_equal(result["target_steiner"], expected["target_steiner"])


# --------------------------------------------------------------------------
# Errors


def test_verification_error_class():
    cls = stickmorph.VerificationError
    assert issubclass(cls, stickmorph.StickMorphError)
    assert issubclass(cls, ValueError)
    assert cls.__module__ == "stickmorph"
    assert cls.__doc__


def test_docstring_gives_shapes():
    doc = stickmorph.compatible_triangulation.__doc__
    for text in ("#V by 2", "#T by 3", "#S by 2", "aronov", "sg2001", "improved",
                 "VerificationError"):
        assert text in doc


@pytest.mark.parametrize("name", ["", "Improved", "reduced", "aronov "])
def test_unknown_method(name):
    with pytest.raises(stickmorph.InvalidArgumentError,
                       match=r"unknown Steiner method '.*' \(choose aronov, sg2001 or improved\)"):
        stickmorph.compatible_triangulation(SQUARE, SQUARE, steiner=name)


@pytest.mark.parametrize("role", ["source", "target"])
def test_clockwise_polygon(role):
    clockwise = SQUARE[::-1]
    arguments = (clockwise, SQUARE) if role == "source" else (SQUARE, clockwise)
    with pytest.raises(stickmorph.InvalidFigureError, match=f"in the {role}.*clockwise"):
        stickmorph.compatible_triangulation(*arguments)


@pytest.mark.parametrize("role", ["source", "target"])
def test_crossing_polygon(role):
    bow_tie = [[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]]
    arguments = (bow_tie, SQUARE) if role == "source" else (SQUARE, bow_tie)
    with pytest.raises(stickmorph.InvalidFigureError, match=f"in the {role}") as info:
        stickmorph.compatible_triangulation(*arguments)
    assert info.value.defect == "crossing_edges"


# Each way a corner sequence can fail to be a weakly simple counter-clockwise
# polygon has its own defect, and the role says which polygon of the pair.
@pytest.mark.parametrize("polygon, defect", [
    (SQUARE[::-1], "clockwise_corners"),
    ([[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]], "crossing_edges"),
    ([[0.0, 0.0], [2.0, 0.0], [2.0, 0.0], [0.0, 2.0]], "coincident_corners"),
])
@pytest.mark.parametrize("role", ["source", "target"])
def test_polygon_defects_are_told_apart(polygon, defect, role):
    arguments = (polygon, SQUARE) if role == "source" else (SQUARE, polygon)
    with pytest.raises(stickmorph.InvalidFigureError, match=f"in the {role}") as info:
        stickmorph.compatible_triangulation(*arguments)
    assert info.value.defect == defect
    assert info.value.role == role


# Defects of the corner sequence itself, shared by both polygons: the source
# is named first.
@pytest.mark.parametrize("corners, defect", [([0, 1], "too_few_corners"),
                                             ([0, 1, 1, 2, 3], "coincident_corners")])
def test_corner_sequence_defects(corners, defect):
    with pytest.raises(stickmorph.InvalidFigureError, match="in the source") as info:
        stickmorph.compatible_triangulation(SQUARE, SQUARE, corners=corners)
    assert (info.value.defect, info.value.role) == (defect, "source")


def test_crossing_comb():
    crossing = COMB[:5] + [[9.0, -1.0]] + COMB[6:]
    with pytest.raises(stickmorph.InvalidFigureError, match="in the target.*cross"):
        stickmorph.compatible_triangulation(STAR, crossing)


def test_too_few_corners():
    with pytest.raises(stickmorph.InvalidFigureError, match="2 corners"):
        stickmorph.compatible_triangulation(SQUARE, SQUARE, corners=[0, 1])


def test_mismatched_vertex_counts():
    with pytest.raises(stickmorph.InvalidArgumentError, match="same number of vertices, got 4 and 5"):
        stickmorph.compatible_triangulation(SQUARE, SQUARE + [[1.0, 1.0]])


@pytest.mark.parametrize("bad, shape", [
    (np.zeros((4, 3)), r"\(4, 3\)"),
    (np.zeros(8), r"\(8,\)"),
    (np.zeros((2, 2, 2)), r"\(2, 2, 2\)"),
])
@pytest.mark.parametrize("role", ["source", "target"])
def test_vertices_of_wrong_shape(role, bad, shape):
    arguments = (bad, SQUARE) if role == "source" else (SQUARE, bad)
    with pytest.raises(stickmorph.InvalidArgumentError, match=rf"{role} must have shape \(#V, 2\), got {shape}"):
        stickmorph.compatible_triangulation(*arguments)


def test_vertices_of_wrong_dtype():
    with pytest.raises(stickmorph.InvalidArgumentError, match="target must hold real numbers"):
        stickmorph.compatible_triangulation(SQUARE, np.ones((4, 2), dtype=bool))


@pytest.mark.parametrize("value, defect", [(math.nan, "non_finite_coordinate"),
                                           (math.inf, "non_finite_coordinate"),
                                           (1e101, "coordinate_too_large")])
def test_bad_coordinates(value, defect):
    target = [list(p) for p in SQUARE]
    target[2][1] = value
    with pytest.raises(stickmorph.InvalidFigureError, match="in the target: vertex 2") as info:
        stickmorph.compatible_triangulation(SQUARE, target)
    assert info.value.defect == defect
    assert info.value.vertices == [2]


@pytest.mark.parametrize("index", [4, -1, 2**40])
def test_corner_out_of_range(index):
    corners = [0, 1, index, 3]
    with pytest.raises(stickmorph.InvalidArgumentError,
                       match=rf"corner 2: vertex index {index} is out of range for 4 vertices"):
        stickmorph.compatible_triangulation(SQUARE, SQUARE, corners=corners)


def test_corners_of_wrong_shape():
    with pytest.raises(stickmorph.InvalidArgumentError, match=r"corners must have shape \(#C,\), got \(2, 2\)"):
        stickmorph.compatible_triangulation(SQUARE, SQUARE, corners=[[0, 1], [2, 3]])


@pytest.mark.parametrize("corners, message", [
    ([0, 1, 2.5, 3], "corner 2: index 2.5 is not an integer"),
    ([0, 1, 2, math.nan], "corner 3: index nan is not an integer"),
    (np.array([0, 2**64 - 1, 2, 3], dtype=np.uint64),
     "corner 1: index 18446744073709551615 does not fit in a 64-bit signed integer"),
    (np.array(["0", "1", "2", "3"]), "corners must hold integer vertex indices, got dtype <U1"),
])
def test_corners_of_wrong_values(corners, message):
    with pytest.raises(stickmorph.InvalidArgumentError, match=message.replace("(", r"\(")):
        stickmorph.compatible_triangulation(SQUARE, SQUARE, corners=corners)


def test_negative_smoothing_rounds():
    with pytest.raises(stickmorph.InvalidArgumentError, match="smoothing_rounds must be at least 0, got -1"):
        stickmorph.compatible_triangulation(SQUARE, SQUARE, smoothing_rounds=-1)
