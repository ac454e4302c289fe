"""Figures drawn separately (issue 13): `--correspond auto`, `--pin`, `check
--correspond auto`, `stickmorph correspond`, and the module's correspond() and
morph(correspond="auto", pins=...).

The contract (docs/FORMAT.md): the morph is of the *matched figure*, whose
vertices are the source's and the target's, each given a dummy partner on an
edge of the other figure where it has none; frames[0] lies on the source
drawing and the last frame on the target drawing; "correspondence" names
for each matched vertex the source (target) vertex it is, or -1 for a
dummy, and every source and target vertex appears exactly once.

The pairs here are made from the shared test figures by resubdividing their
edges, renumbering, reordering the edge lists and moving the target, so the
true correspondence of the original vertices is known.
"""
import json
import subprocess

import numpy as np
import pytest

import stickmorph

TIMEOUT_SECONDS = 120
BASES = ["letter_a", "letter_b", "tree_junction", "polygon", "polyline", "square_with_spikes", "wheel"]


def load(data_dir, name, role="source"):
    document = json.loads((data_dir / "pairs" / "compatible" / f"{name}.{role}.json").read_text())
    return np.asarray(document["vertices"], dtype=float), [tuple(e) for e in document["edges"]]


def redraw(vertices, edges, seed, angle=0.0, scale=1.0, shift=(0.0, 0.0), extra=3):
    """The same drawing, drawn again: every edge split into 1..extra+1 pieces
    at random places, the vertices renumbered, the edges reordered and
    reversed at random, the whole moved by a similarity. Returns (vertices,
    edges, where): where[v] is the new index of original vertex v."""
    rng = np.random.default_rng(seed)
    points = [np.asarray(p, dtype=float) for p in vertices]
    pieces = []
    for a, b in edges:
        cuts = np.sort(rng.uniform(0.1, 0.9, size=int(rng.integers(0, extra + 1))))
        chain = [a]
        for f in cuts:
            points.append(points[a] + f * (points[b] - points[a]))
            chain.append(len(points) - 1)
        chain.append(b)
        pieces += list(zip(chain, chain[1:]))
    order = rng.permutation(len(points))
    where = np.empty(len(points), dtype=int)
    where[order] = np.arange(len(points))
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    moved = (scale * np.asarray(points) @ rotation.T + np.asarray(shift))[order]
    new_edges = [[int(where[a]), int(where[b])] if rng.random() < 0.5 else [int(where[b]), int(where[a])]
                 for a, b in pieces]
    new_edges = [new_edges[k] for k in rng.permutation(len(new_edges))]
    return moved, new_edges, where[: len(vertices)]


def write(path, vertices, edges):
    path.write_text(json.dumps({"vertices": np.asarray(vertices).tolist(), "edges": edges}))
    return path


def run(cli, *arguments):
    return subprocess.run([str(cli), *map(str, arguments)], capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, timeout=TIMEOUT_SECONDS)


def assert_one_error(result, *fragments):
    assert result.returncode == 2, (result.returncode, result.stdout, result.stderr)
    assert result.stdout == ""
    assert result.stderr.startswith("error: ") and result.stderr.count("\n") == 1, result.stderr
    assert "internal error" not in result.stderr
    for fragment in fragments:
        assert fragment in result.stderr, (fragment, result.stderr)


