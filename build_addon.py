#!/usr/bin/env python3
"""Builds the Stick Morph package for one Blender: a legacy add-on zip for
Blender before 4.2, an extension zip carrying the engine's wheel for 4.2 and
later.

    python3 build_addon.py [--blender PATH] [--python PATH] [--build-dir DIR]
                           [--dist DIR] [--jobs N] [--install] [--print-path]
    python3 build_addon.py --wheel WHEEL [--blender PATH] [--dist DIR]

The native module is an ordinary CPython extension, so it loads only in a
Blender whose embedded Python has the ABI it was compiled for (3.11, 3.13,
...), and only on a system with the C/C++ runtime it was linked against
(docs/BLENDER.md). So each package is built for one Python ABI and platform,
and its name says which:

    dist/stick_morph-<version>-blender<M.m>-cp<XY>-<platform>.zip   Blender < 4.2
    dist/stick_morph-<version>-cp<XY>-<platform>.zip                Blender >= 4.2

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
   in that Blender once as a smoke test. For an extension the module is built
   as the engine's wheel, dist/stickmorph-<version>-cp<XY>-cp<XY>-<platform>.whl,
   by the wheel backend (native/python/stickmorph_build_backend.py) run with
   that interpreter.
4. Writes the package, with build_info.json (Python, module or wheel,
   Blender, build system) next to the add-on's __init__.py:
   - Blender < 4.2: a zip holding one folder stick_morph/ with the module
     inside (Preferences > Add-ons > Install).
   - Blender >= 4.2: an extension zip, Blender's convention for native code:
     blender_manifest.toml at the archive root lists the wheel under
     ./wheels/ (`wheels = [...]`), which Blender installs into its own
     site-packages when the extension is enabled; platforms names the wheel's
     platform, and the Blender range is the add-on code's own
     (blender_version_min 4.2.0, the first Blender with extensions). Which
     Blenders can load it is said by the wheel's Python tag: Blender reads
     it and refuses a wheel of another Python. The package is then checked
     with `blender --command extension validate`.
   --wheel WHEEL packages an already built wheel (a release build on another
   platform, docs/RELEASE.md) without building or asking a Blender; with an
   explicit --blender of 4.2 or later it is validated by that Blender too.
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
BACKEND = ROOT / "native" / "python" / "stickmorph_build_backend.py"

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
    """The add-on's version: bl_info, the manifest template and the engine
    (CMakeLists.txt's project(), the wheel's version) must all say the same."""
    text = (PACKAGE / "__init__.py").read_text()
    match = re.search(r'"version":\s*\((\d+),\s*(\d+),\s*(\d+)\)', text)
    if not match:
        fail("no bl_info version in addon/stick_morph/__init__.py")
    version = ".".join(match.groups())
    manifest = (PACKAGE / MANIFEST).read_text()
    if not re.search(rf'^version = "{re.escape(version)}"$', manifest, re.MULTILINE):
        fail(f"{MANIFEST}'s version differs from bl_info's {version}")
    engine = re.search(r"project\(\s*stickmorph\s+VERSION\s+([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not engine or engine.group(1) != version:
        fail(f"CMakeLists.txt's project version ({engine.group(1) if engine else 'none'}) differs from "
             f"the add-on's {version}: the extension's wheel carries the engine's version")
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


# Wheels (PEP 427 names: name-version-python-abi-platform.whl).

WHEEL_NAME = re.compile(r"^stickmorph-(?P<version>[^-]+)-(?P<python>cp(?P<major>\d)(?P<minor>\d+))-"
                        r"(?P<abi>cp\d+[a-z]*)-(?P<platform>[A-Za-z0-9_]+)\.whl$")


def parse_wheel_name(path: Path) -> dict:
    match = WHEEL_NAME.match(path.name)
    if not match:
        fail(f"{path.name} is not a stickmorph wheel name (stickmorph-<version>-cp<XY>-cp<XY>-<platform>.whl)")
    return match.groupdict()


def blender_platform_of_wheel(platform_name: str) -> str:
    """Blender's platform name for a wheel platform tag, the way Blender maps
    them when it installs wheels: linux_x86_64 and manylinux_2_28_x86_64 ->
    linux-x64, win_amd64 -> windows-x64, macosx_11_0_arm64 -> macos-arm64."""
    system = ("linux" if "linux" in platform_name else "windows" if platform_name.startswith("win")
              else "macos" if platform_name.startswith("macosx") else None)
    machine = next((blender for wheel, blender in (("x86_64", "x64"), ("amd64", "x64"), ("aarch64", "arm64"),
                                                   ("arm64", "arm64")) if platform_name.endswith(wheel)), None)
    if system is None or machine is None:
        fail(f"no Blender platform for the wheel platform {platform_name} "
             "(known: linux/manylinux x86_64 and aarch64, win_amd64, win_arm64, macosx x86_64 and arm64)")
    return f"{system}-{machine}"


def _run_backend(python: str, arguments: list[str], pattern: str) -> Path:
    """Runs the wheel backend (native/python/stickmorph_build_backend.py, the
    one place the CMake build of the module is driven) with `python`, so that
    it builds for that interpreter; returns the path its last line names."""
    out = subprocess.run([python, str(BACKEND), *arguments], stdout=subprocess.PIPE, text=True)
    sys.stdout.write(out.stdout)
    match = re.search(pattern, out.stdout, re.MULTILINE)
    if out.returncode != 0 or not match:
        fail(f"building the module with {python} failed (exit {out.returncode})")
    return Path(match.group(1))


def build_module(python: str, build_dir: Path, jobs: int) -> Path:
    """The module alone (a legacy add-on bundles it loose). In a build folder
    of its own the tests are switched off; a shared one (scripts/test.sh
    passes build/) keeps the settings it has, so its Catch2 tests still
    build afterwards. The backend checks the module has this Python's suffix."""
    return _run_backend(python, ["--module-only", "--build-dir", str(build_dir), "--jobs", str(jobs)],
                        r"^built (.*)$")


