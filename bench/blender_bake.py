#!/usr/bin/python3
"""The bake and the playback in Blender at 10^3 to 10^5 vertices (issue 29), headless.

    /usr/bin/python3 bench/blender_bake.py [--build DIR | --cli PATH --module DIR] [--blender BLENDER]
        [--package ZIP | --dist DIR] [--sizes 1000,10000,100000] [--shapes wavy,coral] [--frames 250] [--large-shapes wavy]
        [--playback-frames 250] [--render-max 10000] [--cli-max 10000] [--json FILE] [--keep DIR]

For every (shape, n), in one run and one after the other on the same machine:
  1. the pair is drawn (numpy; checked compatible by the module in --build) and written as the
     CLI's figure files;
  2. the CLI: `stickmorph morph SOURCE TARGET -o OUT --frames F` (the default rigid motion),
     its wall time and peak memory (wait4), and its own stage times (stats.milliseconds);
     n <= --cli-max only (at 10^5 vertices and 250 frames its JSON is 1.2 GB, and the bake's
     engine time is the same work);
  3. a new headless Blender (`--factory-startup`, user folders in a temporary sandbox,
     scripts/blender_sandbox.py) with the add-on package installed: the two meshes are made
     and object.stick_morph_bake runs as a user runs it (source, target, F frames, the
     defaults: rigid, renderable tubes); its wall time, split into the engine's call (the
     module's morph) and the rest (reading the meshes, the checks, writing shape keys and
     keyframes, the tubes: the Blender side), from the operator's stage times
     (scene.stick_morph.last_stages);
  4. playback: scene.frame_set(f) and the result's evaluated mesh (its vertex count read) for
     every frame in order, with the tubes (the viewport's depsgraph: the tubes' viewport
     quality) and with the tubes' modifier off;
  5. a render of the middle frame (Workbench, 480 x 270, final render: the tubes' render
     quality), counted as visible geometry when enough pixels differ from the background
     (n <= --render-max only: a full-quality render of 10^5 vertices is 7 million);
  6. the .blend saved (uncompressed): its size;
  7. the Blender process's peak memory (ru_maxrss) before the bake and at the end.
--large-shapes: the shapes run at sizes above 10^4 (the others stop there, for time).

Prints a Markdown table; --json writes the rows (bench/benchmarks.sh: out/benchmarks/blender.json,
which bench/make_benchmarks.py puts into BENCHMARKS.md).
"""

import argparse
import json
import math
import os
import pathlib
import resource
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parent.parent
SHAPES = ("wavy", "coral", "coil", "meander", "band")
CHILD_FLAG = "--blender-child"


# ----------------------------------------------------------------- figures ----

def wavy(n):
    """The issue's case: a wavy polyline (a graph over x, so simple) into a smoothly warped copy
    (bent into an arc of 120 degrees by a map of the plane that is one-to-one on the strip the
    line lies in, then turned and moved): compatible by construction."""
    import numpy as np
    s = np.linspace(0.0, 1.0, n)
    x = 10.0 * s
    y = 0.4 * np.sin(2 * math.pi * 6 * s) * (1.0 + 0.3 * np.sin(2 * math.pi * 1.7 * s))
    source = np.stack([x, y], axis=1)
    radius = 10.0 / (2 * math.pi / 3)
    theta = (x - 5.0) / radius
    bent = np.stack([(radius - 0.8 * y) * np.sin(theta), (radius - 0.8 * y) * np.cos(theta) - radius], axis=1)
    turn = math.radians(25)
    rotation = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
    target = bent @ rotation.T + np.array([1.0, 0.5])
    edges = [[i, i + 1] for i in range(n - 1)]
    return source, target, edges, "bent into an arc of 120 degrees, turned 25"


def make_pair(shape, n, seed, stickmorph):
    """(source, target, edges, how), checked valid and compatible by the module."""
    if shape == "wavy":
        source, target, edges, how = wavy(n)
        for xy in (source, target):
            stickmorph.validate(xy.tolist(), edges)
        report = stickmorph.check_compatibility(source.tolist(), target.tolist(), edges)
        if not report.compatible:
            raise RuntimeError(f"wavy n={n}: not compatible: {report.reason}")
        return source, target, edges, how
    sys.path.insert(0, str(REPO / "bench"))
    import speed_corpus  # the drawn-looking figures of issue 15
    return speed_corpus.make_pair(shape, n, seed, stickmorph)


def write_figure(path, name, xy, edges):
    with open(path, "w", encoding="utf-8") as f:
        json.dump({"name": name, "vertices": [[float(a), float(b)] for a, b in xy], "edges": edges}, f)


# --------------------------------------------------------------------- CLI ----

