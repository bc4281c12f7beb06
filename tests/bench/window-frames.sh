#!/usr/bin/env bash
# The designer measured from outside, as a user sees it: under Xvfb + openbox, one xdotool
# process sends mouse moves at a steady 60 Hz (a G move of a selected object, or an orbit),
# ffmpeg records the middle of the viewport from the X server, and the recording says how many
# distinct frames a second reached the screen and how long the first input took to show.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/window-frames.sh [--scene FILE] [--object NAME] [--moves N]
                                         [--size WxH] [--json] [--build DIR]

Starts the designer maximised in a WxH screen (default 1920x1080) with FILE open (default
the reference room) and, for each of two gestures, sends N mouse moves (default 240) at
60 Hz from one xdotool process while ffmpeg records a 640x360 region in the middle of the
viewport at 60 frames a second (x11grab, wall-clock timestamps):

  drag    NAME (default "blue ball") selected with --select, moved with G (Blender's free
          move) along a circle of 120 pixels radius, then Esc (nothing is changed)
  orbit   the right button held, the same circle

Prints per gesture: distinct frames a second on screen (ffmpeg mpdecimate over the moves'
span), the median and longest gap between distinct frames, and the input-to-screen latency
(from the first move to the first changed frame); then the designer's own measurement of the
same gesture (raystudio --measure-drag / --measure-orbit) beside it. --json prints one JSON
object instead. Needs Xvfb, openbox, xdotool, ffmpeg and a release build.
USAGE
}

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build/release
scene=$root/scenes/reference-room.scene.json
object="blue ball"
moves=240
size=1920x1080
json=0
while (($#)); do
    case $1 in
        --scene) scene=$2; shift 2 ;;
        --object) object=$2; shift 2 ;;
        --moves) moves=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --build) build=$2; shift 2 ;;
        --json) json=1; shift ;;
        -h | --help) usage; exit 0 ;;
        *) usage >&2; exit 2 ;;
    esac
done
[[ $moves =~ ^[1-9][0-9]*$ && $moves -le 100000 ]] || { echo "window-frames.sh: --moves must be a count in [1, 100000]" >&2; exit 2; }
x11_name=window-frames.sh
# shellcheck source=tests/bench/lib/x11-session.sh
source "$root/tests/bench/lib/x11-session.sh"
x11_parse_size "$size"
width=$x11_width
height=$x11_height
exe=$build/app/raystudio
[[ -f $scene ]] || { echo "window-frames.sh: scene $scene not found" >&2; exit 2; }
[[ -x $exe ]] || { echo "window-frames.sh: $exe not built (bash packaging/setup.sh test)" >&2; exit 2; }
x11_need_tools Xvfb openbox xdotool ffmpeg python3
tmp=$x11_tmp
x11_start "$width" "$height"

# The middle of the screen lies inside the viewport of a maximised window (the docks are at
# the sides); the recorded region is centred there.
cx=$((width / 2)) cy=$((height / 2))
rw=640 rh=360
rx=$((cx - rw / 2)) ry=$((cy - rh / 2))

# Writes the xdotool script of one gesture: press (or G), a circle of `moves` moves at 60 Hz,
# release (or Esc). One xdotool process runs it: its own timing, no process per move.
gesture_script() {  # kind
    python3 - "$1" "$moves" "$cx" "$cy" <<'PY'
import math, sys
kind, moves, cx, cy = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
out = [f"mousemove {cx} {cy}", "sleep 0.3"]
if kind == "drag":
    out.append("key g")
else:
    out.append("mousedown 3")
out.append("sleep 0.2")
for i in range(1, moves + 1):
    a = 2 * math.pi * i / 120.0
    out.append(f"mousemove {cx + round(120 * math.sin(a))} {cy + round(120 * (1 - math.cos(a)) * 0.5)}")
    out.append("sleep 0.0166")
out.append("sleep 0.3")
out.append("key Escape" if kind == "drag" else "mouseup 3")
print("\n".join(out))
PY
}

