"""Every error is an ERROR report and leaves the scene exactly as it was.

The kinds of bad input (selections, faces, vertex counts, edge sets, figure
defects, incompatible pairs, ...) are in tests/data/bad_inputs/catalogue.json
and run by test_bad_inputs.py; these are the cases that need more than one
bake or an exact number.
"""

import re

import bpy
import numpy as np
import pytest

from conftest import TREE, addon_import, make_mesh_object, make_pair, select, snapshot


def bake_fails(**kwargs):
    """Runs the operator expecting an ERROR report; returns its message."""
    before = snapshot()
    with pytest.raises(RuntimeError) as error:
        bpy.ops.object.stick_morph_bake(**kwargs)
    assert snapshot() == before, "the scene changed"
    message = str(error.value)
    assert message.startswith("Error:"), message
    assert "Stick Morph" in message
    return message


def test_not_planar(scene, addon):
    source_xy, target_xy, edges = TREE
    z = np.zeros(len(source_xy))
    z[4] = 0.3
    source = make_mesh_object("Bent", source_xy, edges, z=z)
    target = make_mesh_object("Flat", target_xy, edges)
    select(source, target)
    message = bake_fails(plane="XY")
    assert "not planar" in message and "'Bent'" in message and "vertex 4" in message
    deviation = float(re.search(r"largest deviation ([0-9.eE+-]+)", message).group(1))
    # Distance from the figure's own plane parallel to XY (through its mean height).
    assert deviation == pytest.approx(0.3 * (1 - 1 / len(source_xy)), rel=1e-5)
    message = bake_fails()  # AUTO: no plane holds both either
    assert "not planar" in message and "largest deviation" in message


def test_failed_bake_keeps_the_previous_result(scene, addon):
    source, target = make_pair("tree")
    assert bpy.ops.object.stick_morph_bake(frame_count=4) == {"FINISHED"}
    select(source, target)
    # Now break the source: a crossing.
    source.data.vertices[2].co = (-1.0, -1.0, 0.0)
    source.data.vertices[6].co = (1.0, 1.0, 0.0)
    bake_fails()
    assert len([o for o in bpy.data.objects if o.get("stick_morph_role") == "result"]) == 1


def test_poll_explains_itself(scene, addon):
    source, target = make_pair("polyline")
    bpy.context.view_layer.objects.active = source
    bpy.ops.object.mode_set(mode="EDIT")
    try:
        assert not bpy.ops.object.stick_morph_bake.poll()
        with pytest.raises(RuntimeError, match="Object Mode"):
            bpy.ops.object.stick_morph_bake()
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")


def test_an_incompatible_pair_is_checked_once(scene, addon, monkeypatch):
    # By index the morph checks compatibility as it starts and its exception
    # carries the report (kind, vertices, reason): the bake needs no check of
    # its own. Automatic morphs by index too and, when that morph refuses
    # the pair, matches it and morphs the match (issue 27: no separate
    # check_compatibility first), so this pair (the tree's arms pair the
    # other way round) is checked once and morphed twice.
    engine = addon_import("core").load_engine()
    calls = []
    check, morph = engine.check_compatibility, engine.morph
    monkeypatch.setattr(engine, "check_compatibility",
                        lambda *args, **kwargs: calls.append("check") or check(*args, **kwargs))
    monkeypatch.setattr(engine, "morph", lambda *args, **kwargs: calls.append("morph") or morph(*args, **kwargs))
    source_xy, target_xy, edges = TREE
    source = make_mesh_object("Source", source_xy, edges)
    target = make_mesh_object("Target", np.asarray(target_xy) * [-1.0, 1.0], edges)
    select(source, target)
    message = bake_fails(correspondence="INDEX")
    assert "'Target' is a mirror image of 'Source'" in message and "(vertex " in message, message
    assert calls == ["morph"]
    calls.clear()
    assert bpy.ops.object.stick_morph_bake(frame_count=3) == {"FINISHED"}
    assert calls == ["morph", "morph"]
    assert bpy.context.scene.stick_morph.last_correspondence == "Matched: 7 (0 dummies)"
