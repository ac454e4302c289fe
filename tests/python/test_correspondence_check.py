"""Tests of bench/correspondence_check.py (the independent checker of `morph --correspond
auto`) and bench/correspondence_corpus.py (its corpus).

The checker's geometry is tested on hand-made tiny figures and hand-made morph outputs, with
cases that must fail (a dummy off its edge, a missing source vertex, a crossing frame, a
flipped rotation, a nested loop), so that a checker passing everything fails here. Its
process handling is tested with a fake CLI. One test runs the checker end to end with the
built CLI on a small corpus: it needs the `--correspond auto` feature of `stickmorph morph`.

Every subprocess has a timeout, so a hang fails the test instead of stalling the suite.
"""
import copy
import json
import math
import pathlib
import subprocess
import sys
import textwrap

import numpy as np

from conftest import load_script

REPO = pathlib.Path(__file__).resolve().parents[2]
TIMEOUT_SECONDS = 600

cc = load_script("correspondence_check")
corpus = load_script("correspondence_corpus")


# ---------------------------------------------------------------------------
# the plane-graph test

def test_a_valid_figure_has_no_problems():
    square_with_tail = [(0, 0), (1, 0), (1, 1), (0, 1), (2, 2)]
    assert cc.plane_problems(square_with_tail, [(0, 1), (1, 2), (2, 3), (3, 0), (2, 4)]) == []


def test_crossing_edges_are_found():
    problems = cc.plane_problems([(0, 0), (2, 2), (0, 2), (2, 0)], [(0, 1), (2, 3)])
    assert len(problems) == 1 and "cross" in problems[0]


def test_a_vertex_on_another_edge_is_found():
    # a T whose stem ends on the bar, not at a vertex of it
    problems = cc.plane_problems([(0, 0), (2, 0), (1, 0), (1, -1)], [(0, 1), (2, 3)])
    assert problems == ["vertex 2 lies on edge 0 (0, 1)"]


def test_adjacent_edges_that_overlap_are_found():
    # 0 -> 1 -> 2 goes back along itself: 2 lies on edge (0, 1)
    problems = cc.plane_problems([(0, 0), (2, 0), (1, 0)], [(0, 1), (1, 2)])
    assert problems == ["vertex 2 lies on edge 0 (0, 1)"]


def test_coincident_vertices_are_found():
    problems = cc.plane_problems([(0, 0), (1, 0), (1, 0), (1, 1)], [(0, 1), (2, 3)])
    assert any("coincide" in p for p in problems)


def test_the_test_is_exact_not_approximate():
    # (0.5, 0.5) is on the diagonal; the next double above 0.5 is off it by 1.1e-16,
    # which a tolerance would call "on the edge"
    diagonal = [(0.0, 0.0), (1.0, 1.0)]
    assert cc.plane_problems(diagonal + [(0.5, 0.5), (0.5, -1.0)], [(0, 1), (2, 3)]) == \
        ["vertex 2 lies on edge 0 (0, 1)"]
    above = math.nextafter(0.5, 1.0)
    assert cc.plane_problems(diagonal + [(0.5, above), (0.5, 2.0)], [(0, 1), (2, 3)]) == []
    # a crossing by one ulp: the segment from (0.5, above) down to (0.5, -1) crosses the diagonal
    assert any("lies on" in p or "cross" in p
               for p in cc.plane_problems(diagonal + [(0.5, above), (0.5, -1.0)], [(0, 1), (2, 3)]))


def test_box_filter_keeps_touching_boxes():
    # boxes that meet in one point only (corner to corner): the exact test must still see them
    problems = cc.plane_problems([(0, 0), (1, 1), (1, 1), (2, 0)], [(0, 1), (2, 3)])
    assert any("coincide" in p for p in problems)


def test_components_and_clearance():
    assert cc.components(4, [(0, 1), (2, 3)]) == 2
    assert cc.components(3, [(0, 1), (1, 2)]) == 1
    # vertex 3 is 0.01 above the bar of length 2: relative clearance 0.01 / diagonal
    pts = [(0, 0), (2, 0), (1, 0.01), (1, 1)]
    gap = cc.clearance(pts, [(0, 1), (2, 3)])
    assert math.isclose(gap, 0.01 / math.hypot(2, 1), rel_tol=1e-9)


