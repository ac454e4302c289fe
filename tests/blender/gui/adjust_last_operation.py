"""GUI test: Adjust Last Operation on the bake operator, in a real Blender window.

    /usr/bin/python3 scripts/blender_sandbox.py -- xvfb-run -a -s "-screen 0 1600x900x24" \\
        blender --factory-startup --enable-event-simulate --python-exit-code 1 \\
        --python tests/blender/gui/adjust_last_operation.py -- \\
        [--package ZIP] [--out DIR] [--frames N] [--redo-frames M] [--timeout SECONDS]

(tests/blender/gui/run_gui_tests.sh runs exactly that.) Blender runs WITHOUT
-b, so the operator runs in a window with a 3D Viewport, as when a user
clicks Bake, and its redo panel exists. Steps, each run from a timer once the
window is up:

1. Checks that every user folder is in the sandbox, installs the package
   built for this Blender (legacy add-on before 4.2, extension from 4.2) and
   enables it.
2. Replaces the startup scene by two edge meshes with non-identity world
   matrices: the source translated, rotated and non-uniformly scaled; the
   target parented to a transformed empty, with a parent-inverse matrix and a
   transform of its own. Their world vertices are computed here, from the
   matrices composed by hand, and compared with Blender's matrix_world.
3. Bakes with frame_count=N in the 3D Viewport's context, as a click does
   (INVOKE_DEFAULT: modal, the engine in a worker thread; registered, one
   undo step), waits for it to finish and checks the result: frame
   start is the source in world space, frame start + N - 1 the target.
4. Adjusts the last operation the way the redo panel does: it sets Frames to
   M on the registered operator (window_manager.operators[-1], the operator
   the panel draws) and calls ed.undo_redo, which runs ED_undo_operator_repeat
   exactly as a property change in the panel does: undo the bake's step,
   re-execute the operator with the changed properties.
5. Checks the re-executed result again: one result object, M frames, frame
   start = the source and frame start + M - 1 = the target in world space
   (evaluated vertices, relative tolerance 1e-5 of the figures' size), and
   the old last frame no longer the target.
6. Opens the sidebar on the Stick Morph tab and saves a screenshot of the
   window (printed as STICKMORPH_SCREENSHOT <path>).

Exits with os._exit: 0 if every check passed, 1 on a failed check or error,
2 if the watchdog's timeout ran out.
"""

import argparse
import ctypes
import os
import struct
import sys
import zlib

import bpy
import numpy as np
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui_driver  # noqa: E402
from gui_driver import ROOT, check, view3d  # noqa: E402

log = gui_driver.logger("adjust_last_operation.py")

OPERATOR = "OBJECT_OT_stick_morph_bake"
RELATIVE_TOLERANCE = 1e-5

# A compatible pair (a junction with three arms, two edges each), not one the
# engine's own tests use.
SOURCE_XY = [[0, 0], [1, 0], [2, 0.2], [-0.5, 0.9], [-1.0, 1.8], [-0.5, -0.9], [-0.8, -1.9]]
TARGET_XY = [[0, 0], [0.9, 0.5], [1.5, 1.3], [-0.9, 0.4], [-1.9, 0.2], [0.1, -1.0], [0.9, -1.6]]
EDGES = [[0, 1], [1, 2], [0, 3], [3, 4], [0, 5], [5, 6]]

# The plane both figures lie in (tilted about X and Y). Every other matrix
# below turns about the plane's local Z, scales in its local XY, or moves, so
# both figures stay in parallel planes, as the add-on requires.
TILT = Matrix.Rotation(0.7, 4, "X") @ Matrix.Rotation(-0.4, 4, "Y")


def source_matrix():
    return (Matrix.Translation((2.0, -1.5, 0.75)) @ TILT @ Matrix.Rotation(0.3, 4, "Z")
            @ Matrix.Diagonal((1.6, 0.9, 1.0, 1.0)))