def assert_subdivides(matched, edges, places, edge_of, fraction, figure_vertices, figure_edges):
    """`matched` (m by 2, with the matched `edges`) is a subdivision of the
    figure: its original vertices exactly in place, each once; each dummy at
    a + f (b - a) of its edge (a, b), strictly inside; each matched edge on
    one figure edge, and each figure edge covered exactly once."""
    n = len(figure_vertices)
    originals = [int(v) for v in places if v >= 0]
    assert sorted(originals) == list(range(n)), "every vertex exactly once"
    for i, v in enumerate(places):
        if v >= 0:
            assert tuple(matched[i]) == tuple(figure_vertices[v])
            assert edge_of[i] == -1
        else:
            a, b = figure_edges[edge_of[i]]
            f = fraction[i]
            assert 0 < f < 1
            expected = figure_vertices[a] + f * (figure_vertices[b] - figure_vertices[a])
            assert tuple(matched[i]) == tuple(expected)
    covered = np.zeros(len(figure_edges))
    for i, j in edges:
        def along(k, e):
            if places[k] >= 0:
                return 0.0 if places[k] == figure_edges[e][0] else 1.0 if places[k] == figure_edges[e][1] else None
            return fraction[k] if edge_of[k] == e else None
        candidates = {edge_of[k] for k in (i, j) if places[k] < 0}
        if not candidates:
            pair = {int(places[i]), int(places[j])}
            candidates = {e for e, (a, b) in enumerate(figure_edges) if {a, b} == pair}
        assert len(candidates) == 1, (i, j)
        e = candidates.pop()
        fa, fb = along(i, e), along(j, e)
        assert fa is not None and fb is not None and fa != fb
        covered[e] += abs(fb - fa)
    np.testing.assert_allclose(covered, 1.0, rtol=0, atol=1e-9)


def check_morph_document(document, source, target):
    (sv, se), (tv, te) = source, target
    c = document["correspondence"]
    frames = np.asarray(document["frames"])
    edges = document["edges"]
    m = frames.shape[1]
    assert all(len(c[key]) == m for key in ("source", "target", "source_edge", "target_edge",
                                            "source_fraction", "target_fraction"))
    assert_subdivides(frames[0], edges, c["source"], c["source_edge"], c["source_fraction"], sv, se)
    assert_subdivides(frames[-1], edges, c["target"], c["target_edge"], c["target_fraction"], tv, te)
    # The source's own vertices first (docs/FORMAT.md).
    assert c["source"][: len(sv)] == list(range(len(sv)))
    # Every frame a figure compatible with the first: the exact check.
    for frame in frames[1:]:
        assert stickmorph.check_compatibility(frames[0], frame, edges), "a frame lost the topology"
    stats = document["stats"]["correspondence"]
    assert stats["matched_vertices"] == m
    assert stats["source_dummies"] == sum(1 for v in c["source"] if v < 0)
    assert stats["target_dummies"] == sum(1 for v in c["target"] if v < 0)
    assert document["stats"]["milliseconds"]["correspond"] >= 0
    assert document["triangulation"]["figure_vertices"] == m


@pytest.mark.parametrize("name", BASES)
def test_redrawn_pairs_morph_from_one_drawing_to_the_other(cli, data_dir, tmp_path, name):
    base_source, edges = load(data_dir, name, "source")
    base_target, _ = load(data_dir, name, "target")
    sv, se, _ = redraw(base_source, edges, seed=1)
    tv, te, _ = redraw(base_target, edges, seed=2, angle=0.7, scale=1.6, shift=(3.0, -2.0))
    out = tmp_path / "out.json"
    result = run(cli, "morph", write(tmp_path / "s.json", sv, se), write(tmp_path / "t.json", tv, te),
                 "-o", out, "--correspond", "auto", "--frames", "7")
    assert result.returncode == 0, result.stderr
    check_morph_document(json.loads(out.read_text()), (sv, se), (tv, te))


@pytest.mark.parametrize("method", ["barycentric", "linear"])
def test_the_other_methods_morph_the_matched_figure(cli, data_dir, tmp_path, method):
    base, edges = load(data_dir, "letter_a")
    sv, se, _ = redraw(base, edges, seed=3)
    tv, te, _ = redraw(load(data_dir, "letter_a", "target")[0], edges, seed=4)
    out = tmp_path / "out.json"
    result = run(cli, "morph", write(tmp_path / "s.json", sv, se), write(tmp_path / "t.json", tv, te),
                 "-o", out, "--correspond", "auto", "--method", method, "--frames", "4")
    assert result.returncode == 0, result.stderr
    document = json.loads(out.read_text())
    assert document["stats"]["method"] == method
    frames = np.asarray(document["frames"])
    c = document["correspondence"]
    assert [tuple(frames[0][i]) for i, v in enumerate(c["source"]) if v >= 0] == \
        [tuple(sv[v]) for v in c["source"] if v >= 0]


