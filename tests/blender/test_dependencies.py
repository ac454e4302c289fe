"""The enable-time check of numpy and the native module (dependencies.py) in
Blender: a child Blender enables a package whose module was built for another
Python, and one without numpy, and must register, say what is missing and
refuse the bake with an ERROR.

An extension (4.2+) carries the engine as a wheel, and Blender itself reads
the wheel's Python tag: a package whose wheel is for another Python installs
but does not enable, and `extension install-file` says why, naming both
Pythons. What the add-on reports itself is a wheel of the right Python whose
module does not load (a missing system library, a damaged file).

dependencies.py imports neither bpy nor numpy; its logic on made-up packages
is tested outside Blender, in tests/python/test_addon_dependencies.py.
"""

import io
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import zipfile

import bpy

from conftest import ROOT, addon_package

sys.path.insert(0, os.path.join(ROOT, "scripts"))
import blender_sandbox  # noqa: E402

OTHER_PYTHON = {"python": "3.9", "python_tag": "cpython-39",
                "module": "stickmorph.cpython-39-x86_64-linux-gnu.so", "built_on": "Debian 11, GCC 10"}


# Runs in a child Blender with its own sandbox; argv after --: package, case.
ENABLE = textwrap.dedent('''
    import sys, traceback
    package, case = sys.argv[sys.argv.index("--") + 1:]
    if case == "no-numpy":
        sys.modules["numpy"] = None
    sys.path.insert(0, {scripts!r})
    import bpy, blender_sandbox
    try:
        name = blender_sandbox.install_package(package)
    except Exception:
        traceback.print_exc()
        print("STICKMORPH_ENABLE_FAILED")
        raise SystemExit(1)
    assert name in bpy.context.preferences.addons
    assert hasattr(bpy.types, "VIEW3D_PT_stick_morph") and hasattr(bpy.types, "VIEW3D_PT_stick_morph_advanced")
    import importlib
    operators = importlib.import_module(name + ".operators")
    status = operators.dependency_status()
    print("STICKMORPH_LINES", repr(status.lines()))
    bpy.ops.wm.read_homefile(use_empty=True)
    for n, xy in (("S", [(0, 0, 0), (1, 0, 0)]), ("T", [(0, 1, 0), (1, 1, 0)])):
        mesh = bpy.data.meshes.new(n)
        mesh.from_pydata(xy, [(0, 1)], [])
        bpy.context.scene.collection.objects.link(bpy.data.objects.new(n, mesh))
    count = len(bpy.data.objects)
    try:
        bpy.ops.object.stick_morph_bake(source="S", target="T", frame_count=3)
    except RuntimeError as error:
        print("STICKMORPH_BAKE_ERROR", str(error).replace(chr(10), " "))
    assert len(bpy.data.objects) == count
    print("STICKMORPH_ENABLE_OK")
''')


def this_tag():
    return f"cp{sys.version_info[0]}{sys.version_info[1]}"


def repackage_for_other_python(source_zip, target_zip):
    """The package under test with its module (a legacy add-on) or its wheel
    (an extension, and the manifest's wheels entry) renamed as if built for
    Python 3.9, and a build_info.json that says so."""
    with zipfile.ZipFile(source_zip) as src, zipfile.ZipFile(target_zip, "w") as dst:
        for item in src.infolist():
            folder, name = os.path.split(item.filename)
            if name.startswith("stickmorph") and name.endswith(".so"):
                dst.writestr(os.path.join(folder, OTHER_PYTHON["module"]), src.read(item))
            elif name.startswith("stickmorph-") and name.endswith(".whl"):
                dst.writestr(os.path.join(folder, name.replace(this_tag(), "cp39")), src.read(item))
            elif name == "blender_manifest.toml":
                dst.writestr(item, src.read(item).decode().replace(f"-{this_tag()}-", "-cp39-"))
            elif name == "build_info.json":
                dst.writestr(item, json.dumps(OTHER_PYTHON))
            else:
                dst.writestr(item, src.read(item))