# ---------------------------------------------------------------------------
# rotation order and faces

STAR = [(0.0, 0.0), (1.0, 0.0), (-0.5, 1.0), (-0.5, -1.0)]
STAR_EDGES = [(0, 1), (0, 2), (0, 3)]


def test_rotation_order_is_counter_clockwise_and_cyclic():
    rot = cc.rotation_system(STAR, STAR_EDGES)
    assert rot[0] == (1, 2, 3)
    turned = [(-y, x) for x, y in STAR]  # a quarter turn keeps the order
    assert cc.rotation_system(turned, STAR_EDGES)[0] == (1, 2, 3)


def test_a_reflected_star_has_the_flipped_rotation():
    mirrored = [(-x, y) for x, y in STAR]
    assert cc.plane_problems(mirrored, STAR_EDGES) == []  # still a plane figure ...
    rot = cc.rotation_system(mirrored, STAR_EDGES)
    assert rot[0] == (1, 3, 2)  # ... but the edges around vertex 0 come the other way
    assert cc.rotation_differences(cc.rotation_system(STAR, STAR_EDGES), rot)


def test_rotation_order_all_the_way_round():
    # five neighbours in every half-plane; turning the figure keeps the cyclic order, which is
    # the order of the angles
    angles = [200, 20, 290, 110, 160]
    expected = [1 + k for k in sorted(range(5), key=lambda k: angles[k])]
    expected = tuple(expected[expected.index(1):] + expected[:expected.index(1)])
    edges = [(0, k) for k in range(1, 6)]
    for turn in range(0, 360, 15):
        pts = [(0.0, 0.0)] + [(math.cos(math.radians(a + turn)), math.sin(math.radians(a + turn))) for a in angles]
        assert cc.rotation_system(pts, edges)[0] == expected, turn


def test_rotation_order_is_exact_for_nearly_parallel_edges():
    # two neighbours in directions one ulp apart in slope
    pts = [(0.0, 0.0), (1.0, 1.0), (1.0, math.nextafter(1.0, 2.0)), (-1.0, 0.0)]
    assert cc.rotation_system(pts, [(0, 1), (0, 2), (0, 3)])[0] == (1, 2, 3)
    pts[2] = (1.0, math.nextafter(1.0, 0.0))
    assert cc.rotation_system(pts, [(0, 1), (0, 2), (0, 3)])[0] == (1, 3, 2)


# two triangles sharing vertex 0: side by side, and one inside the other with the same
# counter-clockwise order of edges at every vertex. Only the outer face tells them apart.
BOUQUET_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (3, 4), (4, 0)]
SIDE_BY_SIDE = [(0.0, 0.0), (2.0, -1.0), (2.0, 1.0), (-2.0, 1.0), (-2.0, -1.0)]
NESTED = [(0.0, 0.0), (math.cos(-0.35), math.sin(-0.35)), (math.cos(0.35), math.sin(0.35)),
          (4 * math.cos(1.05), 4 * math.sin(1.05)), (4 * math.cos(-1.05), 4 * math.sin(-1.05))]


def test_faces_and_outer_face():
    rot = cc.rotation_system(SIDE_BY_SIDE, BOUQUET_EDGES)
    assert cc.rotation_system(NESTED, BOUQUET_EDGES) == rot
    face_list = cc.faces(rot, 5)
    assert len(face_list) == 3  # Euler: V - E + F = 2
    assert sorted(len(f) for f in face_list) == [3, 3, 6]
    outer = cc.outer_face(face_list, SIDE_BY_SIDE)
    assert len(face_list[outer]) == 6
    assert cc.outer_face(face_list, NESTED) != outer  # the big triangle's outside only


# ---------------------------------------------------------------------------
# the subdivision test and whole outputs, on hand-made morphs

