"""Local timing (issue 31) at the add-on, outside Blender: a vertex group of
the source mesh gives the delay weights (timing.delay_weights: vertices not
in the group weigh 0; a missing or empty group is refused with a message
naming the group and the object), each vertex's height moves on its own
clock (timing.local_times), the weights are carried onto a matched figure's
dummies, and compute_morph / morph_keys give the engine delay= and overlap=
with the Rigid motion only.

The modules are loaded as tests/python/test_addon_core.py loads them (its
loader, its tree pair and its tilted plane are reused); the Blender side
(the vertex group read from the mesh, the panel, the reports, the scene left
unchanged) is tests/blender/test_timing.py.
"""
import dataclasses
import functools

import numpy as np
import pytest

from test_addon_core import (SOURCE_WORLD, TARGET_WORLD, TREE_EDGES, TREE_SOURCE, TREE_TARGET, _N, common, core,
                             in_space, load_addon_module, prepare)

morph_module = load_addon_module("morph")
sequence = load_addon_module("sequence")


# ------------------------------------------------------- delay weights ----

def test_the_groups_weights_and_zero_elsewhere():
    weights = core.delay_weights(6, [(4, 1.0), (1, 0.25), (5, 0.0)], "lag", "Arm")
    assert weights == [0.0, 0.25, 0.0, 0.0, 1.0, 0.0]
    assert all(isinstance(w, float) for w in weights)
    # Every vertex in the group, at any weight.
    assert core.delay_weights(3, [(0, 0.5), (1, 0.5), (2, 0.5)], "lag", "Arm") == [0.5, 0.5, 0.5]
    # A group holding only vertices of weight 0 is not empty: nothing lags.
    assert core.delay_weights(3, [(1, 0.0)], "lag", "Arm") == [0.0, 0.0, 0.0]
    # The ends of the range are weights too.
    assert core.delay_weights(2, [(0, 0.0), (1, 1.0)], "lag", "Arm") == [0.0, 1.0]


def test_no_group_named_is_no_local_timing():
    assert core.delay_weights(5, None, "", "Arm") is None
    assert core.delay_weights(5, [(1, 1.0)], "", "Arm") is None


def test_a_missing_group_is_refused_naming_it_and_the_object():
    with pytest.raises(core.StickMorphError) as error:
        core.delay_weights(5, None, "lag", "Arm", groups=["pin.001", "hand"])
    message = str(error.value)
    assert message.startswith("the delay group 'lag' is not a vertex group of the source mesh 'Arm'")
    assert "its vertex groups: 'pin.001', 'hand'" in message
    assert "clear Delay Group" in message
    with pytest.raises(core.StickMorphError, match="'lag' is not a vertex group of the first key 'Wave_1' "
                                                   r"\(it has no vertex groups\)"):
        core.delay_weights(5, None, "lag", "Wave_1", role="the first key")


def test_an_empty_group_is_refused_naming_it_and_the_object():
    with pytest.raises(core.StickMorphError) as error:
        core.delay_weights(5, [], "lag", "Arm")
    message = str(error.value)
    assert message.startswith("the delay group 'lag' of the source mesh 'Arm' holds no vertex")
    assert "Weight Paint mode" in message and "clear Delay Group" in message


@pytest.mark.parametrize("members, fragment", [
    ([(5, 1.0)], "names vertex 5, but the mesh has 5 vertices"),
    ([(-1, 1.0)], "names vertex -1"),
    ([(2, 1.5)], r"vertex 2 of the source mesh 'Arm' has the weight 1.5 in the delay group 'lag', outside \[0, 1\]"),
    ([(2, -0.1)], "weight -0.1"),
    ([(2, float("nan"))], "weight nan"),
])
def test_weights_not_from_blender_are_checked(members, fragment):
    # Blender keeps a vertex group's weights in [0, 1] and its members in the
    # mesh; a script calling core directly is checked all the same.
    with pytest.raises(core.StickMorphError, match=fragment):
        core.delay_weights(5, members, "lag", "Arm")


# ---------------------------------------------------------- local times ----

