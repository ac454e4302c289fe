"""The motion option (RIGID, the default; BARYCENTRIC; LINEAR) and the rigid
motion's rotation and extra turns, through the bake operator.

The frame-by-frame comparison of RIGID and BARYCENTRIC bakes with the engine
is test_bake.py's (test_bake_matches_engine_in_world_space, test_ease_in_out);
here: the default, which way a figure turns, the LINEAR baseline's warning,
and a turn count out of range.
"""

import bpy
import numpy as np
import pytest

from conftest import TREE, addon_import, evaluated_world, make_mesh_object, select, snapshot, world_coords
from test_bake import bake, expected_frames, figure_size


def tree_and(transform, name="Turned"):
    """The tree in the XY plane (seen from above) and the tree transformed
    in that plane; selected, the second active."""
    source_xy, _, edges = TREE
    source = make_mesh_object("Tree", source_xy, edges)
    target = make_mesh_object(name, transform(np.asarray(source_xy, dtype=np.float64)), edges)
    bpy.context.view_layer.update()
    select(source, target)
    return source, target


def quarter_turn(xy):
    """A clockwise quarter turn, as seen from above: (x, y) -> (y, -x)."""
    return xy @ np.array([[0.0, -1.0], [1.0, 0.0]]) + [3.0, 0.5]


def turning_angles(frames):
    """Each frame's orientation relative to the first in the XY plane (2D
    Procrustes angle about the centroid), unwrapped: the turn so far, in degrees."""
    first = frames[0][:, :2] - frames[0][:, :2].mean(axis=0)
    angles = []
    for frame in frames:
        d = frame[:, :2] - frame[:, :2].mean(axis=0)
        angles.append(np.arctan2(np.sum(first[:, 0] * d[:, 1] - first[:, 1] * d[:, 0]), np.sum(first * d)))
    return np.degrees(np.unwrap(angles))


def test_the_default_motion_is_rigid(scene, addon, addon_name, capfd):
    common = addon_import("common")
    assert common.BakeSettings().motion == "RIGID"
    holders = {
        "operator": bpy.ops.object.stick_morph_bake.get_rna_type().properties,
        "scene settings": scene.stick_morph.bl_rna.properties,
        "preferences": bpy.context.preferences.addons[addon_name].preferences.bl_rna.properties,
    }
    for where, properties in holders.items():
        assert properties["motion"].default == "RIGID", where
        assert [item.identifier for item in properties["motion"].enum_items] == ["RIGID", "BARYCENTRIC", "LINEAR"]
        assert [item.identifier for item in properties["rotation"].enum_items] == ["SHORT", "CCW", "CW"]

    source, target = tree_and(quarter_turn)
    frame_count = 10
    result = bake(frame_count=frame_count)
    expected, _, src_xy, edges, morph = expected_frames(addon, source, target, frame_count)
    assert morph["stats"]["method"] == "rigid"
    engine = addon.core.load_engine()
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(frame_count):
        got = evaluated_world(result, 1 + k)
        assert np.abs(got - expected[k]).max() <= tolerance, k
        engine.validate(got[:, :2], edges)
        assert engine.check_compatibility(src_xy, got[:, :2], edges), k
    # A pure rotation is its own rigid guide: every inner frame follows it,
    # and the bake says so (the report, the panel's last-bake box).
    guide = morph["stats"]["rigid"]["guide_frames"]
    assert guide["exact"] + guide["blended"] == frame_count - 2 and guide["barycentric"] == 0
    out = capfd.readouterr().out
    assert f"rigid: {frame_count - 2}/{frame_count - 2} frames follow the rigid guide" in out, out
    assert scene.stick_morph.last_motion == f"Rigid guide: {frame_count - 2}/{frame_count - 2}"
    # It turns the short way, clockwise, at even speed, and stays rigid.
    angles = turning_angles([evaluated_world(result, 1 + k) for k in range(frame_count)])
    assert angles[-1] == pytest.approx(-90.0, abs=1e-3)
    assert np.allclose(np.diff(angles), -90.0 / (frame_count - 1), atol=1e-3)