# An L drawn with 3 vertices (source) and with its foot cut in two (target, numbered and
# ordered differently). The matched figure has 4 vertices; vertex 1 is a dummy on the source.
L_SOURCE = ([(0.0, 0.0), (2.0, 0.0), (2.0, 2.0)], [(0, 1), (1, 2)])
L_TARGET = ([(4.0, 2.0), (0.0, 0.0), (2.0, 0.0), (4.0, 0.0)], [(3, 0), (2, 3), (1, 2)])
L_OUTPUT = {"edges": [[0, 1], [1, 2], [2, 3]], "times": [0.0, 0.5, 1.0],
            "frames": [[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 2.0]],
                       [[0.0, 0.0], [1.5, 0.1], [3.0, 0.0], [3.0, 2.0]],
                       [[0.0, 0.0], [2.0, 0.0], [4.0, 0.0], [4.0, 2.0]]],
            "correspondence": {"source": [0, -1, 1, 2], "target": [1, 2, 3, 0],
                               "source_edge": [-1, 0, -1, -1], "source_fraction": [0.0, 0.5, 0.0, 0.0],
                               "target_edge": [-1, -1, -1, -1], "target_fraction": [0.0, 0.0, 0.0, 0.0]}}


def check(doc, pins=(), source=L_SOURCE, target=L_TARGET, **kw):
    return cc.check_match(source, target, doc, pins, **kw)["problems"]


def test_a_correct_output_passes():
    result = cc.check_match(L_SOURCE, L_TARGET, L_OUTPUT, pins=[(2, 0)])
    assert result["problems"] == []
    assert result["m"] == 4 and result["dummies"] == 1 and result["frames_checked"] == [0, 1, 2]


def test_a_dummy_off_its_edge_fails():
    doc = copy.deepcopy(L_OUTPUT)
    doc["frames"][0][1] = [1.0, 1e-6]
    problems = check(doc)
    assert len(problems) == 1 and "dummy 1" in problems[0] and "lies on no edge" in problems[0]


def test_a_dummy_within_rounding_of_its_edge_passes():
    doc = copy.deepcopy(L_OUTPUT)
    doc["frames"][0][1] = [1.0, 1e-12]
    assert check(doc) == []


def test_a_dummy_on_an_endpoint_fails():
    doc = copy.deepcopy(L_OUTPUT)
    doc["frames"][0][1] = [2.0, 0.0]
    assert any("lies on no edge strictly inside" in p for p in check(doc))


def test_a_missing_source_vertex_fails():
    doc = copy.deepcopy(L_OUTPUT)
    doc["correspondence"]["source"] = [0, -1, -1, 2]  # source vertex 1 (the corner) is not matched
    problems = check(doc)
    assert any("[1]" in p and "not in the correspondence" in p for p in problems)


def test_a_source_vertex_twice_fails():
    doc = copy.deepcopy(L_OUTPUT)
    doc["correspondence"]["source"] = [0, -1, 1, 1]
    assert any("vertex 1 is matched vertices 2 and 3" in p for p in check(doc))


def test_an_original_moved_off_its_vertex_fails():
    doc = copy.deepcopy(L_OUTPUT)
    doc["frames"][-1][3] = [4.0, 2.0000000000000004]  # one ulp: originals must be exact
    assert any("target: matched vertex 3 is at" in p for p in check(doc))


def test_dummies_out_of_order_along_the_edge_fail():
    # source: one long edge; target: the same edge cut twice; the two dummies swapped
    source = ([(0.0, 0.0), (3.0, 0.0)], [(0, 1)])
    target = ([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)], [(0, 1), (1, 2), (2, 3)])
    doc = {"edges": [[0, 1], [1, 2], [2, 3]], "times": [0.0, 1.0],
           "frames": [[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]] * 2,
           "correspondence": {"source": [0, -1, -1, 1], "target": [0, 1, 2, 3]}}
    assert check(doc, source=source, target=target) == []
    doc["frames"] = [[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [3.0, 0.0]]] + [doc["frames"][1]]
    problems = check(doc, source=source, target=target)
    # found by the subdivision test itself, before frame 0 is found to fold back on itself
    assert problems and "the dummies [1, 2] on edge 0 (0, 1) are not in order" in problems[0]


