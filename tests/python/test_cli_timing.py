"""`stickmorph morph --timing FILE.json` (docs/FORMAT.md, "Local timing"; issue 31).

The pair tests/data/timing/waving.*: a stick figure whose body bends while its
right forearm (vertices 11 and 12, from the elbow 10) turns up by 100 degrees;
waving.forearm_lags.json weights the forearm 1, the rest 0, overlap 0.5.
"""
import json
import math
import subprocess

import numpy as np
import pytest

TIMEOUT_SECONDS = 120
FOREARM = {11, 12}


def run(cli, *args):
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=TIMEOUT_SECONDS)


@pytest.fixture
def waving(data_dir):
    folder = data_dir / "timing"
    return folder / "waving.source.json", folder / "waving.target.json", folder / "waving.forearm_lags.json"


def morph(cli, tmp_path, source, target, *options, name="out.json"):
    out = tmp_path / name
    result = run(cli, "morph", source, target, "-o", out, "--frames", 61, *options)
    assert result.returncode == 0, result.stderr
    return json.loads(out.read_text())


def half_turn_times(document):
    """Per edge that turns at least 5 degrees: the time it has made half its turn."""
    frames, times = np.array(document["frames"]), np.array(document["times"])
    found = {}
    for a, b in document["edges"]:
        v = frames[:, b] - frames[:, a]
        angle = np.unwrap(np.arctan2(v[:, 1], v[:, 0]))
        turn = angle - angle[0]
        if abs(turn[-1]) < math.radians(5):
            continue
        share = turn / turn[-1]
        k = int(np.argmax(share >= 0.5))
        found[(a, b)] = times[k - 1] + (0.5 - share[k - 1]) / (share[k] - share[k - 1]) * (times[k] - times[k - 1])
    return found


@pytest.mark.parametrize("overlap", [0.3, 0.5])
def test_the_weighted_forearm_lags_by_the_overlap(cli, tmp_path, waving, overlap):
    source, target, timing = waving
    delay = json.loads(timing.read_text())["delay"]
    timing_file = tmp_path / "timing.json"
    timing_file.write_text(json.dumps({"delay": delay, "overlap": overlap}))
    document = morph(cli, tmp_path, source, target, "--timing", timing_file)
    times = half_turn_times(document)
    limb = [t for (a, b), t in times.items() if a in FOREARM and b in FOREARM]
    body = [t for (a, b), t in times.items() if a not in FOREARM and b not in FOREARM]
    assert limb and body
    assert np.median(limb) - np.median(body) == pytest.approx(overlap, abs=0.05)
    # The ends exact; the CLI verified every frame (exit 0).
    assert document["frames"][0] == json.loads(source.read_text())["vertices"]
    assert document["frames"][-1] == json.loads(target.read_text())["vertices"]


def test_a_neck_turning_far_ahead_of_its_first_joint_still_lags_by_the_overlap(cli, tmp_path, data_dir):
    """A quadruped's neck (vertices 4-6 from the junction 3) turns 121 degrees while
    the body bends 5: at d = 0.5 its first bone turns half way ahead of the rest, and
    the triangle of the neck's base, its first joint and the head inverts in the
    default triangulation; the timed morph tries other refinements and keeps the one
    that departs least from its guide."""
    folder = data_dir / "timing"
    source, target = folder / "quadruped_neck.source.json", folder / "quadruped_neck.target.json"
    document = morph(cli, tmp_path, source, target, "--timing", folder / "quadruped_neck.neck_lags.json")
    times = half_turn_times(document)
    neck = {4, 5, 6}
    limb = [t for (a, b), t in times.items() if a in neck or b in neck]
    body = [t for (a, b), t in times.items() if a not in neck and b not in neck]
    assert np.median(limb) - np.median(body) == pytest.approx(0.5, abs=0.1)
    # On the guide at 24 of the 59 interior frames at 87d353c; 13 with the
    # default triangulation alone, whose lag was -0.10.
    guide = document["stats"]["rigid"]["guide_frames"]
    assert guide["exact"] >= 20, guide


