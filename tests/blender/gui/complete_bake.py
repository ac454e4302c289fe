"""GUI test: a 10^4-vertex bake runs to the end in a window, and Ctrl+Z undoes it (issue 29).

    /usr/bin/python3 scripts/blender_sandbox.py -- xvfb-run -a -s "-screen 0 1600x900x24" \\
        blender --factory-startup --enable-event-simulate --python-exit-code 1 \\
        --python tests/blender/gui/complete_bake.py -- [--package ZIP] [--vertices N] [--timeout SECONDS]

(tests/blender/gui/run_gui_tests.sh runs it after cancel_bake.py.) Blender
runs WITHOUT -b, so the bake is modal as when a user clicks Bake: the engine
in a worker thread, the status text showing its stage. Steps, each run from a
timer once the window is up:

1. Installs and enables the package built for this Blender.
2. Makes two edge meshes of N vertices (default 10000), a wave into another
   wave, pushes an undo step for them (as a user's own edits would have) and
   records everything in the file.
3. Bakes in the 3D Viewport's context as the Bake button does
   (INVOKE_DEFAULT, 50 frames): RUNNING_MODAL, and the status text shows a
   stage while the worker runs.
4. Waits for the bake to finish and checks it: one result object with 50
   frames of shape keys, the operator registered (it has an Adjust Last
   Operation), the scene's last result naming it, the worker's job ended
   without an error.
5. Presses Ctrl+Z over the viewport (window.event_simulate) and checks that
   everything recorded in step 2 is as it was. Prints how long the bake took.

Exits with os._exit: 0 if every check passed, 1 on a failed check or error,
2 if the watchdog's timeout ran out.
"""

import importlib
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui_driver  # noqa: E402
from gui_driver import check, file_state, view3d  # noqa: E402

log = gui_driver.logger("complete_bake.py")

OPERATOR = "OBJECT_OT_stick_morph_bake"
FRAMES = 50


def steps(args):
    wm = bpy.context.window_manager
    window, name = yield from gui_driver.open_window_and_install(args.package, OPERATOR, log)
    bake_job = importlib.import_module(f"{name}.bake_job")

    area, region, _ = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        gui_driver.wave_figures(args.vertices)
        # A user's own edits push undo steps; these were made by Python, so
        # push one, or Ctrl+Z would go back to the startup file.
        bpy.ops.ed.undo_push(message="Stick Morph GUI test: figures")
    before = file_state()
    registered = len(wm.operators)
    yield from gui_driver.until_the_event_loop_turns_quickly()

    started = time.monotonic()
    with bpy.context.temp_override(window=window, area=area, region=region):
        result = bpy.ops.object.stick_morph_bake("INVOKE_DEFAULT", True, frame_count=FRAMES)
    check(result == {"RUNNING_MODAL"}, f"the bake returned {result}, not RUNNING_MODAL")
    job = bake_job.last_started()
    check(job is not None, "the modal bake started no job")
    seen = set()
    while job.running and time.monotonic() - started < 180:
        seen.add(job.stage()[0])
        yield 0.01
    check(not job.running, "the bake's worker still runs after 180 s")
    # The operator finishes at its next timer event after the worker.
    while len(wm.operators) == registered and time.monotonic() - started < 200:
        yield 0.05
    took = time.monotonic() - started
    check(job.error is None, f"the engine call ended with {job.error!r}")
    log(f"bake of {args.vertices} vertices, {FRAMES} frames finished in {took:.1f} s (stages seen: {sorted(s for s in seen if s)})")
    check(len(wm.operators) == registered + 1 and wm.operators[-1].bl_idname == OPERATOR,
          "the finished bake was not registered (no Adjust Last Operation)")
    results = [o for o in bpy.data.objects if o.name not in {b[0] for b in before["objects"]}]
    check(len(results) == 1, f"{len(results)} new objects ({[o.name for o in results]}), expected the result only")
    keys = results[0].data.shape_keys
    check(keys is not None and len(keys.key_blocks) >= FRAMES,
          f"the result has {len(keys.key_blocks) if keys else 0} shape keys, expected at least {FRAMES}")
    check(bpy.context.scene.stick_morph.last_result == results[0].name,
          f"the scene's last result is {bpy.context.scene.stick_morph.last_result!r}, not {results[0].name!r}")
    yield 0.5

    x, y = area.x + area.width // 2, area.y + area.height // 2
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    yield 0.2
    window.event_simulate(type="Z", value="PRESS", x=x, y=y, ctrl=True)
    window.event_simulate(type="Z", value="RELEASE", x=x, y=y, ctrl=True)
    yield 1.0
    after = file_state()
    for key in before:
        check(after[key] == before[key], f"{key} after Ctrl+Z differs from before the bake: "
                                         f"{before[key]!r} -> {after[key]!r}")
    log("Ctrl+Z left the scene exactly as before the bake")


def main():
    args = gui_driver.bake_test_args("complete_bake.py", __doc__.split("\n\n")[0], 10000)
    gui_driver.run(steps(args), args.timeout, log, "a 10^4-vertex modal bake finished; Ctrl+Z undid it")


main()
