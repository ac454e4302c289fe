"""Tests of the "Local timing" section that bench/make_benchmarks.py appends to BENCHMARKS.md from
bench/local_timing.py's local_timing.json (issue 31), on hand-made rows whose numbers are known,
and of the measurement itself (bench/local_timing.py) on synthetic frames whose lag is known.
Needs only Debian's python3 with numpy and matplotlib, no build."""
import json
import math

import numpy as np
import pytest

from conftest import load_script

mb = load_script("make_benchmarks")
lt = load_script("local_timing")


# ---------------------------------------------------------------------------
# the measurement on synthetic frames

def arm_frames(times, body_turn, limb_turn, limb_delay):
    """A bent arm: the body, edges 0-1 and 1-2, turns by body_turn degrees about vertex 0 at
    constant speed; the limb, edges 2-3, 3-4 and 4-5, turns by limb_turn degrees about vertex 2 at
    time (t - limb_delay) / (1 - limb_delay) (the body at t / (1 - limb_delay))."""
    frames = []
    for t in times:
        tb = min(1.0, t / (1 - limb_delay)) if limb_delay else t
        tl = min(1.0, max(0.0, (t - limb_delay) / (1 - limb_delay))) if limb_delay else t
        a = math.radians(90 + body_turn * tb)
        b = math.radians(60 + body_turn * tb)
        p0 = np.array([0.0, 0.0])
        p1 = p0 + np.array([math.cos(a), math.sin(a)])
        p2 = p1 + np.array([math.cos(b), math.sin(b)])
        c = math.radians(-30 + body_turn * tl + limb_turn * tl)
        points = [p0, p1, p2]
        for _ in range(3):
            points.append(points[-1] + 0.5 * np.array([math.cos(c), math.sin(c)]))
        frames.append(points)
    return np.array(frames)


EDGES = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5)]
LIMB = [2, 3, 4]


@pytest.mark.parametrize("d", [0.0, 0.3, 0.5])
def test_the_lag_of_a_limb_delayed_by_d_is_d(d):
    times = np.linspace(0, 1, 61)
    result = lt.lag(arm_frames(times, 30.0, 120.0, d), times, EDGES, LIMB)
    assert result["limb_edges_measured"] == 3 and result["other_edges_measured"] == 2
    assert result["lag"] == pytest.approx(d, abs=1e-9)
    assert result["other_half"] == pytest.approx(0.5 * (1 - d), abs=1e-9)


def test_half_times_interpolate_between_frames_and_skip_small_turns():
    times = np.linspace(0, 1, 5)  # coarse: the half of the turn falls between frames
    frames = arm_frames(times, 3.0, 100.0, 0.0)
    total, half = lt.half_times(frames, times, EDGES)
    assert total[0] == pytest.approx(3.0) and math.isnan(half[0]) and math.isnan(half[1])  # under 5 degrees
    assert total[2] == pytest.approx(103.0)
    assert half[2] == pytest.approx(0.5)
    result = lt.lag(frames, times, EDGES, LIMB)
    assert result["lag"] is None and result["other_edges_measured"] == 0


def test_turns_are_unwrapped_through_the_half_turn():
    times = np.linspace(0, 1, 41)
    frames = arm_frames(times, 40.0, -200.0, 0.0)  # the limb passes through 180 degrees
    total, half = lt.half_times(frames, times, EDGES)
    assert total[3] == pytest.approx(-160.0)
    assert half[3] == pytest.approx(0.5)


def test_the_reference_delayed_motion_lags_by_d_and_keeps_the_plain_ends():
    times = np.linspace(0, 1, 61)
    plain = arm_frames(times, 30.0, 120.0, 0.0)
    weights = np.zeros(6)
    weights[[3, 4, 5]] = 1.0
    reference = lt.reference_delayed(plain, times, EDGES, weights, 0.5)
    assert np.allclose(reference[0], plain[0]) and np.allclose(reference[-1], plain[-1])
    # the junction's edge (2-3) moves at the mean local time, so it lags by d/2: the median of
    # the three limb edges still lags by d
    assert lt.lag(reference, times, EDGES, LIMB)["lag"] == pytest.approx(0.5, abs=1e-6)


# ---------------------------------------------------------------------------
# the report section

def summary_row(d, lags, bad=0, failed=0, same=None, misses=()):
    errors = [abs(x - d) for x in lags]
    s = {"overlap": d, "pairs": len(lags) + failed, "failed": failed, "measured": len(lags), "failures": [],
         "lag_median": float(np.median(lags)), "lag_p10": float(np.percentile(lags, 10)),
         "lag_p90": float(np.percentile(lags, 90)), "abs_error_median": float(np.median(errors)),
         "abs_error_max": max(errors), "within": sum(1 for e in errors if e <= 0.1), "bad_frames": bad,
         "pairs_with_bad_frames": 1 if bad else 0, "frames_checked": len(lags), "first_last_exact": len(lags),
         "misses": list(misses)}
    if same is not None:
        s.update(same_as_plain=same, compared_with_plain=len(lags), clear_pairs=len(lags),
                 clear_within=s["within"])
    if d > 0:
        s.update(reference_measured=len(lags), reference_lag_median=d, reference_within=len(lags),
                 reference_bad_frames=0, reference_pairs_with_bad_frames=0)
    return s


