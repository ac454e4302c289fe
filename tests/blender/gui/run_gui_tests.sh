#!/usr/bin/env bash
# The add-on's GUI tests: Blender with a real window under Xvfb.
#
#   tests/blender/gui/run_gui_tests.sh [--blender PATH] [--package ZIP]
#                                      [--sandbox DIR] [--out DIR]
#
#   --blender  the Blender to test (default: $BLENDER, else blender on PATH)
#   --package  the package to install (default: the newest one in dist/ built
#              for that Blender by build_addon.py)
#   --sandbox  folder for Blender's user folders, kept afterwards (default: a
#              temporary folder, removed afterwards); never the real config
#   --out      where the screenshot goes (default: out/gui/blender<M.m>/)
#
# Runs tests/blender/gui/adjust_last_operation.py (Adjust Last Operation on the bake
# operator), tests/blender/gui/cancel_bake.py (Esc cancels a modal bake and
# leaves the scene unchanged, issue 29) and tests/blender/gui/complete_bake.py
# (a 10^4-vertex modal bake runs to the end, Ctrl+Z undoes it), each in its own `blender
# --factory-startup` without -b, on a 1600x900 Xvfb screen, inside
# scripts/blender_sandbox.py. Needs the Debian packages xvfb and xauth. Exits
# with the first failing test's code: 0 passed, 1 failed, 2 timed out (also
# when Blender hangs: `timeout` ends it). Prints the screenshot's path.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../../.."

BLENDER="${BLENDER:-blender}"
package=() sandbox=() out=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --blender) BLENDER=$2; shift 2 ;;
    --package) package=(--package "$(realpath "$2")"); shift 2 ;;
    --sandbox) sandbox=(--dir "$2"); shift 2 ;;
    --out) out=(--out "$(realpath -m "$2")"); shift 2 ;;
    -h|--help) sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "run_gui_tests.sh: unknown argument: $1" >&2; exit 2 ;;
  esac
done

for tool in xvfb-run xauth; do
  command -v "$tool" >/dev/null || { echo "run_gui_tests.sh: $tool is missing (apt-get install xvfb xauth)" >&2; exit 2; }
done

version=$("$BLENDER" --version 2>/dev/null | head -n 1)
# Blender's own exit code is not the test's (a crash or a hang must not pass):
# each script ends the process itself with os._exit, 0 only when every check
# passed; the outer timeout is a second watchdog for a Blender that never
# runs Python at all.
run_gui_test() {  # SCRIPT TITLE [script arguments]
  local script=$1 title=$2
  shift 2
  printf '\n==== %s ====\n' "GUI test: $title ($version)"
  timeout --kill-after=10 300 \
    /usr/bin/python3 scripts/blender_sandbox.py "${sandbox[@]}" -- \
    xvfb-run -a -s "-screen 0 1600x900x24" \
    "$BLENDER" --factory-startup --enable-event-simulate --python-exit-code 1 \
    --python "tests/blender/gui/$script" -- "${package[@]}" "$@"
}
status=0 passed=0 failed=0
for test in adjust_last_operation cancel_bake complete_bake; do
  code=0
  case $test in
    adjust_last_operation) run_gui_test adjust_last_operation.py "Adjust Last Operation" "${out[@]}" || code=$? ;;
    cancel_bake) run_gui_test cancel_bake.py "Esc cancels a bake" || code=$? ;;
    complete_bake) run_gui_test complete_bake.py "a 10^4-vertex bake finishes, Ctrl+Z undoes it" || code=$? ;;
  esac
  if [[ $code -eq 0 ]]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    [[ $status -ne 0 ]] || status=$code
  fi
done
if [[ $status -eq 0 ]]; then
  echo "gui: $passed passed, 0 failed"
else
  echo "gui: $passed passed, $failed failed (exit $status)"
fi
exit "$status"
