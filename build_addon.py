#!/usr/bin/env python3
"""Builds the Stick Morph package for one Blender: a legacy add-on zip for
Blender before 4.2, an extension zip for 4.2 and later.

    python3 build_addon.py [--blender PATH] [--python PATH] [--build-dir DIR]
                           [--dist DIR] [--jobs N] [--install] [--print-path]

The native module is an ordinary CPython extension, so it loads only in a
Blender whose embedded Python has the ABI it was compiled for (3.11, 3.13,
...), and only on a system with the C/C++ runtime it was linked against
(docs/BLENDER.md). So each package is built for one Blender, and its name
says for which:

    dist/stick_morph-<version>-blender<M.m>-cp<XY>-<platform>.zip

Steps:
1. Asks the Blender that will load the package for its version and the
   Python it embeds (`blender -b --factory-startup --python-expr ...`):
   version, sys.executable, the include folder, the extension suffix.
2. Picks an interpreter of exactly that Python to build against: --python if
   given; else, for a Blender that bundles its own Python with headers (an
   official blender.org build), that bundled interpreter; else Debian's
   /usr/bin/python3.X or /usr/bin/python3 (a distro Blender embeds the system
   Python). Its extension suffix must equal Blender's.
3. Builds the pybind11 module with CMake (target stickmorph_python) in
   --build-dir (default build-addon/<blender>-<cpXY>/, one folder per ABI so
   that builds for several Blenders never share a CMake cache), and imports it
   in that Blender once as a smoke test.
4. Writes the package, with build_info.json (Python, module, Blender, build
   system) next to the add-on's __init__.py:
   - Blender < 4.2: a zip holding one folder stick_morph/ (Preferences >
     Add-ons > Install).
   - Blender >= 4.2: an extension zip, blender_manifest.toml at the archive
     root, with blender_version_min/max set to the Blender series built for
     (see extension_version_range), then checked with
     `blender --command extension validate`.
5. --install: installs and enables the package in the user's own Blender:
   legacy add-ons with Preferences > Add-ons > Install (and the preferences
   saved), extensions with `blender --command extension install-file
   -r user_default --enable`.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent
PACKAGE = ROOT / "addon" / "stick_morph"
MANIFEST = "blender_manifest.toml"
BUILD_INFO = "build_info.json"

# The first Blender with the extension system (blender_manifest.toml,
# `blender --command extension ...`). Earlier Blenders install legacy add-ons.
EXTENSIONS_SINCE = (4, 2, 0)

# Printed by the query below, read back by blender_info().
QUERY = r"""
import json, os, platform, sys, sysconfig
import bpy
try:
    import numpy
    numpy_version = numpy.__version__
except ImportError:
    numpy_version = None
