"""What the GUI test scripts share (adjust_last_operation.py, cancel_bake.py,
complete_bake.py): the repository's paths and scripts/blender_sandbox.py, the
checks, the first steps (the window up, the package installed), the 3D
Viewport of a window, what a bake may change in the file, and the driver that
runs a test's steps from a timer under a watchdog and ends Blender with the
test's code.

A test script is `blender --python SCRIPT` in a real window; it imports this
module from its own folder (sys.path[0] is not the script's folder there):

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import gui_driver

Exit codes (os._exit, so that Blender's own code cannot mask them): 0 every
check passed, 1 a failed check or an error, 2 the watchdog's timeout ran out.
"""

import os
import sys
import threading
import time
import traceback

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import blender_sandbox  # noqa: E402,F401 - the scripts' way to it


class CheckFailed(Exception):
    pass


def check(condition, message):
    if not condition:
        raise CheckFailed(message)


def script_args():
    """The arguments after `--` on Blender's command line."""
    return sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []


def logger(script):
    """log(message): a line prefixed with the script's name, flushed."""
    def log(message):
        print(f"{script}: {message}", flush=True)
    return log


def open_window_and_install(package, operator, log):
    """The first steps of every GUI test, a generator to `yield from`: waits
    for the window, closes Blender 4.x's first-start Quick Setup (shown even
    with the splash off; like any popup it takes every event until it is
    closed), checks the window is real, installs and enables `package` (None:
    the newest in dist/ built for this Blender) in the sandbox and checks
    that `operator` (a bpy.types name) is registered. Returns (window, the
    package's module name)."""
    wm = bpy.context.window_manager
    while not wm.windows or wm.windows[0].screen is None:
        yield 0.2
    window = wm.windows[0]
    yield 0.5
    window.event_simulate(type="ESC", value="PRESS", x=window.width // 2, y=window.height // 2)
    window.event_simulate(type="ESC", value="RELEASE", x=window.width // 2, y=window.height // 2)
    yield 0.5
    log(f"Blender {bpy.app.version_string}, Python {sys.version.split()[0]}, window "
        f"{window.width}x{window.height}, background={bpy.app.background}")
    check(not bpy.app.background, "Blender runs in the background (-b): this test needs a window")
    sandbox = blender_sandbox.check_sandboxed()
    package = package or blender_sandbox.find_package(os.path.join(ROOT, "dist"))
    with bpy.context.temp_override(window=window):
        name = blender_sandbox.install_package(package)
    log(f"installed {package} as {name} in {sandbox}")
    check(hasattr(bpy.types, operator), f"{operator} is not registered")
    yield 0.5
    return window, name


def edge_mesh_object(name, xy, edges, x_offset=0.0):
    """A new object with an edge-only mesh: vertices `xy` (#V by 2, z = 0,
    x moved by `x_offset`), `edges` (#E by 2), linked to the scene."""
    import numpy as np
    coords = np.zeros((len(xy), 3))
    coords[:, :2] = xy
    coords[:, 0] += x_offset
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(coords))
    mesh.vertices.foreach_set("co", coords.ravel())
    mesh.edges.add(len(edges))
    mesh.edges.foreach_set("vertices", np.asarray(edges, dtype=np.int32).ravel())
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def bake_test_args(prog, description, vertices):
    """The arguments of a bake test (after `--`): --package, --vertices
    (default `vertices`) and --timeout."""
    import argparse
    parser = argparse.ArgumentParser(prog=prog, description=description)
    parser.add_argument("--package", help="the package to install (default: the newest in dist/ for this Blender)")
    parser.add_argument("--vertices", type=int, default=vertices, help=f"vertices of each figure (default {vertices})")
    parser.add_argument("--timeout", type=float, default=240, help="watchdog, seconds (default 240)")
    return parser.parse_args(script_args())


def wave_figures(n):
    """Two selected edge meshes of n vertices, a wave (Source) into another
    wave (Target, active), side by side: graphs of functions of x, so valid
    and compatible. Call in a 3D Viewport's context."""
    import numpy as np
    x = np.linspace(0.0, 100.0, n)
    source_xy = np.stack([x, 3 * np.sin(0.7 * x) + 1.5 * np.sin(2.3 * x)], axis=1)
    target_xy = np.stack([x, -2 * np.cos(0.3 * x) + 0.5 * np.sin(1.1 * x)], axis=1)
    edges = np.stack([np.arange(n - 1), np.arange(1, n)], axis=1).astype(np.int32)
    source = edge_mesh_object("Source", source_xy, edges, 0.0)
    target = edge_mesh_object("Target", target_xy, edges, 150.0)
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in (source, target))
    bpy.context.view_layer.objects.active = target
    bpy.context.view_layer.update()
    return source, target


