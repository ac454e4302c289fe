"""Tests of `stickmorph triangulate` and `stickmorph morph` through the CLI.

../shared/FORMAT.md fixes the morph document (edges, times, frames,
triangulation, stats) and the error contract (exit 2, one `error:` line on
stderr); docs/CLI.md documents `triangulate`, the options and the extensions
(--svg, --method rigid|barycentric|linear, stats.invalid_frames, stats.rigid).
A failure must leave no output file behind, not even a temporary
(.OUT.json.XXXXXX beside it, or the OUT.json.partial of earlier versions).

The default method is rigid (issue 12): the similarity between the figures
is factored out, so its triangulation is in output space, with the target's
enclosure the source's moved by that similarity (the paper's section 6
"rotated enclosure"). `stickmorph triangulate` writes the barycentric
morph's triangulation, whose enclosure is the same in both figures.

Every subprocess runs with a timeout, so a hang fails the test instead of
stalling the suite.
"""
import json
import math
import pathlib
import subprocess
import xml.etree.ElementTree as ElementTree
from fractions import Fraction

import numpy as np
import pytest

import stickmorph
from rigid_stats import check_rigid_section

TIMEOUT_SECONDS = 120
SVG = "{http://www.w3.org/2000/svg}"

COMPATIBLE = ["letter_a", "letter_b", "tree_junction", "polygon", "polyline", "single_vertex",
              "single_edge", "square_with_spikes", "wheel", "glyph_L_to_V", "glyph_7_to_L"]
INCOMPATIBLE = ["junction_rotation", "mirror_image", "exterior_differs", "polygon_reversed",
                "edge_set_differs", "vertex_count_differs", "nesting_differs"]
# (folder under tests/data, pair name): every compatible pair and the paper's.
PAIRS = [("pairs/compatible", name) for name in COMPATIBLE] + [("paper", "s_to_u")]
PAIR_IDS = [name for _, name in PAIRS]

# The stats each kind of morph documents (FORMAT.md and docs/CLI.md); the
# document may grow more ("extend freely"), so these are checked as subsets.
MORPH_STATS_BARYCENTRIC = {"steiner_vertices", "triangles", "parts", "bridge_vertices", "milliseconds", "method",
                           "steiner_method", "enclosure_sides", "weights", "verified", "refined_frames"}
MORPH_STATS_RIGID = MORPH_STATS_BARYCENTRIC | {"factorizations", "rigid"}
MORPH_STATS_LINEAR = {"steiner_vertices", "triangles", "parts", "bridge_vertices", "milliseconds", "method",
                      "invalid_frames"}
TRIANGULATION_KEYS = {"figure_vertices", "enclosure_vertices", "steiner_vertices", "source", "target",
                      "triangles"}


