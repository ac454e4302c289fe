"""build_addon.py --wheel (issue 33): an extension around an already built
engine wheel, as the release workflow makes one per Python ABI and platform.
No Blender is asked; the archive is checked here as Blender reads it (the
manifest at the root, the wheel under ./wheels/). The Blender suite installs
the packages build_addon.py builds in 4.3 and 5.2.
"""
import importlib.util
import json
import shutil
import subprocess
import sys
import tomllib
import zipfile

import pytest

from conftest import BUILD, REPO

SCRIPT = REPO / "build_addon.py"
BACKEND = REPO / "native" / "python" / "stickmorph_build_backend.py"


def load_build_addon():
    spec = importlib.util.spec_from_file_location("build_addon", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def run(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    """This Python's wheel, packed by the backend from the test build."""
    out = tmp_path_factory.mktemp("wheel")
    result = subprocess.run([sys.executable, str(BACKEND), "--out", str(out), "--build-dir", str(BUILD)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    return next(out.glob("*.whl"))


def version():
    return load_build_addon().addon_version()


def test_the_extension_lists_the_wheel_in_its_manifest(wheel, tmp_path):
    result = run("--wheel", wheel, "--dist", tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    tag = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    path = tmp_path / f"stick_morph-{version()}-{tag}-linux-x64.zip"
    assert f"wrote {path}" in result.stdout
    with zipfile.ZipFile(path) as archive:
        names = set(archive.namelist())
        manifest = tomllib.loads(archive.read("blender_manifest.toml").decode())
        info = json.loads(archive.read("build_info.json"))
        assert archive.read(f"wheels/{wheel.name}") == wheel.read_bytes()
    assert manifest["wheels"] == [f"./wheels/{wheel.name}"]
    assert manifest["platforms"] == ["linux-x64"]
    assert manifest["blender_version_min"] == "4.2.0" and "blender_version_max" not in manifest
    assert manifest["id"] == "stick_morph" and manifest["version"] == version()
    assert "build" not in manifest  # the [build] table only steers `extension build`
    # The add-on at the root, no loose module, no legacy folder.
    assert {"__init__.py", "operators.py", "dependencies.py", "native.py"} <= names
    assert not [n for n in names if n.endswith((".so", ".pyd")) or n.startswith("stick_morph/")]
    assert info["wheel"] == wheel.name and info["python"] == f"{sys.version_info[0]}.{sys.version_info[1]}"
    assert info["platform"] == "linux-x64"


def test_a_file_that_is_not_a_stickmorph_wheel_is_refused(wheel, tmp_path):
    other = tmp_path / "numpy-2.0.0-cp311-cp311-linux_x86_64.whl"
    shutil.copy(wheel, other)
    result = run("--wheel", other, "--dist", tmp_path / "dist")
    assert result.returncode != 0
    assert "is not a stickmorph wheel name" in result.stderr
    assert not (tmp_path / "dist").exists()
    missing = run("--wheel", tmp_path / "nothing.whl", "--dist", tmp_path / "dist")
    assert missing.returncode != 0 and "no wheel at" in missing.stderr


def test_a_wheel_of_another_version_is_refused(wheel, tmp_path):
    other = tmp_path / wheel.name.replace(f"-{version()}-", "-9.9.9-")
    shutil.copy(wheel, other)
    result = run("--wheel", other, "--dist", tmp_path / "dist")
    assert result.returncode != 0
    assert f"is version 9.9.9, the add-on {version()}" in result.stderr


@pytest.mark.parametrize("wheel_platform, blender_platform", [
    ("linux_x86_64", "linux-x64"),
    ("manylinux_2_35_x86_64", "linux-x64"),
    ("manylinux2014_aarch64", "linux-arm64"),
    ("win_amd64", "windows-x64"),
    ("win_arm64", "windows-arm64"),
    ("macosx_14_0_arm64", "macos-arm64"),
    ("macosx_15_0_x86_64", "macos-x64"),
])
def test_wheel_platforms_map_to_blender_platforms(wheel_platform, blender_platform):
    """The names Blender itself gives those wheel platforms (its
    blender_platforms_from_wheel_platform)."""
    assert load_build_addon().blender_platform_of_wheel(wheel_platform) == blender_platform


def test_an_unknown_wheel_platform_is_refused(tmp_path):
    build_addon = load_build_addon()
    with pytest.raises(SystemExit, match="no Blender platform for the wheel platform macosx_11_0_universal2"):
        build_addon.blender_platform_of_wheel("macosx_11_0_universal2")