def run_cli(cli, source_path, target_path, frames, work):
    """Wall seconds, peak MiB (wait4's ru_maxrss of the CLI process alone), its stage times."""
    out = os.path.join(work, "cli_morph.json")
    command = [cli, "morph", source_path, target_path, "-o", out, "--frames", str(frames)]
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    error = process.stderr.read().decode(errors="replace")
    process.stderr.close()
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({process.returncode}): {error.strip()}")
    with open(out, encoding="utf-8") as f:
        stats = json.load(f)["stats"]
    os.remove(out)
    return {"cli_s": wall, "cli_peak_mib": usage.ru_maxrss / 1024,
            "cli_stage_ms": stats.get("milliseconds", {})}


# ------------------------------------------------------------- the parent ----

def find_package(blender, dist):
    sys.path.insert(0, str(REPO / "scripts"))
    import blender_sandbox
    version = subprocess.run([blender, "-b", "--factory-startup", "--python-expr",
                              "import bpy, sys; print('VERSION', *bpy.app.version[:2], *sys.version_info[:2])"],
                             capture_output=True, text=True, check=True).stdout
    line = next(x for x in version.splitlines() if x.startswith("VERSION "))
    major, minor, py_major, py_minor = (int(v) for v in line.split()[1:])
    # build_addon.py's names: a legacy zip per Blender series before 4.2, an
    # extension per Python ABI from 4.2 (whose glob also matches legacy names).
    if (major, minor) >= blender_sandbox.EXTENSIONS_SINCE[:2]:
        pattern = f"stick_morph-*-cp{py_major}{py_minor}-*.zip"
        found = [p for p in pathlib.Path(dist).glob(pattern) if "-blender" not in p.name]
    else:
        pattern = f"stick_morph-*-blender{major}.{minor}-cp{py_major}{py_minor}-*.zip"
        found = list(pathlib.Path(dist).glob(pattern))
    found.sort(key=os.path.getmtime)
    if not found:
        raise SystemExit(f"blender_bake.py: no package {pattern} in {dist} (run build_addon.py first)")
    return str(found[-1]), blender_sandbox


def run_case(args, shape, n, package, blender_sandbox, stickmorph):
    row = {"shape": shape, "n": n, "frames": args.frames, "commit": args.commit}
    work = tempfile.mkdtemp(prefix=f"stickmorph-blender-bench-{shape}-{n}-")
    try:
        source, target, edges, how = make_pair(shape, n, args.seed, stickmorph)
        row.update(how=how, vertices=len(source), edges=len(edges))
        source_path, target_path = os.path.join(work, "source.json"), os.path.join(work, "target.json")
        write_figure(source_path, "Source", source, edges)
        write_figure(target_path, "Target", target, edges)
        if n <= args.cli_max:
            row.update(run_cli(args.cli, source_path, target_path, args.frames, work))
        case = {"source": source_path, "target": target_path, "frames": args.frames,
                "playback_frames": min(args.playback_frames, args.frames), "render": n <= args.render_max,
                "package": package, "out": os.path.join(work, "blender.json"),
                "render_path": os.path.join(args.keep, f"{shape}_{n}.png") if args.keep else
                os.path.join(work, "render.png"),
                "blend_path": os.path.join(work, "bake.blend")}
        case_path = os.path.join(work, "case.json")
        with open(case_path, "w", encoding="utf-8") as f:
            json.dump(case, f)
        sandbox = os.path.join(work, "sandbox")
        env = blender_sandbox.sandbox_env(sandbox)
        command = [args.blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                   str(pathlib.Path(__file__).resolve()), "--", CHILD_FLAG, case_path]
        done = subprocess.run(command, env=env, capture_output=True, text=True)
        if done.returncode != 0 or not os.path.exists(case["out"]):
            tail = "\n".join((done.stdout + done.stderr).strip().splitlines()[-15:])
            raise RuntimeError(f"Blender failed ({done.returncode}):\n{tail}")
        with open(case["out"], encoding="utf-8") as f:
            row.update(json.load(f))
        row["bake_over_cli"] = row["bake_s"] / row["cli_s"] if "cli_s" in row else None
    except Exception as error:  # noqa: BLE001 - the row says what failed; the others still run
        row["error"] = str(error)
    finally:
        if args.keep is None:
            subprocess.run(["rm", "-rf", work], check=False)
    return row


def fmt(value, spec):
    return "–" if value is None else format(value, spec)