def run(cli, *args):
    result = subprocess.run([str(cli), *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                            timeout=TIMEOUT_SECONDS)
    result.stdout = result.stdout.decode("utf-8", "replace")
    result.stderr = result.stderr.decode("utf-8", "replace")
    return result


def run_ok(cli, *args):
    result = run(cli, *args)
    assert result.returncode == 0, (result.returncode, result.stderr)
    assert result.stderr == "" and result.stdout == ""
    return result


def assert_error(result, output):
    """Exit 2, one `error: ` line on stderr, nothing on stdout, and no output
    file (nor its temporary) left behind. Returns the message."""
    assert result.returncode == 2, (result.returncode, result.stdout, result.stderr)
    assert result.stdout == ""
    assert result.stderr.startswith("error: "), result.stderr
    assert result.stderr.endswith("\n") and result.stderr.count("\n") == 1, result.stderr
    for crash_sign in ("Traceback", "terminate called", "Aborted", "Segmentation", "what():"):
        assert crash_sign not in result.stderr
    assert not output.exists(), output
    assert not output.with_name(output.name + ".partial").exists()
    assert list(output.parent.iterdir()) == [], list(output.parent.iterdir())
    return result.stderr[len("error: "):-1]


def pair_paths(data_dir, folder, name):
    return data_dir / folder / f"{name}.source.json", data_dir / folder / f"{name}.target.json"


def read_figure(path):
    document = json.loads(path.read_text())
    return [[float(x), float(y)] for x, y in document["vertices"]], document["edges"]


def exact(point):
    return Fraction(point[0]), Fraction(point[1])


def orient(a, b, c):
    value = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (value > 0) - (value < 0)


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def is_point_list(points, count):
    return (isinstance(points, list) and len(points) == count
            and all(isinstance(p, list) and len(p) == 2 and all(map(is_number, p)) for p in points))


def similarity_image(similarity, points):
    """`points` moved by the rigid morph's fitted similarity at t = 1:
    target_center + scale * R(angle) (x - source_center)."""
    angle = math.radians(similarity["angle_degrees"])
    scale = similarity["scale"]
    c, s = scale * math.cos(angle), scale * math.sin(angle)
    (ax, ay), (bx, by) = similarity["source_center"], similarity["target_center"]
    return [[bx + c * (x - ax) - s * (y - ay), by + s * (x - ax) + c * (y - ay)] for x, y in points]


def check_triangulation_object(tri, source_vertices, target_vertices, edges, similarity=None):
    """FORMAT.md's triangulation object, with its orientation promises checked
    exactly. Without `similarity` (the barycentric morph, `triangulate`) the
    enclosure is the same convex polygon in both figures; with it (the rigid
    morph's stats["rigid"]["similarity"], when factored out) the target's
    enclosure is the source's moved by that similarity, convex in both."""
    assert set(tri) == TRIANGULATION_KEYS
    n, k, s = tri["figure_vertices"], tri["enclosure_vertices"], tri["steiner_vertices"]
    assert all(type(v) is int for v in (n, k, s))
    assert n == len(source_vertices) and k >= 3 and s >= 0
    nodes = n + k + s
    assert is_point_list(tri["source"], nodes) and is_point_list(tri["target"], nodes)
    assert tri["source"][:n] == source_vertices
    assert tri["target"][:n] == target_vertices
    if similarity is None:
        assert tri["source"][n:n + k] == tri["target"][n:n + k]
    else:
        moved = np.array(similarity_image(similarity, tri["source"][n:n + k]))
        ring = np.array(tri["target"][n:n + k])
        size = float(np.ptp(ring, axis=0).max())
        np.testing.assert_allclose(ring, moved, rtol=0, atol=1e-12 * size)
    for embedding in (tri["source"], tri["target"]):
        ring = [exact(p) for p in embedding[n:n + k]]
        assert all(orient(ring[i], ring[(i + 1) % k], ring[(i + 2) % k]) > 0 for i in range(k))
    triangles = tri["triangles"]
    assert isinstance(triangles, list) and len(triangles) == 2 * nodes - k - 2
    for triangle in triangles:
        assert isinstance(triangle, list) and len(triangle) == 3
        assert all(type(v) is int and 0 <= v < nodes for v in triangle), triangle
        assert len(set(triangle)) == 3
    for embedding in (tri["source"], tri["target"]):
        points = [exact(p) for p in embedding]
        for a, b, c in triangles:
            assert orient(points[a], points[b], points[c]) > 0, (a, b, c)
    sides = {frozenset(side) for t in triangles for side in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
    for i, j in edges:
        assert frozenset((i, j)) in sides, (i, j)


def check_rigid_stats(stats, source_vertices, target_vertices, frames, rotation="short", turns=0,
                      easing="none"):
    """stats["rigid"] of a rigid morph (docs/CLI.md), as rigid_stats.py checks it."""
    return check_rigid_section(stats, source_vertices, target_vertices, frames, rotation, turns, easing)


def check_morph_document(document, source_path, target_path, frames, method="rigid", **rigid_options):
    source_vertices, source_edges = read_figure(source_path)
    target_vertices, _ = read_figure(target_path)
    n = len(source_vertices)
    assert set(document) == {"edges", "times", "frames", "triangulation", "stats"}
    assert document["edges"] == source_edges
    times = document["times"]
    assert isinstance(times, list) and len(times) == frames
    assert all(type(t) is float for t in times)
    assert times == [k / (frames - 1) for k in range(frames)]
    assert times[0] == 0.0 and times[-1] == 1.0
    assert isinstance(document["frames"], list) and len(document["frames"]) == frames
    for frame in document["frames"]:
        assert is_point_list(frame, n)
    assert document["frames"][0] == source_vertices
    assert document["frames"][-1] == target_vertices

    stats = document["stats"]
    assert stats["method"] == method
    milliseconds = stats["milliseconds"]
    assert all(is_number(v) and v >= 0 for v in milliseconds.values())
    tri = document["triangulation"]
    if method == "linear":
        assert tri is None
        assert MORPH_STATS_LINEAR <= set(stats)
        assert "steiner_method" not in stats and "refined_frames" not in stats
        assert {"triangulate", "morph"} <= set(milliseconds)
        assert stats["steiner_vertices"] == 0 and stats["triangles"] == 0
        invalid = stats["invalid_frames"]
        assert isinstance(invalid, list) and invalid == sorted(set(invalid))
        assert all(type(f) is int and 0 < f < frames - 1 for f in invalid)
    else:
        assert (MORPH_STATS_RIGID if method == "rigid" else MORPH_STATS_BARYCENTRIC) <= set(stats)
        assert "invalid_frames" not in stats
        assert {"triangulate", "morph", "factorize", "solve", "verify"} <= set(milliseconds)
        similarity = None
        if method == "rigid":
            rigid = check_rigid_stats(stats, source_vertices, target_vertices, frames, **rigid_options)
            if rigid["similarity_factored"]:
                similarity = rigid["similarity"]
        else:
            assert "rigid" not in stats and not rigid_options
        check_triangulation_object(tri, source_vertices, target_vertices, source_edges, similarity)
        assert stats["steiner_vertices"] == tri["steiner_vertices"]
        assert stats["triangles"] == len(tri["triangles"])
        assert stats["enclosure_sides"] == tri["enclosure_vertices"]
        assert stats["verified"] is True
        assert type(stats["refined_frames"]) is int and 0 <= stats["refined_frames"] <= frames


def check_svg(path):
    root = ElementTree.parse(path).getroot()
    assert root.tag == SVG + "svg"
    assert float(root.get("width")) > 0 and float(root.get("height")) > 0
    drawn = [e for e in root.iter() if e.tag in (SVG + "line", SVG + "polyline", SVG + "polygon",
                                                 SVG + "path", SVG + "circle")]
    assert drawn
    return root


# --------------------------------------------------------------------------
# Success


def test_every_pair_is_listed(data_dir):
    on_disk = {p.name.rsplit(".", 2)[0] for p in (data_dir / "pairs" / "compatible").glob("*.json")}
    assert on_disk == set(COMPATIBLE)
    on_disk = {p.name.rsplit(".", 2)[0] for p in (data_dir / "pairs" / "incompatible").glob("*.json")}
    assert on_disk == set(INCOMPATIBLE)


@pytest.mark.parametrize("folder, name", PAIRS, ids=PAIR_IDS)
def test_triangulate(cli, data_dir, tmp_path, folder, name):
    source, target = pair_paths(data_dir, folder, name)
    out, svg = tmp_path / "tri.json", tmp_path / "tri.svg"
    run_ok(cli, "triangulate", source, target, "-o", out, "--svg", svg)
    tri = json.loads(out.read_text())
    source_vertices, edges = read_figure(source)
    target_vertices, _ = read_figure(target)
    check_triangulation_object(tri, source_vertices, target_vertices, edges)
    assert tri["enclosure_vertices"] == 6
    check_svg(svg)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tri.json", "tri.svg"]


@pytest.mark.parametrize("method", [None, "barycentric"], ids=["default-rigid", "barycentric"])
@pytest.mark.parametrize("folder, name", PAIRS, ids=PAIR_IDS)
def test_morph(cli, data_dir, tmp_path, folder, name, method):
    source, target = pair_paths(data_dir, folder, name)
    out, svg = tmp_path / "morph.json", tmp_path / "morph.svg"
    options = [] if method is None else ["--method", method]
    run_ok(cli, "morph", source, target, "-o", out, "--svg", svg, *options)
    document = json.loads(out.read_text())
    check_morph_document(document, source, target, 50, method=method or "rigid")
    check_svg(svg)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["morph.json", "morph.svg"]
    run_ok(cli, "triangulate", source, target, "-o", tmp_path / "tri.json")
    written = json.loads((tmp_path / "tri.json").read_text())
    if method == "barycentric":
        # The barycentric morph used the triangulation `triangulate` writes.
        assert written == document["triangulation"]
    else:
        # The rigid morph's is its own, in output space: its target
        # enclosure moved with the figure unless the similarity is the
        # identity (or was not factored out).
        tri = document["triangulation"]
        n, k = tri["figure_vertices"], tri["enclosure_vertices"]
        rigid = document["stats"]["rigid"]
        similarity = rigid["similarity"]
        identity = (similarity["angle_degrees"] == 0 and similarity["scale"] == 1
                    and similarity["source_center"] == similarity["target_center"])
        moved = tri["target"][n:n + k] != tri["source"][n:n + k]
        assert moved == (rigid["similarity_factored"] and not identity)
        assert written["target"][n:n + written["enclosure_vertices"]] == \
            written["source"][n:n + written["enclosure_vertices"]]


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
@pytest.mark.parametrize("frames", [2, 3, 7])
@pytest.mark.parametrize("name", ["tree_junction", "square_with_spikes"])
def test_morph_frame_counts(cli, data_dir, tmp_path, frames, name, method):
    source, target = pair_paths(data_dir, "pairs/compatible", name)
    out = tmp_path / "morph.json"
    run_ok(cli, "morph", source, target, "-o", out, "--frames", frames, "--method", method)
    check_morph_document(json.loads(out.read_text()), source, target, frames, method=method)


@pytest.mark.parametrize("options", [["--steiner", "sg2001"], ["--steiner", "aronov"],
                                     ["--weights", "uniform"], ["--weights", "floater"],
                                     ["--enclosure-sides", "4"], ["--no-verify"],
                                     ["--frame-check", "full"], ["--frame-check", "certificate"],
                                     ["--svg-triangulation", "--svg", "{tmp}/film.svg"],
                                     ["--svg-compare-linear", "--svg", "{tmp}/film.svg"]])
@pytest.mark.parametrize("method", ["rigid", "barycentric"])
def test_morph_options(cli, data_dir, tmp_path, options, method):
    # The triangulation and check options apply to both methods.
    source, target = pair_paths(data_dir, "pairs/compatible", "polyline")
    out = tmp_path / "morph.json"
    options = [o.format(tmp=tmp_path) for o in options]
    run_ok(cli, "morph", source, target, "-o", out, "--frames", 5, "--method", method, *options)
    document = json.loads(out.read_text())
    stats = document["stats"]
    if "--no-verify" in options:
        # The document says so, and the frames are otherwise as usual.
        assert stats["verified"] is False
        stats["verified"] = True
    check_morph_document(document, source, target, 5, method=method)
    if "--steiner" in options:
        assert stats["steiner_method"] == options[1]
    if "--weights" in options:
        assert stats["weights"] == options[1]
    if "--enclosure-sides" in options:
        assert document["triangulation"]["enclosure_vertices"] == 4
    if "--svg" in options:
        check_svg(tmp_path / "film.svg")


@pytest.mark.parametrize("cli_options, keywords", [
    ([], {}),
    (["--method", "barycentric"], {"method": "barycentric"}),
    (["--rotation", "ccw", "--turns", "-2", "--easing", "in-out"],
     {"rotation": "ccw", "turns": -2, "easing": "in-out"}),
], ids=["default-rigid", "barycentric", "rigid-options"])
def test_morph_agrees_with_the_module(cli, data_dir, tmp_path, cli_options, keywords):
    source, target = pair_paths(data_dir, "paper", "s_to_u")
    out = tmp_path / "morph.json"
    run_ok(cli, "morph", source, target, "-o", out, "--frames", 9, "--weights", "floater", *cli_options)
    document = json.loads(out.read_text())
    a, b = stickmorph.load_figure(source), stickmorph.load_figure(target)
    result = stickmorph.morph(a["vertices"], b["vertices"], a["edges"], frames=9, weights="floater", **keywords)
    # Full double precision: the text reads back as the very same doubles.
    assert np.array_equal(np.array(document["frames"]), result["frames"])
    assert np.array_equal(np.array(document["times"]), result["times"])
    tri = result["triangulation"]
    for key in ("source", "target", "triangles"):
        assert np.array_equal(np.array(document["triangulation"][key]), tri[key])
    assert document["stats"]["method"] == result["stats"]["method"] == keywords.get("method", "rigid")
    if "rigid" in result["stats"]:
        rigid = dict(result["stats"]["rigid"])
        rigid["similarity"] = {key: list(value) if isinstance(value, tuple) else value
                               for key, value in rigid["similarity"].items()}
        assert document["stats"]["rigid"] == rigid


@pytest.mark.parametrize("folder, name", [("paper", "s_to_u"), ("pairs/compatible", "letter_a")])
def test_morph_linear(cli, data_dir, tmp_path, folder, name):
    source, target = pair_paths(data_dir, folder, name)
    out, svg = tmp_path / "morph.json", tmp_path / "morph.svg"
    run_ok(cli, "morph", source, target, "-o", out, "--method", "linear", "--svg", svg)
    document = json.loads(out.read_text())
    check_morph_document(document, source, target, 50, method="linear")
    check_svg(svg)
    invalid = document["stats"]["invalid_frames"]
    if name == "s_to_u":
        assert invalid, "the paper's Figure 8d: the S self-intersects on its way to the U"
    else:
        assert invalid == []
    # Straight lines between the endpoints.
    frames = np.array(document["frames"])
    times = np.array(document["times"])
    straight = (1 - times)[:, None, None] * frames[0][None] + times[:, None, None] * frames[-1][None]
    np.testing.assert_allclose(frames, straight, rtol=0, atol=1e-13)


# The rigid method's own options (docs/CLI.md): they are reported back in
# stats.rigid, and the morph stays a valid morph whichever way it turns.
@pytest.mark.parametrize("options, expected", [
    (["--rotation", "ccw"], {"rotation": "ccw"}),
    (["--rotation", "cw"], {"rotation": "cw"}),
    (["--turns", "1"], {"turns": 1}),
    (["--turns", "-100"], {"turns": -100}),
    (["--turns=100", "--rotation=cw"], {"turns": 100, "rotation": "cw"}),
    (["--easing", "in-out"], {"easing": "in-out"}),
    (["--method", "rigid", "--rotation", "short", "--turns", "0", "--easing", "none"], {}),
])
def test_morph_rigid_options(cli, data_dir, tmp_path, options, expected):
    source, target = pair_paths(data_dir, "pairs/compatible", "letter_a")
    out = tmp_path / "morph.json"
    run_ok(cli, "morph", source, target, "-o", out, "--frames", 7, *options)
    check_morph_document(json.loads(out.read_text()), source, target, 7, **expected)


def half_turn_pair(tmp_path):
    """A tree and its copy turned by exactly 180 degrees about its centroid
    (0.875, 0.5), exact in doubles: x -> 2 c - x."""
    vertices = [[0.0, 0.0], [3.0, 0.0], [0.0, 3.0], [-3.0, 0.0], [0.0, -3.0], [4.0, 1.0], [4.0, -1.0], [-1.0, 4.0]]
    edges = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 5], [1, 6], [2, 7]]
    turned = [[1.75 - x, 1.0 - y] for x, y in vertices]
    source, target = tmp_path / "tree.json", tmp_path / "tree_turned.json"
    source.write_text(json.dumps({"vertices": vertices, "edges": edges}))
    target.write_text(json.dumps({"vertices": turned, "edges": edges}))
    return source, target