@pytest.mark.parametrize("rotation, turns, degrees", [("CCW", 0, 270.0), ("CW", 0, -90.0), ("SHORT", -1, -450.0)])
def test_rotation_chooses_the_way_round(scene, addon, rotation, turns, degrees):
    """The target is the source turned by -90 degrees: CCW turns it by +270."""
    source, target = tree_and(quarter_turn)
    frame_count = 13
    result = bake(frame_count=frame_count, rotation=rotation, turns=turns)
    expected, _, _, _, morph = expected_frames(addon, source, target, frame_count,
                                               rotation=rotation.lower(), turns=turns)
    assert morph["stats"]["rigid"]["similarity"]["angle_degrees"] == pytest.approx(degrees)
    frames = [evaluated_world(result, 1 + k) for k in range(frame_count)]
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(frame_count):
        assert np.abs(frames[k] - expected[k]).max() <= tolerance, k
    angles = turning_angles(frames)
    assert angles[-1] == pytest.approx(degrees, abs=1e-3)
    assert np.allclose(np.diff(angles), degrees / (frame_count - 1), atol=1e-3)
    # Whatever the way round, it ends on the target.
    assert np.abs(frames[-1] - world_coords(target)).max() <= tolerance


def test_rotation_and_turns_do_nothing_without_rigid_motion(scene, addon):
    source, target = tree_and(quarter_turn)
    plain = bake(frame_count=6, motion="BARYCENTRIC")
    first = [evaluated_world(plain, 1 + k) for k in range(6)]
    name = plain.name
    select(source, target)
    turned = bake(frame_count=6, motion="BARYCENTRIC", rotation="CCW", turns=3)
    assert turned.name == name  # the same pair: the new result replaced the old
    for k in range(6):
        assert np.abs(evaluated_world(turned, 1 + k) - first[k]).max() == 0.0, k


def half_turn(xy):
    """Turned by 180 degrees: straight lines collapse the tree onto a point half way."""
    return -xy + [3.0, 0.5]


def test_linear_motion_bakes_and_warns_about_its_invalid_frames(scene, addon, capfd):
    source, target = tree_and(half_turn)
    frame_start, frame_count = 4, 7
    result = bake(frame_count=frame_count, frame_start=frame_start, motion="LINEAR", show_triangulation=True)
    expected, _, src_xy, edges, morph = expected_frames(addon, source, target, frame_count, motion="LINEAR")
    assert morph["stats"]["invalid_frames"] == [3] and morph["triangulation"] is None
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(frame_count):
        assert np.abs(evaluated_world(result, frame_start + k) - expected[k]).max() <= tolerance, k
    # The middle frame (scene frame 7) is every vertex on one point: the
    # bake keeps it and says so, with a WARNING naming the scene frame.
    out = capfd.readouterr().out
    warnings = [line for line in out.splitlines() if "Linear motion crosses or folds the figure" in line]
    assert len(warnings) == 1, out
    assert "in 1 of 7 frames: 7 (Rigid and Barycentric never do)" in warnings[0], warnings[0]
    assert warnings[0].lstrip().lower().startswith("warning"), warnings[0]
    assert scene.stick_morph.last_motion == "Linear: 1 invalid"
    # No triangulation to show: no helper.
    assert not [o for o in bpy.data.objects if o.get("stick_morph_role") == "triangulation"]
    # An even frame count misses the collapse: no warning.
    select(source, target)
    bake(frame_count=6, motion="LINEAR")
    out = capfd.readouterr().out
    assert "Linear motion crosses" not in out and "linear: every frame is valid" in out, out
    assert scene.stick_morph.last_motion == "Linear: all valid"


def test_turns_out_of_range_are_refused_and_change_nothing(scene, addon, monkeypatch):
    # Blender clamps the property to the engine's range, as every option's...
    limits = addon_import("core").load_engine().limits
    op = bpy.context.window_manager.operator_properties_last("object.stick_morph_bake")
    rna = bpy.ops.object.stick_morph_bake.get_rna_type().properties["turns"]
    assert (rna.hard_min, rna.hard_max) == (-limits["max_turns"], limits["max_turns"])
    saved = op.turns
    try:
        op.turns = limits["max_turns"] + 5
        assert op.turns == limits["max_turns"]
    finally:
        op.turns = saved
    # ...so a value beyond what the loaded engine takes only arrives from a
    # module whose limits differ from the add-on's copy: refused before any
    # engine work, as an ERROR report, with the scene as it was.
    engine = addon_import("core").load_engine()
    monkeypatch.setattr(engine, "limits", dict(limits, max_turns=2))
    tree_and(quarter_turn)
    bpy.ops.ed.undo_push(message="pair")
    before = snapshot()
    with pytest.raises(RuntimeError) as error:
        bpy.ops.object.stick_morph_bake(frame_count=5, turns=3)
    message = str(error.value)
    assert message.startswith("Error:") and "Stick Morph: the extra turns must be a whole number from -2 to 2, got 3" \
        in message, message
    assert snapshot() == before, "the scene changed"
    assert bpy.ops.object.stick_morph_bake(frame_count=5, turns=-2) == {"FINISHED"}
