# shellcheck shell=bash
# shellcheck disable=SC2034  # x11_width, x11_height, x11_pid: read by the sourcing script
# Sourced by the benchmarks that drive the designer from outside (window-frames.sh,
# designer-scale.sh): a private X server (Xvfb) with openbox, a throw-away HOME, and on exit
# every process started through it killed and its scratch folder removed.
#
# The sourcing script sets x11_name (its name, for messages) first, then calls:
#   x11_need_tools TOOL...          exits 2 naming every missing tool
#   x11_parse_size WxH              sets x11_width, x11_height (exits 2 on a bad size)
#   x11_start WIDTH HEIGHT [max]    Xvfb + openbox; "max": openbox maps every window maximised
#   x11_track PID                   PID is killed on exit
#   x11_launch LOG ARGS...          starts ARGS in the background, output to LOG; sets x11_pid
#   x11_wait_window PID [SECONDS]   prints the visible top-level window of PID (exits 1 if none)
#   x11_stop PID                    kills PID and waits for it
# x11_tmp is the scratch folder (removed on exit); DISPLAY and HOME point into it.

x11_tmp=$(mktemp -d)
x11_pids=()

x11_cleanup() {
    local p
    for p in "${x11_pids[@]}"; do kill "$p" 2>/dev/null || true; done
    for p in "${x11_pids[@]}"; do wait "$p" 2>/dev/null || true; done
    rm -rf "$x11_tmp"
}
trap x11_cleanup EXIT
trap 'exit 130' INT TERM HUP

x11_need_tools() {
    local tool missing=()
    for tool; do command -v "$tool" >/dev/null 2>&1 || missing+=("$tool"); done
    if ((${#missing[@]})); then
        echo "${x11_name:?}: not found: ${missing[*]} (apt-get install xvfb openbox xdotool ffmpeg python3)" >&2
        exit 2
    fi
}

x11_parse_size() {
    [[ $1 =~ ^([1-9][0-9]{2,4})x([1-9][0-9]{2,4})$ ]] || {
        echo "${x11_name}: --size must be WxH, e.g. 1920x1080, not '$1'" >&2
        exit 2
    }
    x11_width=${BASH_REMATCH[1]}
    x11_height=${BASH_REMATCH[2]}
}

x11_track() { x11_pids+=("$1"); }

x11_start() {  # width height [max]
    Xvfb -displayfd 3 -screen 0 "${1}x${2}x24" -nolisten tcp 3>"$x11_tmp/display" 2>"$x11_tmp/xvfb.log" &
    x11_track $!
    local try
    for try in $(seq 100); do [[ -s $x11_tmp/display ]] && break; sleep 0.05; done
    [[ -s $x11_tmp/display ]] || { echo "${x11_name}: Xvfb did not start: $(tail -3 "$x11_tmp/xvfb.log")" >&2; exit 1; }
    DISPLAY=:$(cat "$x11_tmp/display")
    export DISPLAY
    local config=()
    if [[ ${3:-} == max ]]; then
        # Every window is mapped maximised: its geometry is final from its first frame on.
        cat >"$x11_tmp/openbox.xml" <<'XML'
<?xml version="1.0" encoding="UTF-8"?>
<openbox_config xmlns="http://openbox.org/3.4/rc">
  <applications><application class="*"><maximized>true</maximized></application></applications>
</openbox_config>
XML
        config=(--config-file "$x11_tmp/openbox.xml")
    fi
    openbox "${config[@]}" >"$x11_tmp/openbox.log" 2>&1 &
    x11_track $!
    sleep 1
    # A home of its own: no autosave, settings or recovery of the user's are touched.
    export HOME=$x11_tmp/home XDG_CONFIG_HOME=$x11_tmp/home/.config XDG_DATA_HOME=$x11_tmp/home/.local/share
    mkdir -p "$HOME"
}

x11_launch() {  # log command...
    local log=$1
    shift
    "$@" >"$log" 2>&1 &
    x11_pid=$!
    x11_track "$x11_pid"
}

x11_wait_window() {  # pid [seconds]
    local pid=$1 tries=$(( ${2:-10} * 20 )) win='' try
    for ((try = 0; try < tries; try++)); do
        win=$(xdotool search --onlyvisible --pid "$pid" --name "RayStudio" 2>/dev/null | tail -1 || true)
        [[ -n $win ]] && break
        kill -0 "$pid" 2>/dev/null || { echo "${x11_name}: the designer exited before its window appeared" >&2; exit 1; }
        sleep 0.05
    done
    [[ -n $win ]] || { echo "${x11_name}: the designer's window did not appear in ${2:-10} s" >&2; exit 1; }
    echo "$win"
}

x11_stop() {  # pid
    kill "$1" 2>/dev/null || true
    wait "$1" 2>/dev/null || true
}
