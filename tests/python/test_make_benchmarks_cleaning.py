"""Tests of issue 32's drawing-cleaning benchmark: the corpus (bench/drawing_corpus.py: its exact
analysis of a drawing and the defects it plants), the checker (bench/cleaning.py) on hand-made
cleaned figures whose faults are known, and the "Drawing cleaning" section that
bench/make_benchmarks.py appends to BENCHMARKS.md from cleaning.json. Needs only Debian's python3
with numpy and matplotlib, no build."""
import copy
import json
import math
import random

import numpy as np
import pytest

from conftest import load_script

dc = load_script("drawing_corpus")
cl = load_script("cleaning")
mb = load_script("make_benchmarks")


# ---------------------------------------------------------------------------
# the corpus: exact analysis

def test_analyse_finds_crossings_touches_and_closed_strokes_exactly():
    strokes = [([(0.0, 0.0), (2.0, 0.0), (4.0, 0.0)], False),
               ([(1.0, -1.0), (1.0, 1.0)], False),                    # crosses stroke 0 at (1, 0)
               ([(3.0, 2.0), (3.0, 0.0)], False),                     # ends on stroke 0's segment
               ([(0.0, 3.0), (1.0, 3.0), (1.0, 4.0), (0.0, 3.0)], False)]  # closed on its start
    found = dc.analyse(strokes)
    assert found["problems"] == []
    assert [(c[0], c[2], c[4]) for c in found["crossings"]] == [(0, 1, (1.0, 0.0))]
    contacts = {(i, j, k): on for i, j, k, on, _ in found["contacts"]}
    assert contacts[(2, 1, 0)] == "segment"
    assert contacts[(3, 3, 3)] == "point" and contacts[(3, 0, 3)] == "point"
    # a point a hair off the segment is no contact: exact, not within a tolerance
    near = [(0.0, 0.0), (4.0, 0.0)], False
    assert dc.analyse([near, ([(3.0, 2.0), (3.0, 1e-300)], False)])["contacts"] == []


