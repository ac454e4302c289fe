"""Key poses (issue 28): Bake Key Poses (object.stick_morph_bake_sequence)
and Rebake Shape Keys (object.stick_morph_rebake_shape_keys).

Every frame of a result, evaluated at its scene frame, is compared with the
engine's stickmorph.morph_key_poses on the keys' world coordinates (computed
here from the objects, projected onto their common plane and mapped back);
the keys' own objects and a source animation stay untouched, undo restores
the scene, and bad input is an ERROR report naming the key or the frame.
The first tests are plain tests of the bpy-free sequence.py.

The figure is blend_samples/make_samples.py's waving stick man (4 poses).
"""

import json
import os
import sys

import bpy
import numpy as np
import pytest
from mathutils import Matrix

from conftest import ROOT, TILT, addon_import, evaluated_world, make_mesh_object, select, snapshot, world_coords

sys.path.insert(0, os.path.join(ROOT, "blend_samples"))
import make_samples  # noqa: E402

POSES = make_samples.wave_poses()
EDGES = [list(e) for e in make_samples.STICK_MAN_EDGES]


def sequence_module():
    return addon_import("sequence")


# ------------------------------------------------------------ bpy-free ----

def test_order_by_name_is_natural(addon):
    seq = sequence_module()
    names = ["Pose_10", "Pose_2", "Pose", "Pose.001", "pose_1"]
    assert [names[k] for k in seq.order_by_name(names)] == ["Pose", "Pose.001", "Pose_2", "Pose_10", "pose_1"]


def test_key_frames_automatic_own_and_refused(addon):
    seq = sequence_module()
    core = addon.core
    names = ["A", "B", "C"]
    assert seq.key_frames(names, [0, 0, 0], 5, 10) == [5, 15, 25]
    assert seq.key_frames(names, [3, 8, 30], 5, 10) == [3, 8, 30]
    assert seq.timeline([5, 15, 25], 10, False) == (21, [0, 10, 20])
    assert seq.timeline([5, 15, 25], 10, True) == (31, [0, 10, 20])
    with pytest.raises(core.StickMorphError, match=r"key 3 \('C'\) is at frame 8, not after key 2 \('B'\) at frame 9"):
        seq.key_frames(names, [3, 9, 8], 1, 10)
    with pytest.raises(core.StickMorphError, match=r"key 2 \('B'\) has no key frame"):
        seq.key_frames(names, [3, 0, 8], 1, 10)
    with pytest.raises(core.StickMorphError, match="at least two .* only 'A'"):
        seq.key_frames(["A"], [0], 1, 10)


def test_pose_to_pose_rule(addon):
    seq = sequence_module()
    core = addon.core
    keys = ["P2", "P3"]
    poses = seq.pose_to_pose("Man", [1, 13, 25, 37], keys, [[0, 0], [1, 0], [0, 1], [0, 0]])
    assert [(p.frame, p.key) for p in poses] == [(1, -1), (13, 0), (25, 1), (37, -1)]
    assert seq.pose_holds(poses) == [False] * 4
    held = seq.pose_to_pose("Man", [1, 13, 25], keys, [[0, 0], [1, 0], [1, 0]])
    assert seq.pose_holds(held) == [False, True, True]
    with pytest.raises(core.StickMorphError, match=r"at frame 13 the shape key 'P2' is 0\.5"):
        seq.pose_to_pose("Man", [1, 13], keys, [[0, 0], [0.5, 0]])
    with pytest.raises(core.StickMorphError, match="at frame 25 the shape keys 'P2', 'P3' are all on"):
        seq.pose_to_pose("Man", [1, 25], keys, [[0, 0], [1, 1]])
    with pytest.raises(core.StickMorphError, match="at frame 7 the shape key 'P3' is 2"):
        seq.pose_to_pose("Man", [1, 7], keys, [[0, 0], [0, 2]])
    with pytest.raises(core.StickMorphError, match="frame 3.5"):
        seq.pose_to_pose("Man", [1, 3.5], keys, [[0, 0], [1, 0]])
    with pytest.raises(core.StickMorphError, match="one pose only"):
        seq.pose_to_pose("Man", [1, 5], keys, [[1, 0], [1, 0]])


