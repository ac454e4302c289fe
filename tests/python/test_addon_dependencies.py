"""The add-on's enable-time check of numpy and the native module
(addon/stick_morph/dependencies.py) outside Blender, in /usr/bin/python3.

Each check runs in a child Python with only the repository's add-on folder on
sys.path, on a package made up here: this process has the built module on
sys.path (conftest.py), where check() would find it as the fallback of a
package that has none. That Blender enables a broken package, says what is
missing and refuses the bake is tested in tests/blender/test_dependencies.py.
"""
import importlib.machinery
import json
import pathlib
import subprocess
import sys
import textwrap

import pytest

ADDON_DIR = pathlib.Path(__file__).resolve().parents[2] / "addon"

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

OTHER_PYTHON = {"python": "3.9", "python_tag": "cpython-39",
                "module": "stickmorph.cpython-39-x86_64-linux-gnu.so", "built_on": "Debian 11, GCC 10"}


def run_check(package_dir, case="plain"):
    # The package is imported as pkg_under_test from its parent folder.
    code = f"import sys; sys.path.insert(0, {str(package_dir.parent)!r});" + CHECK
    out = subprocess.run([sys.executable, "-c", code, str(ADDON_DIR), str(package_dir), case],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def make_package(folder, module_name=None, module_bytes=b"", build_info=None):
    package = folder / "pkg_under_test"
    package.mkdir()
    (package / "__init__.py").write_text("")
    if module_name:
        (package / module_name).write_bytes(module_bytes)
    if build_info is not None:
        (package / "build_info.json").write_text(build_info if isinstance(build_info, str)
                                                 else json.dumps(build_info))
    return package


def test_module_for_another_python_is_reported_with_both_pythons(tmp_path):
    status = run_check(make_package(tmp_path, OTHER_PYTHON["module"], b"\x7fELF", OTHER_PYTHON))
    assert not status["ok"] and status["missing"] == ["the native stickmorph module"]
    assert status["numpy_error"] is None
    text = "\n".join(status["lines"])
    for fragment in ("Missing: the native stickmorph module", "stickmorph.cpython-39-x86_64-linux-gnu.so",
                     "Built for: Python 3.9 (cpython-39), on Debian 11, GCC 10",
                     f"This Blender: Python {status['python']} ({status['tag']})",
                     "python3 build_addon.py --blender /opt/blender-x/blender"):
        assert fragment in text, (fragment, text)
    assert status["python"] == f"{sys.version_info[0]}.{sys.version_info[1]}"  # the Python that checked
    message = status["message"]
    assert "built for Python 3.9 (cpython-39)" in message and f"this Blender has Python {status['python']}" in message
    assert "build_addon.py --blender /opt/blender-x/blender" in message


@pytest.mark.parametrize("build_info", [None, "{not json", json.dumps(["a list"]), json.dumps({"python": ""})])
def test_missing_or_broken_build_info_says_unknown(tmp_path, build_info):
    status = run_check(make_package(tmp_path, build_info=build_info))
    assert not status["ok"]
    text = "\n".join(status["lines"])
    assert "Built for: Python unknown" in text and "Module: none found in the add-on" in text, text
    assert "no stickmorph module" in status["message"]


def test_a_module_that_does_not_load_is_caught(tmp_path):
    # The right file name for this Python, but not a shared object: the
    # import fails inside the loader (ImportError), not at the name lookup.
    suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
    status = run_check(make_package(tmp_path, "stickmorph" + suffix, b"not an ELF file"))
    assert not status["ok"] and status["engine_error"].startswith("ImportError")


def test_numpy_missing_is_reported(tmp_path):
    # The module built for this Python (the one conftest.py put on sys.path)
    # inside the package, so that only numpy is missing from its point of
    # view (the module itself may need numpy to load).
    import stickmorph
    built = pathlib.Path(stickmorph.__file__)
    package = make_package(tmp_path)
    (package / built.name).write_bytes(built.read_bytes())
    good = run_check(package)
    without = run_check(package, "no-numpy")
    assert good["ok"] and good["lines"] == [] and good["message"] == "", good
    assert not without["ok"] and "numpy" in without["missing"]
    assert without["numpy_error"].startswith(("ImportError", "ModuleNotFoundError"))
    assert "numpy does not import" in without["message"] and "python3-numpy" in without["message"]


def test_an_extension_names_its_wheel_and_the_extension_for_this_python(tmp_path):
    """An extension carries the engine as wheels/stickmorph-*.whl (issue 33):
    when it does not load, the message names the wheel, the Python it is for
    and the extension file for the running Python."""
    info = {"python": "3.9", "python_tag": "cpython-39", "module": "stickmorph.cpython-39-x86_64-linux-gnu.so",
            "built_on": "Debian 11, GCC 10", "wheel": "stickmorph-0.1.0-cp39-cp39-linux_x86_64.whl",
            "platform": "linux-x64"}
    package = make_package(tmp_path, build_info=info)
    (package / "wheels").mkdir()
    (package / "wheels" / info["wheel"]).write_bytes(b"")
    status = run_check(package)
    this = f"{sys.version_info[0]}.{sys.version_info[1]}"
    tag = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    assert not status["ok"]
    lines = status["lines"]
    assert f"Module: {info['module']}" in lines and f"Wheel: {info['wheel']}" in lines
    assert f"Install the extension for Python {this}: stick_morph-0.1.0-{tag}-linux-x64.zip" in lines
    message = status["message"]
    for fragment in (f"the add-on holds wheels/{info['wheel']}", "built for Python 3.9 (cpython-39)",
                     f"Install the extension for Python {this} (stick_morph-0.1.0-{tag}-linux-x64.zip)"):
        assert fragment in message, (fragment, message)


def test_a_wheel_for_this_python_that_does_not_load_points_at_the_system(tmp_path):
    """A wheel of the running Python whose module fails (no libgmp, an older
    glibc, a damaged file): getting "the extension for this Python" again
    would not help, so the message says what would."""
    this = f"{sys.version_info[0]}.{sys.version_info[1]}"
    tag = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    info = {"python": this, "python_tag": f"cpython-{tag[2:]}", "module": f"stickmorph.cpython-{tag[2:]}-x.so",
            "built_on": "Debian 13, GCC 14", "wheel": f"stickmorph-0.1.0-{tag}-{tag}-linux_x86_64.whl",
            "platform": "linux-x64"}
    package = make_package(tmp_path, build_info=info)
    (package / "wheels").mkdir()
    (package / "wheels" / info["wheel"]).write_bytes(b"")
    status = run_check(package)
    assert not status["ok"]
    assert not any(line.startswith("Install the extension") for line in status["lines"]), status["lines"]
    assert any(line.startswith("Built for this Python, but it does not load: ") for line in status["lines"])
    message = status["message"]
    assert f"The module is built for this Python {this} but does not load here" in message, message
    assert "libgmp.so.10" in message and "Install the extension" not in message, message