def test_an_edge_not_covered_fails():
    # a triangle whose matched figure leaves out one side
    tri = ([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], [(0, 1), (1, 2), (2, 0)])
    doc = {"edges": [[0, 1], [1, 2]], "times": [0.0, 1.0], "frames": [tri[0], tri[0]],
           "correspondence": {"source": [0, 1, 2], "target": [0, 1, 2]}}
    problems = check(doc, source=tri, target=tri)
    assert problems and "edges [2] (1 of 3) are not covered" in problems[0]
    doc["edges"].append([2, 0])
    assert check(doc, source=tri, target=tri) == []


def test_a_matched_edge_that_is_no_source_edge_fails():
    # the diagonal 0 - 2 of the L is not one of its edges
    doc = copy.deepcopy(L_OUTPUT)
    doc["edges"] = [[0, 1], [1, 2], [0, 3]]
    problems = check(doc)
    assert any("are not an edge" in p for p in problems)


def test_a_wrong_extension_field_fails():
    doc = copy.deepcopy(L_OUTPUT)
    doc["correspondence"]["source_edge"] = [-1, 1, -1, -1]
    assert any("source_edge[1] is 1" in p for p in check(doc))
    doc = copy.deepcopy(L_OUTPUT)
    doc["correspondence"]["source_fraction"] = [0.0, 0.25, 0.0, 0.0]
    assert any("source_fraction[1]" in p for p in check(doc))


def test_a_crossing_frame_fails():
    # a Z-shaped zigzag whose middle frame folds the last edge across the first
    source = ([(0.0, 0.0), (2.0, 0.0), (0.0, 1.0), (2.0, 1.0)], [(0, 1), (1, 2), (2, 3)])
    doc = {"edges": [[0, 1], [1, 2], [2, 3]], "times": [0.0, 0.5, 1.0],
           "frames": [source[0], [(0.0, 0.0), (2.0, 0.0), (0.0, 1.0), (1.0, -1.0)], source[0]],
           "correspondence": {"source": [0, 1, 2, 3], "target": [0, 1, 2, 3]}}
    problems = check(doc, source=source, target=source)
    assert len(problems) == 1 and problems[0].startswith("frame 1 is not a plane graph") and "cross" in problems[0]


def test_a_flipped_rotation_fails():
    # the star passes through its mirror image (a plane figure, but reflected)
    mirrored = [(-x, y) for x, y in STAR]
    doc = {"edges": [list(e) for e in STAR_EDGES], "times": [0.0, 0.5, 1.0],
           "frames": [STAR, mirrored, STAR], "correspondence": {"source": [0, 1, 2, 3], "target": [0, 1, 2, 3]}}
    problems = check(doc, source=(STAR, STAR_EDGES), target=(STAR, STAR_EDGES))
    assert len(problems) == 1 and problems[0].startswith("frame 1 changes the order of edges")


def test_a_frame_with_another_outer_face_fails():
    doc = {"edges": [list(e) for e in BOUQUET_EDGES], "times": [0.0, 0.5, 1.0],
           "frames": [SIDE_BY_SIDE, NESTED, SIDE_BY_SIDE],
           "correspondence": {"source": list(range(5)), "target": list(range(5))}}
    fig = (SIDE_BY_SIDE, BOUQUET_EDGES)
    assert check(doc, source=fig, target=fig) == ["frame 1 has another outer face than frame 0"]


def test_a_broken_pin_and_a_double_dummy_fail():
    assert any("pin 1:1 not kept" in p for p in check(L_OUTPUT, pins=[(1, 1)]))
    doc = copy.deepcopy(L_OUTPUT)
    doc["correspondence"]["target"] = [1, -1, 3, 0]  # matched vertex 1 comes from neither figure
    problems = check(doc)
    assert any("dummies in both figures" in p for p in problems)


