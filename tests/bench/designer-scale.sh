#!/usr/bin/env bash
# The designer at scale, seen from outside as a user sees it: 1,000, 10,000 and 100,000
# spheres, one of them moved, undone, redone and edited 100 times, the window recorded.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/designer-scale.sh [--sizes LIST] [--moves N] [--edits N]
                                          [--self-moves N] [--max-wait S] [--size WxH]
                                          [--shots DIR] [--keep DIR] [--json] [--build DIR]

For each sphere count of LIST (default 1000,10000,100000) writes a floor of that many
spheres ("ball 0" ... ), the camera framed on "ball 0", a bright green sphere with no other
within 5 units (the same picture at every count: what grows is the document, not the
image). Under Xvfb (WxH, default 1920x1080) + openbox, the designer is started maximised
with --select "ball 0" --autosave-seconds 0 --recover no, in a HOME of its own. ffmpeg
(x11grab, 60 frames a second, wall-clock timestamps, no mouse pointer) records a 480x300
region around the ball from before the launch to the end; mpdecimate keeps the frames that
differ, and the ball's centre is found in each (its green, 4x4 blocks). A _NET_WM_PING sent
every 10 ms and answered by the designer's GUI thread (tests/bench/lib/wm-ping.py) times
its stalls. Then, waiting each time until the picture and the designer are idle:

  open      launch to the first recorded frame that shows the ball; the longest ping answer
            from the window's mapping to 2 s after that frame (the stall while opening)
  move      G, then N mouse moves (default 240) at 60 Hz from one xdotool process along an
            ellipse 240 px wide and 120 px high above the ball, a turn every 2 s, and the
            last 10 to 80 px right of the start, then a left click confirms:
            distinct frames a second on screen, ball position updates a second on screen
            (distinct frames whose ball moved 2 px or more: the updates that reached the
            user, at most the status bar's upd/s), the median and longest gap between
            distinct frames, first move to the ball moved on screen, longest ping answer
  undo/redo Ctrl+Z, then Ctrl+Shift+Z: from just before xdotool is started (a few ms of its
            own start-up included) to the first frame with the ball within 5 px of where the
            undo (redo) puts it; the first changed frame of any kind is given beside it
  memory    VmRSS (/proc/PID/status) after opening, before and after N confirmed moves
            (--edits, default 100: G, three moves of 40 px, a click; each an undo step)
  own       the designer's own count: raystudio --measure-drag SCENE --object "ball 0"
            --frames N (--self-moves, default 120; 0 skips it) --json, a left-button drag of
            posted events: generations_per_s (frames shown with a newer edit a second, the
            nearest to the status bar's upd/s) and frames_per_s

Prints a table per size with the targets of the designer at 100,000 objects (>= 30 updates
and distinct frames a second, undo and redo <= 50 ms, memory after the edits <= 1.5x before,
first frame <= 3 s with no stall over 100 ms) and whether each is met; --json prints one JSON
object. It measures; it does not fail on a missed target. --max-wait S (default 900) bounds
each wait for the designer to become idle (a phase that did not settle is named). --shots DIR
keeps a screenshot of the screen a quarter turn into each move (DIR/move-N.png, needs
ImageMagick's import). --keep DIR keeps each size's recordings, logs and events in
DIR/nN (to look at what a number came from). Needs Xvfb, openbox, xdotool, ffmpeg, python3 and a release build.
USAGE
}

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build/release
sizes=1000,10000,100000
moves=240
edits=100
self_moves=120
max_wait=900
size=1920x1080
shots=
keep=
json=0
while (($#)); do
    case $1 in
        --json) json=1; shift; continue ;;
        -h | --help) usage; exit 0 ;;
        --sizes | --moves | --edits | --self-moves | --max-wait | --size | --shots | --keep | --build) ;;
        *) echo "designer-scale.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    esac
    (($# >= 2)) || { echo "designer-scale.sh: $1 needs a value" >&2; exit 2; }
    case $1 in
        --sizes) sizes=$2 ;;
        --moves) moves=$2 ;;
        --edits) edits=$2 ;;
        --self-moves) self_moves=$2 ;;
        --max-wait) max_wait=$2 ;;
        --size) size=$2 ;;
        --shots) shots=$2 ;;
        --keep) keep=$2 ;;
        --build) build=$2 ;;
    esac
    shift 2
