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

It also writes <output-dir>/key_poses/stick_man_wave.blend (unless --no-key-poses), the
key-pose sample of issue 28: a stick man waving in four poses (WAVE_POSES, made here, no
JSON) as four edge meshes wave_pose_1 .. 4 in the collection wave_keys, each with its key
frame (1, 25, 49, 73) for Bake Key Poses, and as one mesh wave_shape_keys whose shape keys
are animated pose to pose for Rebake Shape Keys. In a folder of its own: the pair samples
are the *.blend files directly in blend_samples/. `--pairs` with no name writes only it.

And <output-dir>/local_timing/stick_man_lag.blend (unless --no-local-timing), the sample of
local timing (issue 31): a stick man waving, the hand lagging the arm. Two edge meshes,
lag_source and lag_target (LAG_POSES: the body bends a little, the raised forearm and the
hand turn about the elbow); the source has the vertex group `lag` (the wrist and the
fingertip at weight 1, every other vertex 0), and the scene's Stick Morph settings name the
pair, the group and an overlap of 0.3.
"""

import argparse
import json
import math
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
    parser.add_argument("--pairs", nargs="*", default=PAIRS, metavar="NAME",
                        help="pairs to build (default: all five)")
    parser.add_argument("--key-poses", action=argparse.BooleanOptionalAction, default=True,
                        help="also write key_poses/stick_man_wave.blend (default: yes)")
    parser.add_argument("--local-timing", action=argparse.BooleanOptionalAction, default=True,
                        help="also write local_timing/stick_man_lag.blend (default: yes)")
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


# ------------------------------------------------------------ key poses ----
# A stick man waving (issue 28's key poses): vertex 0 the hip, 1 the neck, 2
# the head, 3-4 left arm, 5-6 right arm, 7-8 left leg, 9-10 right leg. Edge
# i joins STICK_MAN_PARENT[i] to vertex i + 1, turned by the pose's bend i
# (degrees) from edge STICK_MAN_REFERENCE[i]'s direction (the spine's from
# the heading), as tests/cpp/figures.h's stick_man.
STICK_MAN_PARENT = (0, 1, 1, 3, 1, 5, 0, 7, 0, 9)
STICK_MAN_REFERENCE = (-1, 0, 0, 2, 0, 4, 0, 6, 0, 8)
STICK_MAN_LENGTHS = (3.0, 0.8, 1.2, 1.2, 1.2, 1.2, 1.5, 1.5, 1.5, 1.5)
# (hip position, heading, bends): standing, then the right arm up, waving.
WAVE_POSES = (
    ((0.0, 0.0), 90, (0, 0, 120, -30, -120, 30, 160, 10, -160, -10)),
    ((0.2, 0.0), 92, (0, 5, 125, -25, -60, 60, 158, 12, -162, -8)),
    ((0.4, 0.05), 88, (0, -5, 118, -35, -40, 10, 162, 8, -158, -12)),
    ((0.6, 0.0), 91, (0, 0, 122, -28, -40, 70, 160, 10, -160, -10)),
)
STICK_MAN_EDGES = tuple((parent, i + 1) for i, parent in enumerate(STICK_MAN_PARENT))
KEY_POSES_DIR = "key_poses"
WAVE_NAME = "stick_man_wave"
WAVE_STEP = 24  # frames from one pose to the next


def stick_man(root, heading, bends, parent=STICK_MAN_PARENT, reference=STICK_MAN_REFERENCE,
              lengths=STICK_MAN_LENGTHS):
    """The (x, y) vertices of the stick man (11 by default) with these bends
    (degrees); parent, reference and lengths describe its edges."""
    points = [tuple(root)]
    direction = [0.0] * len(bends)
    for i, bend in enumerate(bends):
        direction[i] = (heading if reference[i] < 0 else direction[reference[i]]) + bend
        x, y = points[parent[i]]
        angle = math.radians(direction[i])
        points.append((x + lengths[i] * math.cos(angle), y + lengths[i] * math.sin(angle)))
    return points


def wave_poses():
    """The waving stick man's poses, each a list of 11 (x, y) vertices; the
    edges are STICK_MAN_EDGES."""
    return [stick_man(root, heading, bends) for root, heading, bends in WAVE_POSES]


def build_key_poses_scene():
    """The waving stick man twice: four edge meshes wave_pose_1 .. 4 in the
    collection wave_keys (each with its key frame, 1, 25, 49, 73, for Bake
    Key Poses) and one mesh wave_shape_keys whose shape keys Pose 2 .. Pose 4
    (the basis is pose 1) are animated pose to pose at the same frames and
    back to the basis at frame 97 (for Rebake Shape Keys)."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.name = WAVE_NAME
    poses = wave_poses()
    frames = [1 + WAVE_STEP * k for k in range(len(poses))]
    keys = bpy.data.collections.new("wave_keys")
    scene.collection.children.link(keys)
    spacing = 5.0
    for k, pose in enumerate(poses):
        mesh = bpy.data.meshes.new(f"wave_pose_{k + 1}")
        mesh.from_pydata([(x, y, 0.0) for x, y in pose], list(STICK_MAN_EDGES), [])
        mesh.update()
        obj = bpy.data.objects.new(mesh.name, mesh)
        obj.location = (spacing * k, 0.0, 0.0)
        # The storage of the add-on's Object property stick_morph_key_frame.
        obj["stick_morph_key_frame"] = frames[k]
        keys.objects.link(obj)
    mesh = bpy.data.meshes.new("wave_shape_keys")
    mesh.from_pydata([(x, y, 0.0) for x, y in poses[0]], list(STICK_MAN_EDGES), [])
    mesh.update()
    obj = bpy.data.objects.new(mesh.name, mesh)
    obj.location = (0.0, -6.0, 0.0)
    scene.collection.objects.link(obj)
    obj.shape_key_add(name="Basis", from_mix=False)
    blocks = []
    for k, pose in enumerate(poses[1:], start=2):
        block = obj.shape_key_add(name=f"Pose {k}", from_mix=False)
        for point, (x, y) in zip(block.data, pose):
            point.co = (x, y, 0.0)
        blocks.append(block)
    # Pose to pose: at each keyframe one key is 1 and the others 0 (all 0: the basis).
    shown = [None] + blocks + [None]
    for k, on in enumerate(shown):
        for block in blocks:
            block.value = 1.0 if block == on else 0.0
            block.keyframe_insert("value", frame=1 + WAVE_STEP * k)

    camera_data = bpy.data.cameras.new(f"{WAVE_NAME}_camera")
    camera_data.type = "ORTHO"
    camera_data.ortho_scale = 24.0
    camera = bpy.data.objects.new(camera_data.name, camera_data)
    camera.location = (7.5, -1.5, 20.0)
    scene.collection.objects.link(camera)
    scene.camera = camera
    render = scene.render
    render.engine = "BLENDER_WORKBENCH"
    render.resolution_x, render.resolution_y = RESOLUTION
    scene.frame_start, scene.frame_end = 1, 1 + WAVE_STEP * (len(shown) - 1)
    scene.frame_set(1)
    return scene