def test_malformed_outputs_fail():
    for key in ("edges", "frames", "correspondence"):
        doc = copy.deepcopy(L_OUTPUT)
        del doc[key]
        assert check(doc) == [f"the output has no {key!r}"]
    doc = copy.deepcopy(L_OUTPUT)
    doc["frames"][1] = doc["frames"][1][:3]
    assert any("frames are not all lists of 4 points" in p for p in check(doc))
    assert any("3 frames, 5 asked for" in p for p in check(L_OUTPUT, frames_expected=5))


def test_landmarks_kept_counts_matched_pairs():
    # the L output matches source 0 with target 1 and source 2 with target 0, not source 1 with 2
    assert cc.landmarks_kept(L_OUTPUT, [(0, 1), (2, 0), (1, 2)]) == 2


def test_big_figures_get_a_spread_of_frames():
    assert cc.frames_to_check(50, 10, 300) == list(range(50))
    spread = cc.frames_to_check(50, 1000, 300)
    assert spread[0] == 0 and spread[-1] == 49 and len(spread) == cc.SPREAD_FRAMES + 2


def test_refusal_rules():
    assert cc.check_refusal(2, "", "error: no match: a loop against a tree\n") == []
    assert cc.check_refusal(1, "", "error: x\n")  # wrong exit code
    assert cc.check_refusal(-11, "", "")  # a crash
    assert cc.check_refusal(2, "something\n", "error: x\n")  # stdout not empty
    assert cc.check_refusal(2, "", "error: x\nerror: y\n")  # two lines
    assert cc.check_refusal(2, "", "Traceback (most recent call last):\n")
    assert cc.check_refusal(2, "", "error: internal error: assertion\n")


# ---------------------------------------------------------------------------
# the corpus

def reduced_invariants(points, edges):
    """What every match keeps: the degrees other than 2 (junctions and ends) and the number of
    independent cycles."""
    deg = np.zeros(len(points), dtype=int)
    for u, v in edges:
        deg[u] += 1
        deg[v] += 1
    return sorted(int(d) for d in deg if d != 2), len(edges) - len(points) + 1


def test_corpus_is_valid_deterministic_and_disguised(tmp_path):
    entries = corpus.generate(tmp_path / "a", seed=7, count=3)
    corpus.generate(tmp_path / "b", seed=7, count=3)
    manifest = json.loads((tmp_path / "a" / "manifest.json").read_text())
    assert manifest == entries
    assert [e["family"] for e in manifest] == [f for f, _ in corpus.FAMILIES for _ in range(3)]
    assert len({e["name"] for e in manifest}) == len(manifest)
    differing_counts = 0
    for e in manifest:
        assert e["expect"] == ("refuse" if e["family"] == "refuse" else "match") and e["why"]
        figs = []
        for side in ("source", "target"):
            path = tmp_path / "a" / e[side]
            assert path.read_bytes() == (tmp_path / "b" / e[side]).read_bytes()
            pts, edges = cc.load_figure(path)
            assert cc.plane_problems(pts, edges) == [], e["name"]
            assert cc.components(len(pts), edges) == 1, e["name"]
            assert len({frozenset(x) for x in edges}) == len(edges)
            assert len(pts) == e[f"n_{side}"]
            figs.append((pts, edges))
        differing_counts += len(figs[0][0]) != len(figs[1][0])
        for s, t in e.get("pins", []):
            assert 0 <= s < len(figs[0][0]) and 0 <= t < len(figs[1][0])
        # landmarks: junctions and ends of the same degree in both drawings, each vertex once
        if e["family"] in ("stroke", "skeleton"):
            marks = e["landmarks"]
            assert len(marks) >= 2  # a 6 has its junction and its end
            degree = [np.bincount(np.ravel(f[1]), minlength=len(f[0])) for f in figs]
            assert all(degree[0][s] == degree[1][t] != 2 for s, t in marks), e["name"]
            assert len({s for s, _ in marks}) == len({t for _, t in marks}) == len(marks)
        else:
            assert "landmarks" not in e
        inv = [reduced_invariants(*f) for f in figs]
        if e["expect"] == "match":
            assert inv[0] == inv[1], (e["name"], inv)
        elif any(k in e["name"] for k in ("A_vs_H", "outline_C", "T_vs_X")):
            assert inv[0] != inv[1], (e["name"], inv)
        # the target is moved: not at the source's place and size
        if e["family"] != "refuse":
            assert not np.allclose(figs[0][0].mean(axis=0), figs[1][0].mean(axis=0), atol=1e-3)
    assert differing_counts >= len(manifest) * 2 // 3
    # another seed gives another corpus
    other = corpus.generate(tmp_path / "c", seed=8, count=3)
    assert [e["why"] for e in other] != [e["why"] for e in entries]


