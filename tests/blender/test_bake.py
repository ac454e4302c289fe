"""Baking compatible pairs: the result equals the engine's morph in world space."""

import bpy
import numpy as np
import pytest

from conftest import (PAIRS, TILT, evaluated_world, make_pair, select, snapshot, world_coords)


def bake(**kwargs):
    result = bpy.ops.object.stick_morph_bake(**kwargs)
    assert result == {"FINISHED"}, result
    return bpy.context.view_layer.objects.active


def expected_frames(addon, source, target, frame_count, easing="NONE", plane="AUTO", motion="RIGID", **options):
    """The engine's morph mapped to world space, computed here from the meshes'
    world coordinates and the engine directly (not through compute_morph).

    RIGID (the default motion): exactly frame_count engine frames, the
    engine easing them ("in-out"); the height between the figures' planes
    moves with the eased time. BARYCENTRIC and LINEAR: with easing, frames
    picked from an oversampled uniform morph at the eased times. options go
    to stickmorph.morph as they are (engine names: rotation="ccw", ...)."""
    core = addon.core
    engine = core.load_engine()
    src, tgt = world_coords(source), world_coords(target)
    edges = np.array([e.vertices[:] for e in source.data.edges])
    fitted = core.fit_plane(src, tgt, plane)
    u, v, n, o = fitted.u, fitted.v, fitted.normal, fitted.origin
    # The plane's frame is orthonormal and right-handed.
    assert np.allclose(np.array([u, v, n]) @ np.array([u, v, n]).T, np.eye(3), atol=1e-12)
    assert np.allclose(np.cross(u, v), n, atol=1e-12)
    src_xy = np.stack([(src - o) @ u, (src - o) @ v], axis=1)
    tgt_xy = np.stack([(tgt - o) @ u, (tgt - o) @ v], axis=1)
    k = np.arange(frame_count) / (frame_count - 1)
    eased = k if easing == "NONE" else k * k * (3 - 2 * k)
    if motion == "RIGID":
        morph = engine.morph(src_xy, tgt_xy, edges, frames=frame_count, method="rigid",
                             easing="in-out" if easing == "IN_OUT" else None, **options)
        frames = morph["frames"]
        times = eased
    else:
        m = frame_count if easing == "NONE" else (frame_count - 1) * core.EASE_OVERSAMPLING + 1
        morph = engine.morph(src_xy, tgt_xy, edges, frames=m, method=motion.lower(), **options)
        index = np.rint(eased * (m - 1)).astype(int)
        frames = morph["frames"][index]
        times = morph["times"][index]
    hs, ht = (src - o) @ n, (tgt - o) @ n
    heights = (1 - times)[:, None] * hs + times[:, None] * ht
    world = o + frames[..., :1] * u + frames[..., 1:] * v + heights[..., None] * n
    return world, frames, src_xy, edges, morph


def figure_size(source, target):
    both = np.vstack([world_coords(source), world_coords(target)])
    return float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))


@pytest.mark.parametrize("motion", ["RIGID", "BARYCENTRIC"])
@pytest.mark.parametrize("key", sorted(PAIRS))
def test_bake_matches_engine_in_world_space(scene, addon, key, motion):
    """RIGID, the default (not passed), and BARYCENTRIC, what every bake was
    before the motion option: the frames are the engine's with that method."""
    source, target = make_pair(key)
    before_source = (world_coords(source).tobytes(), tuple(map(tuple, source.matrix_world)))
    before_target = (world_coords(target).tobytes(), tuple(map(tuple, target.matrix_world)))
    frame_count, frame_start = 12, 5
    result = bake(frame_count=frame_count, frame_start=frame_start,
                  **({} if motion == "RIGID" else {"motion": motion}))

    # The result is a new object, active and the only one selected.
    assert result is not None and result not in (source, target)
    assert result.get("stick_morph_role") == "result"
    assert result.select_get()
    assert [o.name for o in bpy.context.selected_objects] == [result.name]
    # Source and target untouched.
    assert (world_coords(source).tobytes(), tuple(map(tuple, source.matrix_world))) == before_source
    assert (world_coords(target).tobytes(), tuple(map(tuple, target.matrix_world))) == before_target
    assert source.data.shape_keys is None and target.data.shape_keys is None
    # Same vertices, in order, and the same edges.
    assert len(result.data.vertices) == len(source.data.vertices)
    assert {tuple(sorted(e.vertices)) for e in result.data.edges} == \
        {tuple(sorted(e.vertices)) for e in source.data.edges}

    # The plane found is the tilted plane of the test.
    normal = np.array(np.array(TILT.to_3x3()) @ np.array([0.0, 0.0, 1.0]))
    fitted = addon.core.fit_plane(world_coords(source), world_coords(target), "AUTO")
    assert abs(abs(float(fitted.normal @ normal)) - 1.0) < 1e-9

    expected, frames_xy, src_xy, edges, morph = expected_frames(addon, source, target, frame_count,
                                                                motion=motion)
    assert morph["stats"]["method"] == motion.lower()
    size = figure_size(source, target)
    tolerance = 1e-5 * size
    engine = addon.core.load_engine()
    for k in range(frame_count):
        got = evaluated_world(result, frame_start + k)
        error = np.abs(got - expected[k]).max()
        assert error <= tolerance, f"frame {k}: off by {error} (size {size})"
        # Each frame is a valid stick figure compatible with the source.
        d = got - fitted.origin
        xy = np.stack([d @ fitted.u, d @ fitted.v], axis=1)
        assert engine.check_compatibility(src_xy, xy, edges), f"frame {k}"
    # Starts at the source and ends at the target, in world space.
    assert np.abs(evaluated_world(result, frame_start) - world_coords(source)).max() <= tolerance
    assert np.abs(evaluated_world(result, frame_start + frame_count - 1) - world_coords(target)).max() <= tolerance
    # Before and after the morph: held at the ends.
    assert np.abs(evaluated_world(result, frame_start - 3) - world_coords(source)).max() <= tolerance
    assert np.abs(evaluated_world(result, frame_start + frame_count + 3) - world_coords(target)).max() <= tolerance
    # The scene's frame range is the morph's.
    assert (scene.frame_start, scene.frame_end) == (frame_start, frame_start + frame_count - 1)