# ---------------------------------------------------------- local timing ----
# Issue 31: the stick man with a hand, vertex 11 on the right wrist (vertex
# 6), edge 10 bent from the forearm (edge 5). From the source to the target
# the body bends a little (the legs stay where they are) and the raised
# forearm and the hand turn about the elbow (vertex 5), waving: 75 and 95
# degrees clockwise. The vertex group LAG_GROUP weighs the wrist and the
# fingertip 1 (every other vertex 0), so with local timing the hand lags.
LAG_PARENT = STICK_MAN_PARENT + (6,)
LAG_REFERENCE = STICK_MAN_REFERENCE + (5,)
LAG_LENGTHS = STICK_MAN_LENGTHS + (0.5,)
LAG_EDGES = tuple((parent, i + 1) for i, parent in enumerate(LAG_PARENT))
LAG_POSES = (
    ((0.0, 0.0), 90, (0, 0, 120, -30, -50, 50, 160, 10, -160, -10, 0)),
    ((0.0, 0.0), 80, (0, 6, 124, -26, -40, -25, 170, 8, -150, -12, -20)),
)
LAG_GROUP = "lag"
LAG_VERTICES = (6, 11)  # the wrist and the fingertip: weight 1
LAG_OVERLAP = 0.3
LOCAL_TIMING_DIR = "local_timing"
LAG_NAME = "stick_man_lag"
LAG_FRAMES = 48