def test_plane_of_two_is_the_pair_plane(addon):
    plane = addon_import("plane")
    rng = np.random.default_rng(3)
    a, b = rng.normal(size=(7, 3)), rng.normal(size=(5, 3))
    a[:, 2] *= 1e-3
    b[:, 2] *= 1e-3
    pair, of_two = plane.fit_plane(a, b), plane.fit_plane_of([a, b])
    for name in ("origin", "u", "v", "normal"):
        assert np.array_equal(getattr(pair, name), getattr(of_two, name)), name


# --------------------------------------------------------------- helpers ----

def pose_matrix(k):
    """Key k's place: side by side in the tilted plane of conftest, the second
    key in a parallel plane (its heights move in the morph)."""
    normal = np.array(TILT.to_3x3()) @ np.array([0.0, 0.0, 1.0])
    shift = np.array(TILT.to_3x3()) @ np.array([6.0 * k, 0.0, 0.0]) + (0.4 * normal if k == 1 else 0.0)
    return Matrix.Translation(tuple(shift)) @ TILT


def make_keys(names=("Wave_1", "Wave_2", "Wave_3", "Wave_4"), poses=POSES):
    objects = [make_mesh_object(name, pose, EDGES, pose_matrix(k)) for k, (name, pose) in enumerate(zip(names, poses))]
    bpy.context.view_layer.update()
    return objects


def figure_size(worlds):
    every = np.vstack(worlds)
    return float(np.linalg.norm(every.max(axis=0) - every.min(axis=0)))


def expected_frames(worlds, frames, keys_at, edges=EDGES, **options):
    """The engine's morph through the keys (world coordinates), in world space:
    projected onto their common plane, each frame's heights blended between
    its segment's keys by frame, smoothstep with easing="in-out"
    (sequence.py's docstring)."""
    plane = addon_import("plane").fit_plane_of(worlds, "AUTO")
    projected = [addon_import("plane").project(w, plane) for w in worlds]
    engine = addon_import("core").load_engine()
    result = engine.morph_key_poses([xy for xy, _ in projected], np.asarray(edges), frames=frames,
                                    keys_at=keys_at, **options)
    heights = np.empty(result["frames"].shape[:2])
    for segment in result["segments"]:
        a, b, f0, f1 = (segment[k] for k in ("from_key", "to_key", "first_frame", "last_frame"))
        s = (np.arange(f0, f1 + 1) - f0) / (f1 - f0)
        if options.get("easing") == "in-out":
            s = s * s * (3 - 2 * s)
        heights[f0:f1 + 1] = np.outer(1 - s, projected[a][1]) + np.outer(s, projected[b][1])
    xy = result["frames"]
    world = plane.origin + xy[..., :1] * plane.u + xy[..., 1:] * plane.v + heights[..., None] * plane.normal
    return world, result


def check_result(result, expected, first_frame, size):
    tolerance = 1e-6 * size
    for f in range(len(expected)):
        error = np.abs(evaluated_world(result, first_frame + f) - expected[f]).max()
        assert error <= tolerance, f"frame {first_frame + f}: off by {error} (size {size})"


def operator_fails(operator, **kwargs):
    """Runs the operator expecting an ERROR report and the scene unchanged; its message."""
    before = snapshot()
    with pytest.raises(RuntimeError) as error:
        operator(**kwargs)
    assert snapshot() == before, "the scene changed"
    message = str(error.value)
    assert message.startswith("Error:") and "Stick Morph" in message, message
    return message


# ---------------------------------------------------- Bake Key Poses ----

