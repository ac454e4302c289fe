"""Meshes with several loose parts (issue 14) bake: a dotted i (a stem and a
dot, a vertex on no edge), dots alone and a ring in a ring, in the factory startup scene
(its cube, camera and light stay as they are). The result has every vertex,
every part moves, frame start is the source and the last frame the target;
the dot renders (a sphere of the tubes' radius). A pair whose inner ring
moves out of the outer one is an ERROR report naming the objects and the
part, and the scene is unchanged.

The parts' numbering and the messages are tested without Blender in
tests/python/test_addon_parts.py.
"""

import bpy
import numpy as np
import pytest

from conftest import make_mesh_object, select, snapshot, source_matrix, target_matrix, world_coords
from test_correspond import add_group, attribute, key_world
from test_errors import bake_fails

# A dotted i: the stem 0-1-2, the dot 3. The target bends the stem and
# moves the dot along.
I_SOURCE = [[0.0, 0.0], [0.0, 1.0], [0.0, 2.0], [0.0, 3.0]]
I_TARGET = [[0.0, 0.0], [0.4, 0.9], [0.6, 1.9], [1.1, 2.7]]
I_EDGES = [[0, 1], [1, 2]]


def ring(count, radius, turn=0.0, centre=(0.0, 0.0)):
    angles = turn + 2 * np.pi * np.arange(count) / count
    return np.stack([centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles)], axis=1)


def inner(turn_degrees=0.0, centre=(0.0, 0.0)):
    """The inner ring: a quadrilateral without symmetry (so that a matching
    can pair it only one way), turned by turn_degrees about its centre."""
    angles = np.radians(np.array([0.0, 80.0, 170.0, 260.0]) + turn_degrees)
    radii = np.array([0.7, 0.5, 0.8, 0.6])
    return np.stack([centre[0] + radii * np.cos(angles), centre[1] + radii * np.sin(angles)], axis=1)


def subdivided_hexagon(radius):
    """A hexagon with its edges 0-1 and 3-4 halved: 8 vertices, the corners
    at the hexagon's arc-length fractions k / 6."""
    corners = ring(6, radius)
    points = [corners[0], (corners[0] + corners[1]) / 2, corners[1], corners[2], corners[3],
              (corners[3] + corners[4]) / 2, corners[4], corners[5]]
    return np.array(points)


def cycle(first, count):
    return [[first + k, first + (k + 1) % count] for k in range(count)]


# A hexagon 0..5 around a quadrilateral 6..9; in the target the inner ring is
# turned by 30 degrees (and the outer one a little larger).
RINGS_SOURCE = np.vstack([ring(6, 2.0), inner()]).tolist()
RINGS_TARGET = np.vstack([ring(6, 2.3), inner(30.0)]).tolist()
RINGS_EDGES = cycle(0, 6) + cycle(6, 4)
# The inner ring out of the outer one.
RINGS_OUTSIDE = np.vstack([ring(6, 2.0), inner(centre=(4.0, 0.0))]).tolist()


@pytest.fixture
def factory_scene(addon):
    """The factory startup file (Cube, Light, Camera; Blender runs with
    --factory-startup), the add-on still enabled."""
    bpy.ops.wm.read_homefile()
    assert addon.__name__ in bpy.context.preferences.addons
    assert "Cube" in bpy.data.objects
    return bpy.context.scene


def make(name, xy, edges, matrix):
    obj = make_mesh_object(name, xy, edges, matrix)
    bpy.context.view_layer.update()
    return obj


def bake(**kwargs):
    assert bpy.ops.object.stick_morph_bake(**kwargs) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    assert result.get("stick_morph_role") == "result"
    return result


def size_of(*objects):
    both = np.vstack([world_coords(o) for o in objects])
    return float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))


def check_frames(scene, result, source, target, frame_count, parts, tolerance):
    """Frame start (key 0) is the source, the last frame the target, the
    scene's frames show the keys, and every part moves."""
    keys = result.data.shape_keys.key_blocks
    assert len(keys) == frame_count
    first, last = key_world(result, 0), key_world(result, frame_count - 1)
    assert np.abs(first - world_coords(source)).max() <= tolerance
    assert np.abs(last - world_coords(target)).max() <= tolerance
    from conftest import evaluated_world
    assert np.abs(evaluated_world(result, scene.frame_start) - first).max() <= tolerance
    assert np.abs(evaluated_world(result, scene.frame_end) - last).max() <= tolerance
    middle = key_world(result, frame_count // 2)
    for part in parts:
        assert np.linalg.norm(middle[part] - first[part], axis=1).max() > 100 * tolerance, part
        assert np.linalg.norm(last[part] - first[part], axis=1).max() > 1000 * tolerance, part


def evaluated_render_mesh(obj, frame):
    """World coordinates of the result as rendered (the tubes' modifier on) at a frame."""
    bpy.context.scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        matrix = np.array(evaluated.matrix_world)
        return co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]
    finally:
        evaluated.to_mesh_clear()