def test_overlap_zero_is_the_plain_morph_bit_for_bit(cli, tmp_path, waving):
    source, target, timing = waving
    zero = tmp_path / "zero.json"
    zero.write_text(json.dumps({"delay": json.loads(timing.read_text())["delay"], "overlap": 0}))
    plain = morph(cli, tmp_path, source, target, name="plain.json")
    timed = morph(cli, tmp_path, source, target, "--timing", zero, name="timed.json")
    assert timed["frames"] == plain["frames"]


def test_key_poses_take_the_timing_of_key_one(cli, tmp_path, waving):
    source, target, timing = waving
    out = tmp_path / "seq.json"
    result = run(cli, "morph", source, target, source, "-o", out, "--timing", timing)
    assert result.returncode == 0, result.stderr
    document = json.loads(out.read_text())
    for key, path in zip(document["keys"], (source, target, source)):
        assert document["frames"][key["frame"]] == json.loads(path.read_text())["vertices"]


BAD_FILES = {
    "weight_above_one": ('{"delay": [0,0,0,0,0,0,0,0,0,0,0,1.5,1], "overlap": 0.3}',
                         "delay[11] is 1.5, outside [0, 1]"),
    "weight_below_zero": ('{"delay": [0,0,0,-0.5,0,0,0,0,0,0,0,1,1], "overlap": 0.3}',
                          "delay[3] is -0.5, outside [0, 1]"),
    "overlap_one": ('{"delay": [0,0,0,0,0,0,0,0,0,0,0,1,1], "overlap": 1}', "overlap is 1, outside [0, 1)"),
    "overlap_negative": ('{"delay": [0,0,0,0,0,0,0,0,0,0,0,1,1], "overlap": -0.2}',
                         "overlap is -0.2, outside [0, 1)"),
    "too_short": ('{"delay": [0, 1], "overlap": 0.3}', "delay has 2 entries for 13 vertices of"),
    "too_long": ('{"delay": [0,0,0,0,0,0,0,0,0,0,0,1,1,1], "overlap": 0.3}', "delay has 14 entries for 13 vertices"),
    "weight_not_a_number": ('{"delay": [0,0,0,0,0,0,0,0,0,0,0,"1",1], "overlap": 0.3}',
                            "delay[11] must be a number, got a string"),
    "no_overlap": ('{"delay": [0,0,0,0,0,0,0,0,0,0,0,1,1]}', 'missing field "overlap"'),
    "no_delay": ('{"overlap": 0.3}', 'missing field "delay"'),
    "delay_not_a_list": ('{"delay": 1, "overlap": 0.3}', '"delay" must be an array of numbers'),
    "not_an_object": ("[0, 1]", "a timing file must hold a JSON object"),
    "not_json": ("{delay: [0]}", "timing.json"),
}


@pytest.mark.parametrize("name", sorted(BAD_FILES))
def test_a_bad_timing_file_is_exit_2_naming_the_entry(cli, tmp_path, waving, name):
    source, target, _ = waving
    text, expected = BAD_FILES[name]
    timing = tmp_path / "timing.json"
    timing.write_text(text)
    out = tmp_path / "out.json"
    result = run(cli, "morph", source, target, "-o", out, "--timing", timing)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    assert str(timing) in lines[0] and expected in lines[0], lines[0]
    assert not out.exists()


def test_timing_is_refused_with_another_method(cli, tmp_path, waving):
    source, target, timing = waving
    result = run(cli, "morph", source, target, "-o", tmp_path / "out.json", "--timing", timing,
                 "--method", "barycentric")
    assert result.returncode == 2
    assert result.stderr.strip() == ("error: option --timing has no effect with --method barycentric (only the rigid "
                                      "method factors out a rotation and follows a guide)")


def test_a_missing_timing_file_is_exit_2(cli, tmp_path, waving):
    source, target, _ = waving
    result = run(cli, "morph", source, target, "-o", tmp_path / "out.json", "--timing", tmp_path / "none.json")
    assert result.returncode == 2
    assert "none.json: cannot read file" in result.stderr
