#!/usr/bin/env bash
# Measures the designer end to end in a real window: Xvfb + openbox, Mesa's OpenGL, a
# 1600x1000 main window on the reference room; drags the blue ball, then orbits the camera,
# and prints what `raystudio --measure-drag/--measure-orbit` reports.
#
#   bash tests/bench/measure-designer.sh [--frames N] [--json] [--build DIR] [--display N]
#                                        [--view automatic|opengl|software]
#                                        [--scene FILE --object NAME]
#
# --scene and --object measure another scene (default: the reference room and its "blue
# ball"), e.g. the 1M-triangle mesh of tests/bench/make-bench-scenes.py and its "mesh".
# --display N runs Xvfb on :N (on a shared machine, the display you were given) instead of
# letting it pick a free one. --view sets Preferences -> Display for the run (default
# automatic, which on this software GL is the QPainter view; opengl measures the GL view).
#
# "whole frames" are frames shown with no pixel left from an older edit; "input to a whole
# frame" times a mouse move to the first such frame that shows it. tests/bench/results.sh runs
# this with --json for the headline table of tests/bench/RESULTS.md; earlier measurements are
# in the git history of this file and of README.md.

set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build/release
args=()
display=
scene=$root/scenes/reference-room.scene.json
object="blue ball"
while (($#)); do
    case $1 in
        --build) build=$2; shift 2 ;;
        --display) display=${2#:}; shift 2 ;;
        --frames) args+=(--frames "$2"); shift 2 ;;
        --json) args+=(--json); shift ;;
        --view) args+=(--view "$2"); shift 2 ;;
        --scene) scene=$2; shift 2 ;;
        --object) object=$2; shift 2 ;;
        *) echo "usage: $0 [--frames N] [--json] [--build DIR] [--display N] [--view KIND] [--scene FILE --object NAME]" >&2; exit 2 ;;
    esac
done
exe=$build/app/raystudio
[[ -f $scene ]] || { echo "scene $scene not found" >&2; exit 2; }
[[ -x $exe ]] || { echo "$exe not built (cmake --build --preset release --target raystudio)" >&2; exit 2; }
for tool in Xvfb openbox; do
    command -v $tool >/dev/null || { echo "$tool not found (apt-get install xvfb openbox)" >&2; exit 2; }
done

# Xvfb picks a free display and writes its number to fd 3 (or takes the one named).
tmp=$(mktemp -d)
if [[ -n $display ]]; then
    [[ $display =~ ^[0-9]+$ ]] || { echo "--display needs a number, not '$display'" >&2; exit 2; }
    Xvfb ":$display" -screen 0 1920x1200x24 -nolisten tcp 2>"$tmp/xvfb.log" &
    xvfb=$!
    # Ready when the socket is there and this Xvfb still runs (another one on :N makes it exit).
    for _ in $(seq 100); do
        sleep 0.1
        kill -0 "$xvfb" 2>/dev/null || break
        [[ -S /tmp/.X11-unix/X$display ]] && { echo "$display" >"$tmp/display"; break; }
    done
else
    Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
    xvfb=$!
fi
wm=
cleanup() {
    [[ -n $wm ]] && kill "$wm" 2>/dev/null || true
    kill "$xvfb" 2>/dev/null || true
    wait "$xvfb" 2>/dev/null || true  # The display is free again when this script ends.
    rm -rf "$tmp"
}
trap cleanup EXIT
for _ in $(seq 100); do [[ -s $tmp/display ]] && break; sleep 0.1; done
[[ -s $tmp/display ]] || { echo "Xvfb did not start: $(cat "$tmp/xvfb.log")" >&2; exit 1; }
export DISPLAY=:$(cat "$tmp/display")
openbox >/dev/null 2>&1 &
wm=$!
sleep 1

export QT_QPA_PLATFORM=xcb LIBGL_ALWAYS_SOFTWARE=1
"$exe" --measure-drag "$scene" --object "$object" "${args[@]}"
"$exe" --measure-orbit "$scene" "${args[@]}"
