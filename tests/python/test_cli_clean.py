"""`stickmorph clean INPUT.json -o OUT.json [--tolerance T]` (docs/FORMAT.md,
"Cleaning a drawing"; issue 32).

tests/data/drawings/stick_man_drawn.*: a stick man drawn the way a tablet
records him (dense jittered points, a head ring closed past its start, arms in
one stroke crossing the spine, legs starting a little off the hip, pen pauses),
in two poses.
"""
import json
import math
import subprocess
from fractions import Fraction

import pytest

TIMEOUT_SECONDS = 120


def run(cli, *args):
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=TIMEOUT_SECONDS)


@pytest.fixture
def drawings(data_dir):
    folder = data_dir / "drawings"
    return folder / "stick_man_drawn.source.json", folder / "stick_man_drawn.target.json"


def clean(cli, tmp_path, source, *options, name="clean.json"):
    out = tmp_path / name
    result = run(cli, "clean", source, "-o", out, *options)
    assert result.returncode == 0, result.stderr
    return json.loads(out.read_text()), result.stdout, out


def orientation(a, b, c):
    a, b, c = [tuple(map(Fraction, p)) for p in (a, b, c)]
    value = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (value > 0) - (value < 0)


def segments_meet(a, b, c, d):
    """Whether closed segments ab and cd share a point, in exact arithmetic."""
    o1, o2, o3, o4 = orientation(a, b, c), orientation(a, b, d), orientation(c, d, a), orientation(c, d, b)
    if o1 == o2 == o3 == o4 == 0:
        key = lambda p: (Fraction(p[0]), Fraction(p[1]))
        lo1, hi1 = sorted([key(a), key(b)])
        lo2, hi2 = sorted([key(c), key(d)])
        return not (hi1 < lo2 or hi2 < lo1)
    return o1 * o2 <= 0 and o3 * o4 <= 0


def assert_plane_graph(document):
    """An independent exact check: distinct vertices, edges meeting only at shared ends."""
    vertices, edges = document["vertices"], document["edges"]
    assert len({tuple(v) for v in vertices}) == len(vertices)
    for i, (a, b) in enumerate(edges):
        for c, d in edges[i + 1:]:
            if {a, b} & {c, d}:
                shared = ({a, b} & {c, d}).pop()
                x, y = ({a, b} - {shared}).pop(), ({c, d} - {shared}).pop()
                # Adjacent edges: not folded onto each other.
                p, q, r = vertices[shared], vertices[x], vertices[y]
                if orientation(p, q, r) == 0:
                    assert (q[0] - p[0]) * (r[0] - p[0]) + (q[1] - p[1]) * (r[1] - p[1]) < 0
                continue
            assert not segments_meet(vertices[a], vertices[b], vertices[c], vertices[d]), (a, b, c, d)


def test_a_drawn_stick_man_cleans_into_a_valid_figure_with_every_change_listed(cli, tmp_path, drawings):
    source, _ = drawings
    document, stdout, out = clean(cli, tmp_path, source)
    cleaning = document["cleaning"]
    assert stdout == f"cleaned: {cleaning['summary']}\n"
    assert_plane_graph(document)
    assert run(cli, "check", out, out).returncode == 0
    # Pinned: the arms cross the spine (1 junction); the ring's start, the
    # spine's top and bottom and a leg's start snap; the ring's first three
    # points (its overlap, crossing its end) and two pen pauses merge.
    assert cleaning["summary"] == "1 junction made, 4 ends snapped, 5 points merged"
    kinds = [change["kind"] for change in cleaning["changes"]]
    assert cleaning["junctions_made"] == kinds.count("crossing") + kinds.count("touch") == 1
    assert cleaning["ends_snapped"] == kinds.count("snap")
    assert cleaning["points_merged"] == kinds.count("merge")
    # Every input point lands on its vertex where it was drawn unless a
    # merge or snap names it, with the distance it moved.
    drawn = json.loads(source.read_text())
    named = {(c["stroke"], c["point"]): c["distance"] for c in cleaning["changes"] if c["kind"] in ("merge", "snap")}
    for s, (stroke, mapping) in enumerate(zip(drawn["strokes"], cleaning["point_vertices"])):
        path = cleaning["strokes"][s]["vertices"]
        for j, (point, vertex) in enumerate(zip(stroke["points"], mapping)):
            assert vertex in path
            moved = math.dist(point, document["vertices"][vertex])
            if (s, j) in named:
                assert named[(s, j)] == pytest.approx(moved, rel=1e-12, abs=1e-15)
            else:
                assert moved == 0, (s, j)
    # Each stroke's path walks edges of the figure, and every edge is on a path.
    edges = {frozenset(e) for e in document["edges"]}
    walked = set()
    for stroke in cleaning["strokes"]:
        path = stroke["vertices"]
        steps = list(zip(path, path[1:])) + ([(path[-1], path[0])] if stroke["cyclic"] else [])
        for a, b in steps:
            assert frozenset((a, b)) in edges
            walked.add(frozenset((a, b)))
    assert walked == edges
    # The drawing meant: one ring, a spine crossed by the arms, two legs at
    # the hip. One part, one loop, four free ends, junctions of degree 3, 3, 4.
    degree = {}
    for a, b in document["edges"]:
        degree[a] = degree.get(a, 0) + 1
        degree[b] = degree.get(b, 0) + 1
    assert len(document["edges"]) - len(document["vertices"]) + 1 == 1
    assert sorted(d for d in degree.values() if d != 2) == [1, 1, 1, 1, 3, 3, 4]