def test_renderable_geometry_and_no_runtime_dependencies(scene, addon):
    source, target = make_pair("tree")
    result = bake(frame_count=6)
    assert [m.type for m in result.modifiers] == ["NODES"]
    group = result.modifiers[0].node_group
    # Built-in nodes only.
    assert all(node.bl_idname.startswith(("GeometryNode", "NodeGroup", "FunctionNode", "ShaderNode"))
               for node in group.nodes), [n.bl_idname for n in group.nodes]
    # The radius reached the modifier (5.x: modifier.properties.inputs.<id>.value,
    # earlier modifier[id]) and its tubes: the figures' size times the option.
    from conftest import addon_import
    baking = addon_import("baking")
    modifier = result.modifiers[0]
    radius = baking.get_modifier_input(modifier, baking.radius_identifier(group))
    expected = addon.core.tube_radius(figure_size(source, target), 0.01)
    assert radius == pytest.approx(expected, rel=1e-6)
    if bpy.app.version >= (5, 0, 0):
        value = getattr(modifier.properties.inputs, baking.radius_identifier(group)).value
        assert value == pytest.approx(expected, rel=1e-6)
    scene.frame_set(3)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = result.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        assert len(mesh.polygons) > 10 * len(result.data.edges)
        co = np.array([v.co[:] for v in mesh.vertices]) @ np.array(evaluated.matrix_world)[:3, :3].T \
            + np.array(evaluated.matrix_world)[:3, 3]
    finally:
        evaluated.to_mesh_clear()
    # The spheres at the joints reach about one radius out of the frame's
    # plane (parallel to the figures' planes, between them).
    fitted = addon.core.fit_plane(world_coords(source), world_coords(target), "AUTO")
    frame_height = float(np.mean((evaluated_world(result, 3) - fitted.origin) @ fitted.normal))
    heights = np.abs((co - fitted.origin) @ fitted.normal - frame_height)
    assert 0.8 * expected <= heights.max() <= 1.01 * expected + 1e-6, (heights.max(), expected)
    key = result.data.shape_keys
    assert not key.use_relative
    assert key.animation_data.drivers[:] == []
    assert result.animation_data is None or result.animation_data.drivers[:] == []


@pytest.mark.parametrize("motion", ["RIGID", "BARYCENTRIC"])
def test_ease_in_out(scene, addon, motion):
    # RIGID: the engine's easing="in-out" on its even-speed frames;
    # BARYCENTRIC: frames picked from an oversampled uniform morph.
    source, target = make_pair("polygon_dangling")
    frame_count = 9
    result = bake(frame_count=frame_count, frame_start=1, easing="IN_OUT", motion=motion)
    expected, _, _, _, morph = expected_frames(addon, source, target, frame_count, easing="IN_OUT",
                                               motion=motion)
    assert len(morph["frames"]) == (frame_count if motion == "RIGID"
                                    else (frame_count - 1) * addon.core.EASE_OVERSAMPLING + 1)
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(frame_count):
        assert np.abs(evaluated_world(result, 1 + k) - expected[k]).max() <= tolerance, k
    # Eased: the first step is shorter than the middle one.
    first = np.abs(expected[1] - expected[0]).max()
    middle = np.abs(expected[5] - expected[4]).max()
    assert first < middle


@pytest.mark.parametrize("plane", ["XY", "XZ", "YZ"])
def test_axis_planes(scene, addon, plane):
    source_xy, target_xy, edges = PAIRS["tree"]
    from conftest import make_mesh_object
    from mathutils import Matrix
    # The figures drawn in the chosen axis plane.
    # Local (x, y) of the mesh onto the plane's two axes, so that its 2D view is the same.
    to_plane = {"XY": Matrix.Identity(4),
                "XZ": Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1))),
                "YZ": Matrix(((0, 0, 1, 0), (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 0, 1)))}[plane]
    source = make_mesh_object("S", source_xy, edges, Matrix.Translation((0.5, 0.5, 0.5)) @ to_plane)
    target = make_mesh_object("T", target_xy, edges, Matrix.Translation((3, 3, 3)) @ to_plane)
    bpy.context.view_layer.update()
    select(source, target)
    result = bake(frame_count=5, plane=plane)
    expected, *_ = expected_frames(addon, source, target, 5, plane=plane)
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(5):
        assert np.abs(evaluated_world(result, 1 + k) - expected[k]).max() <= tolerance