def repackage_with_a_module_that_does_not_load(source_zip, target_zip):
    """The extension with its wheel's module replaced by bytes no loader
    takes: the wheel is of this Python, so Blender installs and enables it,
    and the import fails as it would without the system's libgmp."""
    with zipfile.ZipFile(source_zip) as src, zipfile.ZipFile(target_zip, "w") as dst:
        for item in src.infolist():
            data = src.read(item)
            if item.filename.startswith("wheels/") and item.filename.endswith(".whl"):
                buffer = io.BytesIO()
                with zipfile.ZipFile(io.BytesIO(data)) as wheel_in, zipfile.ZipFile(buffer, "w") as wheel_out:
                    for entry in wheel_in.infolist():
                        content = wheel_in.read(entry)
                        if entry.filename.startswith("stickmorph.") and entry.filename.endswith(".so"):
                            content = b"not a shared object"
                        wheel_out.writestr(entry, content)
                data = buffer.getvalue()
            dst.writestr(item, data)


def run_enable(package, case, expect_ok=True):
    script = ENABLE.replace("{scripts!r}", repr(os.path.join(ROOT, "scripts")))
    with tempfile.TemporaryDirectory(prefix="stickmorph-deps-") as tmp:
        env = blender_sandbox.sandbox_env(os.path.join(tmp, "sandbox"))
        out = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1",
                              "--python-expr", script, "--", package, case],
                             env=env, capture_output=True, text=True, timeout=300)
    text = out.stdout + out.stderr
    if not expect_ok:
        assert out.returncode != 0 and "STICKMORPH_ENABLE_FAILED" in out.stdout, text[-4000:]
        return {}, text
    assert out.returncode == 0 and "STICKMORPH_ENABLE_OK" in out.stdout, text[-4000:]
    lines = [l for l in out.stdout.splitlines() if l.startswith("STICKMORPH_")]
    return {l.split(" ", 1)[0]: (l.split(" ", 1) + [""])[1] for l in lines}, text


def test_enabling_a_package_for_another_python(addon):
    python = f"{sys.version_info[0]}.{sys.version_info[1]}"
    with tempfile.TemporaryDirectory() as tmp:
        package = os.path.join(tmp, os.path.basename(addon_package()))
        repackage_for_other_python(addon_package(), package)
        found, text = run_enable(package, "other-python", expect_ok=not blender_sandbox.uses_extensions())
    if blender_sandbox.uses_extensions():
        # Blender refuses to enable it before any of the add-on's code runs.
        assert f"This Python version ({python}) isn't compatible with (3.9)" in text, text[-3000:]
        return
    assert "Built for: Python 3.9 (cpython-39), on Debian 11, GCC 10" in found["STICKMORPH_LINES"], text[-3000:]
    error = found.get("STICKMORPH_BAKE_ERROR", "")
    assert error.startswith("Error: Stick Morph: the native stickmorph module cannot be loaded"), text[-3000:]
    for fragment in ("built for Python 3.9 (cpython-39)", f"this Blender has Python {python}",
                     f"python3 build_addon.py --blender {bpy.app.binary_path}"):
        assert fragment in error, (fragment, error)
    assert "Traceback" not in text


def test_an_extension_whose_wheel_does_not_load(addon):
    if not blender_sandbox.uses_extensions():
        return  # a legacy add-on has no wheel; its module is tested above
    python = f"{sys.version_info[0]}.{sys.version_info[1]}"
    with tempfile.TemporaryDirectory() as tmp:
        package = os.path.join(tmp, os.path.basename(addon_package()))
        repackage_with_a_module_that_does_not_load(addon_package(), package)
        found, text = run_enable(package, "broken-wheel")
    lines = found["STICKMORPH_LINES"]
    for fragment in ("Missing: the native stickmorph module", "Wheel: stickmorph-",
                     f"This Blender: Python {python}"):
        assert fragment in lines, (fragment, text[-3000:])
    error = found.get("STICKMORPH_BAKE_ERROR", "")
    assert error.startswith("Error: Stick Morph: the native stickmorph module cannot be loaded"), text[-3000:]
    for fragment in ("the add-on holds wheels/stickmorph-", f"-{this_tag()}-{this_tag()}-", "ImportError",
                     f"built for Python {python}",
                     f"The module is built for this Python {python} but does not load here"):
        assert fragment in error, (fragment, error)
    assert "Traceback" not in text


def test_enabling_without_numpy(addon):
    found, text = run_enable(addon_package(), "no-numpy")
    assert "Missing: numpy" in found["STICKMORPH_LINES"], text[-3000:]
    error = found.get("STICKMORPH_BAKE_ERROR", "")
    assert error.startswith("Error: Stick Morph: numpy"), error
    assert "install numpy" in error
    assert "Traceback" not in text
