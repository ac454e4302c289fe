"""Bakes a bundled sample with the Stick Morph add-on and renders it, headless.

    blender -b --factory-startup --python-exit-code 1 --python scripts/render_demo.py -- \\
        --sample blend_samples/monkey_to_player.blend --zip dist/stick_morph-<version>.zip \\
        --out out/monkey_to_player [--frames 60] [--resolution 960 540]
    blender ... --python scripts/render_demo.py -- --sample blend_samples/key_poses/stick_man_wave.blend \
        --key-poses wave_keys --zip dist/stick_morph-<version>.zip --out out/stick_man_wave
    blender ... --python scripts/render_demo.py -- --sample blend_samples/local_timing/stick_man_lag.blend \
        --zip dist/stick_morph-<version>.zip --out out/stick_man_lag --frames 48
    blender ... --python scripts/render_demo.py -- --sample blend_samples/drawings/stick_figure_gp.blend \
        --zip dist/stick_morph-<version>.zip --out out/stick_figure_gp --frames 48

Steps:
1. Re-launches Blender with BLENDER_USER_SCRIPTS, BLENDER_USER_CONFIG and
   BLENDER_USER_DATAFILES in a temporary folder (as tests/blender/run_pytest.py
   does), so the real user configuration is never touched; the folder is
   removed afterwards.
2. Installs and enables the add-on from the zip there.
3. Opens the sample and bakes `<name>_source` -> `<name>_target` (or, where
   the sample has no such objects, the Source and Target its scene's Stick
   Morph settings name) with object.stick_morph_bake (renderable Geometry
   Nodes tubes), frames 1..N, with the Delay Group and Overlap those
   settings name (local timing, issue 31: blend_samples/local_timing/);
   a Grease Pencil pair (issue 32: blend_samples/drawings/) bakes into a
   Grease Pencil object, one drawing per frame, which renders with its own
   materials;
   with --key-poses COLLECTION, the collection's meshes as key poses with
   object.stick_morph_bake_sequence, each key at its own key frame (issue 28).
4. Sets up Workbench for a clear picture: flat dark tubes on a light
   background, the source and target meshes hidden from render (only the morph
   shows), Standard view transform so the colours come out as set.
5. Writes <out>/baked.blend (renders in a Blender without the add-on),
   <out>/frames/frame_####.png and <out>/morph.mp4 (H.264 in MPEG-4; fails if
   this Blender has no FFmpeg support).
"""

import argparse
import glob
import os
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_sandbox  # noqa: E402
from blender_sandbox import SANDBOX  # noqa: E402
TUBE_COLOR = (0.008, 0.01, 0.02)    # near-black blue (linear; about #171a26 on screen)
BACKGROUND = (0.93, 0.93, 0.93)     # light gray


def script_args():
    return sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="render_demo.py",
        description="Bake a sample .blend with the Stick Morph add-on and render PNG frames and an MP4.")
    parser.add_argument("--sample", required=True, help="a blend_samples/NAME.blend file")
    parser.add_argument("--zip", required=True, help="the add-on zip, dist/stick_morph-<version>.zip")
    parser.add_argument("--out", required=True, help="output folder")
    parser.add_argument("--frames", type=int, default=60, help="frames of the morph (default 60)")
    parser.add_argument("--key-poses", metavar="COLLECTION",
                        help="bake the collection's meshes as key poses (at their own key frames; --frames "
                             "is then not used) instead of NAME_source -> NAME_target")
    parser.add_argument("--resolution", type=int, nargs=2, default=(960, 540), metavar=("W", "H"),
                        help="render size in pixels (default 960 540)")
    parser.add_argument("--tube-radius", type=float, default=0.006,
                        help="tube radius as a fraction of the figures' size (default 0.006)")
    args = parser.parse_args(argv)
    if args.frames < 2:
        parser.error("--frames must be at least 2")
    if min(args.resolution) < 16 or any(v % 2 for v in args.resolution):
        parser.error("--resolution: even sizes of at least 16 pixels (H.264 needs even sizes)")
    for path, what in ((args.sample, "--sample"), (args.zip, "--zip")):
        if not os.path.isfile(path):
            parser.error(f"{what}: no such file: {path}")
    args.sample, args.zip, args.out = map(os.path.abspath, (args.sample, args.zip, args.out))
    return args


