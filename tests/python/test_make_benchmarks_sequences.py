"""Tests of the "Key poses" section that bench/make_benchmarks.py writes into BENCHMARKS.md from
bench/sequence_motion.py's sequences.json (issue 28): on hand-made rows whose numbers are known.
Needs only Debian's python3 with matplotlib, no build."""
import json

import pytest

from conftest import load_script

mb = load_script("make_benchmarks")


def row(name, kind, mode, jump, invalid=(), strip=False):
    speeds = [1.0] * 8
    r = {"name": name, "kind": kind, "mode": mode, "keys": 3, "vertices": 4, "frames": 9,
         "invalid_frames": list(invalid), "key_error": 0.0, "jump_median": jump, "jumps": [jump],
         "pass_speed_min": 0.8, "pass_keys": 1, "edge_dev_median": 0.01, "keys_at": [0, 4, 8],
         "speeds": speeds, "velocity_changes": [0.02, 0.02, jump, 0.02, 0.02, 0.02, 0.02]}
    if strip:
        square = [[0, 0], [1, 0], [1, 1], [0, 1]]
        r["filmstrip"] = {"frames": [[[x + f, y] for x, y in square] for f in range(9)],
                          "edges": [[0, 1], [1, 2], [2, 3], [3, 0]]}
    return r


def rows():
    return [row("walk", "cycle", "sequence", 0.02, strip=True), row("walk", "cycle", "chained", 1.3),
            row("walk", "cycle", "linear", 1.4, invalid=[3, 4]), row("walk", "cycle", "matched", 0.03),
            row("a", "glyph", "sequence", 0.04), row("a", "glyph", "chained", 0.9),
            row("a", "glyph", "linear", 1.0), row("a", "glyph", "matched", 0.05)]


def test_the_table_has_one_group_per_motion_with_its_medians(tmp_path):
    text = "\n".join(mb.sequences_section(rows(), str(tmp_path / "B.md"), str(tmp_path / "plots")))
    assert text.startswith("\n## Key poses\n")
    lines = text.splitlines()
    sequence = next(line for line in lines if line.startswith("| sequence morph (`morph KEY1 ... KEYK`) | all |"))
    # 2 of 2 sequences, no invalid frame of 18, jump median of 0.02 and 0.04, max 0.04.
    assert "| 2/2 | 0 of 18 |" in sequence and "| 0.030 | 0.040 |" in sequence
    linear = next(line for line in lines if line.startswith("| straight lines key to key"))
    assert "| 2 of 18 |" in linear and "| 1.200 | 1.400 |" in linear
    assert (tmp_path / "plots" / "sequence_filmstrip.svg").exists()
    assert (tmp_path / "plots" / "sequence_velocity_change.svg").exists()
    assert "(plots/sequence_filmstrip.svg)" in text


def test_without_sequences_json_the_section_is_a_note(tmp_path):
    text = "\n".join(mb.sequences_section(None, str(tmp_path / "B.md"), str(tmp_path / "plots")))
    assert "## Key poses" in text and "Not measured in this run" in text
    assert mb.read_sequences(str(tmp_path)) is None
    (tmp_path / "sequences.json").write_text(json.dumps([{"name": "x"}]))
    with pytest.raises(mb.InputError):
        mb.read_sequences(str(tmp_path))
    (tmp_path / "sequences.json").write_text(json.dumps(rows()))
    assert len(mb.read_sequences(str(tmp_path))) == 8


def test_the_headline_line_gives_the_jumps_of_the_three_motions():
    line = mb.sequences_headline(rows())
    assert "median 0.030" in line and "chained pair morphs 1.100" in line and "straight lines 1.200" in line
    assert "0 invalid frames of 18" in line
