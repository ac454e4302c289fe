"""Tests of bench/motion_quality.py (issue 12's measuring instrument) and of the corpus
generator: the metric functions on hand-made frames whose answers are known, and one run
of both scripts through the CLI on tiny pairs.

Every subprocess has a timeout, so a hang fails the test instead of stalling the suite.
"""
import json
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

from conftest import load_script

REPO = pathlib.Path(__file__).resolve().parents[2]
TIMEOUT_SECONDS = 300


mq = load_script("motion_quality")

# an asymmetric little tree: a T with a longer tail, and a square with a spike (has a cycle)
TREE = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, -2.0], [1.0, 1.0]])
TREE_EDGES = [(0, 1), (1, 2), (1, 3), (1, 4)]
SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.8, 1.6]])
SQUARE_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (2, 4)]


def rotate(points, degrees, about=None):
    c = points.mean(axis=0) if about is None else np.asarray(about)
    a = math.radians(degrees)
    r = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    return (points - c) @ r.T + c


def frames_of(fn, count=30):
    times = np.linspace(0.0, 1.0, count)
    return np.array([fn(t) for t in times]), times


def test_rigid_rotation_has_no_deviation_and_turns_by_the_rotation():
    frames, times = frames_of(lambda t: rotate(TREE, 100 * t))
    m = mq.measure(frames, TREE_EDGES, times)
    assert m["edge_dev"] == pytest.approx(0, abs=1e-12)
    assert m["joint_dev_deg"] == pytest.approx(0, abs=1e-9)
    assert m["min_size"] == pytest.approx(1, abs=1e-12)
    assert m["unevenness"] == pytest.approx(1, abs=1e-9)
    assert m["turn_deg"] == pytest.approx(100, abs=1e-9)
    assert m["needed_deg"] == pytest.approx(100, abs=1e-9)
    assert m["beyond_deg"] == pytest.approx(0, abs=1e-9)


def test_clockwise_turn_is_negative():
    frames, _ = frames_of(lambda t: rotate(SQUARE, -70 * t))
    turn = mq.turning(frames)
    assert turn["net"] == pytest.approx(-70)
    assert turn["needed"] == pytest.approx(-70)
    assert turn["beyond"] == pytest.approx(0, abs=1e-9)


def test_long_way_turn_reports_the_extra_turning():
    # 240 degrees clockwise where 120 counter-clockwise reaches the same pose
    frames, _ = frames_of(lambda t: rotate(TREE, -240 * t), count=31)
    turn = mq.turning(frames)
    assert turn["needed"] == pytest.approx(120)
    assert turn["net"] == pytest.approx(-240)
    assert turn["beyond"] == pytest.approx(120)


def test_turn_there_and_back_counts_both_ways():
    frames, _ = frames_of(lambda t: rotate(TREE, 30 * math.sin(math.pi * t)), count=41)
    turn = mq.turning(frames)
    assert turn["needed"] == pytest.approx(0, abs=1e-9)
    assert turn["net"] == pytest.approx(0, abs=1e-9)
    assert turn["beyond"] == pytest.approx(60, abs=1e-6)


def test_self_turn_by_collapse_turns_less_than_by_rotation():
    # straight lines into the figure turned by 180 degrees pass the figure through its
    # centroid: the whole turn happens in one step; a rotation spreads it over every step
    n = 30
    collapse, times = frames_of(lambda t: (1 - 2 * t) * (TREE - TREE.mean(axis=0)), count=n)
    turn = mq.turning(collapse)
    assert abs(turn["net"]) == pytest.approx(180)
    assert max(abs(np.diff([0] + turn["track"]))) == pytest.approx(180)
    assert mq.min_size(collapse, times) < 0.05
    assert mq.speed_unevenness(collapse) == pytest.approx(1)  # straight lines at constant speed