def test_a_dotted_i_bakes_and_its_dot_renders(factory_scene, addon, capfd):
    scene = factory_scene
    source = make("i", I_SOURCE, I_EDGES, source_matrix())
    target = make("i.001", I_TARGET, I_EDGES, target_matrix())
    select(source, target)
    others = {o.name: np.array(o.matrix_world).tobytes() for o in bpy.data.objects if o not in (source, target)}
    result = bake(frame_count=8, frame_start=3)
    assert len(result.data.vertices) == 4 and len(result.data.edges) == 2
    # The dot is a vertex on no edge of the result too.
    assert {v for e in result.data.edges for v in e.vertices} == {0, 1, 2}
    tolerance = 1e-5 * size_of(source, target)
    check_frames(scene, result, source, target, 8, [[0, 1, 2], [3]], tolerance)
    # The factory scene's objects are as they were.
    assert {o.name: np.array(o.matrix_world).tobytes() for o in bpy.data.objects
            if o.name in others} == others
    out = capfd.readouterr().out
    assert f"'{result.name}': 4 vertices, 2 parts (1 dot), " in out, out

    # The dot renders: the tubes put a sphere of the tubes' radius at every
    # vertex, the dot included, at every frame.
    modifier = result.modifiers[0]
    assert modifier.type == "NODES"
    radius = addon.core.tube_radius(size_of(source, target), 0.01)
    for k in (0, 4, 7):
        dot = key_world(result, k)[3]
        rendered = evaluated_render_mesh(result, 3 + k)
        near = np.linalg.norm(rendered - dot, axis=1)
        assert (near <= 1.01 * radius).sum() >= 20, k  # a UV sphere of 12 segments and 6 rings
        # ... and the stem's tubes stay away from it.
        assert (near <= 3 * radius).sum() == (near <= 1.01 * radius).sum(), k


def test_a_mesh_of_dots_only_bakes(factory_scene, addon):
    # Three vertices and no edge at all (a "therefore" sign), each a part.
    scene = factory_scene
    source = make("Dots", [[0.0, 0.0], [2.0, 0.0], [1.0, 1.6]], [], source_matrix())
    target = make("Dots.001", [[0.0, 0.3], [2.4, 0.0], [1.5, 2.0]], [], target_matrix())
    select(source, target)
    result = bake(frame_count=5)
    assert len(result.data.vertices) == 3 and len(result.data.edges) == 0
    tolerance = 1e-5 * size_of(source, target)
    check_frames(scene, result, source, target, 5, [[0], [1], [2]], tolerance)
    # Each dot renders as a sphere.
    radius = addon.core.tube_radius(size_of(source, target), 0.01)
    rendered = evaluated_render_mesh(result, scene.frame_start + 2)
    for dot in key_world(result, 2):
        assert (np.linalg.norm(rendered - dot, axis=1) <= 1.01 * radius).sum() >= 20


@pytest.mark.parametrize("correspondence", ["INDEX_OR_MATCH", "MATCH"])
def test_a_ring_in_a_ring_bakes_and_its_inner_ring_turns(factory_scene, addon, correspondence):
    scene = factory_scene
    source = make("Ring", RINGS_SOURCE, RINGS_EDGES, source_matrix())
    target = make("Ring.001", RINGS_TARGET, RINGS_EDGES, target_matrix())
    select(source, target)
    result = bake(frame_count=7, correspondence=correspondence)
    assert len(result.data.vertices) == 10 and len(result.data.edges) == 10
    tolerance = 1e-5 * size_of(source, target)
    check_frames(scene, result, source, target, 7, [list(range(6)), list(range(6, 10))], tolerance)
    if correspondence == "MATCH":  # the rings pair as numbered: the inner one turns, not jumps
        assert attribute(result, "stick_morph_target_vertex").tolist() == list(range(10))
    assert scene.stick_morph.last_correspondence == ("By index" if correspondence == "INDEX_OR_MATCH"
                                                      else "Matched: 10 (0 dummies)")
    # The inner ring stays inside the outer one in every frame.
    for k in range(7):
        frame = key_world(result, k)
        centre = frame[:6].mean(axis=0)
        assert np.linalg.norm(frame[6:] - centre, axis=1).max() < np.linalg.norm(frame[:6] - centre, axis=1).min()


