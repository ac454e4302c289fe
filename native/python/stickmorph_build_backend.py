"""The engine as a Python wheel: an in-tree PEP 517 build backend over the
CMake project.

    python3 -m build --wheel --no-isolation [-C build-dir=DIR] [-C jobs=N]
    pip wheel . --no-build-isolation --no-deps -w dist [--config-settings build-dir=DIR]
    python3 native/python/stickmorph_build_backend.py --out dist [--build-dir DIR] [--jobs N]

each write dist/stickmorph-<version>-cp<XY>-cp<XY>-<platform>.whl for the
interpreter that runs the backend (sys.executable).

Why a backend of our own: the module is built by CMake (pybind11, CGAL,
Eigen found by find_package), and Debian 12 packages no CMake-driven backend
(scikit-build-core is not in bookworm); setuptools would write its own
build/ folder over CMake's. So the backend is this file: nothing to download,
only CMake, the compiler and the Python that runs it.

What it does (build_wheel):
1. Configures the CMake project in the build folder (default
   build-wheel/cp<XY>-<platform>/; -C build-dir=DIR reuses another one, e.g.
   the test build, so that nothing is compiled twice; or
   $STICKMORPH_WHEEL_BUILD_DIR, and $STICKMORPH_WHEEL_JOBS for -C jobs) with
   -DPython3_EXECUTABLE=sys.executable, the tests off in a folder of its own,
   and any arguments in $CMAKE_ARGS (e.g. a vcpkg toolchain file), then builds
   the one target stickmorph_python.
2. Writes the wheel (PEP 427): the module stickmorph<EXT_SUFFIX> at the top
   level, as `import stickmorph` has always found it; the type stubs as the
   stub-only package stickmorph-stubs/__init__.pyi (PEP 561: a single-module
   distribution cannot carry py.typed, a -stubs package is what type checkers
   look for); and stickmorph-<version>.dist-info with METADATA (core metadata
   2.1: numpy as Requires-Dist, and every shared library the module needs
   from the system as Requires-External, read from the module itself),
   WHEEL (Root-Is-Purelib false, the cp<XY>-cp<XY>-<platform> tag) and RECORD
   (sha256 of every file).

The platform tag is the interpreter's own (sysconfig.get_platform(), e.g.
linux_x86_64): a wheel built on Debian links Debian's libgmp, libstdc++ and
glibc, so it is not manylinux and does not claim to be (docs/RELEASE.md).
"""

from __future__ import annotations

import argparse
import base64
import csv
import hashlib
import io
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NAME = "stickmorph"
STUB = Path(__file__).resolve().parent / "stickmorph.pyi"
SUMMARY = "Morphing planar stick figures without self-intersection (Surazhsky & Gotsman 2001)"
LICENSE = "GPL-3.0-or-later"
# The module converts its arguments with numpy (pybind11's numpy support);
# any numpy from 1.21 on works, 1.x and 2.x alike (tested: Debian's 1.24 and 2.x).
REQUIRES_DIST = ["numpy>=1.21"]


class BuildError(RuntimeError):
    """A build step failed; the message says which and why."""


def project_version() -> str:
    """The version in CMakeLists.txt's project() call: one source for the
    module's __version__, the wheel and the add-on (build_addon.py checks)."""
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*stickmorph\s+VERSION\s+([0-9][0-9.]*)", text)
    if not match:
        raise BuildError("no `project(stickmorph VERSION x.y.z ...)` in CMakeLists.txt")
    return match.group(1)


def abi_tag() -> str:
    """cp<XY> for this CPython (cp<XY>t free-threaded, cp<XY>d debug): the
    module is an ordinary extension module, so it loads in this ABI only."""
    if sys.implementation.name != "cpython":
        raise BuildError(f"the module is a CPython extension; {sys.implementation.name} cannot build it")
    tag = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    if sysconfig.get_config_var("Py_GIL_DISABLED"):
        tag += "t"
    if sysconfig.get_config_var("Py_DEBUG"):
        tag += "d"
    return tag


def python_tag() -> str:
    return f"cp{sys.version_info[0]}{sys.version_info[1]}"


def platform_tag() -> str:
    """The wheel platform tag of this interpreter: linux_x86_64, win_amd64,
    macosx_11_0_arm64 (PEP 425: '-' and '.' become '_')."""
    return re.sub(r"[-.]", "_", sysconfig.get_platform())


def wheel_name(version: str | None = None) -> str:
    return f"{NAME}-{version or project_version()}-{python_tag()}-{abi_tag()}-{platform_tag()}.whl"