def test_uniform_translation_has_unevenness_one_and_no_turn():
    frames, times = frames_of(lambda t: SQUARE + t * np.array([3.0, -1.0]))
    assert mq.speed_unevenness(frames) == pytest.approx(1)
    m = mq.measure(frames, SQUARE_EDGES, times)
    assert m["turn_deg"] == pytest.approx(0, abs=1e-12)
    assert m["edge_dev"] == pytest.approx(0, abs=1e-12)
    assert m["min_size"] == pytest.approx(1)


def test_eased_translation_unevenness_is_largest_over_mean_step():
    # steps 1, 2, 3, 2 (times 0, 1/4, ..., 1): mean 2, largest 3
    offsets = np.cumsum([0, 1, 2, 3, 2])
    frames = np.array([SQUARE + [d, 0.0] for d in offsets], dtype=float)
    assert mq.speed_unevenness(frames) == pytest.approx(1.5)


def test_shrink_then_grow_has_minimum_size_below_one():
    frames, times = frames_of(lambda t: TREE.mean(axis=0) + (1 - 0.5 * math.sin(math.pi * t)) *
                              (TREE - TREE.mean(axis=0)), count=3)
    assert mq.min_size(frames, times) == pytest.approx(0.5)
    # scaling every edge by 1/2 at t = 1/2 where linear-in-length says 1: deviation 1/2
    assert mq.edge_length_deviation(frames, TREE_EDGES, times) == pytest.approx(0.5)


def test_uniform_growth_is_not_shrinking():
    frames, times = frames_of(lambda t: (1 + 2 * t) * TREE)
    assert mq.min_size(frames, times) == pytest.approx(1)
    assert mq.edge_length_deviation(frames, TREE_EDGES, times) == pytest.approx(0, abs=1e-12)


def test_edge_length_deviation_is_relative_to_the_longer_end():
    # one edge: length 1 at both ends, 1.5 in the middle frame -> |1.5 - 1| / 1
    a = np.array([[0.0, 0.0], [1.0, 0.0]])
    frames = np.array([a, [[0.0, 0.0], [1.5, 0.0]], a])
    assert mq.edge_length_deviation(frames, [(0, 1)], [0.0, 0.5, 1.0]) == pytest.approx(0.5)
    # length 1 -> 3 with 1.5 at t = 1/2: linear says 2, so |1.5 - 2| / 3
    frames = np.array([a, [[0.0, 0.0], [1.5, 0.0]], [[0.0, 0.0], [3.0, 0.0]]])
    assert mq.edge_length_deviation(frames, [(0, 1)], [0.0, 0.5, 1.0]) == pytest.approx(0.5 / 3)


def test_joint_angle_deviation_of_a_known_bend():
    # an L whose corner is 90 degrees at both ends and 120 degrees in the middle frame:
    # both angles at the corner (inside and outside) are 30 degrees off
    def corner(deg):
        a = math.radians(deg)
        return np.array([[1.0, 0.0], [0.0, 0.0], [math.cos(a), math.sin(a)]])
    frames = np.array([corner(90), corner(120), corner(90)])
    assert mq.joint_angle_deviation(frames, [(0, 1), (1, 2)], [0.0, 0.5, 1.0]) == pytest.approx(30)
    # opening from 90 to 150 linearly: no deviation, though the edge turns by 60 degrees
    frames, times = frames_of(lambda t: corner(90 + 60 * t))
    assert mq.joint_angle_deviation(frames, [(0, 1), (1, 2)], times) == pytest.approx(0, abs=1e-9)


def test_joint_angles_follow_the_rotation_order():
    joints = mq.joint_angles(TREE, TREE_EDGES)
    # vertex 1 has degree 4: four consecutive pairs; all others are leaves
    assert len(joints) == 4 and set(joints[:, 0]) == {1}
    angles = mq._ccw_angle(TREE[None], joints)[0]
    assert sorted(np.degrees(angles).round(6)) == [90, 90, 90, 90]
    assert np.degrees(angles).sum() == pytest.approx(360)