def test_bake_key_poses_is_the_engine_motion(scene, addon, capfd):
    objects = make_keys()
    # Selected in another order: the keys are ordered by name.
    select(objects[2], objects[0], objects[3], objects[1])
    scene.frame_current = 5
    worlds = [world_coords(o) for o in objects]
    before = [(w.tobytes(), tuple(map(tuple, o.matrix_world))) for w, o in zip(worlds, objects)]
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=10) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    assert result.get("stick_morph_role") == "sequence_result"
    assert json.loads(result["stick_morph_keys"]) == [o.name for o in objects]
    assert [o.name for o in bpy.context.selected_objects] == [result.name]
    assert len(result.data.shape_keys.key_blocks) == 31
    assert [m.type for m in result.modifiers] == ["NODES"]  # renderable by default
    expected, engine_result = expected_frames(worlds, 31, [0, 10, 20, 30])
    size = figure_size(worlds)
    check_result(result, expected, 5, size)
    # Each key exactly at its frame, in world space; held after the last.
    for k, world in enumerate(worlds):
        assert np.abs(evaluated_world(result, 5 + 10 * k) - world).max() <= 1e-6 * size, k
    assert np.abs(evaluated_world(result, 40) - worlds[-1]).max() <= 1e-6 * size
    assert (scene.frame_start, scene.frame_end) == (5, 35)
    # The keys are untouched.
    assert [(world_coords(o).tobytes(), tuple(map(tuple, o.matrix_world))) for o in objects] == before
    assert all(o.data.shape_keys is None for o in objects)
    # The report names every segment.
    out = capfd.readouterr().out
    assert "'Wave_1' \u2192 key 2 'Wave_2': frames 5-15" in out, out
    assert "key 3 'Wave_3' \u2192 key 4 'Wave_4': frames 25-35" in out, out
    assert "Steiner" in out and " ms" in out
    # Baking again replaces the result, under the same name.
    name = result.name
    select(*objects)
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=10, frame_start=5) == {"FINISHED"}
    assert [o.name for o in bpy.data.objects if o.get("stick_morph_role") == "sequence_result"] == [name]


def test_collection_order_own_key_frames_and_loop(scene, addon):
    objects = make_keys(names=("D", "C", "B", "A"))
    keys = bpy.data.collections.new("Wave keys")
    scene.collection.children.link(keys)
    for obj in objects:  # in the collection's order, not by name
        keys.objects.link(obj)
    for obj, frame in zip(objects, (3, 10, 30, 41)):
        obj.stick_morph_key_frame = frame
    select()
    assert bpy.ops.object.stick_morph_bake_sequence(collection="Wave keys", loop=True, frame_step=12,
                                                    renderable=False) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    assert not result.modifiers
    worlds = [world_coords(o) for o in objects]
    expected, engine_result = expected_frames(worlds, 51, [0, 7, 27, 38], loop=True)
    assert len(engine_result["segments"]) == 4
    check_result(result, expected, 3, figure_size(worlds))
    assert np.abs(evaluated_world(result, 53) - worlds[0]).max() <= 1e-6 * figure_size(worlds)
    # The closing frame (53, key 1 again) is baked; the scene's range stops before it, so that
    # looping playback shows key 1 once per cycle.
    assert (scene.frame_start, scene.frame_end) == (3, 52)


def test_hold_stops_at_every_key(scene, addon):
    objects = make_keys()
    select(*objects)
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=8, hold=True, frame_start=1) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    worlds = [world_coords(o) for o in objects]
    expected, _ = expected_frames(worlds, 25, [0, 8, 16, 24], hold=[True] * 4)
    check_result(result, expected, 1, figure_size(worlds))
    # Baking again with the earlier result selected too: the result is not taken as a fifth key.
    select(*objects, result)
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=8, hold=True, frame_start=1) == {"FINISHED"}
    check_result(bpy.context.view_layer.objects.active, expected, 1, figure_size(worlds))


def test_easing_eases_every_segment(scene, addon):
    if not sequence_module().supports_easing():
        pytest.skip("this stickmorph module's morph_key_poses has no easing= (eased segments)")
    objects = make_keys()
    select(*objects)
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=8, easing="IN_OUT", frame_start=1) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    worlds = [world_coords(o) for o in objects]
    expected, _ = expected_frames(worlds, 25, [0, 8, 16, 24], easing="in-out")
    check_result(result, expected, 1, figure_size(worlds))
    obj, _ = make_animated()
    assert bpy.ops.object.stick_morph_rebake_shape_keys(easing="IN_OUT") == {"FINISHED"}
    keys = [shape_world(obj, k) for k in (0, 1, 2, 3, 0)]
    expected, _ = expected_frames(keys, 49, [0, 12, 24, 36, 48], easing="in-out")
    check_result(bpy.context.view_layer.objects.active, expected, 1, figure_size(keys))


