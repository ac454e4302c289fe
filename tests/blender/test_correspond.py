"""Figures drawn separately (issue 13) at the add-on: meshes with different
vertex counts, numbering or edges bake through the Correspondence setting
(the panel's Match), pins come from vertex groups pin.* in both meshes, Pin
Selected Vertices and Clear Pins make and remove them, and every refusal is
an ERROR report that leaves the scene as it was.

The choice between by index and matched, the pins' checks and the heights
of dummy vertices are tested without Blender in
tests/python/test_addon_correspondence.py; here the meshes, vertex groups,
operators and the result object.
"""

import bmesh
import bpy
import numpy as np
import pytest

from conftest import (TREE, POLYLINE, addon_import, make_mesh_object, select, snapshot, source_matrix,
                      target_matrix, world_coords)
from test_errors import bake_fails
from test_ui import FakeLayout

# The tree of conftest drawn again, separately: turned and scaled, numbered
# from the end of the arm along +x, with a vertex more on two arms (9
# vertices, not 7: target 1 halves the source's edge 1-2 and 6 its edge
# 0-5) and the edges listed in another order. Counter-clockwise the
# source's arms end at 2, 4, 6, the target's at 0, 5, 8.
_TURN = np.array([[np.cos(0.5), np.sin(0.5)], [-np.sin(0.5), np.cos(0.5)]])
DENSE_XY = (np.array([[2, 0.2], [1.5, 0.1], [1, 0], [0, 0], [-0.5, 0.9], [-1, 1.8], [-0.25, -0.45],
                      [-0.5, -0.9], [-0.8, -1.9]]) @ _TURN).tolist()
DENSE_EDGES = [[3, 4], [0, 1], [7, 6], [2, 3], [4, 5], [1, 2], [3, 6], [7, 8]]


def make_drawn_pair():
    """The tree and its separately drawn target in tilted parallel planes."""
    source_xy, _, edges = TREE
    source = make_mesh_object("Source", source_xy, edges, source_matrix())
    target = make_mesh_object("Target", DENSE_XY, DENSE_EDGES, target_matrix())
    bpy.context.view_layer.update()
    select(source, target)
    return source, target


def bake(**kwargs):
    assert bpy.ops.object.stick_morph_bake(**kwargs) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    assert result.get("stick_morph_role") == "result"
    return result


def key_world(obj, k):
    """Shape key k of obj in world space (absolute keys: key k is frame k)."""
    block = obj.data.shape_keys.key_blocks[k]
    co = np.empty(len(block.data) * 3, dtype=np.float32)
    block.data.foreach_get("co", co)
    matrix = np.array(obj.matrix_world)
    return co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]


def distance_to_drawing(points, vertices, edges):
    """Each point's distance to the nearest edge of a drawing (world space)."""
    a, b = vertices[np.asarray(edges)[:, 0]], vertices[np.asarray(edges)[:, 1]]
    d = b - a
    best = np.full(len(points), np.inf)
    for p_index, p in enumerate(points):
        t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d), 0.0, 1.0)
        best[p_index] = np.linalg.norm(a + t[:, None] * d - p, axis=1).min()
    return best


def size_of(*objects):
    both = np.vstack([world_coords(o) for o in objects])
    return float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))


def mesh_edges(obj):
    return [tuple(e.vertices) for e in obj.data.edges]


def attribute(obj, name):
    data = obj.data.attributes[name].data
    values = np.empty(len(data), dtype=np.int32)
    data.foreach_get("value", values)
    return values


def add_group(obj, name, vertices):
    group = obj.vertex_groups.new(name=name)
    if vertices:
        group.add(list(vertices), 1.0, "REPLACE")
    return group


def group_members(obj):
    """{group name: sorted vertex indices} of obj (Object Mode data)."""
    members = {group.name: [] for group in obj.vertex_groups}
    for vertex in obj.data.vertices:
        for element in vertex.groups:
            members[obj.vertex_groups[element.group].name].append(vertex.index)
    return members


# ---------------------------------------------------------------- baking ----