measure() {  # kind
    local kind=$1 select=()
    [[ $kind == drag ]] && select=(--select "$object")
    x11_launch "$tmp/designer-$kind.log" "$exe" "${select[@]}" --autosave-seconds 0 --recover no "$scene"
    local app=$x11_pid win
    win=$(x11_wait_window "$app" 10)
    xdotool windowactivate --sync "$win" >/dev/null 2>&1 || true
    wmctrl -i -r "$win" -b add,maximized_vert,maximized_horz >/dev/null 2>&1 ||
        xdotool windowsize "$win" "$width" "$height" windowmove "$win" 0 0
    sleep 3  # the first frame refines
    gesture_script "$kind" >"$tmp/$kind.xdo"
    local seconds
    seconds=$(python3 -c "print($moves / 60.0 + 2.5)")
    # Decimated as it is recorded: each frame that differs from the last kept one (ffmpeg's
    # mpdecimate) is logged with its wall-clock time in microseconds (showinfo's pts).
    # Without the mouse pointer: it moves in the region every frame, designer or not.
    ffmpeg -nostdin -loglevel info -f x11grab -draw_mouse 0 -framerate 60 -use_wallclock_as_timestamps 1 \
        -video_size "${rw}x${rh}" -t "$seconds" -i "$DISPLAY+$rx,$ry" -copyts \
        -vf "mpdecimate,showinfo" -f null - 2>"$tmp/$kind.ffmpeg" &
    local rec=$!
    x11_track $rec
    sleep 0.5
    date +%s.%N >"$tmp/$kind.start"
    xdotool - <"$tmp/$kind.xdo"
    date +%s.%N >"$tmp/$kind.end"
    wait $rec || true
    x11_stop $app
    grep -o ' pts: *[0-9]*' "$tmp/$kind.ffmpeg" | tr -dc '0-9\n' |
        awk 'NF {printf "%.6f\n", $1 / 1e6}' >"$tmp/$kind.kept" || true
    # The designer's own measurement of the same gesture, for the table beside it.
    "$exe" --measure-$kind "$scene" --object "$object" --frames "$moves" --json \
        >"$tmp/$kind.self" 2>/dev/null || echo '{}' >"$tmp/$kind.self"
}

measure drag
measure orbit

python3 - "$tmp" "$json" "$size" <<'PY'
import json, statistics, sys, os
tmp, as_json, size = sys.argv[1], sys.argv[2] == "1", sys.argv[3]
result = {"screen": size}
for kind in ("drag", "orbit"):
    start = float(open(os.path.join(tmp, kind + ".start")).read())
    end = float(open(os.path.join(tmp, kind + ".end")).read())
    kept = [float(x) for x in open(os.path.join(tmp, kind + ".kept")).read().split()]
    # The first kept frame is the picture before any input; the moves' span is what counts.
    first_input = start + 0.5  # the script's own 0.3 s and 0.2 s before its first move
    during = [t for t in kept if first_input <= t <= end]
    changed = [t for t in kept if t > first_input]
    gaps = [b - a for a, b in zip(during, during[1:])]
    span = max(end - first_input, 1e-3)
    entry = {
        "distinct_frames_per_s": round(len(during) / span, 1),
        "median_gap_ms": round(1000 * statistics.median(gaps), 1) if gaps else None,
        "longest_gap_ms": round(1000 * max(gaps), 1) if gaps else None,
        "input_to_screen_ms": round(1000 * (changed[0] - first_input), 1) if changed else None,
    }
    try:
        entry["designer_own"] = json.load(open(os.path.join(tmp, kind + ".self")))
    except Exception:
        entry["designer_own"] = {}
    result[kind] = entry
if as_json:
    print(json.dumps(result))
else:
    for kind in ("drag", "orbit"):
        e = result[kind]
        own = e["designer_own"]
        print(f"{kind:6} on screen: {e['distinct_frames_per_s']} distinct frames/s, median gap "
              f"{e['median_gap_ms']} ms, longest {e['longest_gap_ms']} ms, input to screen "
              f"{e['input_to_screen_ms']} ms; the designer's own: "
              + ", ".join(f"{k} {v}" for k, v in own.items() if not isinstance(v, (list, dict))))
PY