def parent_matrix():
    return (Matrix.Translation((-1.0, 3.0, 1.25)) @ TILT @ Matrix.Rotation(-0.6, 4, "Z")
            @ Matrix.Diagonal((0.7, 0.7, 0.7, 1.0)))


def parent_inverse():
    return Matrix.Translation((0.3, -0.2, 0.0)) @ Matrix.Rotation(0.25, 4, "Z")


def target_basis():
    # Off the parent's plane along its normal (z): a parallel plane.
    return (Matrix.Translation((0.5, -0.4, 0.6)) @ Matrix.Rotation(0.9, 4, "Z")
            @ Matrix.Diagonal((1.3, 1.1, 1.0, 1.0)))


def parse_args():
    argv = gui_driver.script_args()
    parser = argparse.ArgumentParser(prog="adjust_last_operation.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("--package", help="the package to install (default: the newest in dist/ for this Blender)")
    parser.add_argument("--out", help="folder for the screenshot (default: out/gui/blender<M.m>/)")
    parser.add_argument("--frames", type=int, default=6, help="Frames of the first bake (default 6)")
    parser.add_argument("--redo-frames", type=int, default=11,
                        help="Frames set in Adjust Last Operation (default 11)")
    parser.add_argument("--timeout", type=float, default=240, help="watchdog, seconds (default 240)")
    args = parser.parse_args(argv)
    if args.frames < 2 or args.redo_frames <= args.frames:
        parser.error("need 2 <= --frames < --redo-frames")
    return args




# ------------------------------------------------------------------ scene ----

def world_of(matrix, xy):
    """World coordinates of 2D points at z = 0 under a 4x4 matrix (numpy, float64)."""
    m = np.array(matrix, dtype=np.float64)
    local = np.zeros((len(xy), 3))
    local[:, :2] = np.asarray(xy, dtype=np.float64)
    return local @ m[:3, :3].T + m[:3, 3]


def make_mesh(name, xy):
    coords = [(x, y, 0.0) for x, y in xy]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(coords, [tuple(e) for e in EDGES], [])
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def set_up_scene(view_layer):
    """Two edge meshes (see the module's docstring); returns (source, target,
    expected source world, expected target world)."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    source = make_mesh("Source", SOURCE_XY)
    source.matrix_world = source_matrix()
    parent = bpy.data.objects.new("TargetParent", None)
    bpy.context.scene.collection.objects.link(parent)
    parent.matrix_world = parent_matrix()
    target = make_mesh("Target", TARGET_XY)
    target.parent = parent
    target.matrix_parent_inverse = parent_inverse()
    target.matrix_basis = target_basis()
    view_layer.update()

    source_world = world_of(source_matrix(), SOURCE_XY)
    target_world = world_of(parent_matrix() @ parent_inverse() @ target_basis(), TARGET_XY)
    # Blender's world matrices are the ones composed here.
    check(np.allclose(world_of(source.matrix_world, SOURCE_XY), source_world, atol=1e-6),
          "the source's matrix_world is not the matrix set")
    check(np.allclose(world_of(target.matrix_world, TARGET_XY), target_world, atol=1e-6),
          "the target's matrix_world is not parent @ parent inverse @ basis")
    for matrix in (source.matrix_world, target.matrix_world):
        check(not np.allclose(np.array(matrix), np.eye(4), atol=1e-3), "a world matrix is the identity")

    for obj in view_layer.objects:
        obj.select_set(False)
    source.select_set(True)
    target.select_set(True)
    view_layer.objects.active = target
    return source, target, source_world, target_world


def evaluated_world(obj, frame, context):
    """The result's evaluated vertices (shape keys, modifiers off) at a frame, in world space."""
    scene = context.scene
    saved = [(m, m.show_viewport) for m in obj.modifiers]
    for modifier, _ in saved:
        modifier.show_viewport = False
    try:
        scene.frame_set(frame)
        depsgraph = context.evaluated_depsgraph_get()
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        matrix = np.array(evaluated.matrix_world, dtype=np.float64)
        evaluated.to_mesh_clear()
    finally:
        for modifier, shown in saved:
            modifier.show_viewport = shown
    return co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]