def file_state():
    """Everything a bake could change in the file (objects, meshes, shape
    keys, actions, node groups, materials, collections, selection, frame
    range, the add-on's last result)."""
    scene = bpy.context.scene
    view_layer = bpy.context.view_layer
    return {
        "objects": sorted((o.name, o.type, o.data.name if o.data else None, o.select_get(),
                           tuple(m.name for m in o.modifiers)) for o in bpy.data.objects),
        "meshes": sorted((m.name, len(m.vertices), len(m.edges), m.shape_keys is not None) for m in bpy.data.meshes),
        "shape_keys": sorted(k.name for k in bpy.data.shape_keys),
        "actions": sorted(a.name for a in bpy.data.actions),
        "node_groups": sorted(g.name for g in bpy.data.node_groups),
        "materials": sorted(m.name for m in bpy.data.materials),
        "collections": sorted((c.name, tuple(sorted(o.name for o in c.objects))) for c in bpy.data.collections),
        "active": view_layer.objects.active.name if view_layer.objects.active else None,
        "frames": (scene.frame_start, scene.frame_end, scene.frame_current),
        "last_result": scene.stick_morph.last_result,
    }


def until_the_event_loop_turns_quickly():
    """Steps until the event loop turns quickly again: the viewport's first
    drawing of large meshes (seconds with llvmpipe under Xvfb) holds it up,
    and with it every simulated event."""
    last, quick = time.monotonic(), 0
    for _ in range(3000):
        yield 0.01
        now = time.monotonic()
        quick = quick + 1 if now - last < 0.1 else 0
        last = now
        if quick == 5:
            return


def view3d(window):
    """(area, its WINDOW region, its UI region or None) of the window's largest 3D Viewport."""
    areas = [a for a in window.screen.areas if a.type == "VIEW_3D"]
    check(areas, "the window has no 3D Viewport")
    area = max(areas, key=lambda a: a.width * a.height)
    regions = {r.type: r for r in area.regions}
    return area, regions["WINDOW"], regions.get("UI")


def finish(code):
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


def run(steps, timeout, log, passed):
    """Runs the generator `steps` from a timer, each value it yields the
    seconds to the next step; ends Blender with 0 (and the line "PASSED:
    <passed>") when it is done, 1 on CheckFailed or any error, 2 when
    `timeout` seconds pass first."""
    bpy.context.preferences.view.show_splash = False  # no splash over the window (the sandbox's preferences)
    watchdog = threading.Timer(timeout, lambda: (log(f"timed out after {timeout} s"), finish(2)))
    watchdog.daemon = True
    watchdog.start()

    def tick():
        try:
            delay = next(steps)
        except StopIteration:
            log(f"PASSED: {passed}")
            finish(0)
        except CheckFailed as failure:
            log(f"FAILED: {failure}")
            finish(1)
        except Exception:
            traceback.print_exc()
            log("FAILED: error (traceback above)")
            finish(1)
        return delay

    bpy.app.timers.register(tick, first_interval=1.0)