def build_wheel(python: str, build_dir: Path, jobs: int, dist: Path) -> Path:
    """The engine's wheel for `python` (tagged with that Python's ABI)."""
    return _run_backend(python, ["--out", str(dist), "--build-dir", str(build_dir), "--jobs", str(jobs)],
                        r"^wrote (.*\.whl)$")


def module_of_wheel(wheel: Path, folder: Path) -> Path:
    """Unpacks the wheel's extension module into folder."""
    with zipfile.ZipFile(wheel) as archive:
        names = [n for n in archive.namelist() if "/" not in n and n.startswith("stickmorph.")
                 and n.endswith((".so", ".pyd"))]
        if len(names) != 1:
            fail(f"{wheel.name} holds {len(names)} stickmorph modules, expected one")
        archive.extract(names[0], folder)
    return folder / names[0]


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


def smoke_test(blender: str, module: Path | None = None, wheel: Path | None = None):
    """Imports the module (or the wheel's) in Blender once: a wrong ABI or a
    missing shared library shows here, at build time, not when a user
    enables the add-on."""
    with tempfile.TemporaryDirectory(prefix="stickmorph-smoke-") as tmp:
        if wheel is not None:
            module = module_of_wheel(wheel, Path(tmp))
        else:
            shutil.copy2(module, tmp)
        out = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1",
                              "--python-expr", SMOKE, "--", tmp], capture_output=True, text=True)
        if out.returncode != 0 or "STICKMORPH_SMOKE" not in out.stdout:
            fail(f"the built module does not import in {blender}:\n{out.stdout}\n{out.stderr}")
    print(f"{(wheel or module).name} imports in {blender}")


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


def build_info(python_version: tuple, platform_name: str, module: str, built_on: str,
               blender: str | None = None, wheel: str | None = None) -> dict:
    """What the add-on checks when it is enabled (the running Python must be
    this one) and what a bug report needs."""
    major, minor = python_version[:2]
    info = {
        "python": f"{major}.{minor}",
        "python_tag": f"cpython-{major}{minor}",
        "module": module,
        "platform": platform_name,
        "built_on": built_on,
    }
    if blender:
        info["blender"] = blender
    if wheel:
        info["wheel"] = wheel
    return info


# blender_version_min of the extension: the add-on's code runs in every
# Blender with the extension system (4.2 on). There is no maximum: which
# Blenders load the package is decided by its wheel's Python tag, which
# Blender reads (blender.org's 4.2-5.0 embed Python 3.11, 5.1 on 3.13;
# Debian's 4.3 and 5.2 the system's 3.13 and 3.14), not by a version range.
EXTENSION_BLENDER_MIN = "4.2.0"


