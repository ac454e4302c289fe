"""Build the sample .blend files of blend_samples/ from the JSON stick-figure pairs.

Run inside Blender (3.4):

    blender -b --factory-startup --python-exit-code 1 \
        --python blend_samples/make_samples.py -- [--output-dir blend_samples] \
        [--figures-dir blend_samples/figures] [--pairs NAME ...]

For every pair <name> (figures/<name>.source.json and figures/<name>.target.json, written
by make_figures.py) it writes <output-dir>/<name>.blend with
  - two edge-only mesh objects, <name>_source and <name>_target: the figure's vertices
    in the object's XY plane (z = 0) exactly as in the JSON, its edges as in the JSON;
    the objects are moved (object location only) so that the source stands on the
    left, the target on the right, both centred vertically on y = 0;
  - an orthographic camera looking down at both, a sun light;
  - Workbench, 960x540, opaque film, light gray world, frames 1..60.
The result depends only on the JSON files, so rebuilding gives the same scenes.
"""

import argparse
import json
import os
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
PAIRS = ["monkey_to_player", "scorpion_to_dragonfly", "s_to_u", "polygon", "triangulation"]

RESOLUTION = (960, 540)
FRAMES = (1, 60)
WORLD_GRAY = (0.8, 0.8, 0.8)
GAP = 0.25      # space between the two figures, as a fraction of the wider one
MARGIN = 1.15   # camera view / tight box around both figures


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(
        prog="make_samples.py",
        description="Build blend_samples/<pair>.blend from the JSON stick-figure pairs.")
    parser.add_argument("--output-dir", default=HERE,
                        help="where to write <pair>.blend (default: blend_samples)")
    parser.add_argument("--figures-dir", default=os.path.join(HERE, "figures"),
                        help="where <pair>.source.json and <pair>.target.json are "
                             "(default: blend_samples/figures)")
    parser.add_argument("--pairs", nargs="+", default=PAIRS, metavar="NAME",
                        help="pairs to build (default: all five)")
    return parser.parse_args(argv)


def load_figure(path):
    with open(path, encoding="utf-8") as f:
        figure = json.load(f)
    vertices = [(float(x), float(y), 0.0) for x, y in figure["vertices"]]
    edges = [(int(a), int(b)) for a, b in figure["edges"]]
    n = len(vertices)
    for k, (a, b) in enumerate(edges):
        if not (0 <= a < n and 0 <= b < n) or a == b:
            raise ValueError(f"{path}: edge {k} [{a}, {b}] is not an edge of {n} vertices")
    return vertices, edges


def bounds(vertices):
    xs = [v[0] for v in vertices]
    ys = [v[1] for v in vertices]
    return min(xs), min(ys), max(xs), max(ys)


def add_figure(scene, name, vertices, edges, location):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, edges, [])
    mesh.validate()
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.location = location
    scene.collection.objects.link(obj)
    return obj


def build_scene(pair, figures_dir):
    source = load_figure(os.path.join(figures_dir, f"{pair}.source.json"))
    target = load_figure(os.path.join(figures_dir, f"{pair}.target.json"))
    if len(source[0]) != len(target[0]):
        raise ValueError(f"{pair}: {len(source[0])} source vertices but "
                         f"{len(target[0])} target vertices")

    # An empty file: no default cube, camera, light or world.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.name = pair

    # Place the figures side by side: source on the left, target on the right, a gap
    # between them, both boxes centred on y = 0.  Only object locations change.
    s_x0, s_y0, s_x1, s_y1 = bounds(source[0])
    t_x0, t_y0, t_x1, t_y1 = bounds(target[0])
    s_w, s_h = s_x1 - s_x0, s_y1 - s_y0
    t_w, t_h = t_x1 - t_x0, t_y1 - t_y0
    gap = GAP * max(s_w, t_w, s_h, t_h)
    total_w = s_w + gap + t_w
    total_h = max(s_h, t_h)
    left = -total_w / 2.0
    source_location = (left - s_x0, 0.0 - (s_y0 + s_y1) / 2.0, 0.0)
    target_location = (left + s_w + gap - t_x0, 0.0 - (t_y0 + t_y1) / 2.0, 0.0)
    add_figure(scene, f"{pair}_source", source[0], source[1], source_location)
    add_figure(scene, f"{pair}_target", target[0], target[1], target_location)

    # Orthographic camera above the origin looking down -Z, framing both figures.
    aspect = RESOLUTION[0] / RESOLUTION[1]
    camera_data = bpy.data.cameras.new(f"{pair}_camera")
    camera_data.type = "ORTHO"
    camera_data.sensor_fit = "HORIZONTAL"
    camera_data.ortho_scale = MARGIN * max(total_w, total_h * aspect)
    camera_data.clip_start = 0.1
    camera_data.clip_end = 100.0
    camera = bpy.data.objects.new(f"{pair}_camera", camera_data)
    camera.location = (0.0, 0.0, 10.0)
    camera.rotation_euler = (0.0, 0.0, 0.0)
    scene.collection.objects.link(camera)
    scene.camera = camera

    light_data = bpy.data.lights.new(f"{pair}_light", type="SUN")
    light_data.energy = 3.0
    light = bpy.data.objects.new(f"{pair}_light", light_data)
    light.location = (0.0, 0.0, 12.0)
    light.rotation_euler = (0.3, 0.2, 0.0)
    scene.collection.objects.link(light)

    world = bpy.data.worlds.new(f"{pair}_world")
    world.use_nodes = False
    world.color = WORLD_GRAY
    scene.world = world

    render = scene.render
    render.engine = "BLENDER_WORKBENCH"
    render.resolution_x, render.resolution_y = RESOLUTION
    render.resolution_percentage = 100
    render.film_transparent = False
    scene.display.shading.light = "STUDIO"
    scene.display.shading.color_type = "OBJECT"
    scene.frame_start, scene.frame_end = FRAMES
    scene.frame_set(FRAMES[0])
    return scene


def main():
    args = parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    for pair in args.pairs:
        build_scene(pair, args.figures_dir)
        # Overwrite in place: no NAME.blend1 backup (factory settings keep one version;
        # build_scene's factory reset restores that, so set it just before saving).
        bpy.context.preferences.filepaths.save_version = 0
        path = os.path.abspath(os.path.join(args.output_dir, f"{pair}.blend"))
        bpy.ops.wm.save_as_mainfile(filepath=path, compress=True)
        print(f"wrote {path} ({os.path.getsize(path)} bytes)")


if __name__ == "__main__":
    main()
