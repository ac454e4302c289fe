#!/usr/bin/env bash
# Installs the Debian packages that building, testing and the demo need:
# Debian 12 (the tested host, Blender 3.4.1), and Debian 13 or later, whose
# packages differ in two places: no clang-14 (their default clang instead)
# and Catch2 v3 instead of v2 (tests/cpp/catch.h serves both).
#
# Quiet and quick when everything is present, so every other script can call
# it first. As root it installs what is missing; otherwise it prints the
# command to run and fails, rather than prompting for a password.
set -euo pipefail

packages=(
  blender         # the add-on and, later, the demo's bake and render
  cmake
  make            # cmake's default generator; a minimal system has none
  g++
  pybind11-dev
  libeigen3-dev
  libcgal-dev
  libcli11-dev        # command-line parsing of the CLI, the benchmarks and the random-pair harness
  nlohmann-json3-dev  # the JSON reader of the figure and result files (native/io)
  catch2
  python3-dev
  python3-numpy
  python3-pytest
  python3-matplotlib  # the plots of BENCHMARKS.md (bench/make_benchmarks.py)
  python3-build python3-venv  # the engine's wheel (pyproject.toml) and its offline pip install test
  python3-yaml        # tests/python/test_release_workflow.py reads .github/workflows/release.yml
  python3-mypy        # tests/python/test_stubs.py and test_wheel.py type-check against the stubs
  libegl1 libegl-mesa0  # headless Workbench/EEVEE render through surfaceless EGL
  xvfb xauth          # the GUI test of Adjust Last Operation (xvfb-run)
  debootstrap         # scripts/blender_chroot.sh: Debian 13 and sid for Blender 4.3 and 5.2
)
# scripts/sanitize.sh: clang with ASan, UBSan and libFuzzer, and their
# runtimes. Debian 12's default clang is 14, packaged under its version.
codename=$(. /etc/os-release 2>/dev/null && echo "${VERSION_CODENAME:-}")
if [[ "$codename" == bookworm ]]; then
  packages+=(clang-14 libclang-rt-14-dev)
else
  packages+=(clang libclang-rt-dev)
fi

missing=()
for package in "${packages[@]}"; do
  # dpkg-query also knows packages that were removed but not purged; only
  # "install ok installed" counts.
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$package")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "install_deps: missing Debian packages: ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "install_deps: not root; install them with:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi

apt-get update
DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}" </dev/null
echo "install_deps: installed ${missing[*]}"