def test_meshes_with_different_vertex_counts_bake_the_matched_figure(scene, addon, capfd):
    source, target = make_drawn_pair()
    before = (world_coords(source).tobytes(), world_coords(target).tobytes())
    result = bake(frame_count=6, show_triangulation=True)
    # Every vertex of both meshes is kept: 7 of the source, and a dummy on a
    # source edge for each of the target's 2 extra vertices.
    m = 9
    assert len(result.data.vertices) == m and len(result.data.shape_keys.key_blocks) == 6
    assert len(result.data.edges) == m - 1  # still a tree, on the matched vertices
    source_vertex = attribute(result, "stick_morph_source_vertex")
    target_vertex = attribute(result, "stick_morph_target_vertex")
    assert source_vertex[:7].tolist() == list(range(7)) and (source_vertex[7:] == -1).all()
    assert sorted(target_vertex.tolist()) == list(range(9))

    size = size_of(source, target)
    tolerance = 1e-5 * size
    src, tgt = world_coords(source), world_coords(target)
    first, last = key_world(result, 0), key_world(result, 5)
    # The first key lies on the source drawing, its first 7 vertices the
    # source's own; the last on the target drawing, every target vertex
    # where the attribute says.
    assert np.abs(first[:7] - src).max() <= tolerance
    assert distance_to_drawing(first, src, mesh_edges(source)).max() <= tolerance
    assert distance_to_drawing(last, tgt, mesh_edges(target)).max() <= tolerance
    assert np.abs(last - tgt[target_vertex]).max() <= tolerance
    # The arms pair as drawn: the source's ends 2, 4, 6 end on the target's 0, 5, 8.
    assert target_vertex[[0, 2, 4, 6]].tolist() == [3, 0, 5, 8]
    # The source and the target themselves are untouched.
    assert (world_coords(source).tobytes(), world_coords(target).tobytes()) == before

    # The triangulation helper holds the matched figure's vertices first.
    helper = bpy.data.objects[result.name + "_triangulation"]
    assert len(helper.data.vertices) > m
    assert np.abs(key_world(helper, 0)[:m] - first).max() <= tolerance
    assert np.abs(key_world(helper, 1)[:m] - last).max() <= tolerance

    # The report and the panel say how the pair was matched.
    out = capfd.readouterr().out
    assert "9 vertices" in out and "matched (the vertex counts differ): 9 vertices, 2 dummies " \
                                  "(2 on 'Source', 0 on 'Target')" in out, out
    assert scene.stick_morph.last_correspondence == "Matched: 9 (2 dummies)"
    assert scene.stick_morph.last_vertices == m
    labels = [r[1] for r in draw(bpy.types.VIEW3D_PT_stick_morph) if r[0] == "label"]
    assert "Matched: 9 (2 dummies)" in labels


def test_a_pair_by_index_bakes_as_before(scene, addon, capfd):
    source_xy, target_xy, edges = TREE
    source = make_mesh_object("Source", source_xy, edges)
    target = make_mesh_object("Target", target_xy, edges)
    select(source, target)
    result = bake(frame_count=4)
    assert len(result.data.vertices) == 7 and "stick_morph_source_vertex" not in result.data.attributes
    assert np.abs(key_world(result, 3) - world_coords(target)).max() <= 1e-5 * size_of(source, target)
    assert scene.stick_morph.last_correspondence == "By index"
    assert "; by index; rigid" in capfd.readouterr().out


def test_by_shape_matches_a_shuffled_numbering(scene, addon):
    # The same figure turned and numbered otherwise: By Shape finds each
    # vertex again, and so does Automatic (by index the edges differ).
    source_xy, _, edges = TREE
    order = [3, 6, 0, 5, 1, 4, 2]  # new vertex k is old vertex order[k]
    new_of_old = np.argsort(order)
    turned = (np.array(source_xy) @ _TURN * 0.8)[order]
    source = make_mesh_object("Source", source_xy, edges, source_matrix())
    target = make_mesh_object("Target", turned, new_of_old[np.array(edges)].tolist(), target_matrix())
    bpy.context.view_layer.update()
    for setting in ("MATCH", "INDEX_OR_MATCH"):
        select(source, target)
        result = bake(frame_count=3, correspondence=setting)
        assert len(result.data.vertices) == 7
        assert attribute(result, "stick_morph_target_vertex").tolist() == new_of_old.tolist()
        expected = world_coords(target)[new_of_old]
        assert np.abs(key_world(result, 2) - expected).max() <= 1e-5 * size_of(source, target)
    assert bpy.context.scene.stick_morph.last_correspondence == "Matched: 7 (0 dummies)"


