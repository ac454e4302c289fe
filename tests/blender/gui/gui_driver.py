"""What the GUI test scripts share (adjust_last_operation.py, cancel_bake.py):
the repository's paths and scripts/blender_sandbox.py, the checks, the 3D
Viewport of a window, and the driver that runs a test's steps from a timer
under a watchdog and ends Blender with the test's code.

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