include = sysconfig.get_paths().get("include") or ""
print("STICKMORPH_BLENDER " + json.dumps({
    "version": list(bpy.app.version),
    "version_string": bpy.app.version_string,
    "binary_path": bpy.app.binary_path,
    "python": list(sys.version_info[:3]),
    "executable": sys.executable,
    "prefix": sys.prefix,
    "include": include,
    "has_headers": os.path.isfile(os.path.join(include, "Python.h")),
    "ext_suffix": sysconfig.get_config_var("EXT_SUFFIX"),
    "machine": platform.machine(),
    "system": platform.system(),
    "numpy": numpy_version,
}), flush=True)
"""


def run(command, **kwargs):
    print("+", " ".join(str(c) for c in command), flush=True)
    return subprocess.run(command, check=True, **kwargs)


def fail(message: str):
    sys.exit(f"build_addon.py: {message}")


def blender_info(blender: str) -> dict:
    """What the given Blender says about itself and its Python."""
    try:
        out = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1",
                              "--python-expr", QUERY], check=True, capture_output=True, text=True)
    except (OSError, subprocess.CalledProcessError) as error:
        detail = getattr(error, "stdout", "") or ""
        fail(f"could not run {blender} to ask for its Python ({error})\n{detail}")
    match = re.search(r"^STICKMORPH_BLENDER (\{.*\})$", out.stdout, re.MULTILINE)
    if not match:
        fail(f"could not read the Python version of {blender}:\n{out.stdout}\n{out.stderr}")
    info = json.loads(match.group(1))
    info["version"] = tuple(info["version"])
    info["python"] = tuple(info["python"])
    return info


def interpreter_info(path: str) -> dict | None:
    """Version and extension suffix of an interpreter, or None if it does not run."""
    code = ("import json, sys, sysconfig; print(json.dumps({'python': list(sys.version_info[:3]), "
            "'ext_suffix': sysconfig.get_config_var('EXT_SUFFIX'), "
            "'include': sysconfig.get_paths().get('include') or ''}))")
    try:
        out = subprocess.run([path, "-c", code], check=True, capture_output=True, text=True).stdout
        info = json.loads(out.strip().splitlines()[-1])
    except (OSError, subprocess.CalledProcessError, ValueError, IndexError):
        return None
    info["python"] = tuple(info["python"])
    return info


def inside(path: str, folder: str) -> bool:
    """Whether path lies in folder, as written or with symbolic links resolved
    (a bundle may be reached through a link, or link its interpreter)."""
    for resolve in (os.path.abspath, os.path.realpath):
        try:
            if os.path.commonpath([resolve(path), resolve(folder)]) == resolve(folder):
                return True
        except ValueError:
            pass
    return False


def bundled_python(blender: dict) -> str | None:
    """The interpreter an official blender.org build ships
    (<blender folder>/<M.m>/python/bin/python3.X), when Blender reports it as
    its sys.executable and its headers are there. A distro Blender reports
    /usr/bin/python3.X (or its own binary), outside its folder."""
    executable, folder = blender["executable"], os.path.dirname(os.path.abspath(blender["binary_path"]))
    if not executable or not os.path.isfile(executable) or not inside(executable, folder):
        return None
    if os.path.realpath(executable) == os.path.realpath(blender["binary_path"]):
        return None  # Blender itself, not an interpreter
    return executable if blender["has_headers"] else None


def choose_interpreter(blender: dict, override: str | None) -> str:
    """An interpreter of exactly Blender's Python (same major.minor and
    extension suffix, which also encodes debug and free-threaded builds)."""
    major, minor = blender["python"][:2]
    if override:
        candidates = [override]
    else:
        bundled = bundled_python(blender)
        # Debian's interpreters before the one Blender reports when it is not
        # a bundle: a distro Blender's sys.executable may be a pyenv shim on
        # PATH or Blender's own binary.
        candidates = ([bundled] if bundled else []) + [f"/usr/bin/python{major}.{minor}", "/usr/bin/python3"]
        if not bundled and blender["executable"]:
            candidates.append(blender["executable"])
    tried = []
    for candidate in candidates:
        if not candidate or not Path(candidate).exists():
            continue
        info = interpreter_info(candidate)
        tried.append(f"{candidate} ({'not runnable' if info is None else '.'.join(map(str, info['python']))})")
        if info is None or info["python"][:2] != (major, minor):
            continue
        if info["ext_suffix"] != blender["ext_suffix"]:
            tried[-1] += f" suffix {info['ext_suffix']} != Blender's {blender['ext_suffix']}"
            continue
        if not os.path.isfile(os.path.join(info["include"], "Python.h")):
            tried[-1] += f" without headers in {info['include']} (install python{major}.{minor}-dev)"
            continue
        return candidate
    fail(f"no Python {major}.{minor} interpreter with headers and extension suffix "
         f"{blender['ext_suffix']} found (tried: {', '.join(tried) or 'nothing'}); Blender "
         f"{blender['version_string']} embeds that Python. Pass --python PATH.")


def addon_version() -> str:
    text = (PACKAGE / "__init__.py").read_text()
    match = re.search(r'"version":\s*\((\d+),\s*(\d+),\s*(\d+)\)', text)
    if not match:
        fail("no bl_info version in addon/stick_morph/__init__.py")
    version = ".".join(match.groups())
    manifest = (PACKAGE / MANIFEST).read_text()
    if not re.search(rf'^version = "{re.escape(version)}"$', manifest, re.MULTILINE):
        fail(f"{MANIFEST}'s version differs from bl_info's {version}")
    return version


def python_tag(blender: dict) -> str:
    major, minor = blender["python"][:2]
    return f"cp{major}{minor}"


def platform_tag(blender: dict) -> str:
    """The extension platform name (linux-x64, linux-arm64, ...)."""
    machine = {"x86_64": "x64", "amd64": "x64", "aarch64": "arm64", "arm64": "arm64"}.get(
        blender["machine"].lower(), blender["machine"].lower())
    system = {"Linux": "linux", "Darwin": "macos", "Windows": "windows"}.get(blender["system"],
                                                                           blender["system"].lower())
    return f"{system}-{machine}"


def series(blender: dict) -> str:
    return "{}.{}".format(*blender["version"][:2])


def build_module(python: str, build_dir: Path, jobs: int, ext_suffix: str) -> Path:
    # Only the module is needed. In a build folder of its own the tests are
    # switched off; a shared one (scripts/test.sh passes build/) keeps the
    # settings it has, so its Catch2 tests still build afterwards.
    configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                 f"-DPython3_EXECUTABLE={python}"]
    if not (build_dir / "CMakeCache.txt").exists():
        configure.append("-DSTICKMORPH_BUILD_TESTS=OFF")
    run(configure)
    run(["cmake", "--build", str(build_dir), f"-j{jobs}", "--target", "stickmorph_python"])
    # A shared build folder may still hold a module of another Python: take
    # the one with this Python's suffix, and make sure it was just built.
    module = build_dir / "python" / f"stickmorph{ext_suffix}"
    if not module.is_file():
        found = sorted(p.name for p in (build_dir / "python").glob("stickmorph*"))
        fail(f"the build wrote no {module.name} to {module.parent} (found {found}); "
             f"did CMake pick another Python than {python}?")
    return module


SMOKE = r"""
import sys
sys.path.insert(0, sys.argv[sys.argv.index("--") + 1])
import stickmorph
try:
    import numpy  # the engine converts its arguments with numpy
