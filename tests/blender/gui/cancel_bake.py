"""GUI test: Esc cancels a long bake and leaves the scene as it was (issue 29).

    /usr/bin/python3 scripts/blender_sandbox.py -- xvfb-run -a -s "-screen 0 1600x900x24" \\
        blender --factory-startup --enable-event-simulate --python-exit-code 1 \\
        --python tests/blender/gui/cancel_bake.py -- [--package ZIP] [--vertices N] [--timeout SECONDS]

(tests/blender/gui/run_gui_tests.sh runs it after adjust_last_operation.py.)
Blender runs WITHOUT -b, so the bake operator's invoke runs modal: the engine
in a worker thread, a window-manager timer showing its stage. Steps, each run
from a timer once the window is up:

1. Installs and enables the package built for this Blender.
2. Makes two edge meshes of N vertices (default 30000), a wave into another
   wave, and records everything in the file (objects, meshes, shape keys,
   actions, node groups, materials, collections, selection, frame range).
3. Bakes in the 3D Viewport's context as the Bake button does
   (INVOKE_DEFAULT): the operator must answer RUNNING_MODAL.
4. Waits until the bake's job (bake_job.last_started()) is triangulating,
   then presses Esc (window.event_simulate) and waits for the job to end.
5. Checks: the job was cancelled and its engine call raised
   stickmorph.CancelledError; the operator was not registered (a cancelled
   operator leaves no Adjust Last Operation); everything recorded in step 2
   is as it was; where Blender can read it from Python (not 3.4), the Info
   log says the bake was cancelled. Prints how long the cancel took to take
   effect.

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

log = gui_driver.logger("cancel_bake.py")

OPERATOR = "OBJECT_OT_stick_morph_bake"


def steps(args):
    wm = bpy.context.window_manager
    window, name = yield from gui_driver.open_window_and_install(args.package, OPERATOR, log)
    bake_job = importlib.import_module(f"{name}.bake_job")
    engine = importlib.import_module(f"{name}.native").load_engine()
    yield 0.5

    area, region, _ = view3d(window)
    with bpy.context.temp_override(window=window, area=area, region=region):
        gui_driver.wave_figures(args.vertices)
    before = file_state()
    registered = len(wm.operators)
    yield from gui_driver.until_the_event_loop_turns_quickly()

    with bpy.context.temp_override(window=window, area=area, region=region):
        result = bpy.ops.object.stick_morph_bake("INVOKE_DEFAULT", True, frame_count=50)
    check(result == {"RUNNING_MODAL"}, f"the bake returned {result}, not RUNNING_MODAL")
    job = bake_job.last_started()
    check(job is not None, "the modal bake started no job")
    started = time.monotonic()
    while job.running and job.stage()[0] != "triangulate" and time.monotonic() - started < 120:
        yield 0.01
    check(job.running, f"the bake ended before it could be cancelled ({job.timer.summary()}); use more --vertices")
    log(f"bake running: {job.status_text()!r} after {time.monotonic() - started:.2f} s")
    yield 0.3  # the status text shown for a while (for a screenshot by hand)
    check(job.running, "the bake ended while triangulating; use more --vertices")
    pressed = time.monotonic()
    x, y = area.x + area.width // 2, area.y + area.height // 2
    window.event_simulate(type="ESC", value="PRESS", x=x, y=y)
    window.event_simulate(type="ESC", value="RELEASE", x=x, y=y)
    received = None  # when the operator's modal handler had the Esc (it cancels the job)
    while job.running and time.monotonic() - pressed < 60:
        if received is None and job.cancelled:
            received = time.monotonic() - pressed
        yield 0.01
    stopped = time.monotonic() - pressed
    check(not job.running, "the bake's worker still runs 60 s after Esc")
    # The operator ends at its next timer event after the worker.
    yield 0.5
    log(f"Esc took effect in {stopped * 1000:.0f} ms: the operator had it after "
        f"{(received if received is not None else stopped) * 1000:.0f} ms, the engine stopped "
        f"{(stopped - (received or stopped)) * 1000:.0f} ms later (engine stages {job.progress.summary()!r})")
    check(job.cancelled, "the job was not cancelled by Esc")
    check(isinstance(job.error, engine.CancelledError), f"the engine call ended with {job.error!r}, not CancelledError")
    check(len(wm.operators) == registered, "the cancelled bake was registered (it would have an Adjust Last Operation)")
    after = file_state()
    for key in before:
        check(after[key] == before[key], f"{key} changed by the cancelled bake: {before[key]!r} -> {after[key]!r}")
    log("the scene is exactly as before the bake")
    # The Info log (read last: it writes a text block), where an operator
    # reads it (not in 3.4).
    try:
        bpy.ops.ui.reports_to_textblock.get_rna_type()
        readable = True
    except (AttributeError, KeyError, RuntimeError):
        readable = False
    if readable:
        with bpy.context.temp_override(window=window, area=area, region=region):
            bpy.ops.ui.reports_to_textblock()
        text = bpy.data.texts[-1].as_string()
        check("Stick Morph: bake cancelled" in text, f"no cancel report in the Info log:\n{text[-2000:]}")
        log("the Info log says the bake was cancelled")
    else:
        log(f"Blender {bpy.app.version_string} cannot read the Info log from Python: the report is not checked")


def main():
    args = gui_driver.bake_test_args("cancel_bake.py", __doc__.split("\n\n")[0], 30000)
    gui_driver.run(steps(args), args.timeout, log, "Esc cancelled the bake while it triangulated; nothing changed")


main()
