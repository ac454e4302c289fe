"""The saved baked file renders visible geometry in a Blender without the add-on."""

import os
import subprocess
import tempfile

import bpy
import numpy as np
from mathutils import Matrix

from conftest import make_pair, world_coords

CHECK_NO_ADDON = """
import sys, bpy
# The legacy add-on is stick_morph, the extension bl_ext.<repository>.stick_morph.
assert not [a.module for a in bpy.context.preferences.addons if a.module.split(".")[-1] == "stick_morph"], "add-on enabled"
assert not any("stick_morph" in m.split(".") for m in sys.modules), "add-on loaded"
for key in bpy.data.shape_keys:
    assert key.animation_data is None or len(key.animation_data.drivers) == 0
for name in dir(bpy.app.handlers):
    handlers = getattr(bpy.app.handlers, name)
    if isinstance(handlers, list):
        assert not [h for h in handlers if "stick" in getattr(h, "__module__", "")], name
assert bpy.context.scene.render.engine == "BLENDER_WORKBENCH"
print("STICKMORPH_NO_ADDON_OK")
"""


def alpha_pixels(path):
    image = bpy.data.images.load(path)
    try:
        width, height = image.size
        assert (width, height) == (160, 120)
        pixels = np.empty(width * height * 4, dtype=np.float32)
        image.pixels.foreach_get(pixels)
        return pixels.reshape(height, width, 4)
    finally:
        bpy.data.images.remove(image)


def test_saved_file_renders_without_the_addon(scene, addon):
    source, target = make_pair("tree")
    frame_count = 10
    assert bpy.ops.object.stick_morph_bake(frame_count=frame_count, frame_start=1) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active

    # An orthographic camera looking straight at the figures' plane.
    fitted = addon.core.fit_plane(world_coords(source), world_coords(target), "AUTO")
    both = np.vstack([world_coords(source), world_coords(target)])
    size = float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    scene.collection.objects.link(camera)
    rotation = Matrix(np.stack([fitted.u, fitted.v, fitted.normal], axis=1).tolist())
    camera.matrix_world = Matrix.Translation(tuple(fitted.origin + 3 * size * fitted.normal)) @ rotation.to_4x4()
    camera.data.type = "ORTHO"
    camera.data.ortho_scale = 1.2 * size
    camera.data.clip_end = 10 * size
    scene.camera = camera
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x, scene.render.resolution_y = 160, 120
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = True
    if hasattr(scene.render.image_settings, "media_type"):  # 5.x: the formats of one media type
        scene.render.image_settings.media_type = "IMAGE"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGBA"

    with tempfile.TemporaryDirectory(prefix="stickmorph-render-") as tmp:
        blend = os.path.join(tmp, "baked.blend")
        bpy.ops.wm.save_as_mainfile(filepath=blend, copy=True)
        # A fresh Blender with a user config of its own: the add-on is neither
        # installed nor enabled there.
        env = dict(os.environ, BLENDER_USER_SCRIPTS=os.path.join(tmp, "scripts"),
                   BLENDER_USER_CONFIG=os.path.join(tmp, "config"))
        env.pop("STICKMORPH_BLENDER_SANDBOX", None)
        frames = (1, frame_count)
        command = [bpy.app.binary_path, "-b", "--factory-startup", blend, "--python-exit-code", "1",
                   "--python-expr", CHECK_NO_ADDON, "-o", os.path.join(tmp, "frame_####"),
                   "-F", "PNG", "-f", ",".join(map(str, frames))]
        run = subprocess.run(command, env=env, capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
        assert "STICKMORPH_NO_ADDON_OK" in run.stdout
        images = []
        for frame in frames:
            path = os.path.join(tmp, f"frame_{frame:04d}.png")
            assert os.path.exists(path), run.stdout[-3000:]
            images.append(alpha_pixels(path))
    for frame, image in zip(frames, images):
        covered = int((image[..., 3] > 0.5).sum())
        print(f"frame {frame}: {covered} figure pixels of {160 * 120}")
        assert covered > 100, f"frame {frame}: only {covered} figure pixels"
        assert covered < 0.6 * 160 * 120, f"frame {frame}: {covered} pixels, not a stick figure"
    # The figure moved: the two frames differ.
    assert ((images[0][..., 3] > 0.5) != (images[1][..., 3] > 0.5)).sum() > 50
    assert result.name in bpy.data.objects


def test_tubes_render_in_full_and_play_light_in_the_viewport(scene, addon):
    # Issue 29: a render evaluates the tubes at full quality (a 12-sided tube,
    # a 12 x 6 UV sphere at every vertex: what they always rendered); the
    # viewport's depsgraph, which playback evaluates, gets a 4-sided tube and
    # 8 x 4 spheres only where a chain ends or branches. Counted exactly from
    # the figure's vertex degrees: Mesh to Curve puts a degree-2 vertex on one
    # spline and a vertex of degree d != 2 at the end of d splines.
    from conftest import addon_import
    baking = addon_import("baking")
    source, target = make_pair("tree")
    assert bpy.ops.object.stick_morph_bake(frame_count=5, frame_start=1) == {"FINISHED"}
    result = bpy.context.view_layer.objects.active
    degree = np.zeros(len(result.data.vertices), dtype=int)
    for edge in result.data.edges:
        degree[list(edge.vertices)] += 1
    assert (degree == 2).any() and (degree >= 3).any() and (degree == 1).any()
    spline_points = int(sum(d if d != 2 else 1 for d in degree))
    joints = int((degree != 2).sum())

    def sphere_vertices(segments, rings):
        return segments * (rings - 1) + 2

    render_expected = (baking.RENDER_PROFILE * spline_points
                       + len(degree) * sphere_vertices(*baking.RENDER_SPHERE))
    viewport_expected = (baking.VIEWPORT_PROFILE * spline_points
                         + joints * sphere_vertices(*baking.VIEWPORT_SPHERE))

    seen = []

    def evaluated(scene_, depsgraph):  # frame_change_post gets the render's own depsgraph in a render
        seen.append((depsgraph.mode, len(result.evaluated_get(depsgraph).data.vertices)))

    scene.frame_set(3)
    bpy.app.handlers.frame_change_post.append(evaluated)
    try:
        scene.frame_set(2)
        scene.render.engine = "BLENDER_WORKBENCH"
        scene.render.resolution_x, scene.render.resolution_y = 64, 48
        with tempfile.TemporaryDirectory(prefix="stickmorph-render-") as tmp:
            camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
            scene.collection.objects.link(camera)
            scene.camera = camera
            scene.render.filepath = os.path.join(tmp, "frame")
            bpy.ops.render.render()
    finally:
        bpy.app.handlers.frame_change_post.remove(evaluated)
    assert ("VIEWPORT", viewport_expected) in seen, seen
    assert ("RENDER", render_expected) in seen, seen
    assert {mode for mode, _ in seen} == {"VIEWPORT", "RENDER"}, seen