def test_bake_key_poses_undo(scene, addon):
    objects = make_keys()
    select(*objects)
    bpy.ops.ed.undo_push(message="keys")
    before = snapshot()
    # As from the UI: an operator called from Python pushes an undo step only when asked.
    assert bpy.ops.object.stick_morph_bake_sequence("EXEC_DEFAULT", True, frame_step=6) == {"FINISHED"}
    after = snapshot()
    assert after != before
    bpy.ops.ed.undo()
    assert snapshot() == before
    assert not any(o.get("stick_morph_role") == "sequence_result" for o in bpy.data.objects)
    bpy.ops.ed.redo()
    assert snapshot() == after


def test_redo_keeps_the_keys_and_the_start(scene, addon):
    """Redo re-runs with the keys and the start frame the first run took,
    whatever the selection and the current frame are then."""
    objects = make_keys()
    select(*objects)
    scene.frame_current = 7
    worlds = [world_coords(o) for o in objects]
    bpy.ops.ed.undo_push(message="keys")
    assert bpy.ops.object.stick_morph_bake_sequence("EXEC_DEFAULT", True, frame_step=5) == {"FINISHED"}
    # Copied now: undo frees the registered operators.
    last = bpy.context.window_manager.operators[-1].properties
    keys, start = last.keys, last.frame_start
    assert json.loads(keys) == [o.name for o in objects] and start == 7
    bpy.ops.ed.undo()
    select()
    bpy.context.scene.frame_current = 30
    assert bpy.ops.object.stick_morph_bake_sequence("EXEC_DEFAULT", True, keys=keys, frame_start=start,
                                                    frame_step=6) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    expected, _ = expected_frames(worlds, 19, [0, 6, 12, 18])
    check_result(result, expected, 7, figure_size(worlds))


def test_bake_key_poses_refusals_name_the_key(scene, addon):
    bake = bpy.ops.object.stick_morph_bake_sequence
    objects = make_keys()
    select(objects[0])
    assert "1 selected: 'Wave_1'" in operator_fails(bake)
    select(*objects)
    for obj, frame in zip(objects, (1, 10, 8, 20)):
        obj.stick_morph_key_frame = frame
    message = operator_fails(bake)
    assert "key 3 ('Wave_3') is at frame 8, not after key 2 ('Wave_2') at frame 10" in message, message
    for obj in objects:
        obj.stick_morph_key_frame = 0
    message = operator_fails(bake, motion="BARYCENTRIC")
    assert "Rigid motion only" in message, message
    # A mirror image between keys 2 and 3 by index: the engine's report,
    # named. (Automatic would match it where the module matches key poses:
    # the mirrored man is the man with his arms and legs swapped.)
    mirrored = [[-x, y] for x, y in POSES[2]]
    bpy.data.objects.remove(objects[2])
    objects[2] = make_mesh_object("Wave_3", mirrored, EDGES, pose_matrix(2))
    bpy.context.view_layer.update()
    select(*objects)
    message = operator_fails(bake, correspondence="INDEX")
    assert "key 2 ('Wave_2') and key 3 ('Wave_3')" in message and "mirror image" in message, message
    # By index, a key with another vertex count.
    bpy.data.objects.remove(objects[2])
    objects[2] = make_mesh_object("Wave_3", POSES[2] + [[9.0, 9.0]], EDGES, pose_matrix(2))
    bpy.context.view_layer.update()
    select(*objects)
    message = operator_fails(bake, correspondence="INDEX")
    assert "key 3 ('Wave_3') has 12" in message, message


def drawn_separately():
    """The keys, selected, key 3 drawn with its right forearm in two edges
    (12 vertices): (objects, key 3's edges)."""
    objects = make_keys()
    pose = list(POSES[2]) + [list((np.asarray(POSES[2][5]) + np.asarray(POSES[2][6])) / 2)]
    edges = [e for e in EDGES if e != [5, 6]] + [[5, 11], [11, 6]]
    bpy.data.objects.remove(objects[2])
    objects[2] = make_mesh_object("Wave_3", pose, edges, pose_matrix(2))
    bpy.context.view_layer.update()
    select(*objects)
    return objects, edges