def test_local_times_lead_lag_and_exact_ends():
    t = np.linspace(0.0, 1.0, 101)
    weights = [0.0, 0.5, 1.0]
    d = 0.3
    tau = core.local_times(t, weights, d)
    assert tau.shape == (101, 3)
    assert np.array_equal(tau[0], [0, 0, 0]) and np.array_equal(tau[-1], [1, 1, 1])
    assert np.all(np.diff(tau, axis=0) >= 0)
    # Weight w reaches half its motion at d w + (1 - d) / 2: weight 1 lags
    # weight 0 by d.
    for k, w in enumerate(weights):
        assert np.interp(0.5, tau[:, k], t) == pytest.approx(d * w + (1 - d) / 2, abs=1e-12)
    # Weight 0 starts at once and is done at 1 - d; weight 1 waits until d.
    assert tau[1, 0] > 0 and tau[np.searchsorted(t, 1 - d + 1e-9), 0] == 1.0
    assert tau[np.searchsorted(t, d) - 1, 2] == 0.0 and tau[-2, 2] < 1.0
    # Overlap 0 is the plain clock, and so is no weights at all.
    assert np.array_equal(core.local_times(t, weights, 0.0), np.repeat(t[:, None], 3, axis=1))
    plain = core.local_times(t)
    assert plain.shape == (101, 1) and np.array_equal(plain[:, 0], t)


@pytest.mark.parametrize("overlap", [1.0, -0.1, 1.5, float("nan")])
def test_local_times_refuse_an_overlap_outside_the_range(overlap):
    with pytest.raises(core.StickMorphError, match="overlap must be at least 0 and less than 1"):
        core.local_times([0.0, 1.0], [0.0, 1.0], overlap)


def test_the_settings_hold_the_group_and_the_overlap():
    settings = core.BakeSettings()
    assert (settings.delay_group, settings.overlap) == ("", 0.3)
    assert dataclasses.replace(settings, delay_group="lag").delay_group == "lag"


# ------------------------------------------------------ the prepared pair ----

# The tree's arm 0-1-2 leads, the arm 0-5-6 lags (the junction leads).
LAG = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0]


def test_by_index_the_weights_are_the_source_meshs():
    prepared = core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "Arm", TARGET_WORLD, TREE_EDGES, 0, "Arm pose",
                                 core.BakeSettings(), source_delay=LAG)
    assert not prepared.matching.matched
    assert np.array_equal(prepared.delay, LAG)
    assert prepare().delay is None
    with pytest.raises(core.StickMorphError, match="the delay weights of 'Arm' are 3, for 7 vertices"):
        core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "Arm", TARGET_WORLD, TREE_EDGES, 0, "Arm pose",
                          core.BakeSettings(), source_delay=[0.0, 1.0, 0.0])


def test_matched_a_dummy_takes_the_weight_along_its_source_edge():
    # The target drawn again with one edge of an arm split in two and its
    # numbering shuffled: the matched figure has a dummy on a source edge,
    # which takes the weight interpolated between that edge's ends.
    split = (TREE_TARGET[5] + TREE_TARGET[6]) / 2
    target_xy = np.vstack([TREE_TARGET[[0, 3, 4, 1, 2, 5]], [split], TREE_TARGET[[6]]])
    target_edges = np.array([[0, 3], [3, 4], [0, 1], [1, 2], [0, 5], [5, 6], [6, 7]])
    target = in_space(target_xy * 0.8, [4.0, 1.0, -0.5] + 0.7 * _N)
    weights = [0.0, 0.4, 1.0, 0.1, 0.6, 0.2, 0.9]
    prepared = core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "Arm", target, target_edges, 0, "Arm drawn again",
                                 core.BakeSettings(), source_delay=weights)
    matching = prepared.matching
    assert matching.matched and len(prepared.source_xy) == 8
    assert np.array_equal(prepared.delay[:7], weights)  # the source's own vertices first, in order
    dummy = int(np.flatnonzero(matching.source_vertex < 0)[0])
    a, b = (int(e[0] if e[1] == dummy else e[1]) for e in prepared.edges if dummy in e)
    # Where the dummy sits on the source edge a-b is where its weight is.
    pa, pb = prepared.source_xy[a], prepared.source_xy[b]
    fraction = np.linalg.norm(prepared.source_xy[dummy] - pa) / np.linalg.norm(pb - pa)
    assert 0.0 < fraction < 1.0
    assert weights[a] != weights[b]
    assert prepared.delay[dummy] == pytest.approx((1 - fraction) * weights[a] + fraction * weights[b], abs=1e-9)