def test_the_cleaned_figure_cleans_to_itself(cli, tmp_path, drawings):
    for drawing in drawings:
        document, _, out = clean(cli, tmp_path, drawing, name="once.json")
        again, stdout, _ = clean(cli, tmp_path, out, "--tolerance", document["cleaning"]["tolerance"], name="twice.json")
        assert stdout == "cleaned: no changes\n"
        assert again["vertices"] == document["vertices"]
        assert again["edges"] == document["edges"]
        assert again["cleaning"]["changes"] == []


def test_two_drawn_poses_clean_and_morph_with_correspond_auto(cli, tmp_path, drawings):
    source, target = drawings
    _, _, source_clean = clean(cli, tmp_path, source, name="source.json")
    _, _, target_clean = clean(cli, tmp_path, target, name="target.json")
    out = tmp_path / "morph.json"
    result = run(cli, "morph", source_clean, target_clean, "-o", out, "--correspond", "auto", "--frames", 12)
    assert result.returncode == 0, result.stderr
    morph = json.loads(out.read_text())
    assert len(morph["frames"]) == 12


def test_a_figure_file_whose_edges_cross_is_cleaned(cli, tmp_path):
    figure = tmp_path / "x.json"
    figure.write_text(json.dumps({"vertices": [[0, 0], [2, 2], [0, 2], [2, 0]], "edges": [[0, 1], [2, 3]]}))
    assert run(cli, "check", figure, figure).returncode == 2  # not a stick figure as given
    document, stdout, _ = clean(cli, tmp_path, figure)
    assert stdout == "cleaned: 1 junction made\n"
    assert document["vertices"][:4] == [[0, 0], [2, 2], [0, 2], [2, 0]]  # the figure's numbering kept
    assert document["vertices"][4] == [1, 1]
    assert document["cleaning"]["changes"][0]["kind"] == "crossing"


def test_tolerance_zero_snaps_nothing(cli, tmp_path):
    drawing = tmp_path / "t.json"
    drawing.write_text(json.dumps({"strokes": [{"points": [[0, 0], [10, 0]]}, {"points": [[4, -10], [4, -0.1]]}]}))
    document, stdout, _ = clean(cli, tmp_path, drawing, "--tolerance", 0)
    assert stdout == "cleaned: no changes\n"
    document, stdout, _ = clean(cli, tmp_path, drawing)
    assert stdout == "cleaned: 1 end snapped\n"
    assert document["cleaning"]["changes"][0]["at"] == [4, 0]


BAD_DRAWINGS = [
    ({"strokes": []}, "the drawing has no strokes"),
    ({"strokes": [{"points": [[0, 0], [1, 1]]}, {"points": [[3, 3]]}]}, "stroke 1 has a single point, at (3, 3)"),
    ({"strokes": [{"points": []}]}, "stroke 0 has no points"),
    ({"strokes": [{"points": [[0, 0], [5, 0]]}, {"points": [[2, 0], [8, 0]]}]}, "strokes 0 and 1 overlap along a length"),
    ({"strokes": [{"points": [[0, 0], [5, 0], [5, 5], [5, 1]]}]}, "stroke 0 retraces itself"),
    ({"strokes": [{"points": [[1, 1], [1, 1]]}, {"points": [[0, 0], [3, 3]]}]}, "stroke 0 collapses to a single point"),
    ({"strokes": [{"points": [[0, 0], [1, "a"]]}]}, "stroke 0, point 1: expected a number for y"),
    ({"strokes": [{"points": [[0, 0], [1, 1]], "cyclic": "yes"}]}, "stroke 0: \"cyclic\" must be true or false"),
    ({"strokes": [{"cyclic": True}]}, "missing field \"points\" in stroke 0"),
    ({"strokes": [], "vertices": []}, "either \"strokes\" or a figure's \"vertices\" and \"edges\""),
    ({"name": "no content"}, "missing field \"strokes\""),
    ({"vertices": [[0, 0], [1, 1]], "edges": [[0, 5]]}, "edge 0 (0-5): vertex 5 does not exist"),
    ([1, 2], "a drawing file must hold a JSON object"),
]


@pytest.mark.parametrize("content,message", BAD_DRAWINGS, ids=[m[:40] for _, m in BAD_DRAWINGS])
def test_a_bad_drawing_is_exit_2_with_one_error_line_naming_the_stroke(cli, tmp_path, content, message):
    drawing = tmp_path / "bad.json"
    drawing.write_text(json.dumps(content))
    out = tmp_path / "out.json"
    result = run(cli, "clean", drawing, "-o", out)
    assert result.returncode == 2
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ")
    assert str(drawing) in lines[0]
    assert message in lines[0]
    assert not out.exists()


@pytest.mark.parametrize("value,message", [("-1", "must be >= 0"), ("abc", "needs a finite number"),
                                           ("nan", "needs a finite number"), ("inf", "needs a finite number")])
def test_a_bad_tolerance_is_exit_2(cli, tmp_path, drawings, value, message):
    out = tmp_path / "out.json"
    result = run(cli, "clean", drawings[0], "-o", out, "--tolerance", value)
    assert result.returncode == 2
    assert message in result.stderr and result.stderr.count("\n") == 1
    assert not out.exists()


def test_clean_needs_an_output(cli, drawings):
    result = run(cli, "clean", drawings[0])
    assert result.returncode == 2
    assert "missing option --output" in result.stderr