def test_corpus_invariants_of_every_refusal_kind(tmp_path):
    # one pair of each refusal kind; the invariant ones differ in degrees or loops, the others
    # (mirror images, inside/outside, pins) are the subtle kinds that share them
    count = len(corpus.REFUSE)
    written = tmp_path / "r"
    written.mkdir()
    c = corpus.Corpus(written, corpus.random.Random(3))
    corpus.refuse_family(c, count)
    subtle = ("mirror", "clock", "pins", "pinned")
    for e in c.entries:
        figs = [cc.load_figure(written / e[side]) for side in ("source", "target")]
        inv = [reduced_invariants(*f) for f in figs]
        if any(k in e["name"] for k in subtle):
            assert inv[0] == inv[1], (e["name"], inv)
        else:
            assert inv[0] != inv[1], (e["name"], inv)
        if "pin" in e["name"]:
            assert e["pins"]


def test_flattening_tolerance_changes_the_vertex_count():
    coarse = corpus.outline_figure("DejaVuSans.ttf", "S", 1e-2)
    fine = corpus.outline_figure("DejaVuSans.ttf", "S", 1e-3)
    assert coarse is not None and fine is not None
    assert len(fine.points) > len(coarse.points) > 10
    # glyphs of two contours are not single polygons
    assert corpus.outline_figure("DejaVuSans.ttf", "O", 1e-2) is None


