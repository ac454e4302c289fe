"""Can this Blender run the add-on? numpy and the native module, checked once
at enable time.

A package built for one Blender's Python enables without complaint in
another (the extension system only looks at the .py files) and used to fail
only at bake time; without numpy, enabling failed with a raw ImportError.
check() tries both imports, catching ImportError and OSError (a module built
against another libstdc++ or CGAL fails to load with OSError), and says what
is missing, which Python the module was built for (build_info.json, written
into the package by build_addon.py), which Python this Blender has, and how
to rebuild. The panel shows it and the bake operator reports it as an ERROR.

Free of bpy and numpy, so that it imports in any Python and is unit-tested
outside Blender (tests/python/test_addon_dependencies.py).
"""

from __future__ import annotations

import importlib
import json
import os
import sys
from dataclasses import dataclass, field

BUILD_INFO = "build_info.json"
BUILD_INFO_KEYS = ("python", "python_tag", "module", "built_on", "wheel", "platform")
UNKNOWN = "unknown"
BUILD_COMMAND = "python3 build_addon.py --blender {blender}"


def this_python() -> tuple[str, str]:
    """("3.11", "cpython-311") of the running interpreter (Blender's own)."""
    version = f"{sys.version_info[0]}.{sys.version_info[1]}"
    tag = getattr(sys.implementation, "cache_tag", None) or UNKNOWN
    return version, tag


def read_build_info(package_dir: str) -> dict:
    """build_info.json of the package; every key is "unknown" when the file is
    missing or unreadable, or the key is absent (an older or hand-made build)."""
    info = {key: UNKNOWN for key in BUILD_INFO_KEYS}
    try:
        with open(os.path.join(package_dir, BUILD_INFO), encoding="utf-8") as file:
            data = json.load(file)
    except (OSError, ValueError):
        return info
    if isinstance(data, dict):
        for key in BUILD_INFO_KEYS:
            value = data.get(key)
            if isinstance(value, (str, int, float)) and str(value).strip():
                info[key] = str(value).strip()
    return info


def module_files(package_dir: str) -> list[str]:
    """The native module files in the package (whatever Python they are for):
    a loose module in a legacy add-on, wheels/stickmorph-*.whl in an
    extension (Blender installs the wheel into its own site-packages)."""
    try:
        names = os.listdir(package_dir)
    except OSError:
        return []
    found = sorted(n for n in names if n.startswith("stickmorph") and n.endswith((".so", ".pyd")))
    try:
        wheels = os.listdir(os.path.join(package_dir, "wheels"))
    except OSError:
        wheels = []
    found += sorted(f"wheels/{n}" for n in wheels if n.startswith("stickmorph-") and n.endswith(".whl"))
    return found


def _error_text(error: BaseException) -> str:
    return f"{type(error).__name__}: {error}"


def import_engine(package: str | None):
    """The native module: the copy inside the package, else a `stickmorph` on
    sys.path (a development build). Raises ImportError or OSError, with the
    package copy's error when neither loads."""
    if package:
        try:
            return importlib.import_module(".stickmorph", package)
        except (ImportError, OSError) as inside:
            try:
                return importlib.import_module("stickmorph")
            except (ImportError, OSError) as outside:
                # An extension holds no module of its own (its wheel installs
                # a top-level one): then the top-level error is the one to show.
                absent = isinstance(inside, ModuleNotFoundError) and inside.name == f"{package}.stickmorph"
                raise (outside if absent else inside) from None
    return importlib.import_module("stickmorph")