def test_morph_half_turn_is_a_rotation(cli, tmp_path):
    # Issue 12: a figure morphed into itself turned by 180 degrees simply
    # turns, with no Steiner vertex, no stretching and even speed.
    source, target = half_turn_pair(tmp_path)
    out = tmp_path / "morph.json"
    frames = 13
    run_ok(cli, "morph", source, target, "-o", out, "--frames", frames)
    document = json.loads(out.read_text())
    check_morph_document(document, source, target, frames)
    # Steiner vertices only for the angles (compatible refinement, issue 30).
    assert document["stats"]["steiner_vertices"] == document["stats"]["rigid"]["refinement_steiner_vertices"]
    assert document["stats"]["rigid"]["similarity"]["scale"] == pytest.approx(1, abs=1e-12)
    angle = document["stats"]["rigid"]["similarity"]["angle_degrees"]
    assert abs(angle) == pytest.approx(180, abs=1e-9)
    positions = np.array(document["frames"])
    edges = np.array(document["edges"])
    lengths = np.linalg.norm(positions[:, edges[:, 1]] - positions[:, edges[:, 0]], axis=2)
    np.testing.assert_allclose(lengths, np.broadcast_to(lengths[0], lengths.shape), rtol=1e-9, atol=0)
    direction = positions[:, 1] - positions[:, 0]
    turned = np.degrees(np.unwrap(np.arctan2(direction[:, 1], direction[:, 0])))
    np.testing.assert_allclose(turned - turned[0], angle * np.arange(frames) / (frames - 1), rtol=0, atol=1e-7)