def test_procrustes_angle_ignores_scale_and_translation():
    moved = 2.5 * rotate(SQUARE, 37) + [10.0, -4.0]
    assert math.degrees(mq.procrustes_angle(SQUARE, moved)) == pytest.approx(37)


def test_arap_of_a_similarity_is_the_similarity():
    target = 1.5 * rotate(TREE, 65) + [2.0, -1.0]
    times = np.linspace(0, 1, 11)
    frames = mq.arap_frames(TREE, target, TREE_EDGES, times)
    assert np.array_equal(frames[0], TREE) and np.array_equal(frames[-1], target)
    for t, f in zip(times, frames):
        c = (1 - t) * TREE.mean(axis=0) + t * target.mean(axis=0)
        expected = (1 + 0.5 * t) * rotate(TREE - TREE.mean(axis=0), 65 * t, about=(0, 0)) + c
        assert np.allclose(f, expected, atol=1e-12)
    m = mq.measure(frames, TREE_EDGES, times)
    assert m["edge_dev"] == pytest.approx(0, abs=1e-12) and m["turn_deg"] == pytest.approx(65)


def test_arap_turns_a_180_degree_self_turn_rigidly_one_way():
    # every edge alone could turn +180 or -180; taken relative to the figure's rotation they
    # all turn the same way, so the figure stays rigid
    target = rotate(SQUARE, 180)
    times = np.linspace(0, 1, 30)
    frames = mq.arap_frames(SQUARE, target, SQUARE_EDGES, times)
    m = mq.measure(frames, SQUARE_EDGES, times)
    assert abs(m["turn_deg"]) == pytest.approx(180)
    assert m["edge_dev"] == pytest.approx(0, abs=1e-12)
    assert m["min_size"] == pytest.approx(1)
    assert m["unevenness"] == pytest.approx(1)


def test_arap_on_a_cycle_is_a_least_squares_fit():
    # the square's top edge shrinks while its sides keep their length: the interpolated edge
    # vectors do not close up, so the fit is between them, and the centroid moves linearly
    target = SQUARE.copy()
    target[2] = [0.8, 1.0]
    target[3] = [0.2, 1.0]
    target[4] = [1.6, 1.6]
    times = np.linspace(0, 1, 5)
    frames = mq.arap_frames(SQUARE, target, SQUARE_EDGES, times)
    for t, f in zip(times, frames):
        assert np.allclose(f.mean(axis=0), (1 - t) * SQUARE.mean(axis=0) + t * target.mean(axis=0))
    assert np.all(np.isfinite(frames))


# ---------------------------------------------------------------------------
# through the CLI

def write_pair(folder, name, src, tgt, edges):
    for suffix, pts in (("source", src), ("target", tgt)):
        mq.write_figure(folder / f"{name}.{suffix}.json", pts, edges, name=f"{name} {suffix}")


def test_bad_frames_come_from_the_engine(cli, tmp_path):
    src = tmp_path / "src.json"
    mq.write_figure(src, SQUARE, SQUARE_EDGES)
    inside = SQUARE.copy()
    inside[4] = [0.2, 0.3]  # the spike folds into the square: a valid figure, but another edge order at 2
    crossing = SQUARE.copy()
    crossing[4] = [0.5, -0.5]  # the spike 2-4 crosses edge 0-1: not a figure at all
    frames = np.array([SQUARE, inside, crossing, rotate(SQUARE, 10), SQUARE])
    assert mq.bad_frames(cli, src, frames, SQUARE_EDGES, tmp_path) == [1, 2]