@dataclass
class Dependencies:
    """The outcome of check(): None errors mean the import worked."""

    numpy_error: str | None
    engine_error: str | None
    build_info: dict = field(default_factory=lambda: {key: UNKNOWN for key in BUILD_INFO_KEYS})
    module_files: list = field(default_factory=list)
    python: str = UNKNOWN
    python_tag: str = UNKNOWN
    blender: str = "/path/to/blender"

    @property
    def ok(self) -> bool:
        return self.numpy_error is None and self.engine_error is None

    @property
    def missing(self) -> list[str]:
        names = []
        if self.numpy_error is not None:
            names.append("numpy")
        if self.engine_error is not None:
            names.append("the native stickmorph module")
        return names

    def built_for(self) -> str:
        info = self.build_info
        text = f"Python {info['python']}"
        if info["python_tag"] != UNKNOWN:
            text += f" ({info['python_tag']})"
        if info["built_on"] != UNKNOWN:
            text += f", on {info['built_on']}"
        return text

    @property
    def wheel(self) -> str:
        """The wheel an extension carries (build_info.json), or "unknown"."""
        return self.build_info.get("wheel", UNKNOWN)

    def extension_for_this_python(self) -> str:
        """The extension file name for the running Python (docs/BLENDER.md:
        one extension per Python ABI and platform)."""
        tag = "cp" + self.python.replace(".", "")
        wheel = self.wheel
        version = wheel.split("-")[1] if wheel.count("-") >= 4 else "<version>"
        platform = self.build_info.get("platform", UNKNOWN)
        platform = platform if platform != UNKNOWN else "<platform>"
        return f"stick_morph-{version}-{tag}-{platform}.zip"

    def advice(self) -> str:
        """What to do about a module that does not load. A wheel for another
        Python: the extension for this one. A module for this very Python
        that still fails: a system library it needs is missing (libgmp.so.10,
        a newer libstdc++ or glibc; docs/BLENDER.md) or the file is damaged,
        so installing "the extension for this Python" again would not help."""
        if self.build_info["python"] == self.python:
            return (f"The module is built for this Python {self.python} but does not load here: a system "
                    "library it needs is missing or too old (libgmp.so.10, the build system's libstdc++ and "
                    "glibc), or the file is damaged. Install what the error names, or rebuild")
        if self.wheel != UNKNOWN:
            return f"Install the extension for Python {self.python} ({self.extension_for_this_python()}), or rebuild"
        return "Rebuild"

    def rebuild_command(self) -> str:
        return BUILD_COMMAND.format(blender=self.blender or "/path/to/blender")

    def lines(self) -> list[str]:
        """Short lines for the sidebar panel (empty when everything loads)."""
        if self.ok:
            return []
        lines = [f"Missing: {' and '.join(self.missing)}"]
        if self.numpy_error is not None:
            lines.append(f"numpy does not import in this Blender's Python {self.python}")
            lines.append("Install numpy for it (Debian: apt-get install python3-numpy)")
        if self.engine_error is not None:
            module = self.build_info["module"]
            if module == UNKNOWN and self.module_files:
                module = ", ".join(self.module_files)
            lines.append(f"Module: {module if module != UNKNOWN else 'none found in the add-on'}")
            if self.wheel != UNKNOWN:
                lines.append(f"Wheel: {self.wheel}")
            lines.append(f"Built for: {self.built_for()}")
            lines.append(f"This Blender: Python {self.python} ({self.python_tag})")
            if self.build_info["python"] == self.python:
                lines.append(f"Built for this Python, but it does not load: {self.engine_error}")
                lines.append("Install the system library it names (libgmp10, a newer libstdc++), or")
            elif self.wheel != UNKNOWN:
                lines.append(f"Install the extension for Python {self.python}: {self.extension_for_this_python()}")
            lines.append("Rebuild the add-on for this Blender:")
            lines.append(self.rebuild_command())
        return lines

    def message(self) -> str:
        """One paragraph for an ERROR report."""
        if self.ok:
            return ""
        parts = [f"{' and '.join(self.missing)} cannot be loaded"]
        if self.numpy_error is not None:
            parts.append(f"numpy does not import in this Blender's Python {self.python} "
                         f"({self.numpy_error}); install numpy for it (Debian: apt-get install "
                         "python3-numpy)")
        if self.engine_error is not None:
            module = self.build_info["module"]
            found = ", ".join(self.module_files) if self.module_files else "no stickmorph module"
            parts.append(f"the add-on holds {found}"
                         + (f" (build_info.json: {module})" if module != UNKNOWN and module not in found else "")
                         + f", built for {self.built_for()}; this Blender has Python {self.python} "
                         f"({self.python_tag}) ({self.engine_error}). {self.advice()}"
                         f" the add-on for this Blender: {self.rebuild_command()}")
        return "; ".join(parts)


def check(package_dir: str, package: str | None, blender: str | None = None) -> Dependencies:
    """Tries to import numpy and the native module; never raises ImportError
    or OSError. package_dir is the add-on's folder (for build_info.json and
    the module file names), package its import name (None: only sys.path)."""
    python, tag = this_python()
    numpy_error = None
    try:
        import numpy  # noqa: F401
    except (ImportError, OSError) as error:
        numpy_error = _error_text(error)
    engine_error = None
    try:
        import_engine(package)
    except (ImportError, OSError) as error:
        engine_error = _error_text(error)
    return Dependencies(numpy_error=numpy_error, engine_error=engine_error,
                        build_info=read_build_info(package_dir), module_files=module_files(package_dir),
                        python=python, python_tag=tag, blender=blender or "/path/to/blender")