def test_by_index_refuses_meshes_drawn_separately(scene, addon):
    make_drawn_pair()
    message = bake_fails(correspondence="INDEX")
    assert "different vertex counts: 'Source' has 7 vertices, 'Target' has 9" in message
    assert "Correspondence (Match) is By Index" in message and "Automatic or By Shape" in message


@pytest.mark.parametrize("case", ["topology", "exterior"])
def test_unmatchable_meshes_are_an_error_and_change_nothing(scene, addon, case):
    if case == "topology":  # a tree and a polyline
        source = make_mesh_object("Source", TREE[0], TREE[2])
        target = make_mesh_object("Target", POLYLINE[1], POLYLINE[2])
    else:  # a triangle with a stalk outside, and inside
        edges = [[0, 1], [1, 2], [2, 0], [0, 3]]
        source = make_mesh_object("Source", [[0, 0], [2, 0], [1, 1.5], [-1, -0.5]], edges)
        target = make_mesh_object("Target", [[0, 0], [2, 0], [1, 1.5], [1, 0.5]], edges)
    select(source, target)
    objects, meshes = sorted(bpy.data.objects.keys()), sorted(bpy.data.meshes.keys())
    message = bake_fails()  # snapshot() before and after are equal
    assert message.startswith("Error: Stick Morph: cannot match 'Source' and 'Target': "), message
    if case == "topology":
        assert "topologies cannot be matched" in message and "the target 2 ends and no junction" in message
    else:
        assert "another face outside" in message and "nor are they compatible by index" in message
    assert (sorted(bpy.data.objects.keys()), sorted(bpy.data.meshes.keys())) == (objects, meshes)


# ------------------------------------------------------------------ pins ----

def test_pins_from_vertex_groups_steer_the_matching(scene, addon):
    source, target = make_drawn_pair()
    # Unpinned the source's end 2 goes to the target's end 0 (the previous
    # test); pinned to 5, and 6 to 0, the arms pair turned by one.
    add_group(source, "Group", [0, 1])  # not a pin
    add_group(source, "pin.001", [2])
    add_group(target, "pin.001", [5])
    add_group(source, "PIN_hand", [6])
    add_group(target, "PIN_hand", [0])
    result = bake(frame_count=4)
    tgt = world_coords(target)
    last = key_world(result, 3)
    tolerance = 1e-5 * size_of(source, target)
    assert np.abs(last[2] - tgt[5]).max() <= tolerance
    assert np.abs(last[6] - tgt[0]).max() <= tolerance
    assert attribute(result, "stick_morph_target_vertex")[[0, 2, 4, 6]].tolist() == [3, 5, 8, 0]
    assert bpy.context.scene.stick_morph.last_correspondence == "Matched: 9 (2 dummies)"


@pytest.mark.parametrize("case, fragments", [
    ("only_in_source", ["the pin group 'pin.009' is in 'Source' but not in 'Target'"]),
    ("empty", ["the pin group 'pin.001' of 'Target' holds no vertex", "exactly one vertex in each mesh"]),
    ("several", ["the pin group 'pin.001' of 'Source' holds 2 vertices (2, 4)"]),
    ("twice", ["vertex 2 of 'Source' is in two pin groups, 'pin.001' and 'pin.002'"]),
    ("unlike", ["the pin 'pin.001' joins vertex 2 of 'Source', an end, to vertex 1 of 'Target', inside a stroke"]),
    ("unsatisfiable", ["the pins cannot all hold", "'pin.001': vertex 2 of 'Source' to vertex 0 of 'Target'"]),
    ("by_index", ["pins need Correspondence (Match) Automatic or By Shape", "'pin.001'"]),
])
def test_bad_pins_are_an_error_naming_the_group(scene, addon, case, fragments):
    source, target = make_drawn_pair()
    groups = {
        "only_in_source": ({"pin.001": [2], "pin.009": [4]}, {"pin.001": [5]}),
        "empty": ({"pin.001": [2]}, {"pin.001": []}),
        "several": ({"pin.001": [2, 4]}, {"pin.001": [5]}),
        "twice": ({"pin.001": [2], "pin.002": [2]}, {"pin.001": [5], "pin.002": [0]}),
        "unlike": ({"pin.001": [2]}, {"pin.001": [1]}),
        "unsatisfiable": ({"pin.001": [2], "pin.002": [4]}, {"pin.001": [0], "pin.002": [8]}),
        "by_index": ({"pin.001": [2]}, {"pin.001": [5]}),
    }[case]
    for obj, named in zip((source, target), groups):
        for name, vertices in named.items():
            add_group(obj, name, vertices)
    select(source, target)
    before = {obj.name: group_members(obj) for obj in (source, target)}
    message = bake_fails(**({"correspondence": "INDEX"} if case == "by_index" else {}))
    for fragment in fragments:
        assert fragment in message, (fragment, message)
    assert {obj.name: group_members(obj) for obj in (source, target)} == before


