"""Re-launching a script in a Blender whose user folders are temporary.

Used by tests/blender/run_pytest.py and scripts/render_demo.py: both install
the add-on zip, and the real user configuration must never be touched.
"""

import os
import subprocess
import tempfile

# Set in the re-launched Blender to the temporary folder.
SANDBOX = "STICKMORPH_BLENDER_SANDBOX"


def relaunch_in_sandbox(script, args, prefix):
    """Runs `script` with `args` in a new headless Blender whose user scripts,
    config and datafiles live in a temporary folder; returns its exit code."""
    import bpy
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        env = dict(os.environ)
        env.update({
            "BLENDER_USER_SCRIPTS": os.path.join(tmp, "scripts"),
            "BLENDER_USER_CONFIG": os.path.join(tmp, "config"),
            "BLENDER_USER_DATAFILES": os.path.join(tmp, "datafiles"),
            SANDBOX: tmp,
        })
        command = [bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1",
                   "--python", os.path.abspath(script), "--", *args]
        return subprocess.call(command, env=env)