# --------------------------------------------------------------------------
# Errors


@pytest.fixture
def out_dir(tmp_path):
    """An empty folder for the output, so that leftovers show."""
    folder = tmp_path / "out"
    folder.mkdir()
    return folder


def letter_a(data_dir):
    return pair_paths(data_dir, "pairs/compatible", "letter_a")


@pytest.mark.parametrize("command", ["triangulate", "morph"])
def test_missing_output(cli, data_dir, out_dir, command):
    source, target = letter_a(data_dir)
    message = assert_error(run(cli, command, source, target), out_dir / "OUT.json")
    assert message.startswith(f"{command}: missing option --output")


@pytest.mark.parametrize("frames, fragment", [
    ("1", "--frames must be at least 2, got 1"),
    ("0", "--frames must be at least 2, got 0"),
    ("100001", "--frames must be at most 100000, got 100001"),
    ("abc", "--frames needs a whole number, got 'abc'"),
    ("7.5", "--frames needs a whole number"),
    ("", "--frames needs a whole number"),
    ("99999999999999999999", "--frames needs a whole number"),
])
def test_bad_frames(cli, data_dir, out_dir, frames, fragment):
    source, target = letter_a(data_dir)
    out = out_dir / "OUT.json"
    message = assert_error(run(cli, "morph", source, target, "-o", out, "--frames", frames), out)
    assert fragment in message