# ---------------------------------------------------- the pin operators ----

def edit_both(source, target, vertices):
    """Multi-object Edit Mode on both meshes, with vertices[k] (a list) of
    mesh k selected."""
    select(source, target)
    bpy.ops.object.mode_set(mode="EDIT")
    assert {o.name for o in bpy.context.objects_in_mode} == {source.name, target.name}
    for obj, chosen in zip((source, target), vertices):
        mesh = bmesh.from_edit_mesh(obj.data)
        for vertex in mesh.verts:
            vertex.select_set(vertex.index in chosen)
        mesh.select_flush_mode()
        bmesh.update_edit_mesh(obj.data)


def test_pin_selected_vertices_in_multi_object_edit_mode(scene, addon):
    source, target = make_drawn_pair()
    add_group(target, "Group", [1])
    # Not in Object Mode: the poll says what to do.
    assert not bpy.ops.mesh.stick_morph_pin_selected.poll()
    try:
        edit_both(source, target, ([2], [5]))
        assert bpy.ops.mesh.stick_morph_pin_selected() == {"FINISHED"}
        edit_both(source, target, ([6], [0]))
        assert bpy.ops.mesh.stick_morph_pin_selected() == {"FINISHED"}
        # An already pinned vertex, two selected, or one mesh: refused, nothing added.
        for chosen, fragment in ((([2], [7]), "vertex 2 of 'Source' is already pinned by 'pin.001'"),
                                 (([1], [3, 4]), "select exactly one vertex in each mesh: 'Target' has 2 selected"),
                                 (([], [3]), "'Source' has 0 selected")):
            edit_both(source, target, chosen)
            names = [[g.name for g in o.vertex_groups] for o in (source, target)]
            with pytest.raises(RuntimeError) as error:
                bpy.ops.mesh.stick_morph_pin_selected()
            assert fragment in str(error.value) and str(error.value).startswith("Error: Stick Morph"), error.value
            assert [[g.name for g in o.vertex_groups] for o in (source, target)] == names
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")
    assert group_members(source) == {"pin.001": [2], "pin.002": [6]}
    assert group_members(target) == {"Group": [1], "pin.001": [5], "pin.002": [0]}

    # One mesh in Edit Mode is not a pair.
    select(source)
    bpy.ops.object.mode_set(mode="EDIT")
    try:
        with pytest.raises(RuntimeError, match="needs exactly two meshes in Edit Mode.*only 'Source' is"):
            bpy.ops.mesh.stick_morph_pin_selected()
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")

    # The bake respects the pins the operator made.
    select(source, target)
    result = bake(frame_count=3)
    tgt = world_coords(target)
    tolerance = 1e-5 * size_of(source, target)
    assert np.abs(key_world(result, 2)[2] - tgt[5]).max() <= tolerance
    assert np.abs(key_world(result, 2)[6] - tgt[0]).max() <= tolerance


