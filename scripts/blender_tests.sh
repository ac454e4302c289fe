#!/usr/bin/env bash
# Builds the Blender add-on package and runs its tests inside headless Blender
# (the Blender on PATH: the host's, or a chroot's under scripts/blender_chroot.sh).
#
#   scripts/blender_tests.sh [pytest args]
#
# 1. /usr/bin/python3 build_addon.py: builds the native module for Blender's
#    Python (in $STICKMORPH_BUILD_DIR, default build-addon/) and writes
#    its package (docs/BLENDER.md): dist/stick_morph-<version>-blender<M.m>-
#    cp<XY>-linux-x64.zip (a legacy add-on) before Blender 4.2; from 4.2 the
#    engine's wheel and dist/stick_morph-<version>-cp<XY>-linux-x64.zip, an
#    extension carrying it.
# 2. tests/blender/run_pytest.py in `blender -b --factory-startup`: installs
#    and enables that package in a temporary user config, bakes, checks, renders.
# Exits non-zero if the build or any test fails; pytest prints its summary line.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BLENDER="${BLENDER:-blender}"
PYTHON=/usr/bin/python3
# scripts/test.sh passes its own build directory so the engine is built once.
BUILD_DIR="${STICKMORPH_BUILD_DIR:-build-addon}"

printf '\n==== %s ====\n' "Blender add-on: build"
"$PYTHON" build_addon.py --blender "$BLENDER" --build-dir "$BUILD_DIR"

printf '\n==== %s ====\n' "Blender add-on: tests (pytest in headless Blender)"
"$BLENDER" -b --factory-startup --python-exit-code 1 --python tests/blender/run_pytest.py -- -q -ra "$@"