def result_objects():
    return [o for o in bpy.data.objects if o.get("stick_morph_role") == "result"]


def frame_count_of(result):
    keys = result.data.shape_keys
    return len(keys.key_blocks) if keys is not None else 0


def check_result(context, frame_start, frames, source_world, target_world, size, when):
    results = result_objects()
    check(len(results) == 1, f"{when}: {len(results)} result objects ({[o.name for o in results]}), expected one")
    result = results[0]
    check(frame_count_of(result) == frames,
          f"{when}: the result has {frame_count_of(result)} shape keys (frames), expected {frames}")
    check(len(result.data.vertices) == len(SOURCE_XY), f"{when}: the result has {len(result.data.vertices)} vertices")
    tolerance = RELATIVE_TOLERANCE * size
    first = evaluated_world(result, frame_start, context)
    last = evaluated_world(result, frame_start + frames - 1, context)
    first_error = float(np.abs(first - source_world).max())
    last_error = float(np.abs(last - target_world).max())
    log(f"{when}: frame {frame_start} is off the source by {first_error:.3g}, frame "
        f"{frame_start + frames - 1} off the target by {last_error:.3g} (tolerance {tolerance:.3g})")
    check(first_error <= tolerance,
          f"{when}: frame {frame_start} is not the source in world space: off by {first_error:.6g} "
          f"(tolerance {tolerance:.3g}); result at\n{first}\nsource at\n{source_world}")
    check(last_error <= tolerance,
          f"{when}: frame {frame_start + frames - 1} is not the target in world space: off by {last_error:.6g} "
          f"(tolerance {tolerance:.3g}); result at\n{last}\ntarget at\n{target_world}")
    return result


# ---------------------------------------------------------------- window ----