done
count() {  # option value min max
    if ! [[ $2 =~ ^[0-9]+$ ]] || (($2 < $3 || $2 > $4)); then
        echo "designer-scale.sh: $1 must be a whole number in [$3, $4], not '$2'" >&2
        exit 2
    fi
}
[[ $sizes =~ ^[0-9]+(,[0-9]+)*$ ]] ||
    { echo "designer-scale.sh: --sizes must be sphere counts separated by commas, e.g. 1000,10000, not '$sizes'" >&2; exit 2; }
for n in ${sizes//,/ }; do count "a count of --sizes" "$n" 10 1000000; done
count --moves "$moves" 60 100000
count --edits "$edits" 0 10000
count --self-moves "$self_moves" 0 100000
((self_moves == 0 || self_moves >= 2)) || { echo "designer-scale.sh: --self-moves must be 0 or at least 2" >&2; exit 2; }
count --max-wait "$max_wait" 5 86400
exe=$build/app/raystudio
[[ -x $exe ]] || { echo "designer-scale.sh: $exe not built (cmake --build $build --target raystudio)" >&2; exit 2; }
if [[ -n $keep ]]; then
    mkdir -p "$keep" || { echo "designer-scale.sh: cannot create --keep folder '$keep'" >&2; exit 2; }
fi
if [[ -n $shots ]]; then
    mkdir -p "$shots" || { echo "designer-scale.sh: cannot create --shots folder '$shots'" >&2; exit 2; }
    command -v import >/dev/null || { echo "designer-scale.sh: --shots needs ImageMagick's import (apt-get install imagemagick)" >&2; exit 2; }
fi

# shellcheck disable=SC2034  # read by the helper
x11_name=designer-scale.sh
# shellcheck source=tests/bench/lib/x11-session.sh
source "$root/tests/bench/lib/x11-session.sh"
x11_parse_size "$size"
x11_need_tools Xvfb openbox xdotool ffmpeg python3
lib=$root/tests/bench/lib
tmp=$x11_tmp
x11_start "$x11_width" "$x11_height" max

now() { date +%s.%N; }
rss_kib() { awk '/^VmRSS:/ {print $2}' "/proc/$1/status"; }
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null || echo 0; }
# The green of the ball, a 4x smaller grey picture: 2G - 2R - 2B, area-averaged.
mask_filter="colorchannelmixer=rr=-2:rg=2:rb=-2:gr=-2:gg=2:gb=-2:br=-2:bg=2:bb=-2,scale=iw/4:ih/4:flags=area,format=gray"

# Waits until the designer is idle: no distinct frame recorded and under 10 % of a core used
# for `quiet` seconds; idle_since is then the end of its last activity. Returns 1 after
# max_wait seconds (the phase is then named in the result).
wait_idle() {  # pid dir phase [quiet]
    local pid=$1 dir=$2 phase=$3 quiet=${4:-1.5} start t cpu last_cpu busy kept
    start=$(now) busy=$start last_cpu=$(cpu_ticks "$pid")
    while :; do
        sleep 0.2
        t=$(now) cpu=$(cpu_ticks "$pid")
        (( cpu - last_cpu > 2 )) && busy=$t
        last_cpu=$cpu
        kept=$(tail -c 3000 "$dir/record.log" 2>/dev/null | grep -o ' pts: *[0-9]*' | tail -1 | tr -dc '0-9' || true)
        [[ -n $kept ]] && busy=$(awk -v a="$busy" -v k="$kept" 'BEGIN {printf "%.6f\n", (k / 1e6 > a) ? k / 1e6 : a}')
        if awk -v t="$t" -v b="$busy" -v q="$quiet" 'BEGIN {exit !(t - b >= q)}'; then
            idle_since=$busy
            return 0
        fi
        if awk -v t="$t" -v s="$start" -v m="$max_wait" 'BEGIN {exit !(t - s >= m)}'; then
            not_settled+=("$phase")
            return 1
        fi
        kill -0 "$pid" 2>/dev/null || { echo "designer-scale.sh: the designer exited during $phase (see its log below)" >&2; cat "$dir/designer.log" >&2; exit 1; }
    done
}