def test_the_same_drawing_renumbered_and_moved_needs_no_dummy(cli, data_dir, tmp_path):
    # Unsubdivided, the redrawn figure is the same drawing: every vertex
    # finds its true partner and no dummy is added.
    base, edges = load(data_dir, "letter_b")
    tv, te, where = redraw(base, edges, seed=5, angle=2.5, scale=0.5, shift=(10, 0), extra=0)
    out = tmp_path / "out.json"
    result = run(cli, "morph", write(tmp_path / "s.json", base, [list(e) for e in edges]),
                 write(tmp_path / "t.json", tv, te), "-o", out, "--correspond", "auto", "--frames", "3")
    assert result.returncode == 0, result.stderr
    c = json.loads(out.read_text())["correspondence"]
    assert c["source"] == list(range(len(base)))
    assert c["target"] == [int(w) for w in where]


def test_the_correspond_command_agrees_with_the_module(cli, data_dir, tmp_path):
    base, edges = load(data_dir, "tree_junction")
    sv, se, _ = redraw(base, edges, seed=6)
    tv, te, _ = redraw(load(data_dir, "tree_junction", "target")[0], edges, seed=7, angle=-0.4)
    out = tmp_path / "matched.json"
    result = run(cli, "correspond", write(tmp_path / "s.json", sv, se), write(tmp_path / "t.json", tv, te),
                 "-o", out)
    assert result.returncode == 0, result.stderr
    document = json.loads(out.read_text())
    module = stickmorph.correspond(sv, tv, se, target_edges=te)
    np.testing.assert_array_equal(np.asarray(document["source"]["vertices"]), module["source_xy"])
    np.testing.assert_array_equal(np.asarray(document["target"]["vertices"]), module["target_xy"])
    assert document["source"]["edges"] == document["target"]["edges"] == module["edges"].tolist()
    for key, values in module["correspondence"].items():
        assert document["correspondence"][key] == values.tolist(), key
    # The matched pair corresponds by index: the plain morph accepts it.
    assert stickmorph.check_compatibility(module["source_xy"], module["target_xy"], module["edges"])
    # And morph(correspond="auto") morphs exactly that pair, as the CLI does.
    morphed = stickmorph.morph(sv, tv, se, target_edges=te, correspond="auto", frames=5)
    np.testing.assert_array_equal(morphed["frames"][0], module["source_xy"])
    np.testing.assert_array_equal(morphed["frames"][-1], module["target_xy"])
    np.testing.assert_array_equal(morphed["edges"], module["edges"])
    cli_out = tmp_path / "morph.json"
    assert run(cli, "morph", tmp_path / "s.json", tmp_path / "t.json", "-o", cli_out, "--correspond", "auto",
               "--frames", "5").returncode == 0
    np.testing.assert_array_equal(np.asarray(json.loads(cli_out.read_text())["frames"]), morphed["frames"])


# ---------------------------------------------------------------- pins ----

PLUS = np.array([[0, 0], [1, 0], [0, 1], [-1, 0], [0, -1]], dtype=float)  # centre 0, arms 1..4 ccw
PLUS_EDGES = [[0, 1], [0, 2], [0, 3], [0, 4]]


def test_a_pin_turns_a_symmetric_match(cli, tmp_path):
    # Without pins the plus matches arm to arm at no rotation; pinning arm 1
    # to arm 2 turns the whole match a quarter, keeping the order around
    # the centre.
    source = write(tmp_path / "s.json", PLUS, PLUS_EDGES)
    target = write(tmp_path / "t.json", PLUS * 2, PLUS_EDGES)
    plain, pinned = tmp_path / "plain.json", tmp_path / "pinned.json"
    assert run(cli, "correspond", source, target, "-o", plain).returncode == 0
    assert json.loads(plain.read_text())["correspondence"]["target"] == [0, 1, 2, 3, 4]
    result = run(cli, "correspond", source, target, "-o", pinned, "--pin", "1:2")
    assert result.returncode == 0, result.stderr
    assert json.loads(pinned.read_text())["correspondence"]["target"] == [0, 2, 3, 4, 1]
    module = stickmorph.correspond(PLUS, PLUS * 2, PLUS_EDGES, pins=[[1, 2]])
    assert module["correspondence"]["target"].tolist() == [0, 2, 3, 4, 1]