def steps(args):
    """The test, one step per yield; a yielded number is the delay (seconds)
    before the next step, so Blender redraws and handles events in between."""
    wm = bpy.context.window_manager
    window, _ = yield from gui_driver.open_window_and_install(args.package, OPERATOR, log)

    area, region, _ = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        view_layer = bpy.context.view_layer
        _, _, source_world, target_world = set_up_scene(view_layer)
        # A user's own edits push undo steps; this scene was made by Python,
        # so push one, or undoing the bake would go back to the startup file.
        bpy.ops.ed.undo_push(message="Stick Morph GUI test: figures")
    both = np.vstack([source_world, target_world])
    size = float(np.linalg.norm(both.max(axis=0) - both.min(axis=0)))
    frame_start = 3
    yield 0.3

    # The bake, as a click on the panel's Bake button runs it: modal (issue
    # 29), the engine in a worker thread, until the result is built.
    registered = len(wm.operators)
    with bpy.context.temp_override(window=window, area=area, region=region):
        result = bpy.ops.object.stick_morph_bake("INVOKE_DEFAULT", True, frame_start=frame_start,
                                                 frame_count=args.frames)
    check(result in ({"FINISHED"}, {"RUNNING_MODAL"}), f"the bake returned {result}")
    for _ in range(600):
        if len(wm.operators) > registered:
            break
        yield 0.1
    log(f"baked with Frames = {args.frames} ({'modal' if result == {'RUNNING_MODAL'} else 'at once'})")
    yield 0.5

    check(len(wm.operators) > 0 and wm.operators[-1].bl_idname == OPERATOR,
          f"the last registered operator is {wm.operators[-1].bl_idname if len(wm.operators) else None}, "
          f"not {OPERATOR}: no redo panel for it")
    # The "Adjust Last Operation" panel lives in the area's HUD region.
    area, region, _ = view3d(window)
    check(any(r.type == "HUD" for r in area.regions), "the 3D Viewport shows no Adjust Last Operation panel")
    with bpy.context.temp_override(window=window, area=area, region=region):
        context = bpy.context
        check_result(context, frame_start, args.frames, source_world, target_world, size, "first bake")
    yield 0.3

    # Adjust Last Operation: Frames changed in the redo panel.
    op = wm.operators[-1]
    check(op.properties.frame_count == args.frames, f"the registered operator has Frames = {op.properties.frame_count}")
    op.properties.frame_count = args.redo_frames
    with bpy.context.temp_override(window=window, area=area, region=region):
        check(bpy.ops.ed.undo_redo.poll(), "ed.undo_redo cannot run (no redoable last operation)")
        # undo=True: the re-executed bake pushes its undo step, as it does
        # from the panel (a plain Python call would suppress it).
        result = bpy.ops.ed.undo_redo("EXEC_DEFAULT", True)
    check(result == {"FINISHED"}, f"ed.undo_redo returned {result}")
    log(f"adjusted the last operation to Frames = {args.redo_frames}")
    yield 0.5

    check(wm.operators[-1].bl_idname == OPERATOR and wm.operators[-1].properties.frame_count == args.redo_frames,
          "after the redo, the last operator is not the bake with the new Frames")
    area, region, _ = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        context = bpy.context
        # Undo must not have moved the inputs. They are looked up again: undo
        # may have replaced the data the earlier Python references point to.
        for name, xy, world in (("Source", SOURCE_XY, source_world), ("Target", TARGET_XY, target_world)):
            obj = bpy.data.objects.get(name)
            check(obj is not None, f"the {name.lower()} is gone after Adjust Last Operation")
            check(np.allclose(world_of(obj.matrix_world, xy), world, atol=1e-6),
                  f"the {name.lower()} moved in Adjust Last Operation")
        result_obj = check_result(context, frame_start, args.redo_frames, source_world, target_world, size,
                                  "after Adjust Last Operation")
        # The old last frame is now on the way, not at the target.
        old_last = evaluated_world(result_obj, frame_start + args.frames - 1, context)
        moved = float(np.abs(old_last - target_world).max())
        check(moved > 100 * RELATIVE_TOLERANCE * size,
              f"frame {frame_start + args.frames - 1} is still the target: the frame count did not change")
        context.scene.frame_set(frame_start + args.redo_frames // 2)

    # The sidebar on the Stick Morph tab, for the screenshot. No Python API
    # switches a sidebar tab (Region.active_panel_category is read-only in
    # 4.x and missing in 3.4), so Ctrl+Wheel does it, as for a user: one tab
    # per notch, stopping at the last one, which is the add-on's (registered
    # after Blender's own tabs). The pointer is on the first panel's header:
    # the sidebar overlaps the viewport, and where it draws nothing (below its
    # panels) events go to the viewport instead; over a header no button
    # takes the wheel for itself.
    space = area.spaces.active
    space.show_region_ui = True
    yield 0.5
    area, region, ui = view3d(window)
    check(ui is not None and ui.width > 1, "the sidebar did not open")
    x, y = ui.x + ui.width // 2, ui.y + ui.height - 15
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    yield 0.3
    for _ in range(12):
        window.event_simulate(type="WHEELDOWNMOUSE", value="PRESS", x=x, y=y, ctrl=True)
        yield 0.05
    yield 0.5
    out = os.path.abspath(args.out or os.path.join(ROOT, "out", "gui", "blender{}.{}".format(*bpy.app.version[:2])))
    os.makedirs(out, exist_ok=True)
    sidebar = screenshot(window, os.path.join(out, "redo_sidebar.png"))
    print(f"STICKMORPH_SCREENSHOT {sidebar}", flush=True)
    category = getattr(ui, "active_panel_category", None)
    if category is not None:  # readable from 4.x on
        check(category == "Stick Morph", f"the sidebar shows the tab '{category}', not Stick Morph")

    # The Adjust Last Operation popup (F9) over the 3D Viewport: it draws the
    # registered operator's properties, Frames included.
    x, y = region.x + region.width // 2, region.y + region.height // 2
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    yield 0.3
    window.event_simulate(type="F9", value="PRESS", x=x, y=y)
    window.event_simulate(type="F9", value="RELEASE", x=x, y=y)
    yield 1.0
    popup = screenshot(window, os.path.join(out, "redo_popup.png"))
    print(f"STICKMORPH_SCREENSHOT {popup}", flush=True)
    window.event_simulate(type="ESC", value="PRESS", x=x, y=y)
    window.event_simulate(type="ESC", value="RELEASE", x=x, y=y)
    yield 0.5

    area, region, _ = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        context = bpy.context
        # The user's next Ctrl+Z takes the re-baked result away, Ctrl+Shift+Z
        # brings it back: the redo left one proper undo step.
        check(bpy.ops.ed.undo() == {"FINISHED"}, "undo after Adjust Last Operation failed")
        check(not result_objects(), "undo after Adjust Last Operation left a result object")
        check(bpy.data.objects.get("Source") is not None and bpy.data.objects.get("Target") is not None,
              "undo after Adjust Last Operation removed the figures")
        check(bpy.ops.ed.redo() == {"FINISHED"}, "redo after undo failed")
        check_result(context, frame_start, args.redo_frames, source_world, target_world, size, "after undo + redo")


class XImage(ctypes.Structure):
    """The head of Xlib's XImage, up to the fields read here."""
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("xoffset", ctypes.c_int),
                ("format", ctypes.c_int), ("data", ctypes.POINTER(ctypes.c_ubyte)), ("byte_order", ctypes.c_int),
                ("bitmap_unit", ctypes.c_int), ("bitmap_bit_order", ctypes.c_int), ("bitmap_pad", ctypes.c_int),
                ("depth", ctypes.c_int), ("bytes_per_line", ctypes.c_int), ("bits_per_pixel", ctypes.c_int)]