# Where the ball shows: a small scene of the same framing, opened once, the screen's mask.
calibrate() {
    local dir=$tmp/calibrate
    mkdir -p "$dir"
    python3 "$lib/designer-scale.py" scene "$dir/scene.json" 10
    x11_launch "$dir/designer.log" "$exe" --select "ball 0" --autosave-seconds 0 --recover no "$dir/scene.json"
    local app=$x11_pid
    x11_wait_window "$app" 60 >/dev/null
    : >"$dir/record.log"
    not_settled=()
    wait_idle "$app" "$dir" calibration || true
    local w=$((x11_width / 4)) h=$((x11_height / 4))
    ffmpeg -nostdin -loglevel error -f x11grab -draw_mouse 0 -video_size "${x11_width}x${x11_height}" -i "$DISPLAY" \
        -frames:v 1 -vf "$mask_filter" -f rawvideo "$dir/mask.raw"
    x11_stop "$app"
    read -r bx by pixels < <(python3 "$lib/designer-scale.py" locate "$dir/mask.raw" "$w" "$h") || true
    [[ -n ${pixels:-} ]] || { echo "designer-scale.sh: the green ball did not show on the screen (the designer's log: $(tail -3 "$dir/designer.log"))" >&2; exit 1; }
    bx=$(printf '%.0f' "$(awk -v v="$bx" 'BEGIN {print v * 4 + 2}')")
    by=$(printf '%.0f' "$(awk -v v="$by" 'BEGIN {print v * 4 + 2}')")
}

# One xdotool script: G at the ball, `moves` moves at 60 Hz along an ellipse above it, then
# 80 px to its right. Upwards: a free move follows the view plane, and below the ball lies the
# floor, which would hide it.
move_script() {
    python3 - "$moves" "$bx" "$by" <<'PY'
import math, sys
moves, cx, cy = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
out = [f"mousemove {cx} {cy}", "sleep 0.3", "key g", "sleep 0.2"]
circle = moves - 10
for i in range(1, moves + 1):
    if i <= circle:
        a = 2 * math.pi * i / 120.0
        x, y = cx + round(120 * math.sin(a)), cy - round(120 * (1 - math.cos(a)) * 0.5)
    else:  # from where the circle ended, 80 px to the right of the start
        a = 2 * math.pi * circle / 120.0
        x0, y0 = cx + 120 * math.sin(a), cy - 120 * (1 - math.cos(a)) * 0.5
        f = (i - circle) / 10.0
        x, y = round(x0 + f * (cx + 80 - x0)), round(y0 + f * (cy - y0))
    out.append(f"mousemove {x} {y}")
    out.append("sleep 0.0166")
print("\n".join(out))
PY
}

# `edits` confirmed moves, to and fro by 40 px: G, three moves at 60 Hz, a click.
edits_script() {
    local k x0=$((bx + 80)) x1=$((bx + 40)) from to
    for ((k = 0; k < edits; k++)); do
        if ((k % 2 == 0)); then from=$x0 to=$x1; else from=$x1 to=$x0; fi
        echo "mousemove $from $by"
        echo "sleep 0.05"
        echo "key g"
        echo "sleep 0.05"
        echo "mousemove $(((2 * from + to) / 3)) $by"
        echo "sleep 0.0166"
        echo "mousemove $(((from + 2 * to) / 3)) $by"
        echo "sleep 0.0166"
        echo "mousemove $to $by"
        echo "sleep 0.05"
        echo "click 1"
        echo "sleep 0.1"
    done
}

