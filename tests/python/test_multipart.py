"""Figures of several parts (connected components; an isolated vertex is one), through the CLI
and the module, every frame checked by bench/multipart_check.py, and tests of that checker
and of bench/multipart_corpus.py themselves.

The contract (docs/FORMAT.md, "Components"): besides the conditions on each part, a pair is
compatible when every part lies in the same face of every other part in both figures; `check`
names the part when that differs, and the morph keeps every part in its face in every frame.
"""
import json
import math
import random
import subprocess
import sys
import types

import numpy as np
import pytest

import stickmorph
from conftest import REPO, load_script

mc = load_script("multipart_check")
corpus = load_script("multipart_corpus")

TIMEOUT = 120


def run(cli, *arguments):
    return subprocess.run([str(cli), *map(str, arguments)], capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, timeout=TIMEOUT)


def write(path, points, edges):
    path.write_text(json.dumps({"vertices": np.asarray(points, dtype=float).tolist(),
                                "edges": [[int(u), int(v)] for u, v in edges]}))
    return path


def rings(*specs):
    """Rings (centre, radius, vertex count) as one figure, then isolated vertices (a point)."""
    f = corpus.Fig()
    for spec in specs:
        if len(spec) == 2:
            f.vertex(spec, "lone")
        else:
            c, r, k = spec
            f.ring(corpus.circle(c, r, k, 0.3), f"ring{len(f.groups)}")
    return f


def ring_in_ring():
    return rings(((0, 0), 1.0, 16), ((0.1, 0), 0.5, 9))


def dotted_i():
    return corpus.dotted_i(random.Random(4), 0.1, polygon_dot=False)


def bullseye():
    return rings(((0, 0), 1.0, 20), ((0, 0), 0.6, 14), ((0, 0), 0.3, 8), (0.0, 0.0))


def glyph_b():
    fig = corpus.glyph_figure("DejaVuSans.ttf", "B", 10 ** -2.5, 200)
    assert fig is not None and len(fig.groups) == 3
    return fig


FIGURES = {"dotted_i": dotted_i, "ring_in_ring": ring_in_ring, "bullseye": bullseye, "glyph_B": glyph_b}


def deformed(fig, seed):
    pts = fig.array()
    target, strength = corpus.deform(pts, fig.edges, random.Random(seed))
    assert target is not None and strength >= 0.25, "the warp had to be weakened too far"
    return pts, target


# ---------------------------------------------------------------- the engine


@pytest.mark.parametrize("name", sorted(FIGURES))
def test_cli_morphs_a_multipart_figure_into_a_deformed_copy(cli, tmp_path, name):
    fig = FIGURES[name]()
    src, tgt = deformed(fig, seed=sorted(FIGURES).index(name) + 1)
    assert mc.Topology(src, fig.edges).count >= 2
    s, t = write(tmp_path / "s.json", src, fig.edges), write(tmp_path / "t.json", tgt, fig.edges)
    checked = run(cli, "check", s, t)
    assert (checked.returncode, checked.stdout) == (0, "compatible\n"), checked.stdout + checked.stderr
    out = tmp_path / "m.json"
    morphed = run(cli, "morph", s, t, "-o", out, "--frames", 12)
    assert morphed.returncode == 0, morphed.stderr
    doc = json.loads(out.read_text())
    assert mc.check_index_morph((src, fig.edges), (tgt, fig.edges), doc, 12) == []


@pytest.mark.parametrize("name", sorted(FIGURES))
def test_module_morphs_a_multipart_figure_into_a_deformed_copy(name):
    fig = FIGURES[name]()
    src, tgt = deformed(fig, seed=10 + sorted(FIGURES).index(name))
    assert stickmorph.check_compatibility(src, tgt, fig.edges)
    for method in ("rigid", "barycentric"):
        result = stickmorph.morph(src, tgt, fig.edges, frames=8, method=method)
        assert result["frames"].shape == (8, len(src), 2)
        doc = {"edges": fig.edges, "frames": result["frames"]}
        assert mc.check_index_morph((src, fig.edges), (tgt, fig.edges), doc, 8) == [], method


def nesting_pair():
    """A ring in a ring with a dot in the inner ring; in the target the dot is in the annulus."""
    fig = rings(((0, 0), 1.0, 16), ((0, 0), 0.5, 9), (0.05, 0.1))
    src = fig.array()
    tgt = src.copy()
    tgt[-1] = (0.0, 0.75)
    return fig, src, tgt


def test_a_part_that_changes_face_is_refused(cli, tmp_path):
    fig, src, tgt = nesting_pair()
    assert mc.nesting_differences(src, tgt, fig.edges) == [(1, 2)]
    s, t = write(tmp_path / "s.json", src, fig.edges), write(tmp_path / "t.json", tgt, fig.edges)
    checked = run(cli, "check", s, t)
    out = tmp_path / "m.json"
    morphed = run(cli, "morph", s, t, "-o", out)
    assert mc.check_nesting_refusal(checked, morphed, {1, 2}, out.exists()) == [], (checked, morphed)
    assert checked.stdout.startswith("incompatible: ")
    report = stickmorph.check_compatibility(src, tgt, fig.edges)
    assert not report and report.kind == "nesting_differs"
    with pytest.raises(stickmorph.IncompatibleFiguresError) as info:
        stickmorph.morph(src, tgt, fig.edges)
    assert isinstance(info.value, ValueError)
    assert info.value.kind == "nesting_differs"
    assert mc.PART_NAMED.search(str(info.value))