def manifest_text(python_version: tuple, platform_name: str, wheel: Path, built_for: str) -> str:
    """The repository's manifest with this package's wheel and platform, and
    without the [build] table (it only steers `extension build`)."""
    template = re.split(r"^\[build\]\s*$", (PACKAGE / MANIFEST).read_text(), maxsplit=1, flags=re.MULTILINE)[0]
    # The template's comments are about the template; the package's manifest
    # says what it was written for instead.
    lines = [line for line in template.splitlines() if not line.startswith("#")]
    text = re.sub(r"\n{3,}", "\n\n", "\n".join(lines)).strip() + "\n"
    text = (f"# Written by build_addon.py for Python {python_version[0]}.{python_version[1]} on "
            f"{platform_name} ({built_for}):\n# the engine is the wheel below; Blender installs it only "
            f"when it embeds that Python (docs/BLENDER.md).\n" + text)
    text, count = re.subn(r'^blender_version_min = ".*"$', f'blender_version_min = "{EXTENSION_BLENDER_MIN}"',
                          text, flags=re.MULTILINE)
    if count != 1:
        fail(f"no blender_version_min line in {PACKAGE / MANIFEST}")
    text, count = re.subn(r"^platforms = \[.*\]$", f'platforms = ["{platform_name}"]\n'
                          f'wheels = ["./wheels/{wheel.name}"]', text, flags=re.MULTILINE)
    if count != 1:
        fail(f"no platforms line in {PACKAGE / MANIFEST}")
    import tomllib  # Python 3.11+, like every interpreter this script supports
    parsed = tomllib.loads(text)
    assert parsed["blender_version_min"] == EXTENSION_BLENDER_MIN and "blender_version_max" not in parsed
    assert parsed["wheels"] == [f"./wheels/{wheel.name}"] and parsed["platforms"] == [platform_name]
    return text


def package_files():
    for file in sorted(PACKAGE.rglob("*")):
        if file.is_dir() or "__pycache__" in file.parts or file.suffix in (".pyc", ".so", ".whl"):
            continue
        if file.name in (MANIFEST, BUILD_INFO):
            continue  # written per build
        yield file, file.relative_to(PACKAGE)


def legacy_package_path(blender: dict, version: str, dist: Path) -> Path:
    return dist / f"stick_morph-{version}-blender{series(blender)}-{python_tag(blender)}-{platform_tag(blender)}.zip"


def extension_package_path(python: str, platform_name: str, version: str, dist: Path) -> Path:
    """One extension per Python ABI and platform: cp311 serves every
    blender.org Blender 4.2-5.0 on that platform, cp313 5.1 on."""
    return dist / f"stick_morph-{version}-{python}-{platform_name}.zip"


def package_path(blender: dict, version: str, dist: Path) -> Path:
    if blender["version"] >= EXTENSIONS_SINCE:
        return extension_package_path(python_tag(blender), platform_tag(blender), version, dist)
    return legacy_package_path(blender, version, dist)


def _shown(path: Path):
    return path.relative_to(ROOT) if inside(str(path), str(ROOT)) else path


