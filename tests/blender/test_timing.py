"""Local timing (issue 31): a vertex group of the source mesh as the delay
weights, with the overlap, in the pair bake (object.stick_morph_bake) and the
key-pose bakes (object.stick_morph_bake_sequence, the first key's group;
object.stick_morph_rebake_shape_keys, the mesh's own).

The figure is blend_samples/make_samples.py's waving stick man with a hand
(LAG_POSES): the body bends a little, the raised forearm and the hand turn
about the elbow, and the group `lag` weighs the wrist and the fingertip 1.
With the group and an overlap d the baked hand reaches half its turn d later
than the torso (weight 0: at (1 - d) / 2, weight 1: at (1 + d) / 2, the
engine's clamp((t - d w) / (1 - d), 0, 1)); the first and the last frame are
the meshes; overlap 0 is the plain bake, frame for frame. A missing or empty
group is an ERROR report naming it, with the scene unchanged (objects,
meshes, shape keys, actions, vertex groups, the scene's settings).
The bpy-free part (timing.delay_weights, local_times, the dummies' weights)
is tests/python/test_addon_timing.py.
"""

import json
import os
import sys

import bpy
import numpy as np
import pytest
from mathutils import Matrix

from conftest import ROOT, addon_import, evaluated_world, make_mesh_object, select, snapshot, world_coords

sys.path.insert(0, os.path.join(ROOT, "blend_samples"))
import make_samples  # noqa: E402

SOURCE_XY, TARGET_XY = make_samples.lag_poses()
EDGES = [list(e) for e in make_samples.LAG_EDGES]
TORSO = EDGES.index([0, 1])  # hip to neck: weight 0 at both ends
HAND = EDGES.index([6, 11])  # wrist to fingertip: weight 1 at both ends
FOREARM = EDGES.index([5, 6])  # elbow (0) to wrist (1)
LAGGING = make_samples.LAG_VERTICES
SAMPLE = os.path.join(ROOT, "blend_samples", make_samples.LOCAL_TIMING_DIR, f"{make_samples.LAG_NAME}.blend")
# The target lies in a plane parallel to the source's, this far above it:
# the heights move too, each vertex on its own clock.
LIFT = 0.5


def make_waver(group="lag", members=LAGGING, weight=1.0):
    """The source "Waver" (with the vertex group `group` holding `members`
    at `weight`, unless group is None) and the target "Waved", five units to
    the right and LIFT above; both selected, the target active."""
    source = make_mesh_object("Waver", SOURCE_XY, EDGES)
    target = make_mesh_object("Waved", TARGET_XY, EDGES, Matrix.Translation((5.0, 0.0, LIFT)))
    if group is not None:
        made = source.vertex_groups.new(name=group)
        if members:
            made.add(list(members), weight, "REPLACE")
    bpy.context.view_layer.update()
    select(source, target)
    return source, target


def result_object():
    return bpy.data.objects[bpy.context.scene.stick_morph.last_result]


def baked_frames(obj, first, count):
    """(count, V, 3) the result's world coordinates at its frames."""
    return np.array([evaluated_world(obj, first + k) for k in range(count)])


def edge_angles(frames, edges=EDGES):
    """(F, E) every edge's direction in the XY plane, unwrapped over the frames."""
    edges = np.asarray(edges)
    vectors = frames[:, edges[:, 1], :2] - frames[:, edges[:, 0], :2]
    return np.unwrap(np.arctan2(vectors[..., 1], vectors[..., 0]), axis=0)


def half_turn_time(angles, times):
    """When an edge has turned half its whole turn (linear between frames)."""
    turned = (angles - angles[0]) / (angles[-1] - angles[0])
    k = int(np.argmax(turned >= 0.5))
    a, b = turned[k - 1], turned[k]
    return times[k - 1] + (0.5 - a) / (b - a) * (times[k] - times[k - 1])


def size_of(*worlds):
    every = np.vstack(worlds)
    return float(np.linalg.norm(every.max(axis=0) - every.min(axis=0)))


def full_snapshot():
    """conftest.snapshot() and what it leaves out that a bake with a delay
    group could touch: every object's vertex groups and their weights, and
    the scene's Stick Morph settings."""
    state = snapshot()
    state["vertex_groups"] = sorted(
        (obj.name, group.name, tuple((v.index, round(e.weight, 9)) for v in obj.data.vertices for e in v.groups
                                     if e.group == group.index))
        for obj in bpy.data.objects if obj.type == "MESH" for group in obj.vertex_groups)
    settings = bpy.context.scene.stick_morph
    state["settings"] = {prop.identifier: str(getattr(settings, prop.identifier))
                         for prop in settings.bl_rna.properties if prop.identifier != "rna_type"}
    return state