def test_matched_keys_when_the_module_matches(scene, addon):
    seq = sequence_module()
    if not seq.supports_matching():
        pytest.skip("this stickmorph module's morph_key_poses has no correspond= (keys drawn separately)")
    objects, edges = drawn_separately()
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=10, frame_start=1) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    worlds = [world_coords(o) for o in objects]
    plane = addon_import("plane").fit_plane_of(worlds, "AUTO")
    projected = [addon_import("plane").project(w, plane) for w in worlds]
    all_edges = [np.asarray(EDGES), np.asarray(EDGES), np.asarray(edges), np.asarray(EDGES)]
    engine = addon.core.load_engine()
    engine_result = engine.morph_key_poses([xy for xy, _ in projected], all_edges, frames=31,
                                           keys_at=[0, 10, 20, 30], correspond="auto")
    assert len(result.data.vertices) == engine_result["frames"].shape[1] == 12
    size = figure_size(worlds)
    # Every key is shown exactly (its own vertices where the places say).
    for k, world in enumerate(worlds):
        got = evaluated_world(result, 1 + 10 * k)
        vertex = np.asarray(engine_result["places"][k]["vertex"])
        assert np.abs(got[vertex >= 0] - world[vertex[vertex >= 0]]).max() <= 1e-6 * size, k
    for f in range(31):
        got = evaluated_world(result, 1 + f)
        d = got - plane.origin
        xy = np.stack([d @ plane.u, d @ plane.v], axis=1)
        assert np.abs(xy - engine_result["frames"][f]).max() <= 1e-6 * size, f


def test_automatic_matches_keys_incompatible_by_index(scene, addon):
    seq = sequence_module()
    if not seq.supports_matching():
        pytest.skip("this stickmorph module's morph_key_poses has no correspond= (keys drawn separately)")
    objects = make_keys()
    # Key 3 mirrored: by index a mirror image, matched the man with his arms and legs swapped.
    bpy.data.objects.remove(objects[2])
    objects[2] = make_mesh_object("Wave_3", [[-x, y] for x, y in POSES[2]], EDGES, pose_matrix(2))
    bpy.context.view_layer.update()
    select(*objects)
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=6, frame_start=1) == {"FINISHED"}
    assert bpy.context.scene.stick_morph.last_correspondence == "Matched"
    result = bpy.context.view_layer.objects.active
    size = figure_size([world_coords(o) for o in objects])
    for k, obj in enumerate(objects):  # every key shown at its frame (as a set of points)
        got = evaluated_world(result, 1 + 6 * k)
        assert np.abs(np.sort(got, axis=0) - np.sort(world_coords(obj), axis=0)).max() <= 1e-6 * size, k


def pin(obj, name, vertex):
    obj.vertex_groups.new(name=name).add([vertex], 1.0, "REPLACE")


def test_pins_of_neighbouring_keys(scene, addon):
    seq = sequence_module()
    if not seq.supports_matching():
        pytest.skip("this stickmorph module's morph_key_poses has no correspond= (keys drawn separately)")
    objects, _ = drawn_separately()
    for obj in objects:  # the left hand, vertex 4 in every key
        pin(obj, "pin.hand", 4)
    assert bpy.ops.object.stick_morph_bake_sequence(frame_step=6, frame_start=1) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    size = figure_size([world_coords(o) for o in objects])
    for k, obj in enumerate(objects):
        assert np.abs(evaluated_world(result, 1 + 6 * k)[4] - world_coords(obj)[4]).max() <= 1e-6 * size, k
    # A pin group missing in a neighbour is named.
    objects[3].vertex_groups.remove(objects[3].vertex_groups["pin.hand"])
    select(*objects)
    message = operator_fails(bpy.ops.object.stick_morph_bake_sequence)
    assert "'pin.hand' is in 'Wave_3' but not in 'Wave_4'" in message, message
    message = operator_fails(bpy.ops.object.stick_morph_bake_sequence, correspondence="INDEX")
    assert "pins need Correspondence (Match) Automatic or By Shape" in message, message