def test_explicit_names_and_options(scene, addon):
    source, target = make_pair("polyline", tilted=False)
    select()  # nothing selected: names are given
    result = bake(source="Source", target="Target", frame_count=7, steiner="sg2001", weights="uniform",
                  enclosure_sides=8, renderable=False, show_triangulation=True)
    assert result.modifiers[:] == []
    expected, *_ = expected_frames(addon, source, target, 7, steiner="sg2001", weights="uniform",
                                   enclosure_sides=8)
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(7):
        assert np.abs(evaluated_world(result, 1 + k) - expected[k]).max() <= tolerance
    helpers = [o for o in bpy.data.objects if o.get("stick_morph_role") == "triangulation"]
    assert len(helpers) == 1
    helper = helpers[0]
    assert helper.hide_render and len(helper.data.polygons) > 0
    _, _, _, _, morph = expected_frames(addon, source, target, 7, steiner="sg2001", weights="uniform",
                                        enclosure_sides=8)
    assert len(helper.data.polygons) == len(morph["triangulation"]["triangles"])
    assert [k.name for k in helper.data.shape_keys.key_blocks] == ["Source", "Target"]
    settings = scene.stick_morph
    assert settings.last_result == result.name and settings.last_frames == 7
    assert settings.last_vertices == 5


def test_preferences_give_the_defaults(scene, addon, addon_name):
    prefs = bpy.context.preferences.addons[addon_name].preferences
    saved = prefs.frame_count
    prefs.frame_count = 4
    try:
        make_pair("polyline")
        result = bake()
        assert len(result.data.shape_keys.key_blocks) == 4
    finally:
        prefs.frame_count = saved


def test_rebake_replaces_previous_result(scene, addon):
    source, target = make_pair("tree")
    first = bake(frame_count=5, show_triangulation=True)
    name = first.name
    counts = (len(bpy.data.objects), len(bpy.data.meshes), len(bpy.data.actions), len(bpy.data.shape_keys),
              len(bpy.data.node_groups))
    select(source, target)
    second = bake(frame_count=9, show_triangulation=True)
    assert second.name == name
    results = [o for o in bpy.data.objects if o.get("stick_morph_role") == "result"]
    assert results == [second]
    assert len(second.data.shape_keys.key_blocks) == 9
    assert (len(bpy.data.objects), len(bpy.data.meshes), len(bpy.data.actions), len(bpy.data.shape_keys),
            len(bpy.data.node_groups)) == counts
    # A different pair is a different result.
    select(target, source)
    third = bake(frame_count=3)
    assert third.name != name and len([o for o in bpy.data.objects if o.get("stick_morph_role") == "result"]) == 2


def test_undo_restores(scene, addon):
    make_pair("polygon_dangling")
    bpy.ops.ed.undo_push(message="before bake")
    before = snapshot()
    # As from the UI: an operator called from Python pushes an undo step only when asked.
    assert bpy.ops.object.stick_morph_bake("EXEC_DEFAULT", True, frame_count=5) == {"FINISHED"}
    after = snapshot()
    assert after != before
    assert any(o.get("stick_morph_role") == "result" for o in bpy.data.objects)
    bpy.ops.ed.undo()
    assert snapshot() == before
    assert not any(o.get("stick_morph_role") == "result" for o in bpy.data.objects)
    bpy.ops.ed.redo()
    assert snapshot() == after


def test_paper_s_to_u(scene, addon):
    """The paper's Figure 8c figures (tests/data/paper), drawn in the XZ plane."""
    import os
    from conftest import ROOT, make_mesh_object
    from mathutils import Matrix
    engine = addon.core.load_engine()
    data = os.path.join(ROOT, "tests", "data", "paper")
    s = engine.load_figure(os.path.join(data, "s_to_u.source.json"))
    u = engine.load_figure(os.path.join(data, "s_to_u.target.json"))
    to_xz = Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    source = make_mesh_object("S", s["vertices"], s["edges"], Matrix.Translation((0, 2, 0)) @ to_xz)
    target = make_mesh_object("U", u["vertices"], u["edges"], Matrix.Translation((5, 2, 0)) @ to_xz)
    bpy.context.view_layer.update()
    select(source, target)
    frame_count = 20
    result = bake(frame_count=frame_count)
    expected, _, src_xy, edges, _ = expected_frames(addon, source, target, frame_count)
    tolerance = 1e-5 * figure_size(source, target)
    for k in range(frame_count):
        got = evaluated_world(result, 1 + k)
        assert np.abs(got - expected[k]).max() <= tolerance, k
        assert np.allclose(got[:, 1], 2.0, atol=tolerance)  # stays in the plane y = 2