def fail(message):
    print(f"render_demo.py: error: {message}", file=sys.stderr, flush=True)
    sys.exit(1)


def relaunch_in_sandbox():
    """Runs this script again in a Blender whose user folders are temporary."""
    parse_args(script_args())  # usage errors before starting anything
    return blender_sandbox.relaunch_in_sandbox(__file__, script_args(), "stickmorph-render-demo-")


def install_addon(zip_path):
    """Installs and enables the package the way this Blender does (a legacy
    add-on zip before 4.2, an extension from 4.2: blender_sandbox knows)."""
    try:
        name = blender_sandbox.install_package(zip_path)
    except RuntimeError as error:
        fail(str(error))
    print(f"add-on installed and enabled from {zip_path} as {name}", flush=True)


def find_pair(sample):
    import bpy
    name = os.path.splitext(os.path.basename(sample))[0]
    source = bpy.data.objects.get(f"{name}_source")
    target = bpy.data.objects.get(f"{name}_target")
    settings = getattr(bpy.context.scene, "stick_morph", None)
    if (source is None or target is None) and settings is not None and settings.source and settings.target:
        source, target = settings.source, settings.target
    if source is None or target is None:
        meshes = sorted(o.name for o in bpy.data.objects if o.type == "MESH")
        fail(f"{sample} has no objects {name}_source and {name}_target, nor a Source and a Target in its "
             f"scene's Stick Morph settings (meshes: {', '.join(meshes)})")
    return name, source, target


def local_timing():
    """The sample scene's Delay Group and Overlap (none: the plain morph)."""
    import bpy
    settings = getattr(bpy.context.scene, "stick_morph", None)
    if settings is None or not settings.delay_group:
        return {}
    return {"delay_group": settings.delay_group, "overlap": settings.overlap}


def bake(source, target, frames, tube_radius):
    import bpy
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    bpy.context.view_layer.objects.active = None
    started = time.perf_counter()
    timing = local_timing()
    result = bpy.ops.object.stick_morph_bake(
        source=source.name, target=target.name, frame_start=1, frame_count=frames,
        renderable=True, tube_radius=tube_radius, easing="NONE", set_frame_range=True, **timing)
    if result != {"FINISHED"}:
        fail(f"baking {source.name} -> {target.name} failed ({result}); see the report above")
    obj = bpy.context.view_layer.objects.active
    if obj is None or obj.get("stick_morph_role") != "result":
        fail("the bake did not leave its result active")
    lag = f", '{timing['delay_group']}' lagging by {timing['overlap']:g}" if timing else ""
    print(f"baked {source.name} -> {target.name} into '{obj.name}': {describe(obj)}, "
          f"{frames} frames{lag}, {time.perf_counter() - started:.2f} s", flush=True)
    return obj


def describe(obj):
    """"18 vertices" for a mesh result; "Grease Pencil, 48 drawings" for a
    Grease Pencil one (issue 32: a Grease Pencil source's result)."""
    if obj.type == "MESH":
        return f"{len(obj.data.vertices)} vertices"
    return f"Grease Pencil, {sum(len(layer.frames) for layer in obj.data.layers)} drawings"


def bake_key_poses(collection_name, tube_radius):
    """The collection's meshes as key poses (object.stick_morph_bake_sequence), each at its own
    key frame; the scene's frame range becomes the sequence's."""
    import bpy
    collection = bpy.data.collections.get(collection_name)
    if collection is None:
        fail(f"the sample has no collection '{collection_name}'")
    keys = [obj for obj in collection.objects if obj.type == "MESH"]
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    bpy.context.view_layer.objects.active = None
    started = time.perf_counter()
    result = bpy.ops.object.stick_morph_bake_sequence(collection=collection_name, renderable=True,
                                                      tube_radius=tube_radius, set_frame_range=True)
    if result != {"FINISHED"}:
        fail(f"baking the key poses of '{collection_name}' failed ({result}); see the report above")
    obj = bpy.context.view_layer.objects.active
    if obj is None or obj.get("stick_morph_role") is None:
        fail("the key-pose bake did not leave its result active")
    scene = bpy.context.scene
    print(f"baked {len(keys)} key poses of '{collection_name}' into '{obj.name}': {describe(obj)}, "
          f"frames {scene.frame_start}..{scene.frame_end}, {time.perf_counter() - started:.2f} s",
          flush=True)
    return obj, keys