def redrawn_pair():
    """A dotted i (the dot a tiny polygon) drawn twice: other sampling, renumbered, moved."""
    rng = random.Random(7)
    a = corpus.dotted_i(rng, 0.06, polygon_dot=True)
    b = corpus.dotted_i(rng, 0.15, polygon_dot=True)
    assert len(a.points) != len(b.points)
    tp, te = corpus.disguise(b.array(), b.edges, rng, turn=40)
    assert corpus.problems(tp, te) == []
    return (a.array(), a.edges), (tp, te)


def test_correspond_auto_matches_the_parts_of_a_redrawn_pair(cli, tmp_path):
    (sp, se), (tp, te) = redrawn_pair()
    assert mc.Topology(sp, se).count == mc.Topology(tp, te).count == 2
    s, t = write(tmp_path / "s.json", sp, se), write(tmp_path / "t.json", tp, te)
    checked = run(cli, "check", s, t, "--correspond", "auto")
    assert (checked.returncode, checked.stdout) == (0, "compatible\n"), checked.stdout + checked.stderr
    out = tmp_path / "m.json"
    morphed = run(cli, "morph", s, t, "-o", out, "--frames", 10, "--correspond", "auto")
    assert morphed.returncode == 0, morphed.stderr
    doc = json.loads(out.read_text())
    assert mc.check_auto_morph((sp, se), (tp, te), doc, 10) == []


def test_a_small_corpus_run(cli, tmp_path):
    made = subprocess.run([sys.executable, str(REPO / "bench" / "multipart_corpus.py"), str(tmp_path / "c"),
                           "--seed", "3", "--per-kind", "2"], capture_output=True, text=True, timeout=120)
    assert made.returncode == 0, made.stderr
    manifest = json.loads((tmp_path / "c" / "manifest.json").read_text())
    assert sorted({e["kind"] for e in manifest}) == sorted(mc.KINDS) and len(manifest) == 6
    checked = subprocess.run([sys.executable, str(REPO / "bench" / "multipart_check.py"), str(tmp_path / "c"),
                              "--stickmorph", str(cli), "--frames", "8"], capture_output=True, text=True,
                             timeout=300)
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "total: 6/6 ok" in checked.stdout


# ---------------------------------------------------------------- the checker itself


def one_frame_doc(src, frames, edges):
    return {"edges": [list(e) for e in edges], "frames": [np.asarray(f).tolist() for f in frames]}


def test_checker_accepts_a_valid_morph_by_hand():
    fig, src, _ = nesting_pair()
    frames = [src * (1 + 0.1 * k) + [0.2 * k, 0] for k in range(4)]
    doc = one_frame_doc(src, frames, fig.edges)
    assert mc.check_index_morph((src, fig.edges), (frames[-1], fig.edges), doc, 4) == []


def test_checker_fails_a_part_moved_to_another_face():
    fig, src, tgt = nesting_pair()
    middle = src.copy()
    middle[-1] = (0.0, 0.75)  # the dot, in the inner ring in the source, in the annulus
    doc = one_frame_doc(src, [src, middle, src], fig.edges)
    problems = mc.check_index_morph((src, fig.edges), (src, fig.edges), doc, 3)
    assert len(problems) == 1 and problems[0].startswith("frame 1: ")
    assert "part 2 is in the outside of part 1" in problems[0]


def test_checker_fails_a_ring_moved_out_of_its_ring():
    fig = ring_in_ring()
    src = fig.array()
    moved = src.copy()
    moved[fig.groups["ring1"]] += (3.0, 0.0)
    problems = mc.Topology(src, fig.edges).frame_problems(moved)
    assert problems == ["part 1 is in the outside of part 0, in the source in the face of part 0 along the edge 0-1"]


def test_checker_fails_a_crossing_a_touch_and_a_coincidence():
    fig = ring_in_ring()
    src = fig.array()
    topo = mc.Topology(src, fig.edges)
    crossing = src.copy()
    crossing[16] = (1.3, 0.0)  # a vertex of the inner ring pushed through the outer ring
    assert "cross" in topo.frame_problems(crossing)[0]
    touching = src.copy()
    touching[0], touching[1], touching[16] = (1.0, 0.0), (1.0, 0.5), (1.0, 0.25)  # 16 on the edge 0-1
    assert "vertex 16 lies on edge 0 (0, 1)" in topo.frame_problems(touching)[0]
    coincide = src.copy()
    coincide[17] = coincide[16]
    assert "coincide" in topo.frame_problems(coincide)[0]


def test_checker_fails_another_order_of_neighbours():
    pts = [(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1), (3, 3)]
    edges = [(0, 1), (0, 2), (0, 3), (0, 4)]
    topo = mc.Topology(pts, edges)
    swapped = list(pts)
    swapped[2], swapped[4] = pts[4], pts[2]
    assert "order of neighbours changes" in topo.frame_problems(swapped)[0]