def test_a_module_without_local_timing_is_refused_not_ignored(monkeypatch):
    rules = {name: methods for name, methods in core.option_methods().items() if name != "delay"}
    monkeypatch.setattr(morph_module, "option_methods", lambda: rules)
    prepared = core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "Arm", TARGET_WORLD, TREE_EDGES, 0, "Arm pose",
                                 core.BakeSettings(), source_delay=LAG)
    with pytest.raises(core.StickMorphError, match="local timing .* needs a newer stickmorph module"):
        core.compute_morph(prepared, core.BakeSettings(frame_count=3, delay_group="lag"))
    # Without a group the same module bakes as before.
    assert len(core.compute_morph(prepare(), core.BakeSettings(frame_count=3)).frames_world) == 3
    # Nor does a property the module has no rule for apply to any motion
    # (the panel greys it out).
    assert not common.option_applies("delay", "RIGID", rules)


def test_key_poses_refuse_weights_of_the_wrong_length_and_an_old_module(monkeypatch):
    worlds = [SOURCE_WORLD, TARGET_WORLD, SOURCE_WORLD + 3.0]
    names = ["Pose 1", "Pose 2", "Pose 3"]
    args = (worlds, [TREE_EDGES] * 3, [0] * 3, names, core.BakeSettings())
    with pytest.raises(core.StickMorphError, match=r"the delay weights of key 1 \('Pose 1'\) are 2, for 7 vertices"):
        sequence.prepare_keys(*args, delay=[0.0, 1.0])
    monkeypatch.setattr(sequence, "supports_local_timing", lambda engine=None: False)
    with pytest.raises(core.StickMorphError, match="needs a newer stickmorph module: this one's morph_key_poses"):
        sequence.prepare_keys(*args, delay=LAG)
    assert sequence.prepare_keys(*args).delay is None


# ---------------------------------------------------------- with the engine ----

def test_the_engine_has_local_timing():
    # The module built with this add-on: its rule for delay= (and overlap=,
    # given with it) is rigid only, and morph_key_poses takes both.
    engine = core.load_engine()
    assert core.option_methods()["delay"] == ("rigid",)
    assert sequence.supports_local_timing(engine)
    with pytest.raises(engine.InvalidArgumentError, match=r"delay\[1\] is 1.5, outside \[0, 1\]"):
        engine.morph(TREE_SOURCE[:2], TREE_TARGET[:2], [[0, 1]], delay=[0.0, 1.5], overlap=0.3)


def edge_angles(frames_xy, edges):
    """(F, E) every edge's direction, unwrapped over the frames."""
    vectors = frames_xy[:, edges[:, 1]] - frames_xy[:, edges[:, 0]]
    return np.unwrap(np.arctan2(vectors[..., 1], vectors[..., 0]), axis=0)


def half_turn_time(angles, times):
    """When an edge has turned half of its whole turn (linear between frames)."""
    turned = (angles - angles[0]) / (angles[-1] - angles[0])
    k = int(np.argmax(turned >= 0.5))
    a, b = turned[k - 1], turned[k]
    return times[k - 1] + (0.5 - a) / (b - a) * (times[k] - times[k - 1])


def test_the_engine_gets_the_weights_and_the_overlap_with_rigid_only(monkeypatch):
    engine = core.load_engine()
    calls = []
    morph = engine.morph
    monkeypatch.setattr(engine, "morph", lambda *args, **kwargs: calls.append(kwargs) or morph(*args, **kwargs))
    prepared = core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "Arm", TARGET_WORLD, TREE_EDGES, 0, "Arm pose",
                                 core.BakeSettings(), source_delay=LAG)
    settings = core.BakeSettings(frame_count=5, delay_group="lag", overlap=0.25)
    results = [core.compute_morph(prepared, dataclasses.replace(settings, motion=motion)) for motion in core.MOTIONS]
    rigid, barycentric, linear = calls
    assert np.array_equal(rigid["delay"], LAG) and rigid["overlap"] == 0.25
    assert "delay" not in barycentric and "overlap" not in barycentric
    assert "delay" not in linear and "overlap" not in linear
    assert [r.overlap for r in results] == [0.25, None, None]
    assert [r.local_timing_ignored for r in results] == [False, True, True]
    assert core.local_timing_summary(results[0], "lag") == \
        "local timing: the delay group 'lag' lags by 0.25 of the motion"
    assert "Rigid motion only (Motion is Barycentric)" in core.local_timing_summary(results[1], "lag")
    assert core.local_timing_summary(core.compute_morph(prepare(), settings), "") == ""


