"""delay= and overlap= of the module's morphs (issue 31; docs/FORMAT.md, "Local timing").

The pair tests/data/timing/waving.*: the body bends while the right forearm
(vertices 11 and 12, from the elbow 10) turns up; the forearm weighs 1.
"""
import json

import numpy as np
import pytest

import stickmorph

FOREARM = [11, 12]


@pytest.fixture
def waving(data_dir):
    folder = data_dir / "timing"
    source = json.loads((folder / "waving.source.json").read_text())
    target = json.loads((folder / "waving.target.json").read_text())
    delay = np.zeros(len(source["vertices"]))
    delay[FOREARM] = 1
    return np.array(source["vertices"]), np.array(target["vertices"]), np.array(source["edges"]), delay


def forearm_turn(frames, f):
    """How far the forearm's own edge (11, 12) has turned at frame f, radians."""
    v0 = frames[0][12] - frames[0][11]
    v = frames[f][12] - frames[f][11]
    return np.angle(complex(*v) / complex(*v0))


def test_the_forearm_waits_for_the_overlap(waving):
    source, target, edges, delay = waving
    result = stickmorph.morph(source, target, edges, frames=41, delay=delay, overlap=0.5)
    frames = result["frames"]
    # Weight 1, overlap 0.5: still at t = 0.5 (frame 20), half way at 0.75 (frame 30).
    assert abs(forearm_turn(frames, 20)) < 1e-3
    assert forearm_turn(frames, 30) == pytest.approx(forearm_turn(frames, 40) / 2, abs=0.05)
    assert np.array_equal(frames[0], source) and np.array_equal(frames[-1], target)


def test_overlap_zero_is_the_plain_morph_bit_for_bit(waving):
    source, target, edges, delay = waving
    plain = stickmorph.morph(source, target, edges, frames=21)["frames"]
    timed = stickmorph.morph(source, target, edges, frames=21, delay=delay, overlap=0.0)["frames"]
    assert np.array_equal(plain, timed)


def test_the_solvers_take_the_same_timing(waving):
    source, target, edges, delay = waving
    frames = stickmorph.morph(source, target, edges, frames=11, delay=delay, overlap=0.4)["frames"]
    solver = stickmorph.RigidMorphSolver(source, target, edges, delay=delay, overlap=0.4)
    for f in range(11):
        assert np.array_equal(solver.solve(f / 10), frames[f])
    keys = stickmorph.morph_key_poses([source, target, source], edges, frames=21, delay=delay, overlap=0.4)
    assert np.array_equal(keys["frames"][10], target)
    scrub = stickmorph.KeyPoseMorphSolver([source, target, source], edges, frames=21, delay=delay, overlap=0.4)
    assert np.array_equal(scrub.frame(5), keys["frames"][5])


@pytest.mark.parametrize("arguments, message", [
    ({"delay": [0.0] * 11 + [1.5, 1.0], "overlap": 0.3}, "delay[11] is 1.5, outside [0, 1]"),
    ({"delay": [0.0] * 13, "overlap": 1.0}, "overlap is 1, outside [0, 1)"),
    ({"delay": [0.0, 1.0], "overlap": 0.3}, "delay has 2 entries for 13 vertices of the source"),
    ({"delay": [0.0] * 13}, "delay needs overlap"),
    ({"overlap": 0.3}, "overlap needs delay"),
    ({"delay": [[0.0, 1.0]] * 13, "overlap": 0.3}, "delay must have shape (#V,)"),
    ({"delay": ["a"] * 13, "overlap": 0.3}, "delay must hold real numbers"),
    ({"delay": [0.0] * 13, "overlap": "0.3"}, "overlap must be a number"),
    ({"delay": [0.0] * 13, "overlap": 0.3, "method": "linear"}, "delay has no effect with method='linear'"),
])
def test_bad_timing_is_a_value_error_naming_the_entry(waving, arguments, message):
    source, target, edges, _ = waving
    with pytest.raises(stickmorph.InvalidArgumentError) as raised:
        stickmorph.morph(source, target, edges, **arguments)
    assert isinstance(raised.value, ValueError)
    assert message in str(raised.value)


def test_option_rules_list_delay_for_the_rigid_method_only():
    assert stickmorph.option_rules["delay"]["methods"] == ("rigid",)