def set_up_render(scene, hidden, resolution):
    """Workbench: flat dark tubes on a light background; only the morph renders."""
    for obj in hidden:
        obj.hide_render = True
    render = scene.render
    render.engine = "BLENDER_WORKBENCH"
    render.resolution_x, render.resolution_y = resolution
    render.resolution_percentage = 100
    render.film_transparent = False
    shading = scene.display.shading
    shading.light = "FLAT"
    shading.color_type = "SINGLE"
    shading.single_color = TUBE_COLOR
    shading.show_shadows = False
    shading.show_cavity = False
    shading.show_object_outline = False
    shading.show_specular_highlight = False
    scene.display.render_aa = "8"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    if scene.world is None:
        import bpy
        scene.world = bpy.data.worlds.new("World")
    scene.world.color = BACKGROUND


def fit_camera(scene, result, margin=0.1):
    """Points the sample's orthographic camera (looking down -Z, as the samples set it) at the
    whole morph: centred on the box every frame of the result lies in, the scale fitting it with
    `margin` to spare on each side at the render's aspect."""
    import bpy
    from mathutils import Vector
    camera = scene.camera
    if camera is None or camera.data.type != "ORTHO":
        fail("the sample has no orthographic camera to fit to the key poses")
    low, high = [float("inf")] * 2, [float("-inf")] * 2
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        evaluated = result.evaluated_get(bpy.context.evaluated_depsgraph_get())
        for corner in evaluated.bound_box:
            world = evaluated.matrix_world @ Vector(corner)
            low = [min(low[i], world[i]) for i in range(2)]
            high = [max(high[i], world[i]) for i in range(2)]
    scene.frame_set(scene.frame_start)
    aspect = scene.render.resolution_x / scene.render.resolution_y
    width, height = high[0] - low[0], high[1] - low[1]
    camera.location.x, camera.location.y = (low[0] + high[0]) / 2, (low[1] + high[1]) / 2
    camera.rotation_euler = (0.0, 0.0, 0.0)
    # ortho_scale spans the larger side of the render.
    camera.data.ortho_scale = (1 + 2 * margin) * max(width, height * aspect) / (1 if aspect >= 1 else aspect)


def check_framing(scene, result):
    """Fails unless every frame of the morph lies inside the camera's view."""
    import bpy
    from bpy_extras.object_utils import world_to_camera_view
    from mathutils import Vector
    if scene.camera is None:
        fail("the sample has no camera")
    worst = 0.0
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        evaluated = result.evaluated_get(bpy.context.evaluated_depsgraph_get())
        for corner in evaluated.bound_box:
            world = evaluated.matrix_world @ Vector(corner)
            x, y, _ = world_to_camera_view(scene, scene.camera, world)
            worst = max(worst, abs(x - 0.5), abs(y - 0.5))
    scene.frame_set(scene.frame_start)
    if worst > 0.5:
        fail(f"the morph leaves the camera's view (reaches {worst + 0.5:.2f} of the frame)")
    print(f"framing: the morph stays within the central {200 * worst:.0f}% of the frame", flush=True)


def set_file_format(settings, file_format):
    """Sets ImageFormatSettings.file_format. Blender 5.x lists only the formats
    of the current media_type ("IMAGE", "MULTI_LAYER_IMAGE" or "VIDEO"), so
    FFMPEG needs media_type VIDEO first and PNG needs IMAGE; 3.x/4.x have no
    media_type."""
    if hasattr(settings, "media_type"):
        settings.media_type = "VIDEO" if file_format == "FFMPEG" else "IMAGE"
    settings.file_format = file_format


def render_frames(scene, frames_dir):
    import bpy
    os.makedirs(frames_dir, exist_ok=True)
    for old in glob.glob(os.path.join(frames_dir, "frame_*.png")):
        os.remove(old)
    set_file_format(scene.render.image_settings, "PNG")
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "8"
    scene.render.use_file_extension = True
    scene.render.filepath = os.path.join(frames_dir, "frame_####")
    started = time.perf_counter()
    bpy.ops.render.render(animation=True)
    written = sorted(glob.glob(os.path.join(frames_dir, "frame_*.png")))
    expected = scene.frame_end - scene.frame_start + 1
    if len(written) != expected:
        fail(f"expected {expected} PNG frames in {frames_dir}, found {len(written)}")
    print(f"rendered {len(written)} PNG frames in {time.perf_counter() - started:.1f} s", flush=True)
    return written