@pytest.mark.parametrize("command, option, value, fragment", [
    ("morph", "--steiner", "delaunay", "unknown Steiner method 'delaunay'"),
    ("triangulate", "--steiner", "delaunay", "unknown Steiner method 'delaunay'"),
    ("morph", "--weights", "cotan", "unknown weight kind 'cotan'"),
    ("morph", "--method", "spline", "unknown morph method 'spline' (choose rigid, barycentric or linear)"),
    ("morph", "--rotation", "left", "unknown rotation direction 'left' (choose short, ccw or cw)"),
    ("morph", "--rotation", "CCW", "unknown rotation direction 'CCW' (choose short, ccw or cw)"),
    ("morph", "--easing", "smooth", "unknown easing 'smooth' (choose none or in-out)"),
    ("morph", "--turns", "101", "option --turns must be at most 100, got 101"),
    ("morph", "--turns", "-101", "option --turns must be at least -100, got -101"),
    ("morph", "--turns", "1.5", "option --turns needs a whole number, got '1.5'"),
    ("morph", "--turns", "x", "option --turns needs a whole number, got 'x'"),
    ("morph", "--turns", "99999999999999999999", "option --turns needs a whole number"),
    ("triangulate", "--turns", "1", "unknown option '--turns'"),
    ("triangulate", "--rotation", "ccw", "unknown option '--rotation'"),
    ("triangulate", "--easing", "in-out", "unknown option '--easing'"),
    ("morph", "--enclosure-sides", "2", "--enclosure-sides must be at least 3"),
    ("triangulate", "--enclosure-sides", "x", "--enclosure-sides needs a whole number"),
    ("triangulate", "--weights", "mvc", "unknown option '--weights'"),
    ("triangulate", "--frames", "5", "unknown option '--frames'"),
])
def test_bad_options(cli, data_dir, out_dir, command, option, value, fragment):
    source, target = letter_a(data_dir)
    out = out_dir / "OUT.json"
    message = assert_error(run(cli, command, source, target, "-o", out, option, value), out)
    assert fragment in message


