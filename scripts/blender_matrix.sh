#!/usr/bin/env bash
# The add-on's test matrix: the whole Blender suite in every tested Blender.
#
#   scripts/blender_matrix.sh [host] [trixie] [sid]     (default: all three)
#
#   host    Debian 12's Blender 3.4.1 (Python 3.11): the legacy add-on zip
#   trixie  Debian 13's Blender 4.3.2 (Python 3.13): the extension
#   sid     Debian sid's Blender 5.2.2 (Python 3.14): the extension
#
# For each: build_addon.py builds the module against that Blender's Python and
# writes its package (inside the chroot for trixie and sid, with that suite's
# compiler, pybind11, Eigen and CGAL); the headless suite installs it in a
# sandboxed user folder and runs every test (scripts/blender_tests.sh); then
# the GUI test drives Adjust Last Operation in a real window under Xvfb, and
# the demo's bake and render writes its PNG frames and MP4 (render_smoke.sh).
# The chroots are made by scripts/blender_chroot.sh when missing and cached
# outside the repository. Stops at the first failing Blender.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

suites=("$@")
[[ ${#suites[@]} -gt 0 ]] || suites=(host trixie sid)

section() { printf '\n==== %s ====\n' "$*"; }

# Inside a chroot the module is built in the chroot's own /var/tmp, so its
# objects (another compiler, another Python) never meet the host's build/.
CHROOT_BUILD_DIR=/var/tmp/stickmorph-build

gui_test() {
  # $1: the command prefix that runs a command in the right system ("" on the host).
  if [[ -x tests/blender/gui/run_gui_tests.sh || -f tests/blender/gui/run_gui_tests.sh ]]; then
    "$@" bash tests/blender/gui/run_gui_tests.sh
  else
    echo "blender_matrix.sh: tests/blender/gui/run_gui_tests.sh is missing" >&2
    return 1
  fi
}

for suite in "${suites[@]}"; do
  case "$suite" in
    host)
      section "Blender $(blender --version 2>/dev/null | head -n 1 | cut -d' ' -f2) on the host"
      STICKMORPH_BUILD_DIR="${STICKMORPH_BUILD_DIR:-$PWD/build}" bash scripts/blender_tests.sh
      section "GUI test on the host (Xvfb)"
      STICKMORPH_BUILD_DIR="${STICKMORPH_BUILD_DIR:-$PWD/build}" gui_test env
      section "Demo render on the host"
      STICKMORPH_BUILD_DIR="${STICKMORPH_BUILD_DIR:-$PWD/build}" bash scripts/render_smoke.sh
      ;;
    trixie|sid)
      section "Chroot $suite"
      bash scripts/blender_chroot.sh ensure "$suite"
      in_chroot=(bash scripts/blender_chroot.sh run "$suite" -- env STICKMORPH_BUILD_DIR="$CHROOT_BUILD_DIR")
      section "Blender $("${in_chroot[@]}" blender --version 2>/dev/null | head -n 1 | cut -d' ' -f2) in $suite"
      "${in_chroot[@]}" bash scripts/blender_tests.sh
      section "GUI test in $suite (Xvfb)"
      gui_test "${in_chroot[@]}"
      section "Demo render in $suite"
      "${in_chroot[@]}" bash scripts/render_smoke.sh
      ;;
    *)
      echo "blender_matrix.sh: unknown Blender '$suite' (host, trixie or sid)" >&2
      exit 2
      ;;
  esac
done
section "Blender matrix passed: ${suites[*]}"
