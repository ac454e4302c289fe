"""Tests of the "Blender at scale" section that bench/make_benchmarks.py writes into BENCHMARKS.md
from bench/blender_bake.py's blender.json (issue 29): on hand-made rows whose numbers are known.
Needs only Debian's python3, no build and no Blender."""
import json

import pytest

from conftest import load_script

mb = load_script("make_benchmarks")


def row(shape, n, cli, bake, fps, visible=True, peak=900.0):
    r = {"shape": shape, "n": n, "frames": 250, "playback_frames": 250, "blender": "3.4.1", "cli_s": cli,
         "bake_s": bake, "bake_over_cli": bake / cli, "engine_s": 0.7 * bake, "blender_side_s": 0.3 * bake,
         "playback_fps_tubes": fps, "playback_fps_plain": 1500.0, "blend_mib": 30.4, "peak_before_mib": 400.0,
         "peak_mib": peak, "cli_peak_mib": 330.0}
    if visible is not None:
        r.update(render_visible=visible, render_coverage=0.027 if visible else 0.0)
    return r


def without_cli(r):
    """A row above bench/blender_bake.py's --cli-max: the CLI did not run."""
    for key in ("cli_s", "cli_peak_mib"):
        del r[key]
    r["bake_over_cli"] = None
    return r


def rows():
    return [row("wavy", 1000, 0.4, 0.4, 390.0), row("wavy", 10000, 4.0, 5.0, 40.0),
            row("coral", 10000, 5.0, 6.5, 30.0),
            without_cli(row("wavy", 100000, 60.0, 80.0, 3.0, visible=None, peak=6000.0)),
            {"shape": "coral", "n": 100000, "frames": 250, "error": "Blender failed (-9):\nKilled"}]


def test_the_table_has_a_row_per_case_with_its_split_and_render():
    text = "\n".join(mb.blender_section(rows()))
    assert text.startswith("\n## Blender at scale\n") and "Blender 3.4.1" in text
    lines = text.splitlines()
    coral = next(line for line in lines if line.startswith("| coral | 10000 |"))
    # CLI 5 s, bake 6.5 s: 1.30; engine 70 %, Blender side 30 %; 30 fps; rendered.
    assert "| 5.00 | 6.50 | 1.30 | 4.55 | 1.95 | 30.0 | 1500 | visible (2.7 % of pixels) |" in coral
    large = next(line for line in lines if line.startswith("| wavy | 100000 |"))
    assert "| not rendered |" in large and "| 6000 |" in large
    assert large.startswith("| wavy | 100000 | 250 | – | 80.00 | – |") and large.endswith("| 6000 | – |")
    failed = next(line for line in lines if line.startswith("| coral | 100000 |"))
    assert "error: Killed" in failed


def test_the_headline_gives_the_worst_case_at_ten_thousand_vertices():
    line = mb.blender_headline(rows())
    assert "at most 1.30× the CLI" in line and "plays at 30 fps or more" in line
    assert "the largest bake, 100000 vertices, took 80 s and 6000 MiB" in line


def test_without_blender_json_the_section_is_a_note(tmp_path):
    text = "\n".join(mb.blender_section(None))
    assert "## Blender at scale" in text and "Not measured in this run" in text
    assert mb.read_blender(str(tmp_path)) is None
    (tmp_path / "blender.json").write_text(json.dumps([{"shape": "wavy", "n": 10, "frames": 5, "cli_s": 1.0}]))
    with pytest.raises(mb.InputError):
        mb.read_blender(str(tmp_path))
    (tmp_path / "blender.json").write_text(json.dumps(rows()))
    assert len(mb.read_blender(str(tmp_path))) == 5


def test_the_child_reads_the_operators_stage_times():
    bake = load_script("blender_bake")
    assert bake.stage_times("read 12 ms, engine 3100.5 ms, build 900 ms") == {
        "read": 12.0, "engine": 3100.5, "build": 900.0}
    assert bake.stage_times("") == {}
    with pytest.raises(ValueError):
        bake.stage_times("read 12 s")
