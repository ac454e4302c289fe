"""bench/sequence_motion.py's measures of a motion through key poses (issue 28), and
bench/key_pose_corpus.py's sequences: the numbers the sequence morph will be judged by must
themselves be right, on motions whose answer is known."""
import json

import numpy as np

from conftest import load_script

sm = load_script("sequence_motion")
kpc = load_script("key_pose_corpus")

# A single edge: two vertices one apart.
EDGES = [(0, 1)]


def translated(offsets):
    """The unit edge moved by each offset: one frame per offset (N x 2 x 2)."""
    base = np.array([[0.0, 0.0], [1.0, 0.0]])
    return np.array([base + np.asarray(o, dtype=float) for o in offsets])


def test_default_key_frames_follow_the_format():
    assert sm.key_frames(3, 99) == [0, 49, 98]
    assert sm.key_frames(4, 148) == [0, 49, 98, 147]
    assert sm.key_frames(2, 50) == [0, 49]


def test_a_straight_even_motion_has_no_jump_and_does_not_stop():
    frames = translated([(f / 10, 0) for f in range(21)])
    keys_at = [0, 10, 20]
    keys = [frames[f] for f in keys_at]
    m = sm.measure(frames, keys, EDGES, keys_at)
    assert m["key_error"] == 0
    assert m["jump_median"] < 1e-12
    assert m["pass_keys"] == 1 and abs(m["pass_speed_min"] - 1) < 1e-12
    assert m["invalid_frames"] == []
    assert m["edge_dev_median"] < 1e-12


def test_a_turn_at_a_key_is_a_jump_and_a_smooth_curve_is_not():
    # Right, then up: at the key the velocity turns 90 degrees at the same speed, so
    # |v+ - v-| is sqrt 2 times the (constant) step.
    corner = translated([(f / 10, 0) for f in range(11)] + [(1, f / 10) for f in range(1, 11)])
    keys_at = [0, 10, 20]
    m = sm.measure(corner, [corner[f] for f in keys_at], EDGES, keys_at)
    assert abs(m["jump_median"] - np.sqrt(2)) < 1e-9
    # The same keys on a parabola through them (C1): a jump of second order only.
    t = np.linspace(0, 1, 21)
    curve = translated([(s, s * s) for s in t])
    m = sm.measure(curve, [curve[f] for f in keys_at], EDGES, keys_at)
    assert m["jump_median"] < 0.15


def test_a_reversal_is_a_jump_of_two_steps_and_not_a_pass():
    back = translated([(f / 10, 0) for f in range(11)] + [(1 - f / 10, 0) for f in range(1, 11)])
    keys_at = [0, 10, 20]
    m = sm.measure(back, [back[0], back[10], back[20] + [0, 0.5]], EDGES, keys_at)
    assert abs(m["jump_median"] - 2) < 1e-9
    assert m["pass_keys"] == 0 and m["pass_speed_min"] is None


def test_a_missed_key_and_an_invalid_frame_are_reported():
    frames = translated([(f / 10, 0) for f in range(11)])
    keys = [frames[0], frames[10] + [0, 0.25]]
    m = sm.measure(frames, keys, EDGES, [0, 10])
    assert abs(m["key_error"] - 0.25 / 2) < 1e-12  # size: the keys' bounding box, 2 wide
    # Two edges whose frame 1 crosses: the checker (exact, independent) finds it.
    cross = np.array([[[0, 0], [2, 0], [0, 1], [2, 1]], [[0, 0], [2, 0], [0, 1], [2, -1]],
                      [[0, 0], [2, 0], [0, 1], [2, 1]]], dtype=float)
    m = sm.measure(cross, [cross[0], cross[2]], [(0, 1), (2, 3)], [0, 2])
    assert m["invalid_frames"] == [1]


def test_chained_pairs_hit_their_keys_exactly(cli, tmp_path):
    """The baseline through the CLI: a chained morph of a generated sequence is valid and
    shows every key at its frame, bit for bit."""
    assert kpc.main([str(tmp_path), "--build-dir", str(cli.parent), "--per-kind", "1"]) == 0
    manifest = json.loads((tmp_path / "manifest.json").read_text())
    assert {e["kind"] for e in manifest} == {"cycle", "poses", "glyph"}
    entry = next(e for e in manifest if e["kind"] == "glyph")
    paths = [tmp_path / f for f in entry["keys"]]
    keys = [sm.mq.read_figure(p)[0] for p in paths]
    edges = sm.mq.read_figure(paths[0])[1]
    keys_at = sm.key_frames(len(keys), 13 * (len(keys) - 1) + 1)
    frames = sm.chained(cli, paths, keys_at, [], tmp_path)
    assert len(frames) == keys_at[-1] + 1
    m = sm.measure(frames, keys, edges, keys_at)
    assert m["key_error"] == 0 and m["invalid_frames"] == []


def test_loop_mode_measures_the_seam_and_the_closing_frame(cli, tmp_path):
    """--mode loop (asked for only): `morph KEYS --loop` measured with key 1 again at the last
    frame; the seam's jump and the last frame are reported, and stay within issue 28's bounds."""
    corpus = tmp_path / "corpus"
    assert kpc.main([str(corpus), "--build-dir", str(cli.parent), "--per-kind", "1"]) == 0
    out = tmp_path / "loop.json"
    assert sm.main([str(corpus), "--build-dir", str(cli.parent), "--mode", "loop", "--json", str(out)]) == 0
    rows = json.loads(out.read_text())
    assert rows and all(r["mode"] == "loop" and "error" not in r for r in rows)
    for r in rows:
        assert r["last_is_key_1"] and r["invalid_frames"] == [] and r["key_error"] == 0, r["name"]
        assert r["keys_at"][-1] == r["frames"] - 1 and len(r["keys_at"]) == r["keys"] + 1
        assert r["seam_jump"] <= 0.25, r["name"]