@pytest.mark.parametrize("method", ["barycentric", "linear"])
@pytest.mark.parametrize("option, value", [("--rotation", "short"), ("--rotation", "ccw"), ("--turns", "0"),
                                           ("--turns", "3"), ("--easing", "none"), ("--easing", "in-out")])
def test_rigid_options_refused_with_other_methods(cli, data_dir, out_dir, method, option, value):
    # Even its default value, once given, would mean nothing there.
    source, target = letter_a(data_dir)
    out = out_dir / "OUT.json"
    message = assert_error(run(cli, "morph", source, target, "-o", out, "--method", method, option, value), out)
    assert message == (f"option {option} has no effect with --method {method} "
                       "(only the rigid method factors out a rotation and follows a guide)")


def test_rigid_options_refused_before_the_figures_are_read(cli, data_dir, out_dir):
    # As every argument check: a missing figure file is not even looked at.
    source, _ = letter_a(data_dir)
    out = out_dir / "OUT.json"
    message = assert_error(run(cli, "morph", source, out_dir / "nope.json", "-o", out, "--method", "barycentric",
                               "--turns", "1"), out)
    assert message.startswith("option --turns has no effect with --method barycentric")


@pytest.mark.parametrize("name", INCOMPATIBLE)
@pytest.mark.parametrize("arguments", [["triangulate"], ["morph"], ["morph", "--method", "barycentric"],
                                       ["morph", "--method", "linear"]],
                         ids=["triangulate", "morph", "morph-barycentric", "morph-linear"])