except ImportError:
    pass
else:
    stickmorph.validate([[0.0, 0.0], [1.0, 0.0]], [[0, 1]])
print("STICKMORPH_SMOKE", stickmorph.__file__, flush=True)
"""


def smoke_test(blender: str, module: Path):
    """Imports the module in Blender once: a wrong ABI or a missing shared
    library shows here, at build time, not when a user enables the add-on."""
    with tempfile.TemporaryDirectory(prefix="stickmorph-smoke-") as tmp:
        shutil.copy2(module, tmp)
        out = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1",
                              "--python-expr", SMOKE, "--", tmp], capture_output=True, text=True)
        if out.returncode != 0 or "STICKMORPH_SMOKE" not in out.stdout:
            fail(f"the built module does not import in {blender}:\n{out.stdout}\n{out.stderr}")
    print(f"{module.name} imports in {blender}")


def os_release() -> str:
    try:
        for line in Path("/etc/os-release").read_text().splitlines():
            if line.startswith("PRETTY_NAME="):
                return line.split("=", 1)[1].strip().strip('"')
    except OSError:
        pass
    return f"{platform.system()} {platform.release()}"


def compiler(build_dir: Path) -> str:
    """The C++ compiler CMake used, from the build folder's cache."""
    try:
        cache = (build_dir / "CMakeCache.txt").read_text()
    except OSError:
        return "unknown compiler"
    match = re.search(r"^CMAKE_CXX_COMPILER:\w+=(.*)$", cache, re.MULTILINE)
    if not match:
        return "unknown compiler"
    try:
        first = subprocess.run([match.group(1), "--version"], capture_output=True, text=True,
                               check=True).stdout.splitlines()[0]
        return first.strip()
    except (OSError, subprocess.CalledProcessError, IndexError):
        return match.group(1)


def build_info(blender: dict, module: Path, python: str, build_dir: Path) -> dict:
    """What the add-on checks when it is enabled (the running Python must be
    this one) and what a bug report needs."""
    major, minor = blender["python"][:2]
    return {
        "python": f"{major}.{minor}",
        "python_tag": f"cpython-{major}{minor}",
        "module": module.name,
        "blender": blender["version_string"].split()[0],
        "platform": platform_tag(blender),
        "built_on": f"{os_release()}, {compiler(build_dir)}, against {python}",
    }