def test_checker_tells_faces_of_one_part_apart():
    fig = corpus.house(random.Random(1), 0.1)
    src = fig.array()
    moved = corpus.move_group(fig, "fly", into=["pane_ur"])
    topo = mc.Topology(src, fig.edges)
    problems = topo.frame_problems(moved.array())
    fly, window = topo.part[fig.groups["fly"][0]], topo.part[fig.groups["window"][0]]
    assert len(problems) == 1 and f"part {fly} is in the face of part {window}" in problems[0]


def test_checker_fails_wrong_ends_and_edges():
    fig, src, tgt = nesting_pair()
    doc = one_frame_doc(src, [src, src], fig.edges)
    problems = mc.check_index_morph((src, fig.edges), (src * 2, fig.edges), doc, 2)
    assert problems == ["the last frame is not the target bit for bit"]
    doc["edges"] = doc["edges"][1:]
    assert "edge set" in mc.check_index_morph((src, fig.edges), (src, fig.edges), doc, 2)[0]


def proc(code, out="", err=""):
    return types.SimpleNamespace(returncode=code, stdout=out, stderr=err)


def test_checker_of_refusals():
    good_check = proc(1, "incompatible: part 2 is nested in another face of part 1 in the target\n")
    good_morph = proc(2, "", "error: incompatible figures: part 2 ...\n")
    assert mc.check_nesting_refusal(good_check, good_morph, {1, 2}) == []
    assert mc.check_nesting_refusal(good_check, good_morph, {0, 3}) != []
    assert mc.check_nesting_refusal(proc(1, "incompatible: the nesting differs\n"), good_morph, None) != []
    assert mc.check_nesting_refusal(proc(0, "compatible\n"), good_morph, None) != []
    assert mc.check_nesting_refusal(good_check, proc(2, "", "error: a\nerror: b\n"), None) != []
    assert mc.check_nesting_refusal(good_check, good_morph, None, output_exists=True) != []


def test_exact_frame_is_exact():
    pts = [(0.1, 1e-300), (3.0, -2.5e10)]
    ex = mc.exact_frame(pts)
    scale = max(f.denominator for p in pts for f in map(mc.Fraction, p))
    assert all(mc.Fraction(a) * scale == b for p, q in zip(pts, ex) for a, b in zip(p, q))


# ---------------------------------------------------------------- the corpus


def test_corpus_pairs_are_what_the_manifest_says(tmp_path):
    entries = corpus.generate(tmp_path, seed=5)
    kinds = {k: [e for e in entries if e["kind"] == k] for k in mc.KINDS}
    assert len(kinds["deformed"]) >= 25 and len(kinds["redrawn"]) >= 8 and len(kinds["nesting_changes"]) >= 10
    assert 40 <= len(entries) <= 60
    for e in entries:
        src, tgt = mc.load_figure(tmp_path / e["source"]), mc.load_figure(tmp_path / e["target"])
        assert e["parts"] >= 2 and max(len(src[0]), len(tgt[0])) <= 400, e["name"]
        for fig in (src, tgt):
            assert corpus.problems(*fig) == [], e["name"]
        s, t = mc.Topology(*src), mc.Topology(*tgt)
        assert s.count == t.count == e["parts"]
        if e["kind"] == "deformed":
            assert src[1] == tgt[1] and corpus.same_topology(s, t), e["name"]
            assert not np.allclose(src[0], tgt[0]), e["name"]
        elif e["kind"] == "nesting_changes":
            assert src[1] == tgt[1] and s.rotation == t.rotation, e["name"]
            diff = mc.nesting_differences(src[0], tgt[0], src[1])
            assert e["moved_part"] in {p for pair in diff for p in pair}, e["name"]
        else:
            assert len(src[0]) != len(tgt[0]) or src[1] != tgt[1], e["name"]
    names = " ".join(e["name"] for e in entries)
    for shape in ("glyph_O", "glyph_B", "face", "target", "rings_spiral", "bullseye", "house", "dotted_i"):
        assert shape in names


def test_corpus_is_a_function_of_its_options(tmp_path):
    corpus.generate(tmp_path / "a", seed=2, per_kind=3)
    corpus.generate(tmp_path / "b", seed=2, per_kind=3)
    files = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert len(files) == 1 + 2 * 9
    assert all((tmp_path / "a" / f).read_bytes() == (tmp_path / "b" / f).read_bytes() for f in files)


def test_warps_keep_orientation():
    # every term of the warp is an orientation-preserving map: a small triangle stays counter-clockwise
    rng = random.Random(0)
    tri = np.array([[0.0, 0.0], [0.01, 0.0], [0.0, 0.01]])
    cloud = np.array([[math.cos(k), math.sin(2 * k)] for k in range(50)])
    for _ in range(20):
        w = corpus.random_warp(rng)
        for base in cloud[:10]:
            pts = np.vstack([cloud, base + tri])
            out = corpus.apply_warp(pts, w, 1.0)[-3:]
            assert mc.orient(*mc.exact_frame(out)) == 1