def lag_poses():
    """The source and the target of the local-timing sample, each a list of
    12 (x, y) vertices; the edges are LAG_EDGES."""
    return [stick_man(root, heading, bends, LAG_PARENT, LAG_REFERENCE, LAG_LENGTHS)
            for root, heading, bends in LAG_POSES]


def build_local_timing_scene():
    """lag_source and lag_target side by side, the source with the vertex
    group LAG_GROUP, and the scene's Stick Morph settings (stored as the ID
    properties the add-on's scene settings read when it is enabled) naming
    the pair, the delay group, the overlap and the frames."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.name = LAG_NAME
    objects = []
    for name, pose, x in zip(("lag_source", "lag_target"), lag_poses(), (0.0, 5.0)):
        mesh = bpy.data.meshes.new(name)
        mesh.from_pydata([(px, py, 0.0) for px, py in pose], list(LAG_EDGES), [])
        mesh.update()
        obj = bpy.data.objects.new(name, mesh)
        obj.location = (x, 0.0, 0.0)
        scene.collection.objects.link(obj)
        objects.append(obj)
    source, target = objects
    source.vertex_groups.new(name=LAG_GROUP).add(list(LAG_VERTICES), 1.0, "REPLACE")
    # The add-on's scene settings (preferences.StickMorphSceneSettings):
    # Source, Target, Delay Group, Overlap, Frames.
    scene["stick_morph"] = {"source": source, "target": target, "delay_group": LAG_GROUP,
                            "overlap": LAG_OVERLAP, "frame_count": LAG_FRAMES}
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in objects)
    bpy.context.view_layer.objects.active = target

    camera_data = bpy.data.cameras.new(f"{LAG_NAME}_camera")
    camera_data.type = "ORTHO"
    camera_data.ortho_scale = 17.0  # both figures' 8.4 units of height, with a margin, at 16:9
    camera = bpy.data.objects.new(camera_data.name, camera_data)
    camera.location = (2.9, 1.25, 20.0)
    scene.collection.objects.link(camera)
    scene.camera = camera
    render = scene.render
    render.engine = "BLENDER_WORKBENCH"
    render.resolution_x, render.resolution_y = RESOLUTION
    scene.frame_start, scene.frame_end = 1, LAG_FRAMES
    scene.frame_set(1)
    return scene


def main():
    args = parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    if args.key_poses:
        build_key_poses_scene()
        bpy.context.preferences.filepaths.save_version = 0
        folder = os.path.join(args.output_dir, KEY_POSES_DIR)
        os.makedirs(folder, exist_ok=True)
        path = os.path.abspath(os.path.join(folder, f"{WAVE_NAME}.blend"))
        bpy.ops.wm.save_as_mainfile(filepath=path, compress=True)
        print(f"wrote {path} ({os.path.getsize(path)} bytes)")
    if args.local_timing:
        build_local_timing_scene()
        bpy.context.preferences.filepaths.save_version = 0
        folder = os.path.join(args.output_dir, LOCAL_TIMING_DIR)
        os.makedirs(folder, exist_ok=True)
        path = os.path.abspath(os.path.join(folder, f"{LAG_NAME}.blend"))
        bpy.ops.wm.save_as_mainfile(filepath=path, compress=True)
        print(f"wrote {path} ({os.path.getsize(path)} bytes)")
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