def test_rings_drawn_separately_are_matched_ring_to_ring(factory_scene, addon):
    # The target drawn again: the inner ring first (0..3), the outer ring
    # with 8 vertices (4..11), its edges listed backwards.
    scene = factory_scene
    source = make("Ring", RINGS_SOURCE, RINGS_EDGES, source_matrix())
    target_xy = np.vstack([inner(30.0), subdivided_hexagon(2.3)]).tolist()
    target = make("Ring.001", target_xy, (cycle(0, 4) + cycle(4, 8))[::-1], target_matrix())
    select(source, target)
    result = bake(frame_count=5)
    assert len(result.data.vertices) == 12  # 10 and a dummy for each of the outer ring's 2 extra vertices
    target_vertex = attribute(result, "stick_morph_target_vertex")
    assert set(target_vertex[6:10].tolist()) == {0, 1, 2, 3}  # inner to inner
    assert set(target_vertex[:6].tolist()) | set(target_vertex[10:].tolist()) == set(range(4, 12))
    tolerance = 1e-5 * size_of(source, target)
    assert np.abs(key_world(result, 4) - world_coords(target)[target_vertex]).max() <= tolerance
    assert np.abs(key_world(result, 0)[:10] - world_coords(source)).max() <= tolerance
    assert scene.stick_morph.last_correspondence == "Matched: 12 (2 dummies)"


def test_pins_on_dots_choose_which_dot_goes_where(factory_scene, addon):
    # A stem with two dots beside it (4 and 5); pinned, dot 4 of the source
    # ends on dot 5 of the target and the other way round.
    xy = [[0.0, 0.0], [0.0, 1.0], [0.0, 2.0], [0.0, 3.0], [-0.8, 3.6], [0.8, 3.6]]
    edges = [[0, 1], [1, 2], [2, 3]]
    source = make("Dots", xy, edges, source_matrix())
    target = make("Dots.001", xy, edges, target_matrix())
    add_group(source, "pin.a", [4])
    add_group(target, "pin.a", [5])
    add_group(source, "pin.b", [5])
    add_group(target, "pin.b", [4])
    select(source, target)
    result = bake(frame_count=5)
    target_vertex = attribute(result, "stick_morph_target_vertex")
    assert target_vertex[[4, 5]].tolist() == [5, 4]
    tolerance = 1e-5 * size_of(source, target)
    assert np.abs(key_world(result, 4) - world_coords(target)[target_vertex]).max() <= tolerance


@pytest.mark.parametrize("correspondence", ["INDEX_OR_MATCH", "INDEX", "MATCH"])
def test_an_inner_ring_moved_outside_is_an_error_and_changes_nothing(factory_scene, addon, correspondence):
    source = make("Ring", RINGS_SOURCE, RINGS_EDGES, source_matrix())
    target = make("Ring.001", RINGS_OUTSIDE, RINGS_EDGES, target_matrix())
    select(source, target)
    before = snapshot()
    message = bake_fails(correspondence=correspondence)  # the scene is compared there too
    if correspondence == "MATCH":
        # The matching's refusal, naming a part: the parts cannot be paired
        # at their nesting depths.
        assert ("Stick Morph: 'Ring' and 'Ring.001': a part changes face: " in message
                or "Stick Morph: cannot match 'Ring' and 'Ring.001': " in message), message
        assert "part 1 (vertices 6, 7, 8, 9)" in message, message
    else:
        # By index, and Automatic, which checks by index first: the part that changes face.
        assert "Stick Morph: 'Ring' and 'Ring.001': a part changes face: the parts nest differently: " \
               "part 1 (vertices 6, 7, 8, 9) lies inside part 0" in message, message
        assert ("matched by shape" in message) == (correspondence == "INDEX_OR_MATCH"), message
    assert snapshot() == before
    assert not [o for o in bpy.data.objects if o.get("stick_morph_role")]