def test_end_to_end_on_two_tiny_pairs(cli, tmp_path):
    corpus = tmp_path / "corpus"
    corpus.mkdir()
    # the paper's S into U: straight lines self-intersect (Figure 8d), ours must not
    paper = REPO / "tests" / "data" / "paper"
    for suffix in ("source", "target"):
        (corpus / f"s_to_u.{suffix}.json").write_text((paper / f"s_to_u.{suffix}.json").read_text())
    # a figure into itself turned by 180 degrees, tagged as such by its name
    write_pair(corpus, "tree_self_turn_180", TREE, rotate(TREE, 180), TREE_EDGES)
    out_json = tmp_path / "quality.json"
    r = subprocess.run([sys.executable, str(REPO / "bench" / "motion_quality.py"), str(corpus),
                        "--build-dir", str(cli.parent), "--frames", "12", "--weights", "mvc,uniform",
                        "--json", str(out_json), "--filmstrip", str(tmp_path / "strips")],
                       capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    assert r.returncode == 0, r.stderr
    doc = json.loads(out_json.read_text())
    assert doc["methods"] == ["ours[mvc]", "ours[uniform]", "linear", "arap"]
    s_to_u = doc["pairs"]["s_to_u"]
    assert s_to_u["ours[mvc]"]["bad_frames"] == []
    assert s_to_u["ours[uniform]"]["bad_frames"] == []
    # the engine's own list of invalid straight-line frames and the per-frame check agree
    assert s_to_u["linear"]["bad_frames"] and s_to_u["linear"]["bad_frames"] == \
        [k for k in s_to_u["linear"]["engine_invalid_frames"] if 0 < k < 11]
    turn = doc["pairs"]["tree_self_turn_180"]
    assert turn["arap"]["edge_dev"] == pytest.approx(0, abs=1e-12)
    assert abs(turn["arap"]["turn_deg"]) == pytest.approx(180)
    # straight lines into the turned copy shrink it through its centroid
    assert turn["linear"]["min_size"] < 0.2
    targets = {t["target"].split(":")[0]: t for t in doc["targets"]}
    assert targets["180° self-turn"]["arap"]["pass"] is True
    assert targets["180° self-turn"]["linear"]["pass"] is False
    assert "| s_to_u | 12 | ours[mvc] |" in r.stdout
    assert "| target | ours[mvc] | ours[uniform] | linear | arap |" in r.stdout
    assert sorted(p.suffix for p in (tmp_path / "strips").iterdir()) == [".svg"] * 10


def test_ours_args_are_passed_through(cli, tmp_path):
    corpus = tmp_path / "corpus"
    corpus.mkdir()
    write_pair(corpus, "square", SQUARE, rotate(SQUARE, 40) * 1.2, SQUARE_EDGES)
    out_json = tmp_path / "q.json"
    r = subprocess.run([sys.executable, str(REPO / "bench" / "motion_quality.py"), str(corpus),
                        "--build-dir", str(cli.parent), "--frames", "5", "--methods", "ours",
                        "--ours-args", "--weights floater --enclosure-sides 3", "--json", str(out_json)],
                       capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    assert r.returncode == 0, r.stderr
    assert json.loads(out_json.read_text())["methods"] == ["ours"]
    # an option the CLI refuses reaches it and fails that morph, reported per pair
    r = subprocess.run([sys.executable, str(REPO / "bench" / "motion_quality.py"), str(corpus),
                        "--build-dir", str(cli.parent), "--frames", "5", "--methods", "ours",
                        "--ours-args", "--motion nonsense", "--json", str(out_json)],
                       capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    assert r.returncode == 0, r.stderr
    row = json.loads(out_json.read_text())["pairs"]["square"]["ours[mvc]"]
    assert "--motion" in row["error"]


def test_corpus_pairs_are_compatible_and_deterministic(cli, tmp_path):
    args = [sys.executable, str(REPO / "bench" / "motion_corpus.py"), "--build-dir", str(cli.parent)]
    for folder in ("a", "b"):
        r = subprocess.run(args + [str(tmp_path / folder)], capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
        assert r.returncode == 0, r.stderr
    manifest = json.loads((tmp_path / "a" / "manifest.json").read_text())
    kinds = {p["kind"] for p in manifest["pairs"]}
    assert kinds == {"glyph", "skeleton", "polygon", "triangulation", "sample", "special"}
    assert len(manifest["pairs"]) >= 35
    for p in manifest["pairs"]:
        assert 10 <= p["vertices"] <= 200
        for suffix in ("source", "target"):
            assert (tmp_path / "a" / f"{p['name']}.{suffix}.json").read_bytes() == \
                (tmp_path / "b" / f"{p['name']}.{suffix}.json").read_bytes()
    # spot-check the promise that every written pair is compatible
    for p in manifest["pairs"][::7]:
        r = subprocess.run([str(cli), "check", str(tmp_path / "a" / f"{p['name']}.source.json"),
                            str(tmp_path / "a" / f"{p['name']}.target.json")],
                           capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
        assert r.returncode == 0, (p["name"], r.stdout)
    # skeleton bones keep their lengths (forward kinematics)
    sk = next(p for p in manifest["pairs"] if p["kind"] == "skeleton")
    src, edges = mq.read_figure(tmp_path / "a" / f"{sk['name']}.source.json")
    tgt, _ = mq.read_figure(tmp_path / "a" / f"{sk['name']}.target.json")
    lengths = mq.edge_lengths(np.array([src, tgt]), edges)
    ratio = lengths[1] / lengths[0]
    assert np.allclose(ratio, ratio[0])  # one scale for the whole skeleton


# ---------------------------------------------------------------------------
# several CLI variants in one run (--cli-method), cost per frame, filmstrips with rows

def _run_quality(corpus, cli, *args):
    return subprocess.run([sys.executable, str(REPO / "bench" / "motion_quality.py"), str(corpus),
                           "--build-dir", str(cli.parent)] + list(args),
                          capture_output=True, text=True, timeout=TIMEOUT_SECONDS)


def test_cli_method_parses_label_and_arguments():
    assert mq.cli_method("rigid=--method rigid") == ("rigid", ["--method", "rigid"])
    assert mq.cli_method("default=") == ("default", [])
    assert mq.cli_method("b=--weights 'uniform'") == ("b", ["--weights", "uniform"])
    for bad in ("rigid", "=--method rigid", "x=--weights 'open"):
        with pytest.raises(Exception):
            mq.cli_method(bad)


def test_straight_lines_are_recognised_by_their_options():
    assert mq.straight_lines(["--method", "linear"])
    assert mq.straight_lines(["--frames", "3", "--method=linear"])
    assert not mq.straight_lines(["--method", "barycentric"])
    assert not mq.straight_lines(["linear", "--method"])
    assert not mq.straight_lines(None)


def test_cli_methods_run_side_by_side_with_their_time_per_frame(cli, tmp_path):
    corpus = tmp_path / "corpus"
    corpus.mkdir()
    write_pair(corpus, "square", SQUARE, rotate(SQUARE, 40) * 1.2, SQUARE_EDGES)
    write_pair(corpus, "tree_self_turn_180", TREE, rotate(TREE, 180), TREE_EDGES)
    out_json = tmp_path / "q.json"
    strips = tmp_path / "strips"
    (strips).mkdir()
    (strips / "strip_stale.svg").write_text("<svg/>")  # an earlier run's file: removed
    r = _run_quality(corpus, cli, "--frames", "6", "--cli-method", "plain=", "--cli-method", "uni=--weights uniform",
                     "--json", str(out_json), "--filmstrip", str(strips), "--filmstrip-method", "uni",
                     "--filmstrip-rows", "uni,plain,arap", "--filmstrip-worst", "1",
                     "--filmstrip-pairs", "square", "--note", "a note")
    assert r.returncode == 0, r.stderr
    doc = json.loads(out_json.read_text())
    # with --cli-method, the default families are the references only: no ours[...] rows
    assert doc["methods"] == ["plain", "uni", "linear", "arap"]
    assert doc["cli_methods"] == {"plain": "", "uni": "--weights uniform", "linear": "--method linear", "arap": None}
    assert doc["notes"] == ["a note"]
    assert doc["thresholds"]["edge_dev_median"] == 0.02
    square = doc["pairs"]["square"]
    assert square["plain"]["engine_weights"] == "mvc" and square["uni"]["engine_weights"] == "uniform"
    assert square["linear"]["engine_method"] == "linear"
    assert "engine_invalid_frames" in square["linear"]  # recognised as straight lines by its options
    assert "engine_invalid_frames" not in square["plain"]
    for m in ("plain", "uni", "linear"):
        row = square[m]
        assert row["ms_per_frame"] == pytest.approx(row["morph_ms"] / 6)
        assert doc["summary"][m]["ms_per_frame"]["median"] >= 0
    assert "ms_per_frame" not in square["arap"] and "ms_per_frame" not in doc["summary"]["arap"]
    assert doc["pairs"]["tree_self_turn_180"]["tags"] == {}
    assert [t["key"] for t in doc["targets"]] == ["edge_dev", "joint_dev", "min_size", "unevenness", "beyond",
                                                  "self_turn", "invalid_frames"]
    assert "| target | plain | uni | linear | arap |" in r.stdout
    assert "Note: a note" in r.stdout
    # one file per pair, however many metrics it is the worst in; the stale file is gone
    files = sorted(p.name for p in strips.iterdir())
    assert files == ["strip_square.svg", "strip_tree_self_turn_180.svg"]
    listed = {s["pair"]: s for s in doc["filmstrips"]}
    assert set(listed) == {"square", "tree_self_turn_180"}
    worst = [w["metric"] for s in listed.values() for w in s["worst"]]
    assert sorted(worst) == sorted(k for k, _ in mq.WORST_KEYS)  # each metric's worst pair once
    assert all(s["rows"] == ["uni", "plain", "arap"] and s["method"] == "uni" for s in listed.values())
    svg = (strips / "strip_tree_self_turn_180.svg").read_text()
    assert svg.startswith("<svg") and svg.count("<path ") == 3 * 7
    assert ">uni</text>" in svg and ">plain</text>" in svg and ">arap</text>" in svg
    assert len(svg) < 200_000


def test_cli_method_mistakes_are_refused(cli, tmp_path):
    corpus = tmp_path / "corpus"
    corpus.mkdir()
    write_pair(corpus, "square", SQUARE, rotate(SQUARE, 40), SQUARE_EDGES)
    for args, message in ((["--cli-method", "a=", "--cli-method", "a=--weights uniform"], "two methods"),
                          (["--cli-method", "linear=--method linear"], "two methods"),
                          (["--cli-method", "kind="], "cannot label"),
                          (["--cli-method", "a=", "--filmstrip", str(tmp_path / "s"), "--filmstrip-rows", "a,b"],
                           "--filmstrip-rows"),
                          (["--methods", "ours,rigid"], "not one of"),
                          (["--cli-method", "rigid"], "LABEL=ARGS")):
        r = _run_quality(corpus, cli, "--frames", "4", *args)
        assert r.returncode != 0, args
        assert message in r.stderr, (args, r.stderr)


def test_filmstrip_rows_mark_invalid_frames_and_failed_methods(tmp_path):
    frames = np.array([SQUARE, rotate(SQUARE, 10), rotate(SQUARE, 20)])
    path = tmp_path / "strip.svg"
    mq.svg_filmstrip_rows(path, [("good", "caption <1>", frames, set()), ("bad", "c", frames, {1}),
                                 ("failed", "failed: refused", None, None)], SQUARE_EDGES, "title & more", count=3)
    svg = path.read_text()
    assert svg.count("<path ") == 6  # two rows of three frames; the failed row draws none
    assert svg.count("stroke-dasharray") == 1 and "frame 1 invalid" in svg
    assert "caption &lt;1&gt;" in svg and "title &amp; more" in svg and "failed: refused" in svg
