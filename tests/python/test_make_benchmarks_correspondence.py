"""Tests of the "Correspondence" section that bench/make_benchmarks.py writes into
BENCHMARKS.md from stickmorph_benchmark_correspondence's correspondence.json (issue 13): on a
tiny hand-made correspondence.json whose numbers are known, and once through the script's
command line with a minimal data folder. Needs only Debian's python3 with matplotlib, no build.
"""
import json
import pathlib
import subprocess

import pytest

from conftest import load_script

REPO = pathlib.Path(__file__).resolve().parents[2]
TIMEOUT_SECONDS = 300

mb = load_script("make_benchmarks")


def ok_case(family, requested, n_source, ms, n_target=None, m=None, nodes=2, chains=1, candidates=2, known=0,
            correct=0, valid=True, runs=3, peak_kib=4096):
    n_target = n_source if n_target is None else n_target
    return {"family": family, "requested_n": requested, "status": "ok", "wall_ms": 3 * ms + 1, "peak_kib": peak_kib,
            "result": {"n_source": n_source, "n_target": n_target, "m": m or max(n_source, n_target),
                       "nodes": nodes, "chains": chains, "candidates": candidates, "residual": 0.0, "ms": ms,
                       "runs": runs, "runs_ms": [ms] * runs, "valid": valid, "known_partners": known,
                       "correct_partners": correct}}


def tiny_correspondence():
    """Two families at 100, 300 and 1000 vertices: a linear one and a quadratic one whose
    1000-vertex pair is too slow, and a timed-out case."""
    cases = [ok_case("spiral", 100, 100, 1.0, n_target=80, m=131, known=2, correct=2),
             ok_case("spiral", 300, 300, 3.0, n_target=240, m=396, known=2, correct=2),
             ok_case("spiral", 1000, 1000, 10.0, n_target=800, m=1320, known=2, correct=2),
             ok_case("wheel", 100, 100, 12.5, n_target=133, m=199, nodes=34, chains=66, candidates=33, known=34,
                     correct=34),
             ok_case("wheel", 300, 300, 112.5, n_target=397, m=595, nodes=100, chains=198, candidates=99, known=100,
                     correct=99, valid=False),
             ok_case("wheel", 1000, 1000, 1250.0, n_target=1333, m=1999, nodes=334, chains=666, candidates=333,
                     known=334, correct=334, runs=1, peak_kib=43008),
             {"family": "wheel", "requested_n": 3000, "status": "timeout", "wall_ms": 300000.0, "peak_kib": 999,
              "reason": "stopped after the 300 s limit"}]
    return {"program": "stickmorph_benchmark_correspondence",
            "command": "build-bench/release/stickmorph_benchmark_correspondence --sizes 100,300,1000,3000 "
                       "--json out/benchmarks/correspondence.json",
            "repeat": 3, "time_limit_s": 300, "memory_limit_mib": 4096, "fit_min_n": 100,
            "sizes": [100, 300, 1000, 3000], "families": ["spiral", "wheel"], "cases": cases,
            "exponents": {"spiral": {"exponent": 1.0, "sizes": 3}, "wheel": {"exponent": 2.0, "sizes": 3}},
            "requirement": {"requested_n": 1000, "limit_ms": 1000.0, "cases": 2, "pass": False,
                            "worst_family": "wheel", "worst_ms": 1250.0, "unfinished": 0}}


def section(data, tmp_path):
    return "\n".join(mb.correspondence_section(data, str(REPO / "BENCHMARKS.md"), str(tmp_path / "plots")))


def table_rows(text, first_cells):
    rows = [line for line in text.splitlines() if line.startswith(f"| {first_cells} |")]
    return [[cell.strip() for cell in row.strip("|").split("|")] for row in rows]


def test_table_has_one_row_per_case_with_the_counts(tmp_path):
    text = section(tiny_correspondence(), tmp_path)
    assert text.startswith("## Correspondence")
    [header] = table_rows(text, "family | requested n")
    assert header == ["family", "requested n", "n source", "n target", "m", "nodes", "chains", "candidates", "time",
                      "peak MiB", "valid", "partners"]
    wheels = [dict(zip(header, row)) for row in table_rows(text, "wheel")][:-1]  # the last: its exponent
    assert len(wheels) == 4
    assert wheels[0] == {"family": "wheel", "requested n": "100", "n source": "100", "n target": "133", "m": "199",
                         "nodes": "34", "chains": "66", "candidates": "33", "time": "12 ms", "peak MiB": "4",
                         "valid": "yes", "partners": "34/34"}
    assert wheels[1]["valid"] == "**NO**" and wheels[1]["partners"] == "99/100"
    assert wheels[2]["time"] == "1.25 s (1 run)" and wheels[2]["peak MiB"] == "42"
    assert wheels[3]["n source"] == "timed out: stopped after the 300 s limit"
    spirals = [dict(zip(header, row)) for row in table_rows(text, "spiral")][:-1]
    assert [s["time"] for s in spirals] == ["1.0 ms", "3.0 ms", "10 ms"]
    assert spirals[2]["m"] == "1 320"
    # the families are described, in the order of the data
    assert text.index("- **spiral**: an open polyline") < text.index("- **wheel**: a hub with k = n/3 spokes")
    assert "best of 3 runs" in text and "address-space limit 4096 MiB, time limit 300 s" in text