def test_a_pin_inside_a_stroke_splits_its_arc_length(cli, tmp_path):
    # A polyline and the same line drawn with another vertex spacing: the
    # pinned middle vertices match each other, not by arc length.
    source = np.array([[0, 0], [1, 0], [2, 0], [3, 0]], dtype=float)
    target = np.array([[0, 0], [0.5, 0], [2.5, 0], [3, 0]], dtype=float)
    edges = [[0, 1], [1, 2], [2, 3]]
    out = tmp_path / "out.json"
    result = run(cli, "correspond", write(tmp_path / "s.json", source, edges),
                 write(tmp_path / "t.json", target, edges), "-o", out, "--pin", "1:1", "--pin", "2:2")
    assert result.returncode == 0, result.stderr
    c = json.loads(out.read_text())["correspondence"]
    assert c["target"] == [0, 1, 2, 3]


@pytest.mark.parametrize("pins, fragments", [
    (["1:9"], ["pin 1:9", "the target has no vertex 9"]),
    (["7:1"], ["pin 7:1", "the source has no vertex 7"]),
    (["0:1"], ["pin 0:1", "degree 4", "degree 1"]),
    (["1:1", "1:2"], ["source vertex 1 is pinned twice"]),
    (["1:1", "2:1"], ["target vertex 1 is pinned twice"]),
    (["1:x"], ["SOURCE:TARGET", "'1:x'"]),
    (["12"], ["SOURCE:TARGET", "'12'"]),
])
def test_bad_pins_are_one_error_line(cli, tmp_path, pins, fragments):
    source = write(tmp_path / "s.json", PLUS, PLUS_EDGES)
    target = write(tmp_path / "t.json", PLUS, PLUS_EDGES)
    arguments = [a for pin in pins for a in ("--pin", pin)]
    assert_one_error(run(cli, "morph", source, target, "-o", tmp_path / "o.json", "--correspond", "auto",
                         *arguments), *fragments)
    assert not (tmp_path / "o.json").exists()


def test_contradictory_pins_are_refused(cli, tmp_path):
    # Arm 1 to arm 1 and arm 2 to arm 4 would reverse the order around the centre.
    source = write(tmp_path / "s.json", PLUS, PLUS_EDGES)
    assert_one_error(run(cli, "morph", source, source, "-o", tmp_path / "o.json", "--correspond", "auto",
                         "--pin", "1:1", "--pin", "2:4"), "no matching respects every pin")
    with pytest.raises(stickmorph.IncompatibleFiguresError) as info:
        stickmorph.correspond(PLUS, PLUS, PLUS_EDGES, pins=[[1, 1], [2, 4]])
    assert info.value.kind == "pins_unsatisfiable"


def test_pins_need_correspond_auto(cli, tmp_path):
    source = write(tmp_path / "s.json", PLUS, PLUS_EDGES)
    assert_one_error(run(cli, "morph", source, source, "-o", tmp_path / "o.json", "--pin", "1:1"),
                     "--pin needs --correspond auto")
    with pytest.raises(stickmorph.InvalidArgumentError, match="correspond='auto'"):
        stickmorph.morph(PLUS, PLUS, PLUS_EDGES, pins=[[1, 1]])
    with pytest.raises(stickmorph.InvalidArgumentError, match="shape"):
        stickmorph.correspond(PLUS, PLUS, PLUS_EDGES, pins=[1, 2, 3])