def test_the_lagging_arm_turns_later_and_its_heights_follow_its_clock():
    prepared = core.prepare_pair(SOURCE_WORLD, TREE_EDGES, 0, "Arm", TARGET_WORLD, TREE_EDGES, 0, "Arm pose",
                                 core.BakeSettings(), source_delay=LAG)
    d, count = 0.3, 41
    settings = core.BakeSettings(frame_count=count, delay_group="lag", overlap=d)
    lagged = core.compute_morph(prepared, settings)
    plain = core.compute_morph(prepare(), dataclasses.replace(settings, delay_group=""))
    size = prepared.size
    # The ends are the meshes.
    assert np.abs(lagged.frames_world[0] - SOURCE_WORLD).max() <= 1e-9 * size
    assert np.abs(lagged.frames_world[-1] - TARGET_WORLD).max() <= 1e-9 * size
    times = np.linspace(0.0, 1.0, count)
    xy = np.array([core.project(frame, prepared.plane)[0] for frame in lagged.frames_world])
    angles = edge_angles(xy, TREE_EDGES)
    # The leading arm's edges (weight 0) turn half way at (1 - d) / 2, the
    # lagging arm's outer edge (weight 1) at (1 + d) / 2: d later. In the
    # plain morph both at the middle.
    leading, lagging = half_turn_time(angles[:, 1], times), half_turn_time(angles[:, 5], times)
    assert leading == pytest.approx((1 - d) / 2, abs=0.02) and lagging == pytest.approx((1 + d) / 2, abs=0.02)
    plain_xy = np.array([core.project(frame, prepared.plane)[0] for frame in plain.frames_world])
    plain_angles = edge_angles(plain_xy, TREE_EDGES)
    assert half_turn_time(plain_angles[:, 1], times) == pytest.approx(0.5, abs=0.02)
    assert half_turn_time(plain_angles[:, 5], times) == pytest.approx(0.5, abs=0.02)
    # Each vertex's height above the source's plane on its own clock.
    heights = (lagged.frames_world - prepared.plane.origin) @ prepared.plane.normal
    expected = prepared.source_h + core.local_times(times, LAG, d) * (prepared.target_h - prepared.source_h)
    assert np.abs(heights - expected).max() <= 1e-9 * size
    # Half way, the lagging hand is nearer the source's plane than the
    # leading arm (the target's plane is 0.7 further).
    progress = (heights[count // 2] - prepared.source_h) / (prepared.target_h - prepared.source_h)
    assert progress[6] < progress[2] - 0.2
    # Overlap 0 with the group is the plain morph, frame for frame.
    zero = core.compute_morph(prepared, dataclasses.replace(settings, overlap=0.0))
    assert np.array_equal(zero.frames_world, plain.frames_world)


def test_key_poses_run_the_delay_on_each_segment(monkeypatch):
    engine = core.load_engine()
    calls = []
    morph_key_poses = engine.morph_key_poses

    @functools.wraps(morph_key_poses)  # its signature says what it takes (sequence.supports_local_timing)
    def recording(*args, **kwargs):
        calls.append(kwargs)
        return morph_key_poses(*args, **kwargs)

    monkeypatch.setattr(engine, "morph_key_poses", recording)
    middle = in_space((TREE_SOURCE + TREE_TARGET) / 2 + [0.1, 0.0], [2.0, 0.0, 0.0])
    worlds = [SOURCE_WORLD, middle, TARGET_WORLD]
    names = ["Pose 1", "Pose 2", "Pose 3"]
    settings = core.BakeSettings(delay_group="lag", overlap=0.4)
    prepared = sequence.prepare_keys(worlds, [TREE_EDGES] * 3, [0] * 3, names, settings, delay=LAG)
    result = sequence.morph_keys(prepared, settings, 21, [0, 10, 20])
    assert np.array_equal(calls[0]["delay"], LAG) and calls[0]["overlap"] == pytest.approx(0.4)
    assert result.overlap == pytest.approx(0.4)
    size = prepared.size
    for key, frame in zip(worlds, (0, 10, 20)):
        assert np.abs(result.frames_world[frame] - key).max() <= 1e-9 * size