def test_analyse_refuses_overlaps_and_retraces_and_skips_duplicates():
    along = dc.analyse([([(0.0, 0.0), (4.0, 0.0)], False), ([(1.0, 0.0), (2.0, 0.0)], False)])
    assert any("overlap" in p for p in along["problems"])
    back = dc.analyse([([(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)], False)])
    assert any("retraces" in p for p in back["problems"])
    # a pen pause (the same point twice) is neither a contact nor a retrace
    pause = dc.analyse([([(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (2.0, 1.0)], False)])
    assert pause == {"crossings": [], "contacts": [], "problems": []}
    assert dc.analyse([([(0.0, 0.0)], False)])["problems"] == ["stroke 0 has a single point"]


def test_a_star_drawn_in_one_stroke_crosses_itself_five_times():
    angles = [math.pi / 2 + 4 * math.pi * k / 5 for k in range(5)]
    tips = [(math.cos(a), math.sin(a)) for a in angles]
    found = dc.analyse([(tips, True)])
    assert len(found["crossings"]) == 5 and all(c[0] == c[2] == 0 for c in found["crossings"])


# ---------------------------------------------------------------------------
# the corpus: drawings and their planted defects

@pytest.mark.parametrize("kind", dc.KINDS)
def test_every_subject_draws_with_exactly_its_planted_defects(kind):
    subject, drawing, planted, grid, scale, tol, attempts = dc.make_drawing(
        kind, f"t:{kind}:plan", f"t:{kind}:pose", random.Random(f"t:{kind}"), 100.0, np.array([0.0, 0.0]), "dyadic")
    assert attempts <= dc.MAX_ATTEMPTS
    all_points = np.vstack([np.array(p) for p, _ in drawing])
    assert tol == pytest.approx(0.01 * dc.bbox_diagonal(all_points))
    # coordinates on the grid (a power of two), so exact touches are exact
    assert np.all(all_points / grid.step == np.round(all_points / grid.step))
    found = dc.analyse(drawing)
    assert found["problems"] == []
    assert len(found["crossings"]) == len(planted["crossings"])
    for g in planted["gaps"]:
        assert dc.GAP_ACCEPT[0] <= g["distance_tol"] <= dc.GAP_ACCEPT[1]
        assert g["point"] in (0, len(drawing[g["stroke"]][0]) - 1)
    for d in planted["duplicates"]:
        pts = drawing[d["stroke"]][0]
        assert pts[d["point"]] == pts[d["point"] - 1]
    touched = {(i, k) for i, _, k, _, _ in found["contacts"]}
    for t in planted["touches"]:
        assert (t["stroke"], t["other_stroke"]) in touched or (t["other_stroke"], t["stroke"]) in touched


def test_the_corpus_is_deterministic_and_writes_pairs(tmp_path):
    assert dc.main([str(tmp_path / "a"), "--seed", "5", "--count", "4"]) == 0
    assert dc.main([str(tmp_path / "b"), "--seed", "5", "--count", "4"]) == 0
    manifest = json.loads((tmp_path / "a" / "manifest.json").read_text())
    assert len(manifest["drawings"]) == 4 and len(manifest["pairs"]) == 1
    pair = manifest["pairs"][0]
    assert (tmp_path / "a" / pair["a"]).exists() and (tmp_path / "a" / pair["b"]).exists()
    for entry in manifest["drawings"]:
        assert (tmp_path / "a" / entry["file"]).read_text() == (tmp_path / "b" / entry["file"]).read_text()
        assert entry["counts"]["gaps"] == len(entry["planted"]["gaps"])
    a = json.loads((tmp_path / "a" / pair["a"]).read_text())
    b = json.loads((tmp_path / "a" / pair["b"]).read_text())
    assert len(a["strokes"]) == len(b["strokes"]) and a["strokes"] != b["strokes"]  # same plan, two poses


# ---------------------------------------------------------------------------
# the checker, on a hand-made cleaning

# A line with a pen pause (stroke 0), a stroke crossing it at (1, 0) (stroke 1) and one stopping
# 0.03 short of it above (3, 0) (stroke 2). Tolerance 0.05: 1% of the box diagonal, 5.
DRAWING = [([(0.0, 0.0), (2.0, 0.0), (2.0, 0.0), (4.0, 0.0)], False),
           ([(1.0, -1.0), (1.0, 1.0)], False),
           ([(3.0, 2.0), (3.0, 0.03)], False)]
SIZE = 5.0


def cleaned():
    """The cleaning the contract asks for: the duplicate merged, a crossing vertex, the end snapped."""
    return {"vertices": [[0.0, 0.0], [2.0, 0.0], [4.0, 0.0], [1.0, -1.0], [1.0, 1.0], [3.0, 2.0], [3.0, 0.0],
                         [1.0, 0.0]],
            "edges": [[0, 7], [7, 1], [1, 6], [6, 2], [3, 7], [7, 4], [5, 6]],
            "cleaning": {"tolerance": 0.05, "junctions_made": 1, "ends_snapped": 1, "points_merged": 1,
                         "changes": [{"kind": "merge", "stroke": 0, "point": 2, "other_stroke": 0, "at": [2.0, 0.0],
                                      "distance": 0.0},
                                     {"kind": "crossing", "stroke": 0, "point": None, "other_stroke": 1,
                                      "at": [1.0, 0.0], "distance": 0.0},
                                     {"kind": "snap", "stroke": 2, "point": 1, "other_stroke": 0, "at": [3.0, 0.0],
                                      "distance": 0.03}],
                         "strokes": [{"vertices": [0, 7, 1, 6, 2], "cyclic": False},
                                     {"vertices": [3, 7, 4], "cyclic": False},
                                     {"vertices": [5, 6], "cyclic": False}],
                         "point_vertices": [[0, 1, 1, 2], [3, 4], [5, 6]]}}


ENTRY = {"name": "t", "kind": "test", "tolerance": 0.05,
         "counts": {"gaps": 1, "touches": 0, "crossings": 1, "overshoots": 0, "duplicates": 1},
         "planted": {"gaps": [{"stroke": 2, "point": 1, "end": "end", "other_stroke": 0, "distance": 0.03,
                               "distance_tol": 0.6, "near": [3.0, 0.0]}],
                     "touches": [], "crossings": [{"stroke": 0, "other_stroke": 1, "at": [1.0, 0.0],
                                                   "overshoot": False}],
                     "duplicates": [{"stroke": 0, "point": 2}]}}


def all_problems(doc, bends=None):
    return (cl.structure_problems(DRAWING, doc) + cl.validity_problems(doc)
            + cl.accounting_problems(DRAWING, doc, SIZE, bends))


def test_a_correct_cleaning_passes_and_every_planted_defect_is_found():
    doc = cleaned()
    assert all_problems(doc) == []
    found = cl.found_defects(ENTRY, DRAWING, doc, SIZE)
    assert found["missed"] == [] and found["extra_snaps"] == [] and found["extra_crossings"] == []
    assert (found["gaps"], found["crossings"], found["crossings_reported"], found["duplicates"]) == (1, 1, 1, 1)
    assert cl.short_stubs(doc, 0.05) == []
    again = copy.deepcopy(doc)  # cleaned again: the same figure, nothing to do
    again["cleaning"].update(changes=[], junctions_made=0, ends_snapped=0, points_merged=0)
    assert cl.idempotence_problems(doc, again) == []


def test_a_point_moved_without_its_change_is_caught():
    doc = cleaned()
    doc["cleaning"]["changes"].pop()  # the snap
    doc["cleaning"]["ends_snapped"] = 0
    problems = cl.accounting_problems(DRAWING, doc, SIZE)
    assert any("point 1 of stroke 2 moved by 0.03" in p and "no merge or snap" in p for p in problems)
    assert any("nothing explains stroke 2" in p for p in problems)


def test_a_wrong_distance_is_caught_to_1e_12():
    doc = cleaned()
    doc["cleaning"]["changes"][2]["distance"] = 0.03 * (1 + 1e-9)
    assert any("says" in p for p in cl.accounting_problems(DRAWING, doc, SIZE))
    doc["cleaning"]["changes"][2]["distance"] = math.hypot(0.0, 0.03) * (1 + 1e-14)
    assert cl.accounting_problems(DRAWING, doc, SIZE) == []


def test_an_unreported_crossing_and_wrong_counts_are_caught():
    doc = cleaned()
    del doc["cleaning"]["changes"][1]
    problems = cl.accounting_problems(DRAWING, doc, SIZE)
    assert any("vertex 7" in p and "nothing explains stroke 0" in p for p in problems)
    assert any("junctions_made is 1, the changes have 0" in p for p in problems)
    assert cl.found_defects(ENTRY, DRAWING, doc, SIZE)["crossings_reported"] == 0


def test_crossing_edges_and_a_path_off_its_segment_are_caught():
    doc = cleaned()
    # stroke 1 not split at the crossing: its edge crosses stroke 0's
    doc["edges"] = [[0, 7], [7, 1], [1, 6], [6, 2], [3, 4], [5, 6]]
    doc["cleaning"]["strokes"][1]["vertices"] = [3, 4]
    assert any("cross" in p or "lies on" in p for p in cl.validity_problems(doc))
    doc = cleaned()
    doc["vertices"][7] = [1.0, 0.01]  # the crossing moved off stroke 0's line by 0.01, 20 merge distances
    doc["cleaning"]["changes"][1]["at"] = [1.0, 0.01]
    assert any("off their segment" in p for p in cl.accounting_problems(DRAWING, doc, SIZE))


def test_a_bend_within_the_merge_distance_at_a_reported_junction_is_counted_not_failed():
    doc = cleaned()
    doc["vertices"][7] = [1.0, 0.0004]  # under 0.05 / 100
    doc["cleaning"]["changes"][1]["at"] = [1.0, 0.0004]
    bends = []
    assert cl.accounting_problems(DRAWING, doc, SIZE, bends) == []
    assert [(s, v) for s, v, _ in bends] == [(0, 7)] and bends[0][2] == pytest.approx(0.0004)


def test_a_junction_on_the_piece_a_snapped_end_redrew_is_accounted():
    # Stroke 1 crosses stroke 2 at X = (5, 2) and its end, drawn 0.3 above stroke 0, snaps to
    # E = (5.2, 0): the stroke from X to its end is now the straight piece X-E. Stroke 3's end,
    # drawn 0.1 short of that piece, snaps onto it at w = (5.1, 1), 0.1 off stroke 1 as drawn.
    drawing = [([(0.0, 0.0), (10.0, 0.0)], False), ([(5.0, 5.0), (5.0, 0.3)], False),
               ([(0.0, 2.0), (10.0, 2.0)], False), ([(8.0, 1.0), (5.2, 1.0)], False)]
    w = [5.1, 1.0]
    doc = {"vertices": [[0.0, 0.0], [10.0, 0.0], [5.0, 5.0], [5.2, 0.0], [0.0, 2.0], [10.0, 2.0], [8.0, 1.0], w,
                        [5.0, 2.0]],
           "edges": [[0, 3], [3, 1], [2, 8], [8, 7], [7, 3], [4, 8], [8, 5], [6, 7]],
           "cleaning": {"tolerance": 0.5, "junctions_made": 1, "ends_snapped": 2, "points_merged": 0,
                        "changes": [{"kind": "crossing", "stroke": 1, "point": None, "other_stroke": 2,
                                     "at": [5.0, 2.0], "distance": 0.0},
                                    {"kind": "snap", "stroke": 1, "point": 1, "other_stroke": 0, "at": [5.2, 0.0],
                                     "distance": math.dist((5.0, 0.3), (5.2, 0.0))},
                                    {"kind": "snap", "stroke": 3, "point": 1, "other_stroke": 1, "at": w,
                                     "distance": math.dist((5.2, 1.0), w)}],
                        "strokes": [{"vertices": path, "cyclic": False}
                                    for path in ([0, 3, 1], [2, 8, 7, 3], [4, 8, 5], [6, 7])],
                        "point_vertices": [[0, 1], [2, 3], [4, 5], [6, 7]]}}
    assert cl.validity_problems(doc) == [] and cl.limit_problems(drawing, doc) == []
    assert cl.accounting_problems(drawing, doc, 11.18) == []
    # the same junction off that piece (at x = 5.15): stroke 1 bent where nothing says so
    doc["vertices"][7] = [5.15, 1.0]
    doc["cleaning"]["changes"][2].update(at=[5.15, 1.0], distance=0.05)
    assert any("off their segment" in p for p in cl.accounting_problems(drawing, doc, 11.18))


def test_a_gap_left_open_is_missed():
    doc = cleaned()
    doc["vertices"][6] = [3.0, 0.03]  # the end stays where it was drawn, stroke 0 not through it
    doc["edges"] = [[0, 7], [7, 1], [1, 2], [3, 7], [7, 4], [5, 6]]
    doc["cleaning"]["strokes"][0]["vertices"] = [0, 7, 1, 2]
    doc["cleaning"]["changes"].pop()
    doc["cleaning"]["ends_snapped"] = 0
    assert all_problems(doc) == []  # a valid cleaning, only not the one the corpus planted
    found = cl.found_defects(ENTRY, DRAWING, doc, SIZE)
    assert found["gaps"] == 0 and any(m.startswith("gap: the end of stroke 2") for m in found["missed"])


def test_idempotence_problems_say_what_changed():
    first, second = cleaned(), cleaned()
    second["cleaning"]["changes"] = [{"kind": "snap", "stroke": 3, "point": 1, "other_stroke": 0, "at": [3.0, 0.0],
                                      "distance": 0.001}]
    second["cleaning"]["ends_snapped"] = 1
    assert any("made 1 changes" in p for p in cl.idempotence_problems(first, second))
    # the same figure numbered otherwise
    second = cleaned()
    second["vertices"] = second["vertices"][1:] + second["vertices"][:1]
    second["edges"] = [[(u - 1) % 8, (v - 1) % 8] for u, v in second["edges"]]
    second["cleaning"]["changes"] = []
    second["cleaning"].update(junctions_made=0, ends_snapped=0, points_merged=0)
    assert cl.idempotence_problems(first, second) == [
        "the figure changed: 8 -> 8 vertices, 7 -> 7 edges (the same geometry, numbered otherwise)"]


def test_merges_and_snaps_beyond_their_limits_are_caught():
    doc = cleaned()
    assert cl.limit_problems(DRAWING, doc) == []
    doc["cleaning"]["changes"][2]["distance"] = 0.06  # a snap beyond the tolerance
    assert any("snapped 0.06 (1.2 tolerances)" in p for p in cl.limit_problems(DRAWING, doc))
    doc = cleaned()
    doc["cleaning"]["changes"].append({"kind": "snap", "stroke": 0, "point": 1, "other_stroke": 1, "at": [2.0, 0.0],
                                       "distance": 0.0})
    assert any("point 1 of stroke 0 (of 4) snapped onto stroke 1 by 0: it is no free end" in p
               for p in cl.limit_problems(DRAWING, doc))


def test_a_pen_pause_at_a_snapped_end_moves_with_it_and_a_tail_merges():
    # stroke 2 ends with a pen pause: both copies snap to (3, 0), the copy a merge of 0.03
    drawing = DRAWING[:2] + [([(3.0, 2.0), (3.0, 0.03), (3.0, 0.03)], False)]
    doc = cleaned()
    doc["cleaning"]["point_vertices"][2] = [5, 6, 6]
    doc["cleaning"]["changes"].append({"kind": "merge", "stroke": 2, "point": 2, "other_stroke": 2,
                                       "at": [3.0, 0.0], "distance": 0.03})
    doc["cleaning"]["points_merged"] = 2
    assert cl.limit_problems(drawing, doc) == [] and cl.accounting_problems(drawing, doc, SIZE) == []
    # a tail: stroke 2 runs on along stroke 0, 0.02 above it, to (3.5, 0.02); its inner end snaps
    drawing = DRAWING[:2] + [([(3.0, 2.0), (3.0, 0.03), (3.5, 0.02)], False)]
    doc["cleaning"]["changes"][-1].update(distance=math.dist((3.5, 0.02), (3.0, 0.0)))
    assert cl.limit_problems(drawing, doc) == []
    # the same merge of a point far from every other stroke is no tail
    drawing = DRAWING[:2] + [([(3.0, 2.0), (3.0, 0.03), (3.5, 0.9)], False)]
    doc["cleaning"]["changes"][-1].update(distance=math.dist((3.5, 0.9), (3.0, 0.0)))
    assert any("more than the tolerance from every other stroke" in p for p in cl.limit_problems(drawing, doc))
    # a merge into a vertex no point was drawn near, with no snap there: beyond the merge distance
    doc = cleaned()
    doc["cleaning"]["changes"][0]["distance"] = 0.001
    doc["cleaning"]["point_vertices"][0] = [0, 1, 7, 2]
    assert any("no point of that vertex was drawn within" in p for p in cl.limit_problems(DRAWING, doc))


def test_an_edge_on_two_paths_is_counted_within_the_tolerance_and_fails_beyond():
    doc = cleaned()
    doc["cleaning"]["strokes"][1]["vertices"] = [3, 7, 4]
    doc["cleaning"]["strokes"][2]["vertices"] = [5, 6, 1, 6]  # stroke 2 along stroke 0's edge 1-6 (length 1)
    problems = cl.accounting_problems(DRAWING, doc, SIZE)
    assert any("strokes [0, 2] run along each other for 1 (20 tolerances, 1 edges" in p for p in problems)
    # many short edges along each other add up: stroke 1 drawn over stroke 0 in 0.05 steps
    line = [(0.05 * k, 0.0) for k in range(21)]
    drawing = [(line, False), (line[4:17], False)]
    doc = {"vertices": [list(p) for p in line], "edges": [[k, k + 1] for k in range(20)],
           "cleaning": {"tolerance": 0.1, "junctions_made": 0, "ends_snapped": 0, "points_merged": 13,
                        "changes": [{"kind": "merge", "stroke": 1, "point": j, "other_stroke": 0,
                                     "at": list(line[j + 4]), "distance": 0.0} for j in range(13)],
                        "strokes": [{"vertices": list(range(21)), "cyclic": False},
                                    {"vertices": list(range(4, 17)), "cyclic": False}],
                        "point_vertices": [list(range(21)), list(range(4, 17))]}}
    shared = []
    problems = cl.accounting_problems(drawing, doc, 1.0, shared_edges=shared)
    assert any("strokes [0, 1] run along each other for 0.6 (6 tolerances, 12 edges" in p for p in problems)
    assert shared == []


def test_short_stubs_neighbours_and_names():
    doc = cleaned()
    doc["vertices"][0] = [0.97, 0.0]  # stroke 0's start 0.03 from the crossing: a stub under the tolerance
    stubs = cl.short_stubs(doc, 0.05)
    assert [(e, j) for e, j, _ in stubs] == [(0, 7)] and stubs[0][2] == pytest.approx(0.03)
    assert cl.not_neighbours([(0, 5, False), (4, 5, False)])  # an open path closed on its start
    assert not cl.not_neighbours([(0, 5, True), (4, 5, True)])  # neighbours around a loop
    assert cl.not_neighbours([(1, 9, True), (5, 9, True)])
    assert cl.names_stroke("error: d.json: strokes 0 and 7 overlap along a length", 7)
    assert cl.names_stroke("error: d.json: point 3 of stroke 12 retraces it", 12)
    assert not cl.names_stroke("error: d.json: stroke 1 has a single point", 11)


def test_the_bad_drawings_are_what_the_corpus_analysis_refuses():
    cases = {label: strokes for label, strokes, _ in cl.bad_drawings(
        [([(float(k), float(k % 3)) for k in range(14)], False), ([(0.0, 5.0), (3.0, 6.0)], False)])}
    as_drawing = {label: [([tuple(p) for p in s["points"]], s["cyclic"]) for s in strokes]
                  for label, strokes in cases.items()}
    assert cases["no strokes"] == []
    assert any("single point" in p for p in dc.analyse(as_drawing["a stroke of one point"])["problems"])
    assert any("overlap" in p for p in dc.analyse(as_drawing["a stroke along another"])["problems"])
    assert any("retraces" in p for p in dc.analyse(as_drawing["a stroke that retraces itself"])["problems"])


# ---------------------------------------------------------------------------
# the report section

def row(name, kind, points=300, gaps=2, found_gaps=2, problems=None, **extra):
    r = {"name": name, "kind": kind, "pair": None, "strokes": 4, "points": points, "seconds": 0.01,
         "planted": {"gaps": gaps, "touches": 1, "crossings": 3, "overshoots": 1, "duplicates": 5},
         "problems": problems or {}, "changes": {"merge": 6, "snap": found_gaps, "crossing": 3, "touch": 1},
         "found": {"gaps": found_gaps, "touches": 1, "crossings": 3, "crossings_reported": 3, "duplicates": 5},
         "extra_snaps": [], "extra_crossings": [], "stubs": [], "bends": [], "valid_cli": True, "valid_exact": True,
         "accounted": not problems, "idempotent": True, "idempotent_default": True}
    r.update(extra)
    return r


def document():
    missed = {"missed": ["gap: the end of stroke 2 (point 40, 0.81 tolerances from stroke 0) is not joined to it"]}
    rows = [row("stickman_1", "stickman"), row("house_1", "house", points=700, gaps=3, found_gaps=2, problems=missed)]
    pairs = [{"name": "house_2", "kind": "house", "a": "house_2_a", "b": "house_2_b", "error": "exit 2: error: no"}]
    refusals = [{"case": "no strokes", "from": "stickman_1", "exit": 2, "stderr": "error: x", "stroke": None,
                 "ok": True}]
    summary = cl.summarize(rows, pairs, refusals)
    show = {"name": "stickman_1", "kind": "stickman", "subject": "stick figure", "tolerance": 0.05,
            "strokes": [{"points": [list(p) for p in pts], "cyclic": cyc} for pts, cyc in DRAWING]}
    show.update({k: cleaned()[k] for k in ("vertices", "edges")}, changes=cleaned()["cleaning"]["changes"])
    return {"command": "/usr/bin/python3 bench/cleaning.py c --build-dir build --json out/benchmarks/cleaning.json",
            "build": {"commit": "abc123", "uncommitted_native": False}, "seed": 32, "summary": summary,
            "drawings": rows, "pairs": pairs, "refusals": refusals, "showcase": show}


def test_the_section_tables_each_kind_and_all_with_failures_and_a_figure(tmp_path):
    text = "\n".join(mb.cleaning_section(document(), str(tmp_path / "B.md"), str(tmp_path / "plots")))
    assert text.startswith("\n## Drawing cleaning\n")
    lines = text.splitlines()
    total = next(line for line in lines if line.startswith("| **all** |"))
    # 2 drawings, 1000 points, 8 strokes; gaps 4/5 found, every touch, crossing and duplicate
    assert total.startswith("| **all** | 2 | 1000 | 8 | 4/5 | 2/2 | 6/6 | 10/10 | 12 / 4 / 6 / 2 | 2/2 | 1/2 | 2/2 |")
    assert "| house | 1 | 700 | 4 | 2/3 |" in text
    assert "CLI built from abc123." in text
    assert "house_1 (missed): gap: the end of stroke 2" in text and "house_2 (morph): exit 2: error: no" in text
    assert "0/1 morphed" in text and "1/1 refused" in text
    assert (tmp_path / "plots" / "cleaning_before_after.svg").exists()
    assert "(plots/cleaning_before_after.svg)" in text
    svg = (tmp_path / "plots" / "cleaning_before_after.svg").read_text()
    assert "snapped by 0.60 tolerance" in svg and "crossing (1)" in svg


def test_without_cleaning_json_the_section_is_a_note(tmp_path):
    text = "\n".join(mb.cleaning_section(None, str(tmp_path / "B.md"), str(tmp_path / "plots")))
    assert "## Drawing cleaning" in text and "Not measured in this run" in text
    assert not (tmp_path / "plots").exists()
    assert mb.read_cleaning(str(tmp_path)) is None
    (tmp_path / "cleaning.json").write_text(json.dumps({"drawings": []}))
    with pytest.raises(mb.InputError):
        mb.read_cleaning(str(tmp_path))
    (tmp_path / "cleaning.json").write_text(json.dumps(document()))
    assert len(mb.read_cleaning(str(tmp_path))["drawings"]) == 2


def test_make_benchmarks_appends_the_section_after_local_timing(tmp_path):
    out = tmp_path / "B.md"
    out.write_text("# Benchmarks\n\n## Key poses\n\ntext\n")
    mb.append_sections(str(out), mb.local_timing_section(None, str(out), str(tmp_path / "plots")))
    mb.append_sections(str(out), mb.cleaning_section(None, str(out), str(tmp_path / "plots")))
    text = out.read_text()
    assert text.index("## Key poses") < text.index("## Local timing") < text.index("## Drawing cleaning")
    assert text.endswith(".\n")