def test_corpus_command_line(tmp_path):
    r = subprocess.run([sys.executable, str(REPO / "bench" / "correspondence_corpus.py"), str(tmp_path),
                        "--seed", "2", "--count-per-family", "1"],
                       capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    assert r.returncode == 0, r.stderr
    assert "5 pairs written" in r.stdout
    assert len(json.loads((tmp_path / "manifest.json").read_text())) == 5


# ---------------------------------------------------------------------------
# the runner, with a fake CLI and with the real one

def write_l_corpus(folder):
    """The L pair (expect match, pinned) and a T/X pair (expect refuse), as figure files."""
    folder.mkdir(parents=True, exist_ok=True)
    for name, (pts, edges) in (("l.source", L_SOURCE), ("l.target", L_TARGET),
                               ("t.source", (STAR, STAR_EDGES)),
                               ("t.target", ([(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1)],
                                             [(0, 1), (0, 2), (0, 3), (0, 4)]))):
        (folder / f"{name}.json").write_text(json.dumps({"vertices": pts, "edges": edges}))
    manifest = [{"name": "l", "family": "hand", "source": "l.source.json", "target": "l.target.json",
                 "expect": "match", "why": "an L", "pins": [[2, 0]]},
                {"name": "t", "family": "hand", "source": "t.source.json", "target": "t.target.json",
                 "expect": "refuse", "why": "degree 3 against 4"}]
    (folder / "manifest.json").write_text(json.dumps(manifest))


def fake_cli(path, refusal='sys.stderr.write("error: no match\\n"); sys.exit(2)', output=L_OUTPUT):
    """A stand-in for stickmorph: answers the L pair with OUTPUT and the T pair with REFUSAL,
    and writes its arguments next to the output for the test to read."""
    path.write_text(textwrap.dedent(f"""\
        #!{sys.executable}
        import json, sys, time
        args = sys.argv[1:]
        out = args[args.index("-o") + 1]
        open(out + ".args", "w").write(json.dumps(args))
        if args[1].endswith("t.source.json"):
            {refusal}
        json.dump({json.dumps(output)}, open(out, "w"))
        """))
    path.chmod(0o755)
    return path


def test_runner_passes_a_right_fake_and_passes_its_arguments(tmp_path):
    write_l_corpus(tmp_path / "corpus")
    cli = fake_cli(tmp_path / "fake")
    report = tmp_path / "report.json"
    rc = cc.main([str(tmp_path / "corpus"), "--stickmorph", str(cli), "--frames", "3", "--json", str(report),
                  "--keep", str(tmp_path / "out")])
    rows = json.loads(report.read_text())
    assert rc == 0, rows
    assert [r["result"] for r in rows] == ["ok", "ok"]
    assert rows[0]["m"] == 4 and rows[0]["dummies"] == 1 and rows[0]["frames_checked"] == "all 3"
    args = json.loads((tmp_path / "out" / "l.morph.json.args").read_text())
    assert args[0] == "morph" and args[-6:] == ["--correspond", "auto", "--frames", "3", "--pin", "2:0"]


def test_runner_fails_a_wrong_fake(tmp_path):
    write_l_corpus(tmp_path / "corpus")
    broken = copy.deepcopy(L_OUTPUT)
    broken["frames"][1] = [[2.5, 1.0], [1.5, 0.1], [3.0, 0.0], [1.5, 2.0]]  # the upright crosses the foot
    cli = fake_cli(tmp_path / "fake", refusal='print("error: no match"); sys.exit(2)', output=broken)
    report = tmp_path / "report.json"
    rc = cc.main([str(tmp_path / "corpus"), "--stickmorph", str(cli), "--frames", "3", "--json", str(report)])
    rows = json.loads(report.read_text())
    assert rc == 1
    assert rows[0]["result"] == "FAIL" and "frame 1 is not a plane graph" in rows[0]["problems"][0]
    assert rows[1]["result"] == "FAIL" and "stdout is not empty" in rows[1]["problems"][0]


def test_runner_reports_a_hang_and_a_match_that_should_be_a_refusal(tmp_path):
    write_l_corpus(tmp_path / "corpus")
    cli = fake_cli(tmp_path / "fake", refusal="time.sleep(30)")
    report = tmp_path / "report.json"
    rc = cc.main([str(tmp_path / "corpus"), "--stickmorph", str(cli), "--frames", "3", "--timeout", "2",
                  "--json", str(report)])
    rows = json.loads(report.read_text())
    assert rc == 1 and rows[1]["problems"] == ["timed out after 2.0 s"]
    # a CLI that "matches" the T against the X (writing the L's output) is caught as well
    cli = fake_cli(tmp_path / "fake2", refusal="pass")
    rc = cc.main([str(tmp_path / "corpus"), "--stickmorph", str(cli), "--frames", "3", "--json", str(report)])
    rows = json.loads(report.read_text())
    assert rc == 1 and any("matched a pair expected to be refused" in p for p in rows[1]["problems"])


def test_checker_end_to_end_with_the_built_cli(cli, tmp_path):
    # Needs `stickmorph morph --correspond auto`: fails until the CLI has it.
    r = subprocess.run([sys.executable, str(REPO / "bench" / "correspondence_corpus.py"), str(tmp_path / "corpus"),
                        "--seed", "5", "--count-per-family", "2"],
                       capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    assert r.returncode == 0, r.stderr
    report = tmp_path / "report.json"
    r = subprocess.run([sys.executable, str(REPO / "bench" / "correspondence_check.py"), str(tmp_path / "corpus"),
                        "--stickmorph", str(cli), "--frames", "8", "--timeout", "120", "--json", str(report)],
                       capture_output=True, text=True, timeout=TIMEOUT_SECONDS * 2)
    assert r.returncode == 0, r.stdout[-6000:] + r.stderr[-2000:]
    rows = json.loads(report.read_text())
    assert len(rows) == 10 and all(row["result"] == "ok" for row in rows)