def render_movie(scene, mp4_path):
    import bpy
    if not bpy.app.build_options.codec_ffmpeg:
        fail("this Blender was built without FFmpeg (bpy.app.build_options.codec_ffmpeg is False), "
             "so it cannot write the MP4; the PNG frames were written")
    # Blender names movies itself (frame range appended); render into a
    # scratch folder and move the one file it writes.
    scratch = tempfile.mkdtemp(prefix="movie-", dir=os.path.dirname(mp4_path))
    try:
        settings = scene.render.image_settings
        set_file_format(settings, "FFMPEG")
        settings.color_mode = "RGB"
        ffmpeg = scene.render.ffmpeg
        ffmpeg.format = "MPEG4"
        ffmpeg.codec = "H264"
        ffmpeg.constant_rate_factor = "HIGH"
        ffmpeg.ffmpeg_preset = "GOOD"
        ffmpeg.gopsize = scene.render.fps
        ffmpeg.audio_codec = "NONE"
        scene.render.use_file_extension = True
        scene.render.filepath = os.path.join(scratch, "morph")
        started = time.perf_counter()
        bpy.ops.render.render(animation=True)
        movies = glob.glob(os.path.join(scratch, "*"))
        if len(movies) != 1 or os.path.getsize(movies[0]) == 0:
            fail(f"the movie render wrote {movies or 'nothing'}")
        os.replace(movies[0], mp4_path)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    print(f"encoded {mp4_path} in {time.perf_counter() - started:.1f} s", flush=True)


def main():
    import bpy
    args = parse_args(script_args())
    started = time.perf_counter()
    print(f"Blender {bpy.app.version_string}, FFmpeg support: {bool(bpy.app.build_options.codec_ffmpeg)}",
          flush=True)
    if not bpy.app.build_options.codec_ffmpeg:
        fail("this Blender was built without FFmpeg (bpy.app.build_options.codec_ffmpeg is False): "
             "it cannot write morph.mp4")
    install_addon(args.zip)

    bpy.ops.wm.open_mainfile(filepath=args.sample, load_ui=False)
    scene = bpy.context.scene
    if args.key_poses:
        name = args.key_poses
        result, hidden = bake_key_poses(args.key_poses, args.tube_radius)
    else:
        name, source, target = find_pair(args.sample)
        result = bake(source, target, args.frames, args.tube_radius)
        hidden = [source, target]
    set_up_render(scene, hidden, args.resolution)
    if args.key_poses:
        # The keys stand side by side in the sample; the morph walks from the
        # first to the last: the camera is fitted to its whole way.
        fit_camera(scene, result)
    check_framing(scene, result)

    os.makedirs(args.out, exist_ok=True)
    baked = os.path.join(args.out, "baked.blend")
    # Saved with the render settings: the file renders the same in a Blender
    # without the add-on. copy=True keeps the open file's path the sample's.
    bpy.ops.wm.save_as_mainfile(filepath=baked, copy=True, compress=True)
    print(f"saved {baked}", flush=True)

    frames = render_frames(scene, os.path.join(args.out, "frames"))
    mp4 = os.path.join(args.out, "morph.mp4")
    render_movie(scene, mp4)

    size = lambda path: f"{os.path.getsize(path) / 1024:.0f} KiB"
    print(f"\nrender_demo.py: {name}, {len(frames)} frames at {args.resolution[0]}x{args.resolution[1]}, "
          f"{time.perf_counter() - started:.1f} s. Written:", flush=True)
    print(f"  {baked} ({size(baked)})")
    print(f"  {os.path.dirname(frames[0])}/frame_####.png: {len(frames)} PNG frames "
          f"({os.path.basename(frames[0])} .. {os.path.basename(frames[-1])})")
    print(f"  {mp4} ({size(mp4)}, {scene.render.fps} fps)", flush=True)


if __name__ == "__main__":
    if not os.environ.get(SANDBOX):
        sys.exit(relaunch_in_sandbox())
    main()