def default_build_dir() -> Path:
    return ROOT / "build-wheel" / f"{abi_tag()}-{platform_tag()}"


def _run(command: list[str], verbose: bool):
    if verbose:
        print("+", " ".join(str(part) for part in command), flush=True)
    try:
        subprocess.run(command, check=True, stdout=None if verbose else subprocess.DEVNULL)
    except FileNotFoundError as error:
        raise BuildError(f"{command[0]} is not installed ({error}); the wheel is built with CMake") from None
    except subprocess.CalledProcessError as error:
        raise BuildError(f"`{' '.join(map(str, command))}` failed with exit code {error.returncode}") from None


def build_module(build_dir: Path, jobs: int, verbose: bool = True) -> Path:
    """Configures and builds the stickmorph_python target for this
    interpreter; returns the module file."""
    configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                 f"-DPython3_EXECUTABLE={sys.executable}"]
    # A folder of its own builds only what the wheel needs; a shared one (the
    # test build) keeps its settings, so its tests still build afterwards.
    if not (build_dir / "CMakeCache.txt").exists():
        configure.append("-DSTICKMORPH_BUILD_TESTS=OFF")
    configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
    _run(configure, verbose)
    _run(["cmake", "--build", str(build_dir), "--config", "Release", f"-j{jobs}",
          "--target", "stickmorph_python"], verbose)
    # A shared folder may hold modules of several Pythons; a multi-config
    # generator (Visual Studio, Xcode) adds a Release/ folder.
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    found = sorted((build_dir / "python").rglob(f"{NAME}{suffix}"))
    if not found:
        present = sorted(p.name for p in (build_dir / "python").rglob(f"{NAME}*"))
        raise BuildError(f"the build wrote no {NAME}{suffix} under {build_dir / 'python'} (found {present}); "
                         f"did CMake pick another Python than {sys.executable}?")
    return found[0]