measure() {  # spheres
    local n=$1 dir=$tmp/n$1
    mkdir -p "$dir"
    not_settled=()
    echo "designer-scale.sh: $n spheres" >&2
    python3 "$lib/designer-scale.py" scene "$dir/scene.json" "$n"
    local rw=480 rh=300
    local rx=$((bx - rw / 2)) ry=$((by - 200))
    ((rx < 0)) && rx=0
    ((ry < 0)) && ry=0
    ((rx + rw > x11_width)) && rx=$((x11_width - rw))
    ((ry + rh > x11_height)) && ry=$((x11_height - rh))
    ffmpeg -nostdin -nostats -loglevel info -f x11grab -draw_mouse 0 -framerate 60 -use_wallclock_as_timestamps 1 \
        -video_size "${rw}x${rh}" -i "$DISPLAY+$rx,$ry" -copyts \
        -vf "mpdecimate,showinfo,$mask_filter" -fps_mode passthrough -f rawvideo "$dir/mask.raw" \
        2>"$dir/record.log" &
    local rec=$!
    x11_track $rec
    sleep 1
    : >"$dir/events"
    echo "launch $(now)" >>"$dir/events"
    x11_launch "$dir/designer.log" "$exe" --select "ball 0" --autosave-seconds 0 --recover no "$dir/scene.json"
    local app=$x11_pid win
    win=$(x11_wait_window "$app" "$max_wait")
    echo "window $(now)" >>"$dir/events"
    python3 "$lib/wm-ping.py" "$win" "$dir/pings" 10 &
    local ping=$!
    x11_track $ping
    wait_idle "$app" "$dir" open && echo "opened $(now)" >>"$dir/events"
    echo "rss_open_kib $(rss_kib "$app")" >>"$dir/events"

    move_script >"$dir/move.xdo"
    if [[ -n $shots ]]; then
        (sleep 1; import -window root "$shots/move-$n.png") &  # a quarter turn in
        x11_track $!
    fi
    echo "drag_start $(now)" >>"$dir/events"
    xdotool - <"$dir/move.xdo"
    echo "drag_end $(now)" >>"$dir/events"
    sleep 0.3
    xdotool click 1
    wait_idle "$app" "$dir" move || true
    echo "undo $(now)" >>"$dir/events"
    xdotool key ctrl+z
    wait_idle "$app" "$dir" undo || true
    echo "redo $(now)" >>"$dir/events"
    xdotool key ctrl+shift+z
    wait_idle "$app" "$dir" redo || true

    echo "rss_before_kib $(rss_kib "$app")" >>"$dir/events"
    if ((edits > 0)); then
        edits_script >"$dir/edits.xdo"
        echo "edits_start $(now)" >>"$dir/events"
        xdotool - <"$dir/edits.xdo"
        echo "edits_end $(now)" >>"$dir/events"
        wait_idle "$app" "$dir" edits && echo "edits_settled $idle_since" >>"$dir/events"
        echo "rss_after_kib $(rss_kib "$app")" >>"$dir/events"
    fi
    x11_stop "$app"
    x11_stop "$ping"
    kill -INT "$rec" 2>/dev/null || true
    wait "$rec" 2>/dev/null || true

    if ((self_moves > 0)); then
        timeout "$max_wait" "$exe" --measure-drag "$dir/scene.json" --object "ball 0" --frames "$self_moves" \
            --json >"$dir/self.out" 2>"$dir/self.err" || not_settled+=("own measurement (exit $?)")
        grep '^{' "$dir/self.out" | tail -1 >"$dir/self.json" || true
    fi
    python3 - "$dir/info.json" "$n" "$size" "${rw}x${rh}+$rx+$ry" "$moves" "$edits" "${not_settled[@]}" <<'PY'
import json, sys
out, n, screen, region, moves, edits, *late = sys.argv[1:]
json.dump({"spheres": int(n), "screen": screen, "region": region, "moves": int(moves),
           "edits": int(edits), "not_settled": late, "mask_w": 120, "mask_h": 75}, open(out, "w"))
PY
    python3 "$lib/designer-scale.py" analyse "$dir" >>"$tmp/results.jsonl"
    if [[ -n $keep ]]; then rm -rf "$keep/n$n" && cp -r "$dir" "$keep/n$n"; fi
}

calibrate
echo "designer-scale.sh: the ball shows at ($bx, $by) on the screen" >&2
: >"$tmp/results.jsonl"
for n in ${sizes//,/ }; do measure "$n"; done
report=(python3 "$lib/designer-scale.py" report "$tmp/results.jsonl")
((json)) && report+=(--json)
"${report[@]}"
