"""The enable-time check of numpy and the native module (dependencies.py).

dependencies.py imports neither bpy nor numpy, so its logic is tested in
Debian's /usr/bin/python3 on made-up packages; then a child Blender enables
a package whose module was built for another Python, and one without numpy,
and must register, say what is missing and refuse the bake with an ERROR.
"""

import json
import os
import subprocess
import sys
import tempfile
import textwrap
import zipfile

import bpy
import pytest

from conftest import ROOT, addon_package

ADDON_DIR = os.path.join(ROOT, "addon")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import blender_sandbox  # noqa: E402

# Runs in /usr/bin/python3 with the repository's add-on folder on sys.path;
# argv: addon dir, package dir to check, case.
CHECK = textwrap.dedent('''
    import json, sys
    sys.path.insert(0, sys.argv[1])
    case = sys.argv[3]
    if case == "no-numpy":
        sys.modules["numpy"] = None  # import numpy raises ImportError
    from stick_morph import dependencies
    status = dependencies.check(sys.argv[2], "pkg_under_test", "/opt/blender-x/blender")
    assert "bpy" not in sys.modules
    print(json.dumps({"ok": status.ok, "missing": status.missing, "lines": status.lines(),
                      "message": status.message(), "python": status.python,
                      "tag": status.python_tag, "numpy_error": status.numpy_error,
                      "engine_error": status.engine_error}))
''')