def _tool_output(command: list[str]) -> str | None:
    try:
        return subprocess.run(command, check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None


def runtime_libraries(module: Path) -> list[str]:
    """The shared libraries the module needs from the system, as
    Requires-External entries: on Linux the DT_NEEDED entries (readelf -d)
    with the newest glibc and libstdc++ symbol versions used (readelf -V),
    on macOS otool -L. Empty on Windows, where the release workflow links
    GMP statically (vcpkg's x64-windows-static-md triplet, docs/RELEASE.md)."""
    if sys.platform.startswith("linux"):
        dynamic = _tool_output(["readelf", "-d", "-W", str(module)])
        if dynamic is None:
            raise BuildError("readelf (binutils) is needed to list the module's runtime libraries")
        needed = re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", dynamic)
        versions = _tool_output(["readelf", "-V", "-W", str(module)]) or ""
        newest: dict[str, tuple[int, ...]] = {}
        for family, number in re.findall(r"Name: (GLIBC|GLIBCXX|CXXABI)_([0-9.]+)", versions):
            key = tuple(int(part) for part in number.split("."))
            newest[family] = max(newest.get(family, key), key)
        owner = {"libc.so.6": "GLIBC", "libstdc++.so.6": "GLIBCXX"}
        entries = []
        for library in needed:
            family = owner.get(library)
            if family in newest:
                entries.append(f"{library} (>={'.'.join(map(str, newest[family]))})")
            else:
                entries.append(library)
        return entries
    if sys.platform == "darwin":
        listing = _tool_output(["otool", "-L", str(module)]) or ""
        return [line.split()[0] for line in listing.splitlines()[1:]
                if line.strip() and not line.strip().startswith("/usr/lib/") and not line.strip().startswith("/System/")]
    return []


def metadata_text(version: str, libraries: list[str]) -> str:
    major, minor = sys.version_info[:2]
    lines = [
        "Metadata-Version: 2.1",
        f"Name: {NAME}",
        f"Version: {version}",
        f"Summary: {SUMMARY}",
        f"License: {LICENSE}",
        # The module is compiled for this Python's ABI; the tag says so to
        # pip, this says so to a human reading the metadata.
        f"Requires-Python: =={major}.{minor}.*",
        *(f"Requires-Dist: {requirement}" for requirement in REQUIRES_DIST),
        *(f"Requires-External: {library}" for library in libraries),
        "Classifier: Programming Language :: C++",
        f"Classifier: Programming Language :: Python :: {major}.{minor}",
        "Classifier: Topic :: Multimedia :: Graphics :: 3D Modeling",
        "Description-Content-Type: text/markdown",
        "",
        f"# {NAME} {version}",
        "",
        "Morphs one planar stick figure (polylines, polygons, skeletons, triangulations)",
        "into a compatible one so that no frame self-intersects, checked in exact",
        "arithmetic; after Surazhsky & Gotsman, \"Morphing Stick Figures Using Optimized",
        "Compatible Triangulations\" (2001). `import stickmorph`; `help(stickmorph)`.",
        "",
        f"Built for CPython {major}.{minor} ({abi_tag()}) on {platform_tag()}. Type stubs:",
        "the stickmorph-stubs package in this wheel.",
        "",
        "Shared libraries it needs from the system (Requires-External; symbol versions in",
        "parentheses): " + (", ".join(libraries) if libraries else "none recorded") + ".",
        "",
    ]
    return "\n".join(lines)


def wheel_text() -> str:
    return "\n".join([
        "Wheel-Version: 1.0",
        "Generator: stickmorph_build_backend",
        "Root-Is-Purelib: false",
        f"Tag: {python_tag()}-{abi_tag()}-{platform_tag()}",
        "",
    ])


def _record_hash(data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode("ascii")
    return f"sha256={digest}"


def write_wheel(module: Path, out_dir: Path, version: str | None = None) -> Path:
    """Writes the wheel of an already built module into out_dir."""
    version = version or project_version()
    if not STUB.is_file():
        raise BuildError(f"the type stubs {STUB} are missing")
    info = f"{NAME}-{version}.dist-info"
    files: list[tuple[str, bytes]] = [
        (module.name, module.read_bytes()),
        (f"{NAME}-stubs/__init__.pyi", STUB.read_bytes()),
        (f"{info}/METADATA", metadata_text(version, runtime_libraries(module)).encode("utf-8")),
        (f"{info}/WHEEL", wheel_text().encode("utf-8")),
        (f"{info}/top_level.txt", f"{NAME}\n".encode("utf-8")),
    ]
    record = io.StringIO()
    writer = csv.writer(record, lineterminator="\n")
    for name, data in files:
        writer.writerow([name, _record_hash(data), len(data)])
    writer.writerow([f"{info}/RECORD", "", ""])
    files.append((f"{info}/RECORD", record.getvalue().encode("utf-8")))

    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / wheel_name(version)
    tmp = path.with_name(path.name + ".tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in files:
            entry = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            # The module must stay executable once unpacked; the rest is data.
            mode = 0o755 if name == module.name else 0o644
            entry.external_attr = (0o100000 | mode) << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(entry, data)
    os.replace(tmp, path)
    return path


def _settings(config_settings: dict | None) -> tuple[Path, int]:
    settings = config_settings or {}
    build_dir = settings.get("build-dir") or os.environ.get("STICKMORPH_WHEEL_BUILD_DIR")
    jobs = settings.get("jobs") or os.environ.get("STICKMORPH_WHEEL_JOBS") or 2
    try:
        jobs = int(jobs)
    except ValueError:
        raise BuildError(f"jobs must be a whole number, not {jobs!r}") from None
    path = Path(build_dir).resolve() if build_dir else default_build_dir()
    return path, jobs


def build(out_dir: Path, build_dir: Path, jobs: int, verbose: bool = True) -> Path:
    module = build_module(build_dir, jobs, verbose)
    return write_wheel(module, out_dir)


# PEP 517 hooks.

def get_requires_for_build_wheel(config_settings=None):
    return []  # CMake and the compiler are system tools, not Python packages


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build_dir, jobs = _settings(config_settings)
    # The frontend captures stdout; CMake's progress goes to stderr's reader too.
    return build(Path(wheel_directory), build_dir, jobs).name


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Build the stickmorph wheel for this Python.")
    parser.add_argument("--out", default=str(ROOT / "dist"), help="where to write the wheel (default dist/)")
    parser.add_argument("--build-dir", help="CMake build folder (default build-wheel/<abi>-<platform>/)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel build jobs (default 2)")
    parser.add_argument("--print-name", action="store_true", help="only print the wheel's file name")
    parser.add_argument("--module-only", action="store_true",
                        help="only build the module and print its path (build_addon.py's legacy add-on zip)")
    args = parser.parse_args(argv)
    try:
        if args.print_name:
            print(wheel_name())
            return 0
        build_dir = Path(args.build_dir).resolve() if args.build_dir else default_build_dir()
        if args.module_only:
            print(f"built {build_module(build_dir, args.jobs)}")
            return 0
        path = build(Path(args.out).resolve(), build_dir, args.jobs)
    except BuildError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