def extension_version_range(blender: dict) -> tuple[str, str]:
    """blender_version_min and blender_version_max (exclusive) of the extension.

    The module only imports in a Blender embedding the Python it was built
    for. Blender keeps one Python through a minor series (x.y.*), and a
    distro may embed any Python it likes, so without knowing better the
    package claims exactly the series it was built for: x.y.0 up to, but
    excluding, x.(y+1).0. A Debian rebuild of the same Blender against a newer
    Python is caught at enable time by the add-on's build_info.json check."""
    major, minor = blender["version"][:2]
    return f"{major}.{minor}.0", f"{major}.{minor + 1}.0"


def manifest_text(blender: dict) -> str:
    """The repository's manifest with this build's version range and platform,
    and without the [build] table (it only steers `extension build`)."""
    template = re.split(r"^\[build\]\s*$", (PACKAGE / MANIFEST).read_text(), maxsplit=1, flags=re.MULTILINE)[0]
    # The template's comments are about the template; the package's manifest
    # says what it was written for instead.
    lines = [line for line in template.splitlines() if not line.startswith("#")]
    text = re.sub(r"\n{3,}", "\n\n", "\n".join(lines)).strip() + "\n"
    text = (f"# Written by build_addon.py for Blender {blender['version_string'].split()[0]} "
            f"(Python {blender['python'][0]}.{blender['python'][1]}); the bundled module\n"
            f"# imports only in a Blender embedding that Python (docs/BLENDER.md).\n" + text)
    low, high = extension_version_range(blender)
    text, count = re.subn(r'^blender_version_min = ".*"$',
                          f'blender_version_min = "{low}"\nblender_version_max = "{high}"', text,
                          flags=re.MULTILINE)
    if count != 1:
        fail(f"no blender_version_min line in {PACKAGE / MANIFEST}")
    text, count = re.subn(r"^platforms = \[.*\]$", f'platforms = ["{platform_tag(blender)}"]', text,
                          flags=re.MULTILINE)
    if count != 1:
        fail(f"no platforms line in {PACKAGE / MANIFEST}")
    try:
        import tomllib  # Python 3.11+
        parsed = tomllib.loads(text)
        assert parsed["blender_version_min"] == low and parsed["blender_version_max"] == high
    except ImportError:
        pass
    return text


def package_files():
    for file in sorted(PACKAGE.rglob("*")):
        if file.is_dir() or "__pycache__" in file.parts or file.suffix in (".pyc", ".so"):
            continue
        if file.name in (MANIFEST, BUILD_INFO):
            continue  # written per build
        yield file, file.relative_to(PACKAGE)


def package_path(blender: dict, version: str, dist: Path) -> Path:
    return dist / f"stick_morph-{version}-blender{series(blender)}-{python_tag(blender)}-{platform_tag(blender)}.zip"