def test_a_module_without_matching_or_easing_refuses_them(scene, addon, monkeypatch):
    """A module whose morph_key_poses lacks correspond= or easing= (the
    module before issue 28's matching and easing; simulated where the module
    has them) gives a clear report, never a wrong result."""
    seq = sequence_module()
    if seq.supports_matching():
        monkeypatch.setattr(seq, "supports_matching", lambda engine=None: False)
    if seq.supports_easing():
        monkeypatch.setattr(seq, "supports_easing", lambda engine=None: False)
    objects, edges = drawn_separately()
    message = operator_fails(bpy.ops.object.stick_morph_bake_sequence)
    assert "the vertex counts differ" in message and "cannot match key poses" in message, message
    objects = make_keys(names=("Other_1", "Other_2", "Other_3", "Other_4"))
    select(*objects)
    message = operator_fails(bpy.ops.object.stick_morph_bake_sequence, easing="IN_OUT")
    assert "Easing of key poses needs a newer stickmorph module" in message, message


# ------------------------------------------------- Rebake Shape Keys ----

def make_animated(frames=(1, 13, 25, 37, 49), shown=(None, 1, 2, 3, None), name="Waver"):
    """One mesh: basis pose 1, shape keys Pose 2 .. Pose 4, animated pose to
    pose: at frames[i] the key shown[i] is 1 and the others 0 (None: the basis)."""
    obj = make_mesh_object(name, POSES[0], EDGES, Matrix.Translation((1.0, 2.0, 0.5)) @ TILT)
    obj.shape_key_add(name="Basis", from_mix=False)
    blocks = []
    for k in (1, 2, 3):
        block = obj.shape_key_add(name=f"Pose {k + 1}", from_mix=False)
        for point, (x, y) in zip(block.data, POSES[k]):
            point.co = (x, y, 0.0)
        blocks.append(block)
    for frame, on in zip(frames, shown):
        for k, block in enumerate(blocks):
            block.value = 1.0 if on == k + 1 else 0.0
            block.keyframe_insert("value", frame=frame)
    bpy.context.view_layer.update()
    select(obj)
    return obj, blocks


def animation_state(obj):
    """The shape keys' animation: action name, every keyframe and handle, every key's points."""
    baking = addon_import("baking")
    key = obj.data.shape_keys
    curves = []
    for block in key.key_blocks[1:]:
        curve = baking.find_fcurve(key.animation_data, f'key_blocks["{block.name}"].value')
        curves.append([(tuple(p.co), tuple(p.handle_left), tuple(p.handle_right), p.interpolation)
                       for p in curve.keyframe_points])
    shapes = [tuple(x for point in block.data for x in point.co) for block in key.key_blocks]
    return key.animation_data.action.name, curves, shapes, [b.value for b in key.key_blocks]


def shape_world(obj, k):
    matrix = np.array(obj.matrix_world)
    co = np.array([p.co[:] for p in obj.data.shape_keys.key_blocks[k].data], dtype=np.float64)
    return co @ matrix[:3, :3].T + matrix[:3, 3]


def test_rebake_shape_keys_is_the_engine_motion(scene, addon):
    obj, blocks = make_animated()
    bpy.context.scene.frame_set(20)
    before = animation_state(obj)
    assert bpy.ops.object.stick_morph_rebake_shape_keys() == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    assert result is not obj and result.get("stick_morph_role") == "rebake_result"
    assert result.get("stick_morph_source") == obj.name
    # The user's object, its shape keys and action untouched.
    assert animation_state(obj) == before
    assert obj.data.shape_keys.animation_data.action != result.data.shape_keys.animation_data.action
    keys = [shape_world(obj, k) for k in (0, 1, 2, 3, 0)]
    expected, engine_result = expected_frames(keys, 49, [0, 12, 24, 36, 48])
    size = figure_size(keys)
    check_result(result, expected, 1, size)
    for k, frame in enumerate((1, 13, 25, 37, 49)):
        assert np.abs(evaluated_world(result, frame) - keys[k]).max() <= 1e-6 * size
    assert (scene.frame_start, scene.frame_end) == (1, 49)


def test_rebake_holds_a_repeated_pose(scene, addon):
    obj, _ = make_animated(frames=(1, 11, 21, 31), shown=(None, 1, 1, 2))
    assert bpy.ops.object.stick_morph_rebake_shape_keys() == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    keys = [shape_world(obj, k) for k in (0, 1, 1, 2)]
    expected, _ = expected_frames(keys, 31, [0, 10, 20, 30], hold=[False, True, True, False])
    size = figure_size(keys)
    check_result(result, expected, 1, size)
    for frame in range(11, 22):
        assert np.abs(evaluated_world(result, frame) - keys[1]).max() <= 1e-6 * size, frame