def pair(name, kind, lags, strip=False):
    runs = {label: {"lag": lag, "first_exact": True, "last_exact": True, "bad_frames": []}
            for label, lag in lags.items()}
    p = {"name": name, "kind": kind, "vertices": 6, "edges": 5, "limb": "arm", "turn_deg": 120.0, "runs": runs,
         "delayed_clear": {}}
    if strip:
        times = np.linspace(0, 1, 9)
        rows = {label: arm_frames(times, 30.0, 120.0, float(label) if label != "plain" else 0.0).tolist()
                for label in lags}
        p["filmstrip"] = {"edges": [list(e) for e in EDGES], "limb_edges": LIMB, "frames": 9,
                          "frame_indices": list(range(9)), "rows": rows,
                          "progress": {label: {"limb": [k / 8 for k in range(9)], "other": [k / 8 for k in range(9)]}
                                       for label in lags}}
    return p


def document():
    lags_a = {"plain": 0.0, "0": 0.0, "0.3": 0.30, "0.5": 0.50}
    lags_b = {"plain": 0.0, "0": 0.0, "0.3": 0.28, "0.5": 0.21}
    miss = {"name": "tree_1", "lag": 0.21, "limb": "branch2", "reference_lag": 0.5, "reference_valid": True}
    return {"seed": 31, "frames": 61, "overlaps": [0.3, 0.5], "tolerance": 0.1, "min_turn_deg": 5.0,
            "timing_in_help": True,
            "summary": {"plain": summary_row(0.0, [0.0, 0.0]), "0": summary_row(0.0, [0.0, 0.0], same=2),
                        "0.3": summary_row(0.3, [0.30, 0.28], same=0),
                        "0.5": summary_row(0.5, [0.50, 0.21], same=0, misses=[miss])},
            "pairs": [pair("humanoid_1", "humanoid", lags_a, strip=True), pair("tree_1", "tree", lags_b)]}


def test_the_table_has_one_row_per_overlap_with_its_lag_and_checks(tmp_path):
    text = "\n".join(mb.local_timing_section(document(), str(tmp_path / "B.md"), str(tmp_path / "plots")))
    assert text.startswith("\n## Local timing\n")
    lines = text.splitlines()
    half = next(line for line in lines if line.startswith("| 0.5 |"))
    # 2 of 2 measured, median 0.355, |lag - d| max 0.290, 1 of 2 within 0.1, no invalid frame
    assert "| 2/2 | 0.355 |" in half and "| 0.290 | 1/2 | 0 (0 pairs) | 2/2 |" in half
    zero = next(line for line in lines if line.startswith("| 0 |"))
    assert zero.endswith("| 2/2 |")  # d = 0 bit for bit the plain morph on both pairs
    plain = next(line for line in lines if line.startswith("| none (no `--timing`) |"))
    assert "| 0.000 |" in plain and "-0.000" not in plain
    assert "tree_1 (limb branch2, d = 0.5: lag 0.210; the reference valid)" in text
    assert "| tree | 1 | 6–6 |" in text
    assert (tmp_path / "plots" / "local_timing_lag.svg").exists()
    assert (tmp_path / "plots" / "local_timing_filmstrip_1.svg").exists()
    assert "(plots/local_timing_filmstrip_1.svg)" in text and "(plots/local_timing_lag.svg)" in text


def test_without_local_timing_json_the_section_is_a_note(tmp_path):
    text = "\n".join(mb.local_timing_section(None, str(tmp_path / "B.md"), str(tmp_path / "plots")))
    assert "## Local timing" in text and "Not measured in this run" in text
    assert not (tmp_path / "plots").exists()
    assert mb.read_local_timing(str(tmp_path)) is None
    (tmp_path / "local_timing.json").write_text(json.dumps({"pairs": []}))
    with pytest.raises(mb.InputError):
        mb.read_local_timing(str(tmp_path))
    (tmp_path / "local_timing.json").write_text(json.dumps(document()))
    assert len(mb.read_local_timing(str(tmp_path))["pairs"]) == 2


def test_make_benchmarks_appends_the_section_after_the_others(tmp_path):
    out = tmp_path / "B.md"
    out.write_text("# Benchmarks\n\n## Key poses\n\ntext\n")
    mb.append_sections(str(out), mb.local_timing_section(None, str(out), str(tmp_path / "plots")))
    text = out.read_text()
    assert text.index("## Key poses") < text.index("## Local timing") and text.endswith(".\n")