def write_package(blender: dict, module: Path, info: dict, version: str, dist: Path) -> Path:
    extension = blender["version"] >= EXTENSIONS_SINCE
    dist.mkdir(parents=True, exist_ok=True)
    path = package_path(blender, version, dist)
    # Blender's extension format wants the manifest at the archive root (as
    # `blender --command extension build` writes it); a legacy add-on zip
    # holds the package folder.
    prefix = Path() if extension else Path("stick_morph")
    tmp = path.with_name(path.name + ".tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as archive:
        for file, relative in package_files():
            archive.write(file, str(prefix / relative))
        archive.write(module, str(prefix / module.name))
        archive.writestr(str(prefix / BUILD_INFO), json.dumps(info, indent=2) + "\n")
        if extension:
            archive.writestr(MANIFEST, manifest_text(blender))
    os.replace(tmp, path)
    kind = "extension" if extension else "legacy add-on"
    shown = path.relative_to(ROOT) if inside(str(path), str(ROOT)) else path
    print(f"wrote {shown} ({kind} for Blender {series(blender)}, Python {info['python']})")
    return path


def validate_extension(blender_path: str, archive: Path):
    out = subprocess.run([blender_path, "--command", "extension", "validate", str(archive)],
                         capture_output=True, text=True)
    text = (out.stdout + out.stderr).strip()
    if out.returncode != 0:
        fail(f"`blender --command extension validate` refused {archive}:\n{text}")
    print(f"`blender --command extension validate` accepts {archive.name}: {text}")


LEGACY_INSTALL = """
import sys, bpy
path = sys.argv[sys.argv.index("--") + 1]
assert bpy.ops.preferences.addon_install(filepath=path, overwrite=True) == {"FINISHED"}
assert bpy.ops.preferences.addon_enable(module="stick_morph") == {"FINISHED"}
import stick_morph.core as core
core.load_engine()
bpy.context.preferences.use_preferences_save = True
bpy.ops.wm.save_userpref()
print("STICKMORPH_INSTALLED", bpy.utils.user_resource("SCRIPTS", path="addons"))
"""


def install(blender_path: str, blender: dict, archive: Path):
    """Installs and enables the package in the user's own Blender."""
    if blender["version"] >= EXTENSIONS_SINCE:
        # Blender's own installer: unpacks into the user_default repository,
        # enables the extension and saves the preferences.
        run([blender_path, "--command", "extension", "install-file", "-r", "user_default", "--enable",
             str(archive)])
        print("installed and enabled as the extension bl_ext.user_default.stick_morph")
        return
    print(f"+ {blender_path} -b --python-expr <install and enable> -- {archive}", flush=True)
    out = subprocess.run([blender_path, "-b", "--python-exit-code", "1", "--python-expr", LEGACY_INSTALL,
                          "--", str(archive)], capture_output=True, text=True)
    for line in out.stdout.splitlines():
        if out.returncode == 0 and line.startswith("STICKMORPH_INSTALLED"):
            print(f"installed and enabled in {line.split(' ', 1)[1]}")
            return
    fail(f"installing failed:\n{out.stdout}\n{out.stderr}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blender", default=shutil.which("blender") or "blender",
                        help="the Blender that will load the package (default: blender on PATH)")
    parser.add_argument("--python", help="build against this interpreter (default: found from Blender)")
    parser.add_argument("--build-dir", help="CMake build directory for the module "
                                            "(default: build-addon/blender<M.m>-cp<XY>/)")
    parser.add_argument("--dist", default=str(ROOT / "dist"), help="where to write the package (default: dist/)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel build jobs (default 2)")
    parser.add_argument("--install", action="store_true",
                        help="install and enable the package in the user's Blender")
    parser.add_argument("--print-path", action="store_true",
                        help="only print the path of the package for this Blender (nothing is built)")
    args = parser.parse_args(argv)

    version = addon_version()
    blender = blender_info(args.blender)
    if args.print_path:
        print(package_path(blender, version, Path(args.dist).resolve()))
        return 0
    python = choose_interpreter(blender, args.python)
    print(f"Blender {blender['version_string']} embeds Python {'.'.join(map(str, blender['python']))} "
          f"({blender['executable']}); building against {python}"
          , flush=True)
    if not blender["numpy"]:
        # The add-on needs numpy at run time. A distro Blender finds the
        # system's (python3-numpy) unless its embedded Python picked another
        # prefix, e.g. a pyenv interpreter first on PATH.
        print(f"WARNING: numpy does not import in this Blender (its Python's sys.prefix is "
              f"{blender['prefix']}); the add-on needs it: install python3-numpy, or run Blender "
              f"without another Python first on PATH", flush=True)
    build_dir = Path(args.build_dir or ROOT / "build-addon" / f"blender{series(blender)}-{python_tag(blender)}")
    module = build_module(python, build_dir.resolve(), args.jobs, blender["ext_suffix"])
    smoke_test(args.blender, module)
    info = build_info(blender, module, python, build_dir.resolve())
    archive = write_package(blender, module, info, version, Path(args.dist).resolve())
    if blender["version"] >= EXTENSIONS_SINCE:
        validate_extension(args.blender, archive)
    if args.install:
        install(args.blender, blender, archive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