def _write_zip(path: Path, prefix: Path, extra: dict[str, bytes | Path]):
    tmp = path.with_name(path.name + ".tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as archive:
        for file, relative in package_files():
            archive.write(file, str(prefix / relative))
        for name, content in extra.items():
            if isinstance(content, Path):
                archive.write(content, name)
            else:
                archive.writestr(name, content)
    os.replace(tmp, path)


def write_legacy_package(blender: dict, module: Path, info: dict, version: str, dist: Path) -> Path:
    """A zip holding the folder stick_morph/ with the module inside."""
    dist.mkdir(parents=True, exist_ok=True)
    path = legacy_package_path(blender, version, dist)
    prefix = Path("stick_morph")
    _write_zip(path, prefix, {str(prefix / module.name): module,
                              str(prefix / BUILD_INFO): json.dumps(info, indent=2) + "\n"})
    print(f"wrote {_shown(path)} (legacy add-on for Blender {series(blender)}, Python {info['python']})")
    return path


def write_extension_package(wheel: Path, info: dict, version: str, dist: Path) -> Path:
    """An extension zip: the manifest at the archive root (as `blender
    --command extension build` writes it), the add-on beside it, the wheel
    under wheels/."""
    fields = parse_wheel_name(wheel)
    if fields["version"] != version:
        fail(f"{wheel.name} is version {fields['version']}, the add-on {version}")
    python_version = (int(fields["major"]), int(fields["minor"]))
    platform_name = blender_platform_of_wheel(fields["platform"])
    dist.mkdir(parents=True, exist_ok=True)
    path = extension_package_path(fields["python"], platform_name, version, dist)
    manifest = manifest_text(python_version, platform_name, wheel, info["built_on"])
    _write_zip(path, Path(), {f"wheels/{wheel.name}": wheel, BUILD_INFO: json.dumps(info, indent=2) + "\n",
                              MANIFEST: manifest})
    print(f"wrote {_shown(path)} (extension for Blender {EXTENSION_BLENDER_MIN[:3]}+ embedding Python "
          f"{info['python']}, {platform_name}, with {wheel.name})")
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
        # installs the wheel, enables the extension and saves the preferences.
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


def package_given_wheel(args, version: str) -> int:
    """--wheel: an extension around an already built wheel, no build."""
    wheel = Path(args.wheel).resolve()
    if not wheel.is_file():
        fail(f"no wheel at {args.wheel}")
    fields = parse_wheel_name(wheel)
    info = build_info((int(fields["major"]), int(fields["minor"])), blender_platform_of_wheel(fields["platform"]),
                      module=f"stickmorph ({fields['python']}, in {wheel.name})",
                      built_on=f"the wheel {wheel.name}", wheel=wheel.name)
    archive = write_extension_package(wheel, info, version, Path(args.dist).resolve())
    if args.blender_given:
        blender = blender_info(args.blender)
        if blender["version"] < EXTENSIONS_SINCE:
            fail(f"Blender {blender['version_string']} has no extensions; it cannot validate {archive.name}")
        validate_extension(args.blender, archive)
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blender", help="the Blender that will load the package (default: blender on PATH)")
    parser.add_argument("--python", help="build against this interpreter (default: found from Blender)")
    parser.add_argument("--wheel", help="package this already built engine wheel as an extension "
                                        "(nothing is built; --blender, if given, validates it)")
    parser.add_argument("--build-dir", help="CMake build directory for the module "
                                            "(default: build-addon/blender<M.m>-cp<XY>/)")
    parser.add_argument("--dist", default=str(ROOT / "dist"), help="where to write the package (default: dist/)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel build jobs (default 2)")
    parser.add_argument("--install", action="store_true",
                        help="install and enable the package in the user's Blender")
    parser.add_argument("--print-path", action="store_true",
                        help="only print the path of the package for this Blender (nothing is built)")
    args = parser.parse_args(argv)
    args.blender_given = args.blender is not None
    args.blender = args.blender or shutil.which("blender") or "blender"

    version = addon_version()
    if args.wheel:
        if args.install or args.print_path or args.python:
            fail("--wheel only packages (and validates) a wheel: no --install, --print-path or --python")
        return package_given_wheel(args, version)
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
    build_dir = build_dir.resolve()
    dist = Path(args.dist).resolve()
    blender_version = blender["version_string"].split()[0]
    if blender["version"] >= EXTENSIONS_SINCE:
        wheel = build_wheel(python, build_dir, args.jobs, dist)
        smoke_test(args.blender, wheel=wheel)
        info = build_info(blender["python"], platform_tag(blender), module=f"stickmorph{blender['ext_suffix']}",
                          built_on=f"{os_release()}, {compiler(build_dir)}, against {python}",
                          blender=blender_version, wheel=wheel.name)
        archive = write_extension_package(wheel, info, version, dist)
        validate_extension(args.blender, archive)
    else:
        module = build_module(python, build_dir, args.jobs)
        smoke_test(args.blender, module=module)
        info = build_info(blender["python"], platform_tag(blender), module=module.name,
                          built_on=f"{os_release()}, {compiler(build_dir)}, against {python}",
                          blender=blender_version)
        archive = write_legacy_package(blender, module, info, version, dist)
    if args.install:
        install(args.blender, blender, archive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