def test_incompatible_pair(cli, data_dir, out_dir, name, arguments):
    source, target = pair_paths(data_dir, "pairs/incompatible", name)
    out = out_dir / "OUT.json"
    svg = out_dir / "OUT.svg"
    command, *options = arguments
    message = assert_error(run(cli, command, source, target, "-o", out, "--svg", svg, *options), out)
    assert "incompatible" in message
    assert not svg.exists()


MALFORMED = sorted(p.name for p in (pathlib.Path(__file__).resolve().parents[1]
                                    / "data" / "malformed").iterdir())


@pytest.mark.parametrize("name", MALFORMED)
@pytest.mark.parametrize("command", ["triangulate", "morph"])
def test_malformed_file(cli, data_dir, out_dir, name, command):
    good_source, good_target = letter_a(data_dir)
    bad = data_dir / "malformed" / name
    out = out_dir / "OUT.json"
    for source, target in ((bad, good_target), (good_source, bad)):
        message = assert_error(run(cli, command, source, target, "-o", out), out)
        assert message.startswith(str(bad)), message


def test_missing_file(cli, data_dir, out_dir):
    source, _ = letter_a(data_dir)
    out = out_dir / "OUT.json"
    message = assert_error(run(cli, "morph", source, out_dir / "nope.json", "-o", out), out)
    assert "cannot read file" in message


def test_unwritable_output(cli, data_dir, out_dir):
    source, target = letter_a(data_dir)
    out = out_dir / "missing-folder" / "OUT.json"
    message = assert_error(run(cli, "morph", source, target, "-o", out), out_dir / "OUT.json")
    assert "cannot write file" in message


def test_failure_keeps_an_existing_output(cli, data_dir, tmp_path):
    # The file is replaced only by a complete result.
    source, target = pair_paths(data_dir, "pairs/incompatible", "mirror_image")
    out = tmp_path / "OUT.json"
    out.write_text("previous")
    result = run(cli, "morph", source, target, "-o", out)
    assert result.returncode == 2 and out.read_text() == "previous"
    assert not (tmp_path / "OUT.json.partial").exists()


@pytest.mark.parametrize("method", ["rigid", "barycentric"])
def test_morph_frame_check_full_gives_the_same_frames(cli, data_dir, tmp_path, method):
    # The certificate (default) and the full check accept the same frames:
    # the documents agree except for the timings.
    source, target = pair_paths(data_dir, "pairs/compatible", "square_with_spikes")
    documents = []
    for check in ("certificate", "full"):
        out = tmp_path / f"{check}.json"
        run_ok(cli, "morph", source, target, "-o", out, "--frames", 9, "--method", method, "--frame-check", check)
        documents.append(json.loads(out.read_text()))
    assert documents[0]["frames"] == documents[1]["frames"]


@pytest.mark.parametrize("options, message", [
    (["--frame-check", "full", "--no-verify"],
     "option --frame-check has no effect with --no-verify (no frame is checked)"),
    (["--frame-check", "full", "--method", "linear"],
     "option --frame-check has no effect with --method linear (the straight-line morph uses no triangulation)"),
    (["--frame-check", "quick"], "unknown frame check 'quick' (choose certificate or full)"),
])
def test_morph_frame_check_refusals(cli, data_dir, tmp_path, options, message):
    source, target = pair_paths(data_dir, "pairs/compatible", "polyline")
    out = tmp_path / "morph.json"
    assert assert_error(run(cli, "morph", source, target, "-o", out, *options), out) == message