def test_requirement_and_exponents(tmp_path):
    data = tiny_correspondence()
    text = section(data, tmp_path)
    assert ("Issue 13's requirement, \"matching a 1000-vertex pair takes under a second\": **not met**; the slowest "
            "of the 2 pairs at n ≈ 1000 is wheel (1 000 against 1 333 vertices, 333 candidates): 1.25 s.") in text
    assert table_rows(text, "spiral")[-1] == ["spiral", "1.00 (3)"]
    assert table_rows(text, "wheel")[-1] == ["wheel", "2.00 (3)"]
    # under a second: met
    data["cases"][5]["result"]["ms"] = 900.0
    text = section(data, tmp_path)
    assert "under a second\": **met**; the slowest of the 2 pairs at n ≈ 1000 is wheel" in text
    assert mb.correspondence_requirement(data)[0] is True
    # a 1000-vertex case that did not finish: not met
    data["cases"][2] = {"family": "spiral", "requested_n": 1000, "status": "crashed", "reason": "signal 11"}
    text = section(data, tmp_path)
    assert "**not met**" in text and "1 of them did not finish" in text
    # without the program's exponents they are fitted here from the times
    del data["exponents"]
    text = section(data, tmp_path)
    assert table_rows(text, "wheel")[-1] == ["wheel", f"{mb.fit_exponent([(100, 12.5), (300, 112.5), (1000, 900.0)])[0]:.2f} (3)"]
    # no size 1000: not measured
    data["cases"] = [c for c in data["cases"] if c["requested_n"] != 1000]
    assert "was not measured: this run has no size 1000" in section(data, tmp_path)


def test_plot_and_command(tmp_path):
    text = section(tiny_correspondence(), tmp_path)
    plot = tmp_path / "plots" / "correspondence.svg"
    assert plot.exists() and plot.read_text().lstrip().startswith("<?xml")
    svg = plot.read_text()
    assert "spiral" in svg and "wheel" in svg  # the legend names the families
    assert "![Correspondence time against n](" in text and "correspondence.svg)" in text
    assert "```\nbuild-bench/release/stickmorph_benchmark_correspondence --sizes 100,300,1000,3000 --json " \
           "out/benchmarks/correspondence.json\n```" in text


def test_without_correspondence_json_the_section_is_a_note(tmp_path):
    text = section(None, tmp_path)
    assert text.startswith("## Correspondence") and "Not measured in this run" in text
    assert not (tmp_path / "plots").exists()
    assert mb.read_correspondence(str(tmp_path)) is None
    (tmp_path / "correspondence.json").write_text('{"repeat": 3}')  # no cases: not the program's output
    with pytest.raises(mb.InputError):
        mb.read_correspondence(str(tmp_path))
    (tmp_path / "correspondence.json").write_text(json.dumps(tiny_correspondence()))
    assert len(mb.read_correspondence(str(tmp_path))["cases"]) == 7


# ---------------------------------------------------------------------------
# through the command line, with the smallest data folder make_benchmarks.py accepts

STAGE_RESULT = {key: 0.5 for key, _, _ in mb.STAGES if key not in ("solve_frame_ms", "verify_frame_ms")}


def write_data(folder, correspondence):
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
    if correspondence is not None:
        (folder / "correspondence.json").write_text(json.dumps(correspondence))


def run_make_benchmarks(data, out, plots):
    return subprocess.run(["/usr/bin/python3", str(REPO / "bench" / "make_benchmarks.py"), "--data", str(data),
                           "--output", str(out), "--plots", str(plots)],
                          capture_output=True, text=True, timeout=TIMEOUT_SECONDS)


@pytest.mark.skipif(not pathlib.Path("/usr/bin/python3").exists(), reason="needs Debian's python3 (matplotlib)")
def test_make_benchmarks_writes_the_correspondence_section(tmp_path):
    write_data(tmp_path / "data", tiny_correspondence())
    (tmp_path / "with").mkdir()
    r = run_make_benchmarks(tmp_path / "data", tmp_path / "with" / "BENCHMARKS.md", tmp_path / "with" / "plots")
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "with" / "BENCHMARKS.md").read_text()
    assert "\n## Correspondence\n" in text and "| wheel | 1000 | 1 000 | 1 333 | 1 999 | 334 |" in text
    # after the other sections, which stay as they were
    assert text.index("\n## Motion quality\n") < text.index("\n## Correspondence\n")
    assert (tmp_path / "with" / "plots" / "correspondence.svg").exists()
    # without correspondence.json the rest of the report is written, and says so
    write_data(tmp_path / "data2", None)
    (tmp_path / "without").mkdir()
    r = run_make_benchmarks(tmp_path / "data2", tmp_path / "without" / "BENCHMARKS.md",
                            tmp_path / "without" / "plots")
    assert r.returncode == 0, r.stderr
    without = (tmp_path / "without" / "BENCHMARKS.md").read_text()
    assert "## Correspondence\n\nNot measured in this run" in without
    assert not (tmp_path / "without" / "plots" / "correspondence.svg").exists()
    # and everything before the section is the same with and without it
    assert without.split("\n## Correspondence\n")[0] == text.split("\n## Correspondence\n")[0]
    # a broken correspondence.json is an incomplete run
    (tmp_path / "data2" / "correspondence.json").write_text("{")
    r = run_make_benchmarks(tmp_path / "data2", tmp_path / "B3.md", tmp_path / "plots3")
    assert r.returncode == 2 and "correspondence.json" in r.stderr
