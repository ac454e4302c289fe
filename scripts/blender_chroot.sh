#!/usr/bin/env bash
# Debian chroots with newer Blenders, for the add-on's test matrix (docs/BLENDER.md).
#
#   scripts/blender_chroot.sh ensure SUITE         create or complete the chroot
#   scripts/blender_chroot.sh run SUITE -- CMD...  run CMD inside it, repo at /stickmorph
#   scripts/blender_chroot.sh path SUITE           print the chroot's folder
#
# SUITE is trixie (Debian 13: Blender 4.3.2, Python 3.13) or sid (Blender 5.2.2,
# Python 3.14). The host is never upgraded: each Blender lives in its own
# `debootstrap --variant=minbase` tree under $STICKMORPH_CHROOT_CACHE (default
# /var/cache/stickmorph/chroots), outside the repository, and is reused by
# later runs. Needs root, as the rest of the set-up does.
#
# `run` mounts /proc, /sys, /dev and the repository inside a private mount
# namespace (unshare), so the mounts vanish with the command, even when it is
# killed, and two runs never see each other's mounts.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
CACHE=${STICKMORPH_CHROOT_CACHE:-/var/cache/stickmorph/chroots}
MIRROR=${STICKMORPH_DEBIAN_MIRROR:-http://deb.debian.org/debian}

# What the chroot needs: Blender and numpy for the add-on, the build
# dependencies of the module (build_addon.py builds it inside, against that
# suite's Python, pybind11, Eigen and CGAL), make (minbase has none),
# pytest for the suite, EGL for headless Workbench/EEVEE, and Xvfb for the
# GUI test of Adjust Last Operation.
PACKAGES=(
  blender python3-numpy
  cmake make g++ pybind11-dev libeigen3-dev libcgal-dev libgmp-dev python3-dev
  nlohmann-json3-dev libcli11-dev
  python3-pytest
  libegl1 libegl-mesa0
  xvfb xauth
)
# sid's Blender 5.2 loads its extensions add-on (bl_pkg) through a downloader
# that imports cattrs and requests, which the Debian package does not depend
# on: without them the add-on fails to register at every start.
SID_PACKAGES=(python3-cattr python3-requests)

suite_packages() {
  printf '%s\n' "${PACKAGES[@]}"
  if [[ "$1" == sid ]]; then printf '%s\n' "${SID_PACKAGES[@]}"; fi
}

usage() {
  sed -n '2,8p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
}

die() { echo "blender_chroot.sh: $*" >&2; exit 2; }

check_suite() {
  case "$1" in
    trixie|sid) ;;
    *) die "unknown suite '$1' (trixie or sid)" ;;
  esac
}

need_root() {
  [[ $(id -u) -eq 0 ]] || die "needs root (debootstrap, chroot and mounts); run it as root"
}

# The chroot is complete when its marker names exactly the packages above; a
# run that was interrupted leaves no marker and is resumed, a changed package
# list installs only what is new.
marker_text() { suite_packages "$1"; }

in_chroot_plain() {
  # Package installation needs /proc and /dev but not the repository.
  local dir=$1; shift
  unshare --mount --propagation private -- bash -c '
    set -e
    dir=$1; shift
    mount -t proc proc "$dir/proc"
    mount --rbind /dev "$dir/dev"
    mount --rbind /sys "$dir/sys"
    exec chroot "$dir" "$@"' _ "$dir" "$@"
}

ensure() {
  local suite=$1 dir="$CACHE/$1"
  need_root
  mkdir -p "$CACHE"
  # One set-up at a time per suite: parallel test runs may call ensure together.
  exec 9>"$CACHE/$suite.lock"
  flock 9
  if [[ -f "$dir/.stickmorph-ready" ]] && [[ "$(cat "$dir/.stickmorph-ready")" == "$(marker_text "$suite")" ]]; then
    return 0
  fi
  if ! command -v debootstrap >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends debootstrap </dev/null
  fi
  if [[ ! -x "$dir/usr/bin/apt-get" || ! -f "$dir/.stickmorph-bootstrapped" ]]; then
    echo "blender_chroot.sh: debootstrap $suite into $dir (about a minute)"
    rm -rf "$dir"
    debootstrap --variant=minbase "$suite" "$dir" "$MIRROR"
    touch "$dir/.stickmorph-bootstrapped"
  fi
  # sid's Release file can be older than its Valid-Until while the archive is
  # frozen for a snapshot; the packages are still signed, only the date check goes.
  printf 'Acquire::Check-Valid-Until "false";\n' > "$dir/etc/apt/apt.conf.d/99stickmorph-valid-until"
  printf 'APT::Install-Recommends "false";\n' > "$dir/etc/apt/apt.conf.d/99stickmorph-no-recommends"
  echo "blender_chroot.sh: installing Blender and the build dependencies in $suite"
  in_chroot_plain "$dir" /usr/bin/env DEBIAN_FRONTEND=noninteractive apt-get update </dev/null
  in_chroot_plain "$dir" /usr/bin/env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y $(suite_packages "$suite") </dev/null
  in_chroot_plain "$dir" /usr/bin/env apt-get clean </dev/null
  mkdir -p "$dir/stickmorph"
  marker_text "$suite" > "$dir/.stickmorph-ready"
}

run() {
  local suite=$1 dir="$CACHE/$1"; shift
  [[ "${1:-}" == "--" ]] && shift
  [[ $# -gt 0 ]] || die "run: no command given"
  ensure "$suite"
  exec 9>&-
  # The repository is bound read-write: build_addon.py writes dist/ there.
  # Build folders go inside the chroot (/var/tmp), never in the repository,
  # so the host's build/ and each suite's build never mix.
  unshare --mount --propagation private -- bash -c '
    set -e
    dir=$1 root=$2; shift 2
    mount -t proc proc "$dir/proc"
    mount --rbind /dev "$dir/dev"
    mount --rbind /sys "$dir/sys"
    mount -t tmpfs tmpfs "$dir/tmp"
    mount --bind "$root" "$dir/stickmorph"
    exec chroot "$dir" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      LANG=C.UTF-8 CI="${CI:-}" TERM="${TERM:-dumb}" \
      /bin/bash -c "cd /stickmorph && exec \"\$@\"" _ "$@"' _ "$dir" "$ROOT" "$@"
}

[[ $# -ge 2 ]] || { usage; exit 2; }
command=$1 suite=$2; shift 2
check_suite "$suite"
case "$command" in
  ensure) ensure "$suite" ;;
  run) run "$suite" "$@" ;;
  path) echo "$CACHE/$suite" ;;
  *) usage; exit 2 ;;
esac
