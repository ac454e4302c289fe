"""The way a farm or a script installs the extension (issue 33): `blender
--command extension install-file -r user_default --enable PACKAGE` in one
process, then a new `blender -b` that bakes. The second Blender reads the
preferences the first one saved, so the extension is enabled at startup and
the engine is imported from the wheel Blender installed into the user's
extensions/.local site-packages, with nothing done by the test in between.

The rest of the suite installs the same package with the same command but in
its own, already running Blender (scripts/blender_sandbox.py); this test is
the two-process path end to end. Blender before 4.2 has no extensions.
"""

import json
import os
import subprocess
import sys
import tempfile
import textwrap

import bpy
import pytest

from conftest import POLYGON_DANGLING, ROOT, addon_package

sys.path.insert(0, os.path.join(ROOT, "scripts"))
import blender_sandbox  # noqa: E402

FRAMES = 7

# Runs in the second Blender: bakes the pair and reports what it sees.
BAKE = textwrap.dedent('''
    import json, os, sys
    import bpy
    source_xy, target_xy, edges = json.loads(sys.argv[sys.argv.index("--") + 1])
    frames = int(sys.argv[sys.argv.index("--") + 2])
    enabled = sorted(bpy.context.preferences.addons.keys())
    bpy.ops.wm.read_homefile(use_empty=True)
    for name, xy in (("Source", source_xy), ("Target", target_xy)):
        mesh = bpy.data.meshes.new(name)
        mesh.from_pydata([(x, y, 0.0) for x, y in xy], edges, [])
        bpy.context.scene.collection.objects.link(bpy.data.objects.new(name, mesh))
    before = set(bpy.data.objects.keys())
    result = bpy.ops.object.stick_morph_bake(source="Source", target="Target", frame_count=frames)
    made = [bpy.data.objects[n] for n in set(bpy.data.objects.keys()) - before]
    keyed = [o for o in made if o.type == "MESH" and o.data.shape_keys is not None]
    blocks = keyed[0].data.shape_keys.key_blocks if keyed else []
    world = keyed[0].matrix_world if keyed else None
    import stickmorph
    print("STICKMORPH_BAKED " + json.dumps({
        "enabled": enabled, "result": sorted(result), "engine": stickmorph.__file__,
        "keys": [[list(world @ v.co) for v in block.data] for block in blocks]}))
''')


def test_install_file_then_bake_in_a_new_blender(addon):
    if not blender_sandbox.uses_extensions():
        pytest.skip(f"Blender {bpy.app.version_string} has no extensions (the legacy add-on zip)")
    package = addon_package()
    source, target, edges = POLYGON_DANGLING
    with tempfile.TemporaryDirectory(prefix="stickmorph-install-file-") as tmp:
        sandbox = os.path.join(tmp, "sandbox")
        env = blender_sandbox.sandbox_env(sandbox)
        install = subprocess.run([bpy.app.binary_path, "--command", "extension", "install-file", "-r",
                                  blender_sandbox.USER_REPOSITORY, "--enable", package],
                                 env=env, capture_output=True, text=True, timeout=300)
        assert install.returncode == 0, install.stdout + install.stderr
        # No --factory-startup: the preferences install-file saved are read.
        bake = subprocess.run([bpy.app.binary_path, "-b", "--python-exit-code", "1", "--python-expr", BAKE,
                               "--", json.dumps([source, target, edges]), str(FRAMES)],
                              env=env, capture_output=True, text=True, timeout=300)
        text = bake.stdout + bake.stderr
        assert bake.returncode == 0, text[-4000:]
        line = next(l for l in bake.stdout.splitlines() if l.startswith("STICKMORPH_BAKED "))
        report = json.loads(line.split(" ", 1)[1])
        local = os.path.realpath(os.path.join(sandbox, "extensions", ".local"))
        assert os.path.realpath(report["engine"]).startswith(local), report["engine"]
    assert blender_sandbox.addon_module_name() in report["enabled"], report["enabled"]
    assert report["result"] == ["FINISHED"]
    keys = report["keys"]
    # The basis and one key per frame; the first frame on the source, the
    # last on the target, in world space (the figures lie in z = 0).
    assert len(keys) >= FRAMES, len(keys)
    first, last = keys[-FRAMES], keys[-1]
    for got, want in ((first, source), (last, target)):
        assert len(got) == len(want)
        for (x, y, z), (wx, wy) in zip(got, want):
            assert abs(x - wx) < 1e-5 and abs(y - wy) < 1e-5 and abs(z) < 1e-5, (got, want)