def refused(operator, **kwargs):
    """Runs a bake operator expecting an ERROR report and no change at all;
    returns the message."""
    before = full_snapshot()
    with pytest.raises(RuntimeError) as error:
        operator(**kwargs)
    assert full_snapshot() == before, "the scene changed"
    message = str(error.value)
    assert message.startswith("Error:") and "Stick Morph" in message, message
    return message


# ------------------------------------------------------------ the pair ----

def test_the_hand_lags_the_torso_by_the_overlap(scene, addon, capfd):
    source, target = make_waver()
    count, d = 41, 0.3
    assert bpy.ops.object.stick_morph_bake(frame_count=count, delay_group="lag", overlap=d) == {"FINISHED"}
    lagged = result_object()
    report = capfd.readouterr().out
    assert "local timing: the delay group 'lag' lags by 0.3 of the motion" in report, report
    frames = baked_frames(lagged, 1, count)
    source_world, target_world = world_coords(source), world_coords(target)
    size = size_of(source_world, target_world)
    assert np.abs(frames[0] - source_world).max() <= 1e-5 * size
    assert np.abs(frames[-1] - target_world).max() <= 1e-5 * size
    times = np.linspace(0.0, 1.0, count)
    angles = edge_angles(frames)
    torso, hand = half_turn_time(angles[:, TORSO], times), half_turn_time(angles[:, HAND], times)
    # Weight 0 half way at (1 - d) / 2, weight 1 at (1 + d) / 2: d later.
    assert torso == pytest.approx((1 - d) / 2, abs=0.03)
    assert hand == pytest.approx((1 + d) / 2, abs=0.03)
    assert hand - torso == pytest.approx(d, abs=0.05)
    # The hand turns 95 degrees clockwise, the torso 10.
    assert np.degrees(angles[-1, HAND] - angles[0, HAND]) == pytest.approx(-95.0, abs=0.5)
    assert np.degrees(angles[-1, TORSO] - angles[0, TORSO]) == pytest.approx(-10.0, abs=0.5)
    # The heights move on the same clocks: half way, the hand is still
    # nearer the source's plane than the torso is.
    middle = frames[count // 2, :, 2] / LIFT
    assert middle[0] == pytest.approx(0.5 / (1 - d), abs=1e-3)
    assert middle[11] == pytest.approx(max(0.0, (0.5 - d) / (1 - d)), abs=1e-3)

    # The plain bake: both half way at the middle.
    select(source, target)
    assert bpy.ops.object.stick_morph_bake(frame_count=count, delay_group="") == {"FINISHED"}
    plain = baked_frames(result_object(), 1, count)
    angles = edge_angles(plain)
    assert half_turn_time(angles[:, TORSO], times) == pytest.approx(0.5, abs=0.03)
    assert half_turn_time(angles[:, HAND], times) == pytest.approx(0.5, abs=0.03)
    assert "local timing" not in capfd.readouterr().out


def test_overlap_zero_with_a_group_is_the_plain_bake(scene, addon):
    source, target = make_waver()
    results = []
    for group, overlap in (("", 0.3), ("lag", 0.0)):
        select(source, target)
        assert bpy.ops.object.stick_morph_bake(frame_count=9, delay_group=group, overlap=overlap) == {"FINISHED"}
        obj = result_object()
        results.append([np.array([p.co[:] for p in block.data]) for block in obj.data.shape_keys.key_blocks])
    plain, zero = results
    assert len(plain) == len(zero) == 9
    for a, b in zip(plain, zero):
        assert np.array_equal(a, b)


def test_a_missing_group_is_refused_with_the_scene_unchanged(scene, addon):
    make_waver(group="hand")
    message = refused(bpy.ops.object.stick_morph_bake, frame_count=5, delay_group="lag")
    assert "the delay group 'lag' is not a vertex group of the source mesh 'Waver'" in message
    assert "its vertex groups: 'hand'" in message
    # The target's groups do not count: the weights are the source's.
    source, target = bpy.data.objects["Waver"], bpy.data.objects["Waved"]
    target.vertex_groups.new(name="lag").add([6], 1.0, "REPLACE")
    select(source, target)
    message = refused(bpy.ops.object.stick_morph_bake, frame_count=5, delay_group="lag")
    assert "not a vertex group of the source mesh 'Waver'" in message


def test_an_empty_group_is_refused_with_the_scene_unchanged(scene, addon):
    make_waver(members=())
    # A previous result stays as it was too.
    assert bpy.ops.object.stick_morph_bake(frame_count=4) == {"FINISHED"}
    select(bpy.data.objects["Waver"], bpy.data.objects["Waved"])
    message = refused(bpy.ops.object.stick_morph_bake, frame_count=5, delay_group="lag")
    assert "the delay group 'lag' of the source mesh 'Waver' holds no vertex" in message
    assert "Weight Paint mode" in message


def test_a_group_of_weight_zero_is_not_empty(scene, addon, capfd):
    # Assigned with weight 0, the vertices are in the group: nothing lags.
    make_waver(weight=0.0)
    assert bpy.ops.object.stick_morph_bake(frame_count=9, delay_group="lag", overlap=0.5) == {"FINISHED"}
    frames = baked_frames(result_object(), 1, 9)
    angles = edge_angles(frames)
    times = np.linspace(0.0, 1.0, 9)
    assert half_turn_time(angles[:, HAND], times) == pytest.approx(0.25, abs=0.05)
    assert half_turn_time(angles[:, TORSO], times) == pytest.approx(0.25, abs=0.05)


def test_other_motions_bake_without_local_timing_and_say_so(scene, addon, capfd):
    source, target = make_waver()
    assert bpy.ops.object.stick_morph_bake(frame_count=5, motion="BARYCENTRIC", delay_group="lag") == {"FINISHED"}
    out = capfd.readouterr().out
    assert "local timing off: the delay group 'lag' applies to the Rigid motion only (Motion is Barycentric)" in out
    # A missing group is refused whatever the motion, like turns out of range.
    select(source, target)
    message = refused(bpy.ops.object.stick_morph_bake, frame_count=5, motion="LINEAR", delay_group="nope")
    assert "'nope' is not a vertex group" in message


def test_matched_meshes_carry_the_weights_onto_the_dummies(scene, addon):
    # The target drawn with its forearm split in two: matched, the source
    # gets a dummy on its forearm, half way between the elbow (weight 0)
    # and the wrist (1), which lags by half the overlap.
    source, _ = make_waver()
    target_xy = list(TARGET_XY) + [tuple((np.array(TARGET_XY[5]) + np.array(TARGET_XY[6])) / 2)]
    edges = [e for e in EDGES if e != [5, 6]] + [[5, 12], [12, 6]]
    bpy.data.objects.remove(bpy.data.objects["Waved"])
    target = make_mesh_object("Waved", target_xy, edges, Matrix.Translation((5.0, 0.0, LIFT)))
    bpy.context.view_layer.update()
    select(source, target)
    count, d = 21, 0.4
    assert bpy.ops.object.stick_morph_bake(frame_count=count, delay_group="lag", overlap=d) == {"FINISHED"}
    obj = result_object()
    vertex = np.empty(len(obj.data.vertices), dtype=np.int32)
    obj.data.attributes["stick_morph_source_vertex"].data.foreach_get("value", vertex)
    assert len(vertex) == 13 and list(vertex[:12]) == list(range(12)) and vertex[12] == -1
    frames = baked_frames(obj, 1, count)
    assert np.abs(frames[-1][[5, 6]] - world_coords(target)[[5, 6]]).max() <= 1e-5 * size_of(frames[0], frames[-1])
    # The dummy's height: its weight is 1/2 (half way along the edge by arc
    # length), so a quarter of the way through the motion it has moved
    # (1/4 - d/2) / (1 - d) of the way, the elbow (weight 0) 1/4 / (1 - d)
    # and the wrist (weight 1) nothing yet.
    quarter = frames[count // 4, :, 2] / LIFT
    assert quarter[12] == pytest.approx((0.25 - d / 2) / (1 - d), abs=0.03)
    assert quarter[5] == pytest.approx(0.25 / (1 - d), abs=1e-3) and quarter[6] == pytest.approx(0.0, abs=1e-3)


# ----------------------------------------------------------- key poses ----

def make_keys(group=True):
    """Three keys: the source pose, half way (by the bends), the target pose."""
    root, heading, bends = make_samples.LAG_POSES[0]
    _, heading_b, bends_b = make_samples.LAG_POSES[1]
    middle = make_samples.stick_man(root, (heading + heading_b) / 2, [(a + b) / 2 for a, b in zip(bends, bends_b)],
                                    make_samples.LAG_PARENT, make_samples.LAG_REFERENCE, make_samples.LAG_LENGTHS)
    objects = [make_mesh_object(f"Wave_{k + 1}", pose, EDGES, Matrix.Translation((5.0 * k, 0.0, 0.0)))
               for k, pose in enumerate((SOURCE_XY, middle, TARGET_XY))]
    if group:
        objects[0].vertex_groups.new(name="lag").add(list(LAGGING), 1.0, "REPLACE")
    bpy.context.view_layer.update()
    select(*objects)
    return objects


def test_key_poses_lag_in_every_segment_and_keep_their_keys(scene, addon, capfd):
    keys = make_keys()
    step, d = 20, 0.3
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=step, frame_start=1, delay_group="lag",
                                                    overlap=d) == {"FINISHED"}
    assert "local timing: the delay group 'lag' lags by 0.3 of each segment" in capfd.readouterr().out
    frames = baked_frames(result_object(), 1, 2 * step + 1)
    size = size_of(*(world_coords(k) for k in keys))
    for k, key in enumerate(keys):
        assert np.abs(frames[step * k] - world_coords(key)).max() <= 1e-5 * size, k
    times = np.linspace(0.0, 1.0, step + 1)
    for segment in range(2):
        angles = edge_angles(frames[segment * step:(segment + 1) * step + 1])
        torso, hand = half_turn_time(angles[:, TORSO], times), half_turn_time(angles[:, HAND], times)
        assert hand - torso == pytest.approx(d, abs=0.1), segment


def test_key_poses_refuse_a_missing_or_empty_group_of_the_first_key(scene, addon):
    keys = make_keys(group=False)
    # A group of another key is not the first key's.
    keys[1].vertex_groups.new(name="lag").add([6], 1.0, "REPLACE")
    select(*keys)
    message = refused(bpy.ops.object.stick_morph_bake_sequence, frame_step=6, delay_group="lag")
    assert "the delay group 'lag' is not a vertex group of the first key 'Wave_1'" in message
    keys[0].vertex_groups.new(name="lag")
    select(*keys)
    message = refused(bpy.ops.object.stick_morph_bake_sequence, frame_step=6, delay_group="lag")
    assert "the delay group 'lag' of the first key 'Wave_1' holds no vertex" in message


def make_shape_key_waver(group=True):
    """One mesh whose shape keys go pose to pose: the source pose at frame 1,
    the target pose at frame 13."""
    obj = make_mesh_object("Shaped", SOURCE_XY, EDGES)
    obj.shape_key_add(name="Basis", from_mix=False)
    block = obj.shape_key_add(name="Wave", from_mix=False)
    for point, (x, y) in zip(block.data, TARGET_XY):
        point.co = (x, y, 0.0)
    for frame, value in ((1, 0.0), (13, 1.0)):
        block.value = value
        block.keyframe_insert("value", frame=frame)
    if group:
        obj.vertex_groups.new(name="lag").add(list(LAGGING), 1.0, "REPLACE")
    bpy.context.view_layer.update()
    select(obj)
    return obj


def test_rebake_shape_keys_lags_with_the_meshs_group(scene, addon, capfd):
    obj = make_shape_key_waver()
    assert bpy.ops.object.stick_morph_rebake_shape_keys(delay_group="lag", overlap=0.5) == {"FINISHED"}
    assert "local timing: the delay group 'lag'" in capfd.readouterr().out
    frames = baked_frames(result_object(), 1, 13)
    times = np.linspace(0.0, 1.0, 13)
    angles = edge_angles(frames)
    assert half_turn_time(angles[:, HAND], times) - half_turn_time(angles[:, TORSO], times) == \
        pytest.approx(0.5, abs=0.12)
    select(obj)
    message = refused(bpy.ops.object.stick_morph_rebake_shape_keys, delay_group="hand")
    assert "the delay group 'hand' is not a vertex group of the mesh 'Shaped'" in message


# --------------------------------------------------------------- panel ----

def test_the_panel_searches_the_sources_groups_and_greys_the_overlap(scene, addon):
    from test_ui import FakeLayout, active_rows, draw  # noqa: F401
    source, target = make_waver()
    settings = scene.stick_morph
    settings.delay_group = ""
    record = draw(bpy.types.VIEW3D_PT_stick_morph_local_timing, bpy.context)
    assert ("search", "delay_group", "Waver", "vertex_groups") in record
    assert active_rows(record) == {"delay_group": True, "overlap": False}  # no group: nothing lags
    settings.delay_group = "lag"
    record = draw(bpy.types.VIEW3D_PT_stick_morph_local_timing, bpy.context)
    assert active_rows(record) == {"delay_group": True, "overlap": True}
    settings.delay_group = "gone"
    labels = [r[1] for r in draw(bpy.types.VIEW3D_PT_stick_morph_local_timing, bpy.context) if r[0] == "label"]
    assert "'gone' is not a vertex group of 'Waver'" in " ".join(labels), labels
    # The Bake buttons pass the group and the overlap.
    passed = {}  # each operator button: the properties the panel sets on it
    for entry in draw(bpy.types.VIEW3D_PT_stick_morph, bpy.context):
        if entry[0] == "operator":
            current = passed.setdefault(entry[1], set())
        elif entry[0] == "set":
            current.add(entry[1])
    for idname in ("object.stick_morph_bake", "object.stick_morph_bake_sequence",
                   "object.stick_morph_rebake_shape_keys"):
        assert {"delay_group", "overlap"} <= passed[idname], idname


def test_the_redo_panel_lists_the_groups_of_the_bakes_source(scene, addon):
    from test_ui import FakeLayout
    ui = addon_import("ui")
    make_waver()
    assert bpy.ops.object.stick_morph_bake(frame_count=4, delay_group="lag") == {"FINISHED"}
    # The redo panel draws the operator that ran, which holds the names it
    # resolved; here its properties are set as they were.
    op = bpy.context.window_manager.operator_properties_last("object.stick_morph_bake")
    saved = op.source, op.target, op.delay_group
    op.source, op.target, op.delay_group = "Waver", "Waved", "lag"
    try:
        record = []
        ui.draw_operator(FakeLayout(record), op)
        assert ("search", "delay_group", "Waver", "vertex_groups") in record
        assert ui.operator_delay_owner(op).name == "Waver"
    finally:
        op.source, op.target, op.delay_group = saved
    keys = make_keys()
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=4, delay_group="lag") == {"FINISHED"}
    op = bpy.context.window_manager.operator_properties_last("object.stick_morph_bake_sequence")
    saved = op.keys
    op.keys = json.dumps([k.name for k in keys])
    try:
        record = []
        ui.draw_key_pose_operator(FakeLayout(record), op, ("collection",), ("loop",), ("motion",))
        assert ("search", "delay_group", "Wave_1", "vertex_groups") in record
        assert ui.operator_delay_owner(op) == keys[0]
    finally:
        op.keys = saved


