"""Shared fixtures: where the built CLI, the built module and the test data are.

The build directory comes from STICKMORPH_BUILD_DIR (default: <repo>/build),
the layout that `cmake -S . -B build` produces (../shared/FORMAT.md).
"""
import importlib.util
import os
import pathlib
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("STICKMORPH_BUILD_DIR", REPO / "build")).resolve()
DATA = REPO / "tests" / "data"
BENCH = REPO / "bench"  # the benchmark and corpus tooling (bench/README.md)

# The extension module is built into <build>/python (native/CMakeLists.txt).
sys.path.insert(0, str(BUILD / "python"))


@pytest.fixture(scope="session")
def cli():
    """Path of the built `stickmorph` executable."""
    path = BUILD / "stickmorph"
    if not path.exists():
        pytest.fail(f"{path} is missing: build the project first (scripts/test.sh does)")
    return path


@pytest.fixture(scope="session")
def data_dir():
    """tests/data: golden figures and malformed inputs."""
    return DATA


def load_script(name):
    """bench/NAME.py imported as a module, for the tests of the benchmark scripts."""
    spec = importlib.util.spec_from_file_location(name, BENCH / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