def test_rebake_undo(scene, addon):
    obj, _ = make_animated()
    bpy.ops.ed.undo_push(message="animated")
    before = snapshot()
    state = animation_state(obj)
    assert bpy.ops.object.stick_morph_rebake_shape_keys("EXEC_DEFAULT", True) == {"FINISHED"}
    after = snapshot()
    assert after != before
    bpy.ops.ed.undo()
    assert snapshot() == before
    assert animation_state(bpy.data.objects["Waver"]) == state
    bpy.ops.ed.redo()
    assert snapshot() == after


def test_rebake_refuses_what_is_not_pose_to_pose(scene, addon):
    rebake = bpy.ops.object.stick_morph_rebake_shape_keys
    obj, blocks = make_animated()
    blocks[0].value = 0.5
    blocks[0].keyframe_insert("value", frame=13)
    message = operator_fails(rebake)
    assert "at frame 13 the shape key 'Pose 2' is 0.5" in message, message
    blocks[0].value = 1.0
    blocks[0].keyframe_insert("value", frame=13)
    blocks[2].value = 1.0
    blocks[2].keyframe_insert("value", frame=25)  # Pose 3 is on there too
    message = operator_fails(rebake)
    assert "at frame 25 the shape keys 'Pose 3', 'Pose 4' are all on" in message, message
    # A mesh without shape keys, and not a mesh.
    plain = make_mesh_object("Plain", POSES[0], EDGES)
    select(plain)
    assert "no shape keys" in operator_fails(rebake)
    empty = bpy.data.objects.new("Empty", None)
    scene.collection.objects.link(empty)
    select(empty)
    assert "not a mesh" in operator_fails(rebake)


def test_panel_draws_the_key_pose_buttons(scene, addon):
    from test_ui import draw
    make_keys()
    main = draw(bpy.types.VIEW3D_PT_stick_morph, bpy.context)
    assert ("operator", "object.stick_morph_bake_sequence") in main
    assert ("operator", "object.stick_morph_rebake_shape_keys") in main
    sub = draw(bpy.types.VIEW3D_PT_stick_morph_key_poses, bpy.context)
    assert {r[1] for r in sub if r[0] == "prop"} >= {"key_collection", "frame_step", "loop", "hold"}


def test_the_key_pose_sample_bakes_both_ways(addon, addon_name):
    """blend_samples/key_poses/stick_man_wave.blend: the four meshes of the
    collection wave_keys at their own key frames, and the mesh whose shape
    keys go through the same poses, give the same motion."""
    path = os.path.join(ROOT, "blend_samples", make_samples.KEY_POSES_DIR, f"{make_samples.WAVE_NAME}.blend")
    assert bpy.ops.wm.open_mainfile(filepath=path, load_ui=False) == {"FINISHED"}
    assert addon_name in bpy.context.preferences.addons
    objects = list(bpy.data.collections["wave_keys"].objects)
    assert [o.stick_morph_key_frame for o in objects] == [1, 25, 49, 73]
    select()
    assert bpy.ops.object.stick_morph_bake_sequence(collection="wave_keys") == {"FINISHED"}
    keyed = bpy.context.view_layer.objects.active
    worlds = [world_coords(o) for o in objects]
    expected, _ = expected_frames(worlds, 73, [0, 24, 48, 72])
    check_result(keyed, expected, 1, figure_size(worlds))
    animated = bpy.data.objects["wave_shape_keys"]
    select(animated)
    assert bpy.ops.object.stick_morph_rebake_shape_keys() == {"FINISHED"}
    rebaked = bpy.context.view_layer.objects.active
    assert rebaked.get("stick_morph_source") == "wave_shape_keys"
    keys = [shape_world(animated, k) for k in (0, 1, 2, 3, 0)]
    expected, _ = expected_frames(keys, 97, [0, 24, 48, 72, 96])
    check_result(rebaked, expected, 1, figure_size(keys))
    assert (bpy.context.scene.frame_start, bpy.context.scene.frame_end) == (1, 97)