def test_clear_pins_removes_only_pins(scene, addon):
    source, target = make_drawn_pair()
    add_group(source, "pin.001", [2])
    add_group(source, "Group", [0])
    add_group(target, "pin.001", [5])
    add_group(target, "Pin_other", [0])
    select(source)
    assert bpy.ops.object.stick_morph_clear_pins() == {"FINISHED"}
    assert [g.name for g in source.vertex_groups] == ["Group"]
    assert [g.name for g in target.vertex_groups] == ["pin.001", "Pin_other"]  # not selected
    # In Edit Mode too (the meshes being edited).
    try:
        edit_both(source, target, ([0], [0]))
        assert bpy.ops.object.stick_morph_clear_pins() == {"FINISHED"}
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")
    assert [g.name for g in target.vertex_groups] == []
    # Nothing left to clear: a warning, nothing changes.
    select(source, target)
    assert bpy.ops.object.stick_morph_clear_pins() == {"CANCELLED"}
    assert [g.name for g in source.vertex_groups] == ["Group"]
    select()
    assert not bpy.ops.object.stick_morph_clear_pins.poll()


# ---------------------------------------------------------------- panel ----

def draw(panel_class):
    record = []
    panel_class.draw(type("FakePanel", (), {"layout": FakeLayout(record)})(), bpy.context)
    return record


def test_the_pins_panel_counts_the_pins_and_says_what_a_bake_would_refuse(scene, addon):
    ui = addon_import("ui")
    assert bpy.types.VIEW3D_PT_stick_morph_pins.bl_parent_id == "VIEW3D_PT_stick_morph"
    source, target = make_drawn_pair()

    def labels():
        """The panel's lines, each as one text (_label_lines wraps them at
        the region's width), with the icon of its first label."""
        lines = []
        for r in draw(bpy.types.VIEW3D_PT_stick_morph_pins):
            if r[0] == "label":
                if r[2] == "BLANK1" and lines:
                    lines[-1] = (lines[-1][0] + " " + r[1], lines[-1][1])
                else:
                    lines.append((r[1], r[2]))
        return lines

    record = draw(bpy.types.VIEW3D_PT_stick_morph_pins)
    assert ("operator", "mesh.stick_morph_pin_selected") in record
    assert ("operator", "object.stick_morph_clear_pins") in record
    assert labels() == [("No pins", "PINNED")]
    add_group(source, "pin.001", [2])
    add_group(target, "pin.001", [5])
    add_group(source, "pin.002", [6])
    add_group(target, "pin.002", [0])
    add_group(target, "pin.003", [8])
    assert labels() == [("2 pins: pin.001, pin.002", "PINNED"),
                        ("'pin.003' is in 'Target', not in 'Source'", "ERROR")]
    scene.stick_morph.correspondence = "INDEX"
    assert labels()[-1] == ("Pins need Match Automatic or By Shape", "ERROR")
    # The count is that of the pair a bake would use.
    assert ui.pin_preview(bpy.context, scene.stick_morph)[0] == 2
    select(source)
    assert ui.pin_preview(bpy.context, scene.stick_morph) == (0, "Pins join vertices of two meshes", [])


def test_undo_of_a_pin_in_edit_mode(scene, addon):
    # Edit-mode undo restores the meshes' vertices and their group
    # membership, but in Blender 3.4 and 4.3 not the names of groups added
    # in Edit Mode: Blender's own Assign to New Group leaves an empty group
    # behind just the same (measured; 5.2 removes it). An empty pin group is
    # then no silent non-pin: the bake names it, and Clear Pins removes it.
    source, target = make_drawn_pair()
    try:
        edit_both(source, target, ([2], [5]))
        bpy.ops.ed.undo_push(message="before pin")
        # As from the UI: an operator called from Python pushes an undo step only when asked.
        assert bpy.ops.mesh.stick_morph_pin_selected("EXEC_DEFAULT", True) == {"FINISHED"}
        bpy.ops.ed.undo()
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")
    left = [group_members(obj) for obj in (source, target)]
    assert all(not vertices for members in left for vertices in members.values()), left
    if left != [{}, {}]:
        assert left == [{"pin.001": []}, {"pin.001": []}]
        select(source, target)
        assert "the pin group 'pin.001' of 'Source' holds no vertex" in bake_fails()
        assert bpy.ops.object.stick_morph_clear_pins() == {"FINISHED"}
    select(source, target)
    bake(frame_count=3)