def test_an_unknown_correspondence_is_refused(cli, tmp_path):
    source = write(tmp_path / "s.json", PLUS, PLUS_EDGES)
    assert_one_error(run(cli, "morph", source, source, "-o", tmp_path / "o.json", "--correspond", "nearest"),
                     "unknown correspondence 'nearest'", "index or auto")


# -------------------------------------------------------- unmatchable ----

SQUARE = [[0, 0], [1, 0], [1, 1], [0, 1]]
SQUARE_EDGES = [[0, 1], [1, 2], [2, 3], [3, 0]]
T_SHAPE = ([[0, 2], [1, 2], [2, 2], [1, 0]], [[0, 1], [1, 2], [1, 3]])
# A junction of degree 4 whose arms are told apart by what hangs on them:
# an end, a fork of two, a fork of three, an end (counter-clockwise). Its
# mirror image has the forks the other way round, which no rotation gives
# (a figure with only interchangeable arms, such as an F, matches its
# mirror image by a rotation and is not refused).
TREE_SHAPE = ([[0, 0], [1, 0], [0, 1], [-0.5, 2], [0.5, 2], [-1, 0], [-2, 0.5], [-2, 0], [-2, -0.5], [0, -1]],
              [[0, 1], [0, 2], [2, 3], [2, 4], [0, 5], [5, 6], [5, 7], [5, 8], [0, 9]])

UNMATCHABLE = {
    "loop_against_tree": ((SQUARE, SQUARE_EDGES), ([[0, 0], [1, 0], [2, 0]], [[0, 1], [1, 2]]),
                          "topology_differs", ["loop"]),
    "junction_degrees": (T_SHAPE, (PLUS.tolist(), PLUS_EDGES), "topology_differs",
                         ["junction of degree 3", "junction of degree 4"]),
    "ends": (T_SHAPE, ([[0, 0], [1, 0], [2, 0]], [[0, 1], [1, 2]]), "topology_differs", ["3 ends", "2 ends"]),
    "mirror_image": (TREE_SHAPE, ([[-x, y] for x, y in TREE_SHAPE[0]], TREE_SHAPE[1]), "mirror_image",
                     ["mirror image"]),
    "single_vertex_against_edge": (([[0, 0]], []), ([[0, 0], [1, 0]], [[0, 1]]), "topology_differs",
                                   ["a single vertex"]),
}


@pytest.mark.parametrize("name", sorted(UNMATCHABLE))
def test_unmatchable_pairs_exit_2_check_exits_1(cli, tmp_path, name):
    (sv, se), (tv, te), kind, fragments = UNMATCHABLE[name]
    source, target = write(tmp_path / "s.json", sv, se), write(tmp_path / "t.json", tv, te)
    assert_one_error(run(cli, "morph", source, target, "-o", tmp_path / "o.json", "--correspond", "auto"),
                     *fragments)
    assert_one_error(run(cli, "correspond", source, target, "-o", tmp_path / "c.json"), *fragments)
    checked = run(cli, "check", source, target, "--correspond", "auto")
    assert checked.returncode == 1, checked.stderr
    assert checked.stdout.startswith("incompatible: ") and checked.stdout.count("\n") == 1
    with pytest.raises(stickmorph.IncompatibleFiguresError) as info:
        stickmorph.morph(sv, tv, se, target_edges=te, correspond="auto")
    assert info.value.kind == kind
    assert all(fragment in str(info.value) for fragment in fragments)


def test_check_correspond_auto_accepts_a_redrawn_pair(cli, data_dir, tmp_path):
    base, edges = load(data_dir, "wheel")
    sv, se, _ = redraw(base, edges, seed=8)
    tv, te, _ = redraw(base, edges, seed=9, angle=1.0)
    source, target = write(tmp_path / "s.json", sv, se), write(tmp_path / "t.json", tv, te)
    assert run(cli, "check", source, target).stdout.startswith("incompatible: ")
    result = run(cli, "check", source, target, "--correspond", "auto")
    assert (result.returncode, result.stdout) == (0, "compatible\n"), result.stderr
