#!/usr/bin/env python3
"""Builds the Blender add-on zip, dist/stick_morph-<version>.zip.

    python3 build_addon.py [--blender PATH] [--build-dir DIR] [--jobs N] [--install]

1. Asks the Blender that will load the add-on which Python it embeds
   (`blender -b --factory-startup --python-expr ...`).
2. Finds an interpreter of that version with development headers to build
   against (sys.executable reported by Blender if it matches, else
   /usr/bin/python3.X, else /usr/bin/python3): on Debian 12, Blender 3.4.1
   embeds the system Python 3.11, so this is /usr/bin/python3.
3. Builds the pybind11 module with CMake (target stickmorph_python) in
   --build-dir (default build-addon/, apart from the main build/).
4. Copies addon/stick_morph with the built stickmorph*.so into the zip; the zip
   holds one folder stick_morph/ (a classic add-on for Blender 3.4, and an
   extension with blender_manifest.toml for 4.2+).
5. --install: installs and enables the zip in the user's Blender
   (Preferences > Add-ons > Install, then saves the preferences).
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent
PACKAGE = ROOT / "addon" / "stick_morph"


def run(command, **kwargs):
    print("+", " ".join(str(c) for c in command), flush=True)
    return subprocess.run(command, check=True, **kwargs)


def blender_python(blender: str) -> tuple[tuple[int, int], str]:
    """(major, minor) and sys.executable of the Python inside Blender."""
    expr = "import sys; print('STICKMORPH_PY', sys.version_info[0], sys.version_info[1], sys.executable)"
    out = subprocess.run([blender, "-b", "--factory-startup", "--python-expr", expr],
                         check=True, capture_output=True, text=True).stdout
    match = re.search(r"^STICKMORPH_PY (\d+) (\d+) (.*)$", out, re.MULTILINE)
    if not match:
        sys.exit(f"build_addon.py: could not read the Python version of {blender}:\n{out}")
    return (int(match.group(1)), int(match.group(2))), match.group(3).strip()


def interpreter_version(path: str) -> tuple[int, int] | None:
    try:
        out = subprocess.run([path, "-c", "import sys; print(*sys.version_info[:2])"],
                             check=True, capture_output=True, text=True).stdout.split()
        return int(out[0]), int(out[1])
    except (OSError, subprocess.CalledProcessError, ValueError, IndexError):
        return None


def matching_interpreter(version: tuple[int, int], reported: str) -> str:
    """An interpreter of Blender's Python version to build against. Blender may
    report a sys.executable that is not the Python it embeds (a pyenv shim on
    PATH, or its own binary), so Debian's interpreters come first."""
    candidates = [f"/usr/bin/python{version[0]}.{version[1]}", "/usr/bin/python3", reported]
    for candidate in candidates:
        if candidate and Path(candidate).exists() and interpreter_version(candidate) == version:
            return candidate
    sys.exit(f"build_addon.py: no Python {version[0]}.{version[1]} interpreter found "
             f"(tried {', '.join(c for c in candidates if c)}); Blender embeds that version")


def addon_version() -> str:
    text = (PACKAGE / "__init__.py").read_text()
    match = re.search(r'"version":\s*\((\d+),\s*(\d+),\s*(\d+)\)', text)
    if not match:
        sys.exit("build_addon.py: no bl_info version in addon/stick_morph/__init__.py")
    version = ".".join(match.groups())
    manifest = (PACKAGE / "blender_manifest.toml").read_text()
    if f'version = "{version}"' not in manifest:
        sys.exit(f"build_addon.py: blender_manifest.toml's version differs from bl_info's {version}")
    return version


def build_module(python: str, build_dir: Path, jobs: int) -> Path:
    # Only the module is needed. In a build folder of its own the tests are
    # switched off; a shared one (scripts/test.sh passes build/) keeps the
    # settings it has, so its Catch2 tests still build afterwards.
    configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                 f"-DPython3_EXECUTABLE={python}"]
    if not (build_dir / "CMakeCache.txt").exists():
        configure.append("-DSTICKMORPH_BUILD_TESTS=OFF")
    run(configure)
    run(["cmake", "--build", str(build_dir), f"-j{jobs}", "--target", "stickmorph_python"])
    modules = sorted((build_dir / "python").glob("stickmorph*.so"))
    if len(modules) != 1:
        sys.exit(f"build_addon.py: expected one stickmorph*.so in {build_dir / 'python'}, found {modules}")
    return modules[0]


def write_zip(module: Path, version: str) -> Path:
    dist = ROOT / "dist"
    dist.mkdir(exist_ok=True)
    path = dist / f"stick_morph-{version}.zip"
    tmp = path.with_suffix(".zip.tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as archive:
        for file in sorted(PACKAGE.rglob("*")):
            if file.is_dir() or "__pycache__" in file.parts or file.suffix in (".pyc", ".so"):
                continue
            archive.write(file, Path("stick_morph") / file.relative_to(PACKAGE))
        archive.write(module, Path("stick_morph") / module.name)
    os.replace(tmp, path)
    print(f"wrote {path.relative_to(ROOT)}")
    return path


INSTALL_SCRIPT = """
import sys, bpy
path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.preferences.addon_install(filepath=path, overwrite=True)
bpy.ops.preferences.addon_enable(module="stick_morph")
import stick_morph.core as core
core.load_engine()
bpy.context.preferences.use_preferences_save = True
bpy.ops.wm.save_userpref()
print("STICKMORPH_INSTALLED", bpy.utils.user_resource("SCRIPTS", path="addons"))
"""


def install(blender: str, archive: Path):
    """Installs into the user's Blender: classic add-on install (3.x, and the
    legacy add-ons folder of 4.2+), enables it and saves the preferences."""
    print(f"+ {blender} -b --python-expr <install and enable> -- {archive}", flush=True)
    out = subprocess.run([blender, "-b", "--python-exit-code", "1", "--python-expr", INSTALL_SCRIPT, "--",
                          str(archive)], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if line.startswith("STICKMORPH_INSTALLED"):
            print(f"installed and enabled in {line.split(' ', 1)[1]}")
            return
    sys.exit(f"build_addon.py: installing failed:\n{out}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blender", default=shutil.which("blender") or "blender",
                        help="the Blender that will load the add-on (default: blender on PATH)")
    parser.add_argument("--build-dir", default=str(ROOT / "build-addon"),
                        help="CMake build directory for the module (default: build-addon/)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel build jobs (default 2)")
    parser.add_argument("--install", action="store_true",
                        help="install and enable the zip in the user's Blender")
    args = parser.parse_args(argv)

    version = addon_version()
    py_version, reported = blender_python(args.blender)
    python = matching_interpreter(py_version, reported)
    print(f"Blender embeds Python {py_version[0]}.{py_version[1]}; building against {python}")
    module = build_module(python, Path(args.build_dir).resolve(), args.jobs)
    archive = write_zip(module, version)
    if args.install:
        install(args.blender, archive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