def print_table(rows):
    print("| shape | n | frames | CLI s | bake s | bake / CLI | engine s | Blender side s | playback fps (tubes) "
          "| playback fps (no tubes) | render | .blend MiB | Blender peak MiB | CLI peak MiB |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|--:|--:|--:|")
    for r in rows:
        if "error" in r:
            print(f"| {r['shape']} | {r['n']} | {r['frames']} | error: {r['error'].splitlines()[-1]} |")
            continue
        render = ("–" if r.get("render_visible") is None else
                  f"{'visible' if r['render_visible'] else 'EMPTY'} ({100 * r['render_coverage']:.1f} %)")
        print(f"| {r['shape']} | {r['n']} | {r['frames']} | {fmt(r.get('cli_s'), '.2f')} | {r['bake_s']:.2f} | "
              f"{fmt(r['bake_over_cli'], '.2f')} | {fmt(r.get('engine_s'), '.2f')} | {fmt(r.get('blender_side_s'), '.2f')} | "
              f"{r['playback_fps_tubes']:.1f} | {r['playback_fps_plain']:.0f} | {render} | {r['blend_mib']:.1f} | "
              f"{r['peak_mib']:.0f} | {fmt(r.get('cli_peak_mib'), '.0f')} |", flush=True)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=str(REPO / "build"), help="build directory (the CLI, python/ the module)")
    parser.add_argument("--cli", help="the stickmorph CLI (default: BUILD/stickmorph)")
    parser.add_argument("--module", help="the folder of the stickmorph module for /usr/bin/python3, which draws "
                        "and checks the pairs (default: BUILD/python)")
    parser.add_argument("--blender", default=os.environ.get("BLENDER", "blender"))
    parser.add_argument("--package", help="the add-on package (default: the newest one in --dist for that Blender)")
    parser.add_argument("--dist", default=str(REPO / "dist"), help="where build_addon.py wrote the packages")
    parser.add_argument("--sizes", default="1000,10000,100000")
    parser.add_argument("--shapes", default="wavy,coral")
    parser.add_argument("--large-shapes", default="wavy", help="the shapes measured above 10^4 vertices")
    parser.add_argument("--frames", type=int, default=250)
    parser.add_argument("--playback-frames", type=int, default=250)
    parser.add_argument("--render-max", type=int, default=10000)
    parser.add_argument("--cli-max", type=int, default=10000, help="run the CLI up to this size")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--json", help="write the rows here")
    parser.add_argument("--keep", help="keep the work folders and renders in this folder")
    args = parser.parse_args(argv)
    build = pathlib.Path(args.build).resolve()
    args.commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short=12", "HEAD"], capture_output=True,
                                 text=True).stdout.strip() or "unknown"
    args.cli = str(pathlib.Path(args.cli).resolve()) if args.cli else str(build / "stickmorph")
    sys.path.insert(0, str(pathlib.Path(args.module).resolve()) if args.module else str(build / "python"))
    import stickmorph
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
    if args.package:
        sys.path.insert(0, str(REPO / "scripts"))
        import blender_sandbox
        package = str(pathlib.Path(args.package).resolve())
    else:
        package, blender_sandbox = find_package(args.blender, args.dist)
    shapes = args.shapes.split(",")
    large = set(args.large_shapes.split(","))
    for shape in shapes:
        if shape not in SHAPES:
            parser.error(f"unknown shape {shape!r} (choose from {', '.join(SHAPES)})")
    rows = []
    for n in (int(v) for v in args.sizes.split(",")):
        for shape in shapes:
            if n > 10000 and shape not in large:
                continue
            print(f"blender_bake.py: {shape} n={n} ...", file=sys.stderr, flush=True)
            rows.append(run_case(args, shape, n, package, blender_sandbox, stickmorph))
            if "error" in rows[-1]:
                print(f"  error: {rows[-1]['error']}", file=sys.stderr, flush=True)
    print_table(rows)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(rows, f, indent=1)
    return 0 if all("error" not in r for r in rows) else 1


# ------------------------------------------------------ the Blender child ----

def peak_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def stage_times(text):
    """{'read': ms, ...} from scene.stick_morph.last_stages ("read 12 ms, engine 3100 ms, ...")."""
    out = {}
    for part in filter(None, (p.strip() for p in text.split(","))):
        name, value, unit = part.rsplit(" ", 2)
        if unit != "ms":
            raise ValueError(f"unexpected stage time {part!r}")
        out[name] = float(value)
    return out


