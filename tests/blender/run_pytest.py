"""Runs the add-on's pytest tests inside Blender.

    blender -b --factory-startup --python-exit-code 1 --python tests/blender/run_pytest.py -- [pytest args]

The tests install the package built for this Blender (the newest
dist/stick_morph-*-blender<M.m>-cp<XY>-*.zip on Blender < 4.2, a legacy
add-on; dist/stick_morph-*-cp<XY>-*.zip on 4.2+, an extension with the
engine's wheel, installed into the user_default repository with `blender
--command extension install-file`; or $STICKMORPH_ADDON_ZIP). So that the real user configuration is never touched, this script first
re-launches Blender with every user folder (config, scripts, datafiles,
extensions) in a temporary folder (scripts/blender_sandbox.py), and runs
pytest there; conftest.py checks that Blender really uses those folders.
Blender's exit code is pytest's; "no tests collected" (5) counts as a failure.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import blender_sandbox  # noqa: E402
from blender_sandbox import SANDBOX  # noqa: E402


def pytest_args():
    return sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []


def relaunch_in_sandbox():
    return blender_sandbox.relaunch_in_sandbox(__file__, pytest_args(), "stickmorph-blender-")


def run_pytest():
    import pytest
    args = pytest_args()
    # Test paths given (tests/blender/test_bake.py::test_x)? Else all of tests/blender.
    if not any(os.path.exists(a.split("::")[0]) for a in args if not a.startswith("-")):
        args = [HERE, *args]
    code = int(pytest.main(["-p", "no:cacheprovider", "-o", "console_output_style=classic", *args]))
    if code == 5:
        print("run_pytest.py: no tests were collected; that counts as a failure", flush=True)
        code = 1
    return code


if __name__ == "__main__":
    if not os.environ.get(SANDBOX):
        sys.exit(relaunch_in_sandbox())
    sys.exit(run_pytest())
