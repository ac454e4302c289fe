"""Every error is an ERROR report and leaves the scene exactly as it was."""

import re

import bpy
import numpy as np
import pytest

from conftest import PAIRS, TREE, make_mesh_object, make_pair, select, snapshot


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


def test_not_two_mesh_objects(scene, addon):
    source, target = make_pair("tree")
    select(source)
    assert "select two mesh objects" in bake_fails()
    select()
    assert "0 selected" in bake_fails()
    camera = bpy.data.objects.new("Cam", bpy.data.cameras.new("Cam"))
    scene.collection.objects.link(camera)
    select(source, camera)
    message = bake_fails()
    assert "not two mesh objects" in message and "'Cam'" in message
    select(source, target, camera)
    assert "3 selected" in bake_fails()
    assert "no object named 'Nope'" in bake_fails(source="Nope", target="Target")
    assert "same object" in bake_fails(source="Source", target="Source")


def test_meshes_with_faces(scene, addon):
    xy = [[0, 0], [1, 0], [0, 1]]
    source = make_mesh_object("FaceA", xy, [], faces=[(0, 1, 2)])
    target = make_mesh_object("FaceB", [[0, 0], [2, 0], [0, 1]], [], faces=[(0, 1, 2)])
    select(source, target)
    message = bake_fails()
    assert "'FaceA' has 1 face" in message and "edge-only" in message


def test_different_vertex_counts(scene, addon):
    source = make_mesh_object("A", [[0, 0], [1, 0], [2, 1]], [[0, 1], [1, 2]])
    target = make_mesh_object("B", [[0, 0], [1, 0]], [[0, 1]])
    select(source, target)
    message = bake_fails()
    assert "different vertex counts" in message and "3" in message and "2" in message


def test_different_edge_sets(scene, addon):
    source = make_mesh_object("A", [[0, 0], [1, 0], [2, 1]], [[0, 1], [1, 2]])
    target = make_mesh_object("B", [[0, 0], [1, 0], [2, 1]], [[0, 1], [0, 2]])
    select(source, target)
    message = bake_fails()
    assert "different edges" in message and "1-2" in message and "0-2" in message


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


def test_crossing_edges_are_named(scene, addon):
    # 0-1 and 2-3 cross in the source.
    source = make_mesh_object("Bowtie", [[0, 0], [2, 2], [2, 0], [0, 2]], [[0, 1], [1, 2], [2, 3]])
    target = make_mesh_object("Zigzag", [[0, 0], [1, 2], [2, 0], [3, 2]], [[0, 1], [1, 2], [2, 3]])
    select(source, target)
    message = bake_fails()
    assert "crossing edges" in message and "'Bowtie'" in message
    assert "0 (0-1)" in message and "2 (2-3)" in message


def test_mirror_image(scene, addon):
    source_xy, _, edges = TREE
    mirrored = [[-x, y] for x, y in source_xy]
    source = make_mesh_object("Tree", source_xy, edges)
    target = make_mesh_object("Mirrored", mirrored, edges)
    select(source, target)
    message = bake_fails()
    assert "mirror image" in message and "'Mirrored'" in message and "'Tree'" in message
    assert "vertex 0" in message  # the junction


def test_incompatible_rotation_names_the_vertex(scene, addon):
    # The same tree with two arms swapped around the junction (not a mirror).
    source_xy, _, edges = TREE
    target_xy = [list(p) for p in source_xy]
    target_xy[1], target_xy[2], target_xy[3], target_xy[4] = [-0.5, 0.9], [-1.0, 1.8], [1, 0], [2, 0.2]
    target_xy[5], target_xy[6] = [0.6, -0.9], [0.8, -1.9]
    source = make_mesh_object("T1", source_xy, edges)
    target = make_mesh_object("T2", target_xy, edges)
    select(source, target)
    message = bake_fails()
    assert "incompatible" in message and "vertex 0" in message


def test_engine_error_disconnected(scene, addon):
    xy = [[0, 0], [1, 0], [3, 0], [4, 1]]
    source = make_mesh_object("Apart", xy, [[0, 1], [2, 3]])
    target = make_mesh_object("Apart2", [[0, 0], [1, 1], [3, 0], [4, 2]], [[0, 1], [2, 3]])
    select(source, target)
    message = bake_fails()
    assert "not connected" in message and "'Apart'" in message


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