def render_coverage(bpy, obj, path):
    """Renders the scene's frame with Workbench from an orthographic camera above the result and
    returns the fraction of pixels that differ from the background."""
    import numpy as np
    scene = bpy.context.scene
    co = np.empty(len(obj.data.vertices) * 3, dtype=np.float32)
    obj.data.vertices.foreach_get("co", co)  # the basis: the source, where its bounds are
    key = obj.data.shape_keys.key_blocks[len(obj.data.shape_keys.key_blocks) // 2]
    key.data.foreach_get("co", co)  # the middle frame, which is rendered
    matrix = np.array(obj.matrix_world)
    world = co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]
    low, high = world.min(axis=0), world.max(axis=0)
    camera_data = bpy.data.cameras.new("Bench Camera")
    camera_data.type = "ORTHO"
    camera_data.ortho_scale = 1.15 * float(max(high[0] - low[0], (high[1] - low[1]) * 16 / 9, 1e-6))
    camera = bpy.data.objects.new("Bench Camera", camera_data)
    centre = (low + high) / 2
    camera.location = (float(centre[0]), float(centre[1]), float(high[2]) + 10.0)
    scene.collection.objects.link(camera)
    scene.camera = camera
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 480, 270, 100
    scene.render.filepath = path
    scene.render.image_settings.file_format = "PNG"
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    seconds = time.perf_counter() - start
    image = bpy.data.images.load(path)
    pixels = np.empty(image.size[0] * image.size[1] * image.channels, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    rgb = pixels.reshape(-1, image.channels)[:, :3]
    background = np.median(rgb[: image.size[0]], axis=0)  # the bottom row: empty in this framing
    differs = np.abs(rgb - background).max(axis=1) > 0.1
    bpy.data.images.remove(image)
    bpy.data.objects.remove(camera)
    return float(differs.mean()), seconds


def blender_child(case_path):
    sys.path.insert(0, str(REPO / "scripts"))
    import blender_sandbox
    import bpy
    import numpy as np
    with open(case_path, encoding="utf-8") as f:
        case = json.load(f)
    blender_sandbox.check_sandboxed()
    blender_sandbox.install_package(case["package"])
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    objects = []
    for role in ("source", "target"):
        with open(case[role], encoding="utf-8") as f:
            figure = json.load(f)
        xy = np.asarray(figure["vertices"], dtype=np.float64)
        mesh = bpy.data.meshes.new(role.title())
        mesh.vertices.add(len(xy))
        co = np.zeros((len(xy), 3), dtype=np.float32)
        co[:, :2] = xy
        mesh.vertices.foreach_set("co", co.ravel())
        mesh.edges.add(len(figure["edges"]))
        mesh.edges.foreach_set("vertices", np.asarray(figure["edges"], dtype=np.int32).ravel())
        mesh.update()
        obj = bpy.data.objects.new(role.title(), mesh)
        bpy.context.scene.collection.objects.link(obj)
        objects.append(obj)
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[1]
    out = {"blender": bpy.app.version_string, "peak_before_mib": peak_mib()}

    start = time.perf_counter()
    done = bpy.ops.object.stick_morph_bake(source="Source", target="Target", frame_start=1,
                                           frame_count=case["frames"])
    out["bake_s"] = time.perf_counter() - start
    if done != {"FINISHED"}:
        raise RuntimeError(f"the bake returned {done}")
    out["peak_after_bake_mib"] = peak_mib()
    settings = bpy.context.scene.stick_morph
    stages = stage_times(getattr(settings, "last_stages", ""))
    out["stage_ms"] = stages
    if "engine" in stages:
        out["engine_s"] = stages["engine"] / 1000.0
        out["blender_side_s"] = out["bake_s"] - out["engine_s"]
    result = bpy.data.objects[settings.last_result]

    scene = bpy.context.scene
    frames = case["playback_frames"]
    out["playback_frames"] = frames

    def playback():
        depsgraph = bpy.context.evaluated_depsgraph_get()
        count = 0
        start = time.perf_counter()
        for frame in range(1, frames + 1):
            scene.frame_set(frame)
            count = len(result.evaluated_get(depsgraph).data.vertices)
        return frames / (time.perf_counter() - start), count

    modifier = result.modifiers[0]
    out["playback_fps_tubes"], out["evaluated_vertices_tubes"] = playback()
    modifier.show_viewport = False
    out["playback_fps_plain"], _ = playback()
    modifier.show_viewport = True
    scene.frame_set(1 + len(result.data.shape_keys.key_blocks) // 2)
    if case["render"]:
        coverage, seconds = render_coverage(bpy, result, case["render_path"])
        out.update(render_coverage=coverage, render_s=seconds, render_visible=coverage > 0.002)
    start = time.perf_counter()
    bpy.ops.wm.save_as_mainfile(filepath=case["blend_path"], compress=False)
    out["save_s"] = time.perf_counter() - start
    out["blend_mib"] = os.path.getsize(case["blend_path"]) / 2**20
    out["peak_mib"] = peak_mib()
    with open(case["out"], "w", encoding="utf-8") as f:
        json.dump(out, f)


if __name__ == "__main__":
    if CHILD_FLAG in sys.argv:
        blender_child(sys.argv[sys.argv.index(CHILD_FLAG) + 1])
    else:
        sys.exit(main())
