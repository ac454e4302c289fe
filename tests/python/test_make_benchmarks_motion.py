"""Tests of the "Motion quality" section that bench/make_benchmarks.py writes into
BENCHMARKS.md from bench/motion_quality.py's motion.json (issue 12, item 6): on a tiny
hand-made motion.json whose numbers are known, and once through the script's command line
with a minimal data folder. Needs only Debian's python3 with matplotlib, no build.
"""
import copy
import json
import pathlib
import subprocess

import pytest

from conftest import load_script

REPO = pathlib.Path(__file__).resolve().parents[2]
TIMEOUT_SECONDS = 300


mb = load_script("make_benchmarks")
METHODS = ["rigid", "barycentric", "linear", "arap"]


def result(edge, uneven, min_size=1.0, joint=0.5, turn=10.0, needed=10.0, bad=(), ms=0.1):
    r = {"edge_dev": edge, "joint_dev_deg": joint, "min_size": min_size, "unevenness": uneven, "turn_deg": turn,
         "needed_deg": needed, "beyond_deg": abs(turn) - abs(needed), "bad_frames": list(bad)}
    if ms is not None:
        r["ms_per_frame"] = ms
    return r


def summary_of(rows, failed=0):
    def stats(key):
        values = sorted(r[key] for r in rows)
        return {"median": values[len(values) // 2] if len(values) % 2 else
                sum(values[len(values) // 2 - 1:len(values) // 2 + 1]) / 2,
                "p90": values[-1], "p10": values[0], "max": values[-1]}
    s = {"pairs": len(rows), "failed": failed,
         **{k: stats(k) for k in ("edge_dev", "joint_dev_deg", "min_size", "unevenness", "beyond_deg")},
         "bad_frames": sum(len(r["bad_frames"]) for r in rows),
         "pairs_with_bad_frames": sum(1 for r in rows if r["bad_frames"]), "bad_frames_checked": True,
         "min_size_share_ok": sum(1 for r in rows if r["min_size"] >= 0.9) / len(rows)}
    if all("ms_per_frame" in r for r in rows):
        s["ms_per_frame"] = {"median": stats("ms_per_frame")["median"], "p90": 0, "max": 0}
    return s


def tiny_motion(filmstrip_files=("docs/benchmarks/steiner.svg",), methods=METHODS):
    """Two pairs, a glyph and a 180-degree self-turn, four methods with known numbers."""
    pairs = {
        "glyph_J_to_U": {"kind": "glyph", "vertices": 51, "tags": {},
                         "rigid": result(0.011, 1.10, ms=0.2), "barycentric": result(0.595, 8.93, 0.646, ms=0.08),
                         "linear": result(0.114, 1.0, 0.687, bad=[10], ms=0.04),
                         "arap": result(0.0, 1.09, bad=[13], ms=None)},
        "special_self_turn_180": {"kind": "special", "vertices": 40, "tags": {"self_turn_deg": 180},
                                  "rigid": result(0.003, 1.02, 1.0, turn=180.0, needed=180.0, ms=0.4),
                                  "barycentric": result(0.229, 1.54, 0.955, turn=164.9, needed=180.0, ms=0.06),
                                  "linear": result(0.517, 1.0, 0.034, turn=180.0, needed=180.0, ms=0.02),
                                  "arap": result(0.0, 1.0, 1.0, turn=180.0, needed=180.0, ms=None)},
    }
    for pair in pairs.values():
        for m in METHODS:
            if m not in methods:
                del pair[m]
    summary = {m: summary_of([p[m] for p in pairs.values()]) for m in methods}
    targets = [{"target": "edge dev median ≤ 0.02 and p90 ≤ 0.08", "key": "edge_dev",
                **{m: {"pass": m in ("rigid", "arap"), "value": f"{summary[m]['edge_dev']['median']:.3f}"}
                   for m in methods}},
               {"target": "0 invalid frames (and every morph succeeds)", "key": "invalid_frames",
                **{m: {"pass": m in ("rigid", "barycentric"), "value": "x"} for m in methods}}]
    cli = {"rigid": "--method rigid", "barycentric": "--method barycentric", "linear": "--method linear",
           "arap": None}
    return {"command": "/usr/bin/python3 bench/motion_quality.py out/benchmarks/motion_corpus --json x",
            "corpus": "out/benchmarks/motion_corpus", "corpus_seed": 12, "build_dir": "build-bench/release",
            "cli_version": "stickmorph 0.1.0", "frames": 30, "check_frames": "all", "methods": list(methods),
            "cli_methods": {m: cli[m] for m in methods}, "notes": [], "pairs": pairs, "summary": summary,
            "targets": targets, "runtime_s": 41.0,
            "filmstrips": [{"file": f, "pair": "glyph_J_to_U", "method": methods[0], "rows": methods[:2],
                            "worst": [{"metric": "edge_dev", "rank": 1, "value": 0.011},
                                      {"metric": "beyond_deg", "rank": 1, "value": 3.5}]}
                           for f in filmstrip_files]}


def section(motion, tmp_path):
    return "\n".join(mb.motion_section(motion, str(REPO / "BENCHMARKS.md"), str(tmp_path / "plots")))


def table_row(text, first_cell):
    rows = [line for line in text.splitlines() if line.startswith(f"| {first_cell} |")]
    assert len(rows) == 1, (first_cell, rows)
    return [cell.strip() for cell in rows[0].strip("|").split("|")]


def test_summary_table_has_one_row_per_method_and_the_targets(tmp_path):
    text = section(tiny_motion(), tmp_path)
    assert text.startswith("## Motion quality")
    header = table_row(text, "method")
    rigid = dict(zip(header, table_row(text, "**rigid**")))
    assert rigid["options"] == "`--method rigid`"
    assert rigid["pairs"] == "2"
    assert rigid["edge dev median"] == "0.007" and rigid["edge dev p90"] == "0.011"
    assert rigid["unevenness median"] == "1.06" and rigid["unevenness p90"] == "1.10"
    assert rigid["min size ≥ 0.9"] == "100% (2/2)"
    assert rigid["invalid frames (pairs)"] == "0 (0)"
    assert rigid["per frame"] == "0.30 ms"
    barycentric = dict(zip(header, table_row(text, "**barycentric**")))
    assert barycentric["min size ≥ 0.9"] == "50% (1/2)"
    assert barycentric["max beyond °"] == "0.0"
    arap = dict(zip(header, table_row(text, "arap")))  # a reference: not bold, no time
    assert arap["options"] == "computed in the script" and arap["per frame"] == "–"
    assert arap["invalid frames (pairs)"] == "1 (1)"
    must = dict(zip(header, table_row(text, "*must show*")))
    assert must["edge dev median"] == "≤ 0.02" and must["edge dev p90"] == "≤ 0.08"
    assert must["joint dev ° median"] == "≤ 2" and must["min size ≥ 0.9"] == "≥ 90%"
    assert must["unevenness median"] == "≤ 1.2" and must["unevenness p90"] == "≤ 1.6"
    assert must["max beyond °"] == "≤ 45" and must["invalid frames (pairs)"] == "0"
    # pass/fail per target and method, and the count met
    assert table_row(text, "target") == ["target"] + METHODS
    assert table_row(text, "edge dev median ≤ 0.02 and p90 ≤ 0.08")[1:] == [
        "PASS (0.007)", "FAIL (0.412)", "FAIL (0.316)", "PASS (0.000)"]
    assert table_row(text, "**targets met**")[1:] == ["**2/2**", "**1/2**", "**0/2**", "**1/2**"]
    assert "no `rigid` row" not in text


def test_breakdown_by_kind_and_the_self_turn(tmp_path):
    text = section(tiny_motion(), tmp_path)
    header = table_row(text, "kind")
    glyph = dict(zip(header, table_row(text, "glyph")))
    assert glyph["pairs"] == "1"
    assert glyph["edge dev rigid"] == "0.011" and glyph["edge dev barycentric"] == "0.595"
    assert glyph["uneven barycentric"] == "8.93" and glyph["min size linear"] == "0.69"
    special = dict(zip(header, table_row(text, "special")))
    assert special["edge dev linear"] == "0.517"
    # glyph before special: the corpus's order of kinds, not the alphabet's
    assert text.index("| glyph |") < text.index("| special |")
    turn_rows = [line for line in text.splitlines() if line.startswith("| special_self_turn_180 |")]
    assert len(turn_rows) == 4
    assert "| special_self_turn_180 | barycentric | 164.9 | 180.0 | -15.1 | 0.229 | 0.955 | 1.54 | 0 |" in text


def test_filmstrips_inside_the_repository_are_linked_and_others_are_not(tmp_path):
    outside = tmp_path / "strip_outside.svg"
    text = section(tiny_motion(("docs/benchmarks/steiner.svg", str(outside), "out/strip_ignored.svg")), tmp_path)
    assert "### Filmstrips of the worst `rigid` pairs" in text
    assert "[glyph_J_to_U](docs/benchmarks/steiner.svg): worst by edge-length deviation 0.011, turning beyond " \
           "the need 3.5°" in text
    assert "![glyph_J_to_U](docs/benchmarks/steiner.svg)" in text
    assert f"`{outside}` (not a file of the repository, so not linked)" in text
    # out/ is ignored by git, so never committed: named, not linked
    assert "`out/strip_ignored.svg` (not a file of the repository, so not linked)" in text
    assert "](out/" not in text and f"]({tmp_path}" not in text
    assert "rows at one scale" in text and "(rigid, barycentric)" in text


def test_plot_and_the_commands(tmp_path):
    text = section(tiny_motion(), tmp_path)
    plot = tmp_path / "plots" / "motion_quality.svg"
    assert plot.exists() and plot.read_text().lstrip().startswith("<?xml")
    assert "rigid" in plot.read_text()  # the legend names the methods
    assert "/usr/bin/python3 bench/motion_corpus.py out/benchmarks/motion_corpus --seed 12 " \
           "--build-dir build-bench/release\n/usr/bin/python3 bench/motion_quality.py " \
           "out/benchmarks/motion_corpus --json x" in text
    assert "the measuring took 41 s" in text
    assert "[docs/MOTION.md](docs/MOTION.md)" in text


def test_without_rigid_the_report_says_so(tmp_path):
    motion = tiny_motion(methods=["barycentric", "linear", "arap"])
    text = section(motion, tmp_path)
    assert "Note: no `rigid` row" in text
    assert "| **rigid** |" not in text
    motion["notes"] = ["no rigid row: `stickmorph morph --help` at abc lists no rigid method"]
    text = section(motion, tmp_path)
    assert "- Note: no rigid row: `stickmorph morph --help` at abc lists no rigid method" in text
    assert text.count("Note:") == 1


def test_without_motion_json_the_section_is_a_note(tmp_path):
    text = section(None, tmp_path)
    assert text.startswith("## Motion quality") and "Not measured in this run" in text
    assert not (tmp_path / "plots").exists()
    assert mb.read_motion(str(tmp_path)) is None
    (tmp_path / "motion.json").write_text('{"methods": []}')  # no pairs: not a motion_quality.py output
    with pytest.raises(mb.InputError):
        mb.read_motion(str(tmp_path))


# ---------------------------------------------------------------------------
# through the command line, with the smallest data folder make_benchmarks.py accepts

STAGE_RESULT = {key: 0.5 for key, _, _ in mb.STAGES if key not in ("solve_frame_ms", "verify_frame_ms")}


def write_data(folder, motion):
    folder.mkdir()
    record = {"family": "polyline", "requested_n": 10, "method": "improved", "status": "ok", "peak_kib": 4096,
              "wall_ms": 5.0,
              "result": {"n": 10, "edges": 9, "interior_faces": 0, "twist": 0, "steiner": 3, "frames": 5,
                         "solve_ms": 1.0, "verify_frames_ms": 1.0, "invalid_frames": 0, "linear_invalid_frames": 1,
                         "linear_first_invalid": 2, "triangulate_ms": 2.0, "factorizations": 2, "morph_ms": 3.0,
                         **STAGE_RESULT}}
    (folder / "morph.jsonl").write_text(json.dumps(record) + "\n")
    (folder / "polygon_pairs.json").write_text(json.dumps({"repeat": 1, "pairs": []}))
    (folder / "run.json").write_text(json.dumps({
        "command": "bash bench/benchmarks.sh --quick", "date": "d", "commit": "c", "machine": "m", "compiler": "c",
        "build": "b", "frames": 5, "aronov_max": 300, "sg2001_max": 1000, "memory_limit_mib": 4096,
        "runtime_s": 1}))
    if motion is not None:
        (folder / "motion.json").write_text(json.dumps(motion))


def run_make_benchmarks(data, out, plots):
    return subprocess.run(["/usr/bin/python3", str(REPO / "bench" / "make_benchmarks.py"), "--data", str(data),
                           "--output", str(out), "--plots", str(plots)],
                          capture_output=True, text=True, timeout=TIMEOUT_SECONDS)


@pytest.mark.skipif(not pathlib.Path("/usr/bin/python3").exists(), reason="needs Debian's python3 (matplotlib)")
def test_make_benchmarks_writes_the_motion_section(tmp_path):
    write_data(tmp_path / "data", tiny_motion())
    r = run_make_benchmarks(tmp_path / "data", tmp_path / "BENCHMARKS.md", tmp_path / "plots")
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "BENCHMARKS.md").read_text()
    assert "\n## Motion quality\n" in text and "| **rigid** | `--method rigid` | 2 |" in text
    assert "- Motion quality ([below](#motion-quality)), issue 12's targets met: rigid 2/2, barycentric 1/2, " \
           "linear 0/2, arap 1/2." in text
    assert (tmp_path / "plots" / "motion_quality.svg").exists()
    # without motion.json the rest of the report is written, and says so
    write_data(tmp_path / "data2", None)
    r = run_make_benchmarks(tmp_path / "data2", tmp_path / "B2.md", tmp_path / "plots2")
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "B2.md").read_text()
    assert "## Motion quality\n\nNot measured in this run" in text and "targets met" not in text
    assert not (tmp_path / "plots2" / "motion_quality.svg").exists()
    # a broken motion.json is an incomplete run
    (tmp_path / "data2" / "motion.json").write_text("{")
    r = run_make_benchmarks(tmp_path / "data2", tmp_path / "B3.md", tmp_path / "plots3")
    assert r.returncode == 2 and "motion.json" in r.stderr


def test_following_the_guide_and_the_triangulation_shape(tmp_path):
    """Issue 30's table: only the CLI methods that report the triangulation's shape; judged
    against arap only on pairs whose arap motion is valid (here the self-turn only)."""
    motion = tiny_motion()
    shapes = {"glyph_J_to_U": (2.0, 0.1, 0.5), "special_self_turn_180": (8.0, 0.3, 1.0)}
    for name, (angle, steiner, exact) in shapes.items():
        motion["pairs"][name]["rigid"].update(triangle_min_angle_deg=angle, steiner_per_vertex=steiner,
                                              exact_frame_share=exact)
    motion["pairs"]["special_self_turn_180"]["arap"]["bad_frames"] = []
    text = section(motion, tmp_path)
    assert "### Following the guide, and the triangulation's shape (issue 30)" in text
    rows = [line for line in text.splitlines() if line.startswith("| **rigid** |")]
    assert len(rows) == 2  # the summary's row and this table's
    header = [c.strip() for c in [line for line in text.splitlines()
                                  if line.startswith("| method | within")][0].strip("|").split("|")]
    rigid = dict(zip(header, [c.strip() for c in rows[1].strip("|").split("|")]))
    assert rigid["within 0.005 of arap"] == "1/1 (100%)"
    assert rigid["edge dev p90"] == "0.011"
    assert rigid["exact frames median"] == "75%"
    assert rigid["smallest angle ° median"] == "5.00" and rigid["p10"] == "2.00" and rigid["min"] == "2.000"
    assert rigid["Steiner / vertex median"] == "0.20"
    lines = text.splitlines()
    start = lines.index([line for line in lines if line.startswith("| method | within")][0])
    table_lines = lines[start:lines.index("", start)]
    # barycentric reports no shape here: no row; the must-show row last
    assert [line.split("|")[1].strip() for line in table_lines[2:]] == ["**rigid**", "*must show*"]


def test_without_shapes_there_is_no_issue_30_table(tmp_path):
    assert "(issue 30)" not in section(tiny_motion(), tmp_path)


def test_an_earlier_run_is_shown_before(tmp_path):
    """motion_before.json (an earlier run on the same corpus, with its label) adds a "before"
    row per measured method above the current ones; judged against the current arap validity."""
    motion = tiny_motion()
    before = copy.deepcopy(motion)
    for name, (angle, steiner, exact) in {"glyph_J_to_U": (2.0, 0.1, 0.5),
                                          "special_self_turn_180": (8.0, 0.3, 1.0)}.items():
        motion["pairs"][name]["rigid"].update(triangle_min_angle_deg=angle, steiner_per_vertex=steiner,
                                              exact_frame_share=exact)
        before["pairs"][name]["rigid"].update(triangle_min_angle_deg=angle / 4, steiner_per_vertex=0.0,
                                              exact_frame_share=exact / 2, edge_dev=0.05)
    motion["pairs"]["special_self_turn_180"]["arap"]["bad_frames"] = []
    data = tmp_path / "data"
    data.mkdir()
    (data / "motion.json").write_text(json.dumps(motion))
    (data / "motion_before.json").write_text(json.dumps(dict(before, label="abc1234")))
    text = section(mb.read_motion(str(data)), tmp_path)
    assert "measured at `abc1234`" in text
    old = table_row(text, "rigid, before (`abc1234`)")
    assert old[1] == "0/1 (0%)" and old[4] == "1.25"
    new = [line for line in text.splitlines() if line.startswith("| **rigid** |")][1]
    assert "1/1 (100%)" in new
    # without its label the earlier run is an incomplete input
    (data / "motion_before.json").write_text(json.dumps(before))
    with pytest.raises(mb.InputError, match="motion_before.json"):
        mb.read_motion(str(data))