def screenshot(window, path):
    """Saves the X screen (the Blender window fills it) as a PNG.

    Not bpy.ops.screen.screenshot: it reads the window's front buffer, which
    Blender 4.3 with Mesa's llvmpipe under Xvfb returns black; the X server's
    own copy is what a user would see."""
    x11 = ctypes.CDLL("libX11.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XDefaultRootWindow.restype = ctypes.c_ulong
    x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    x11.XGetImage.restype = ctypes.POINTER(XImage)
    x11.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint,
                              ctypes.c_uint, ctypes.c_ulong, ctypes.c_int]
    x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    display = x11.XOpenDisplay(None)
    check(display, f"cannot open the X display {os.environ.get('DISPLAY')}")
    try:
        z_pixmap = 2
        image = x11.XGetImage(display, x11.XDefaultRootWindow(display), 0, 0, window.width, window.height,
                              0xFFFFFFFF, z_pixmap)
        check(bool(image), "XGetImage failed")
        im = image.contents
        check(im.bits_per_pixel == 32 and im.byte_order == 0,
              f"unexpected X image format ({im.bits_per_pixel} bits per pixel, byte order {im.byte_order})")
        raw = np.ctypeslib.as_array(im.data, shape=(im.height * im.bytes_per_line,)).copy()
        height, width, stride = im.height, im.width, im.bytes_per_line
    finally:
        x11.XCloseDisplay(display)
    # 32-bit least-significant-byte-first pixels are B, G, R, unused.
    rgb = raw.reshape(height, stride)[:, :width * 4].reshape(height, width, 4)[:, :, [2, 1, 0]]
    check(rgb.max() > 0, "the screen is black: Blender drew nothing")

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    rows = b"".join(b"\x00" + row.tobytes() for row in rgb)  # filter type 0 per row
    with open(path, "wb") as file:
        file.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                   + chunk(b"IDAT", zlib.compress(rows, 6)) + chunk(b"IEND", b""))
    return path


def main():
    args = parse_args()
    gui_driver.run(steps(args), args.timeout, log, "Adjust Last Operation re-bakes in world space with the new frame count")


main()