def run_check(package_dir, case="plain"):
    # The package is imported as pkg_under_test from its parent folder.
    parent = os.path.dirname(package_dir)
    code = f"import sys; sys.path.insert(0, {parent!r});" + CHECK
    out = subprocess.run(["/usr/bin/python3", "-c", code, ADDON_DIR, package_dir, case],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def make_package(folder, module_name=None, module_bytes=b"", build_info=None):
    package = os.path.join(folder, "pkg_under_test")
    os.makedirs(package)
    open(os.path.join(package, "__init__.py"), "w").close()
    if module_name:
        with open(os.path.join(package, module_name), "wb") as file:
            file.write(module_bytes)
    if build_info is not None:
        with open(os.path.join(package, "build_info.json"), "w") as file:
            file.write(build_info if isinstance(build_info, str) else json.dumps(build_info))
    return package


OTHER_PYTHON = {"python": "3.9", "python_tag": "cpython-39",
                "module": "stickmorph.cpython-39-x86_64-linux-gnu.so", "built_on": "Debian 11, GCC 10"}


def test_module_for_another_python_is_reported_with_both_pythons(addon):
    with tempfile.TemporaryDirectory() as tmp:
        package = make_package(tmp, OTHER_PYTHON["module"], b"\x7fELF", OTHER_PYTHON)
        status = run_check(package)
    assert not status["ok"] and status["missing"] == ["the native stickmorph module"]
    assert status["numpy_error"] is None
    text = "\n".join(status["lines"])
    for fragment in ("Missing: the native stickmorph module", "stickmorph.cpython-39-x86_64-linux-gnu.so",
                     "Built for: Python 3.9 (cpython-39), on Debian 11, GCC 10",
                     f"This Blender: Python {status['python']} ({status['tag']})",
                     "python3 build_addon.py --blender /opt/blender-x/blender"):
        assert fragment in text, (fragment, text)
    assert status["python"] == f"{sys.version_info[0]}.{sys.version_info[1]}"  # Debian's Python is Blender's
    message = status["message"]
    assert "built for Python 3.9 (cpython-39)" in message and f"this Blender has Python {status['python']}" in message
    assert "build_addon.py --blender /opt/blender-x/blender" in message


@pytest.mark.parametrize("build_info", [None, "{not json", json.dumps(["a list"]), json.dumps({"python": ""})])
def test_missing_or_broken_build_info_says_unknown(addon, build_info):
    with tempfile.TemporaryDirectory() as tmp:
        package = make_package(tmp, build_info=build_info)
        status = run_check(package)
    assert not status["ok"]
    text = "\n".join(status["lines"])
    assert "Built for: Python unknown" in text and "Module: none found in the add-on" in text, text
    assert "no stickmorph module" in status["message"]


def test_a_module_that_does_not_load_is_caught(addon):
    # The right file name for this Python, but not a shared object: the
    # import fails inside the loader (ImportError), not at the name lookup.
    import importlib.machinery
    suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
    with tempfile.TemporaryDirectory() as tmp:
        package = make_package(tmp, "stickmorph" + suffix, b"not an ELF file")
        status = run_check(package)
    assert not status["ok"] and status["engine_error"].startswith("ImportError")


def test_numpy_missing_is_reported(addon):
    installed = os.path.dirname(addon.__file__)
    with tempfile.TemporaryDirectory() as tmp:
        package = make_package(tmp)
        # The real module of this Blender, so that only numpy is missing from
        # its point of view (the module itself may need numpy to load).
        for name in os.listdir(installed):
            if name.startswith("stickmorph") and name.endswith(".so"):
                with open(os.path.join(installed, name), "rb") as src, \
                        open(os.path.join(package, name), "wb") as dst:
                    dst.write(src.read())
        good = run_check(package)
        without = run_check(package, "no-numpy")
    assert good["ok"] and good["lines"] == [] and good["message"] == "", good
    assert not without["ok"] and "numpy" in without["missing"]
    assert without["numpy_error"].startswith(("ImportError", "ModuleNotFoundError"))
    assert "numpy does not import" in without["message"] and "python3-numpy" in without["message"]


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


def repackage_for_other_python(source_zip, target_zip):
    """The package under test with its module renamed as if built for Python
    3.9, and a build_info.json that says so."""
    with zipfile.ZipFile(source_zip) as src, zipfile.ZipFile(target_zip, "w") as dst:
        for item in src.infolist():
            folder, name = os.path.split(item.filename)
            if name.startswith("stickmorph") and name.endswith(".so"):
                dst.writestr(os.path.join(folder, OTHER_PYTHON["module"]), src.read(item))
            elif name == "build_info.json":
                dst.writestr(item, json.dumps(OTHER_PYTHON))
            else:
                dst.writestr(item, src.read(item))


def run_enable(package, case):
    script = ENABLE.replace("{scripts!r}", repr(os.path.join(ROOT, "scripts")))
    with tempfile.TemporaryDirectory(prefix="stickmorph-deps-") as tmp:
        env = blender_sandbox.sandbox_env(os.path.join(tmp, "sandbox"))
        out = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1",
                              "--python-expr", script, "--", package, case],
                             env=env, capture_output=True, text=True, timeout=300)
    text = out.stdout + out.stderr
    assert out.returncode == 0 and "STICKMORPH_ENABLE_OK" in out.stdout, text[-4000:]
    lines = [l for l in out.stdout.splitlines() if l.startswith("STICKMORPH_")]
    return {l.split(" ", 1)[0]: (l.split(" ", 1) + [""])[1] for l in lines}, text


def test_enabling_a_package_for_another_python(addon):
    python = f"{sys.version_info[0]}.{sys.version_info[1]}"
    with tempfile.TemporaryDirectory() as tmp:
        package = os.path.join(tmp, os.path.basename(addon_package()))
        repackage_for_other_python(addon_package(), package)
        found, text = run_enable(package, "other-python")
    assert "Built for: Python 3.9 (cpython-39), on Debian 11, GCC 10" in found["STICKMORPH_LINES"], text[-3000:]
    error = found.get("STICKMORPH_BAKE_ERROR", "")
    assert error.startswith("Error: Stick Morph: the native stickmorph module cannot be loaded"), text[-3000:]
    for fragment in ("built for Python 3.9 (cpython-39)", f"this Blender has Python {python}",
                     f"python3 build_addon.py --blender {bpy.app.binary_path}"):
        assert fragment in error, (fragment, error)
    assert "Traceback" not in text


def test_enabling_without_numpy(addon):
    found, text = run_enable(addon_package(), "no-numpy")
    assert "Missing: numpy" in found["STICKMORPH_LINES"], text[-3000:]
    error = found.get("STICKMORPH_BAKE_ERROR", "")
    assert error.startswith("Error: Stick Morph: numpy"), error
    assert "install numpy" in error
    assert "Traceback" not in text