# -------------------------------------------------------------- sample ----

def test_the_sample_bakes_with_its_settings(addon, addon_name):
    assert os.path.isfile(SAMPLE), SAMPLE
    assert bpy.ops.wm.open_mainfile(filepath=SAMPLE, load_ui=False) == {"FINISHED"}
    assert addon_name in bpy.context.preferences.addons
    scene = bpy.context.scene
    settings = scene.stick_morph
    source, target = bpy.data.objects["lag_source"], bpy.data.objects["lag_target"]
    assert (settings.source, settings.target) == (source, target)
    assert settings.delay_group == "lag" and settings.overlap == pytest.approx(0.3)
    group = source.vertex_groups["lag"]
    weights = {v.index: e.weight for v in source.data.vertices for e in v.groups if e.group == group.index}
    assert weights == {6: 1.0, 11: 1.0}
    # The panel's Bake button, with the scene's settings.
    preferences = addon_import("preferences")
    options = {name: getattr(settings, name) for name in preferences.OPTION_NAMES + preferences.MESH_OPTIONS}
    assert bpy.ops.object.stick_morph_bake(source=source.name, target=target.name, frame_start=settings.frame_start,
                                           **options) == {"FINISHED"}
    count = settings.frame_count
    frames = baked_frames(result_object(), settings.frame_start, count)
    size = size_of(world_coords(source), world_coords(target))
    assert np.abs(frames[0] - world_coords(source)).max() <= 1e-5 * size
    assert np.abs(frames[-1] - world_coords(target)).max() <= 1e-5 * size
    times = np.linspace(0.0, 1.0, count)
    angles = edge_angles(frames)
    lag = half_turn_time(angles[:, HAND], times) - half_turn_time(angles[:, TORSO], times)
    assert lag == pytest.approx(0.3, abs=0.05)
