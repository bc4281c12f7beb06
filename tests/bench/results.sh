#!/usr/bin/env bash
# Runs the project's benchmarks and writes their current tables, with the machine, the date and
# the commit, to tests/bench/RESULTS.md. The numbers are data: why they are what they are is in
# the commit messages, not here.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/results.sh [--quick | --full] [--threads N] [--skip LIST]
                                   [--display N] [--output FILE]

Runs the benchmarks of tests/bench/ on the release build (build/release) and writes
tests/bench/RESULTS.md (or FILE): the machine (CPU, cores, memory, OS), the date, the commit
built, the load average before and after, and then

  headline   the reference room against POV-Ray 3.7    compare-povray.sh RUNS THREADS
             a 1M-triangle mesh against Embree alone   compare-embree.sh RUNS THREADS
             the designer in a window (Xvfb)           measure-designer.sh --json, RUNS times
             checker + sky, 4k textures vs flat        looks-cost.sh RUNS THREADS
  full only  both ray engines on every scene           engine-table.sh 5 THREADS
             the designer at 1k, 10k and 100k spheres  designer-scale.sh --json (minutes)
             session frame against renderImage         session-frame.sh 15 THREADS
             the interaction policies                  policy-table.sh
             the cost curve (spheres, triangles)       scaling.sh 3 THREADS

  --quick        (default) the headline rows only, 3 runs each, the designer once:
                 under a minute on a 2-core machine
  --full         7 runs each, the designer 3 times, and the four tables: 5-10 minutes
                 (the 1M-triangle and 100,000-sphere scenes are generated and loaded often)
  --threads N    render threads (default 2)
  --skip LIST    comma-separated rows to leave out: povray, embree, designer, window, looks,
                 scale
                 (written as "not measured" in the file)
  --display N    the X display measure-designer.sh gives Xvfb (default: a free one)
  --output FILE  write FILE instead of tests/bench/RESULTS.md

Needs build/release/app/raystudio-cli and build/release/app/raystudio (bash packaging/setup.sh
test, or cmake --build build/release), povray, python3, a C++ compiler with Embree 3's headers,
Xvfb and openbox; it stops with an error naming what is missing, and writes the file only when
every benchmark it ran succeeded.
USAGE
}

mode=quick
threads=2
skip=","
display=()
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
output="${root}/tests/bench/RESULTS.md"
while (($#)); do
    case "$1" in
        -h | --help) usage; exit 0 ;;
        --quick) mode=quick; shift; continue ;;
        --full) mode=full; shift; continue ;;
        --threads | --skip | --display | --output) ;;
        *) echo "results.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    esac
    (($# >= 2)) || { echo "results.sh: $1 needs a value" >&2; exit 2; }
    case "$1" in
        --threads) threads="$2" ;;
        --skip) skip=",$2," ;;
        --display) display=(--display "$2") ;;
        --output) output="$2" ;;
    esac
    shift 2
done
[[ "${threads}" =~ ^[1-9][0-9]*$ ]] || { echo "results.sh: --threads needs a positive number, not '${threads}'" >&2; exit 2; }
[[ -n "${output}" ]] || { echo "results.sh: --output needs a file name" >&2; exit 2; }
for s in ${skip//,/ }; do
    [[ "${s}" =~ ^(povray|embree|designer|window|looks|scale)$ ]] || { echo "results.sh: --skip knows povray, embree, designer, window, looks and scale, not '${s}'" >&2; exit 2; }
done
skipped() { [[ "${skip}" == *",$1,"* ]]; }
if [[ "${mode}" == full ]]; then runs=7; designer_runs=3; else runs=3; designer_runs=1; fi

# What is needed, all checked before anything runs, every missing piece named.
build="${root}/build/release"
cli="${build}/app/raystudio-cli"
gui="${build}/app/raystudio"
missing=()
[[ -x "${cli}" ]] || missing+=("${cli} is not built (bash packaging/setup.sh test, or cmake --build build/release --target raystudio-cli)")
if ! skipped designer; then
    [[ -x "${gui}" ]] || missing+=("${gui} is not built (cmake --build build/release --target raystudio), or pass --skip designer")
    for tool in Xvfb openbox; do
        command -v "${tool}" >/dev/null 2>&1 || missing+=("${tool} not found (apt-get install xvfb openbox), or pass --skip designer")
    done
fi
if ! skipped window || { [[ "${mode}" == full ]] && ! skipped scale; }; then
    for tool in Xvfb openbox xdotool ffmpeg; do
        command -v "${tool}" >/dev/null 2>&1 || missing+=("${tool} not found (apt-get install xvfb openbox xdotool ffmpeg), or pass --skip window,scale")
    done
fi
skipped povray || command -v povray >/dev/null 2>&1 || missing+=("povray not found (apt-get install povray), or pass --skip povray")
command -v python3 >/dev/null 2>&1 || missing+=("python3 not found")
if ! skipped embree; then
    command -v c++ >/dev/null 2>&1 || missing+=("c++ not found (compare-embree.sh builds its yardstick), or pass --skip embree")
    [[ -f /usr/include/embree3/rtcore.h ]] || missing+=("Embree 3's headers not found (apt-get install libembree-dev), or pass --skip embree")
fi
if ((${#missing[@]})); then
    echo "results.sh: cannot run the benchmarks:" >&2
    printf '  %s\n' "${missing[@]}" >&2
    exit 1
fi

work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
median() { sort -g | awk '{v[NR]=$1} END {if (NR) print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
# Runs one benchmark script, its output kept in a file; a failure stops everything with it.
stage_log=()
run_stage() {  # name outfile command...
    local name="$1" out="$2" t0 load0 status=0
    shift 2
    echo "results.sh: ${name}: $*" >&2
    t0="$(date +%s)"
    load0="$(loadavg)"
    "$@" >"${out}" 2>"${out}.err" || status=$?
    if ((status != 0)); then
        echo "results.sh: ${name} failed (exit ${status}): $*" >&2
        cat "${out}" "${out}.err" >&2
        exit 1
    fi
    stage_log+=("| ${name} | \`$(printf '%s ' "$@" | sed "s|${work}/[^ ]*|(a scratch file)|g; s|${root}/||g; s/ \$//")\` | $(($(date +%s) - t0)) s | ${load0} | $(loadavg) |")
}
# One number read from a benchmark's output; an empty answer is an error, not a blank cell.
need() {  # what value
    [[ -n "$2" ]] || { echo "results.sh: could not read $1 from the benchmark's output" >&2; exit 1; }
    printf '%s' "$2"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.2f", a / b}'; }
# What a designer row measured: "orbit" rows orbit the camera, the others move the blue ball
# ($2: how, e.g. dragging).
designer_action() {
    if [[ "$1" == orbit ]]; then echo "orbiting the reference room's camera"; else echo "$2 the reference room's blue ball"; fi
}

started="$(date -u '+%Y-%m-%d %H:%M UTC')"
start_s="$(date +%s)"
load_start="$(loadavg)"
headline=()

if skipped povray; then
    headline+=("| reference room, 1280x720, ${threads} threads: render time against POV-Ray 3.7's Trace Time | not measured (--skip povray) | | | |")
else
    run_stage "room vs POV-Ray" "${work}/povray" bash "${root}/tests/bench/compare-povray.sh" "${runs}" "${threads}"
    pov="$(need "POV-Ray's trace time" "$(awk '$1 == "render" {print $3}' "${work}/povray")")"
    rs="$(need "RayStudio's render time" "$(awk '$1 == "render" {print $6}' "${work}/povray")")"
    povw="$(need "POV-Ray's wall time" "$(awk '$1 == "wall" {print $3}' "${work}/povray")")"
    rsw="$(need "RayStudio's wall time" "$(awk '$1 == "wall" {print $6}' "${work}/povray")")"
    headline+=("| reference room, 1280x720, ${threads} threads: render time (\`--stats\` ms) against POV-Ray 3.7's Trace Time | ${rs} ms | ${pov} ms | **$(ratio "${pov}" "${rs}")x** faster | \`bash tests/bench/compare-povray.sh ${runs} ${threads}\` |")
    headline+=("| the same, whole process (start to image written) | ${rsw} ms | ${povw} ms | $(ratio "${povw}" "${rsw}")x faster | the same |")
fi

if skipped embree; then
    headline+=("| 1,000,000-triangle mesh, 1280x720 primary rays + Lambert, against Embree's \`rtcIntersect1\` alone | not measured (--skip embree) | | | |")
else
    run_stage "1M triangles vs Embree" "${work}/embree" bash "${root}/tests/bench/compare-embree.sh" "${runs}" "${threads}"
    em="$(need "Embree's time" "$(awk '/rtcIntersect1 alone/ {print $4}' "${work}/embree")")"
    rs="$(need "RayStudio's mesh time" "$(awk '/RayStudio, shaded image/ {print $4}' "${work}/embree")")"
    headline+=("| 1,000,000-triangle mesh, 1280x720 primary rays + Lambert shading (the whole trace path), against Embree 3's \`rtcIntersect1\` alone (no shading) on the same rays, ${threads} threads | ${rs} ms | ${em} ms | **$(ratio "${em}" "${rs}")x** (Embree / RayStudio) | \`bash tests/bench/compare-embree.sh ${runs} ${threads}\` |")
fi

if skipped looks; then
    headline+=("| the classic scene's checker and sky, and 4k textures on the reference room, against flat colours | not measured (--skip looks) | | | |")
else
    command -v oiiotool >/dev/null 2>&1 || { echo "results.sh: oiiotool not found (apt-get install openimageio-tools), or pass --skip looks" >&2; exit 1; }
    run_stage "looks vs flat" "${work}/looks" bash "${root}/tests/bench/looks-cost.sh" "${runs}" "${threads}"
    for what in classic textured; do
        read -r flat patterned factor < <(awk -v w="${what}" '$1 == w {print $3, $6, $9}' "${work}/looks")
        need "the ${what} times" "${factor:-}" >/dev/null
        if [[ "${what}" == classic ]]; then
            label="classic scene (checkered floor, glass and mirror balls, HDR sky), 1280x720, 4 samples a pixel, against the same with flat colours and a flat background"
        else
            label="reference room with a 4096x4096 PNG texture on every material, against flat colours (texture cache warm)"
        fi
        headline+=("| ${label}, ${threads} threads | ${patterned} ms | ${flat} ms | **${factor}x** the flat scene's time | \`bash tests/bench/looks-cost.sh ${runs} ${threads}\` |")
    done
fi

if skipped designer; then
    headline+=("| designer, dragging a ball in the window | not measured (--skip designer) | | | |")
else
    : >"${work}/designer.jsonl"
    for ((i = 1; i <= designer_runs; i++)); do
        run_stage "designer, run ${i}" "${work}/designer-${i}" bash "${root}/tests/bench/measure-designer.sh" --json "${display[@]}"
        cat "${work}/designer-${i}" >>"${work}/designer.jsonl"
    done
    # Medians over the runs of what measure-designer reports, one line per gesture.
    python3 - "${work}/designer.jsonl" "${designer_runs}" >"${work}/designer.rows" <<'PY'
import json, statistics, sys
runs = [json.loads(l) for l in open(sys.argv[1]) if l.startswith("{")]
n = int(sys.argv[2])
for kind in ("drag", "orbit"):
    rs = [r for r in runs if r.get("kind") == kind]
    if len(rs) != n:
        sys.exit(f"measure-designer.sh gave {len(rs)} {kind} results for {n} runs")
    m = lambda k: statistics.median(float(r[k]) for r in rs)
    print(kind, rs[0]["viewport"], "opengl" if rs[0]["opengl"] else "raster",
          "%.1f %.1f %.1f %.1f %.2f" % (m("whole_frames_per_s"), m("frames_per_s"),
          m("whole_latency_median_ms"), m("gui_stall_max_ms"), m("full_frame_ratio")))
PY
    while read -r kind viewport view whole shown latency stall full; do
        what=$(designer_action "${kind}" dragging)
        headline+=("| designer in a window (Xvfb, Mesa llvmpipe, ${view} view, viewport ${viewport}), ${what}, 240 mouse moves at 60 Hz | **${whole} whole frames/s** (${shown} shown), input to a whole frame ${latency} ms, longest GUI stall ${stall} ms | | viewport full frame ${full}x \`renderImage\` | \`bash tests/bench/measure-designer.sh --json\`, median of ${designer_runs} |")
    done <"${work}/designer.rows"
fi

if skipped window; then
    headline+=("| designer seen from outside (x11grab), G-moving a ball and orbiting | not measured (--skip window) | | | |")
else
    run_stage "designer from outside" "${work}/window" bash "${root}/tests/bench/window-frames.sh" --json
    python3 - "${work}/window" >"${work}/window.rows" <<'PY'
import json, sys
lines = [l for l in open(sys.argv[1]) if l.startswith("{")]
if not lines:
    sys.exit("window-frames.sh gave no result")
r = json.loads(lines[-1])
for kind in ("drag", "orbit"):
    e, own = r[kind], r[kind].get("designer_own", {})
    print(kind, r["screen"], e["distinct_frames_per_s"], e["median_gap_ms"], e["longest_gap_ms"],
          e["input_to_screen_ms"], "%.1f" % float(own.get("frames_per_s", "nan")),
          "%.1f" % float(own.get("latency_median_ms", "nan")))
PY
    while read -r kind screen fps gap longest latency own_fps own_latency; do
        what=$(designer_action "${kind}" G-moving)
        headline+=("| designer seen from outside (Xvfb ${screen} + openbox, maximised; one xdotool process at 60 Hz; ffmpeg x11grab + mpdecimate of the viewport's middle), ${what}, 240 moves | **${fps} distinct frames/s** on screen, median gap ${gap} ms, longest ${longest} ms, first input to screen ${latency} ms | the designer's own (\`--measure-${kind}\`): ${own_fps} frames/s, latency ${own_latency} ms | | \`bash tests/bench/window-frames.sh --json\` |")
    done <"${work}/window.rows"
fi

tables=()
scale_what="the designer at 100,000 spheres seen from outside (Xvfb, xdotool at 60 Hz, x11grab): G-moving one, undo, redo, 100 edits, opening"
if [[ "${mode}" != full ]]; then
    headline+=("| ${scale_what} | not measured (--full only, or \`bash tests/bench/designer-scale.sh\`) | | | |")
elif skipped scale; then
    headline+=("| ${scale_what} | not measured (--skip scale) | | | |")
else
    run_stage "designer at scale" "${work}/scale" bash "${root}/tests/bench/designer-scale.sh" --json
    python3 - "${work}/scale" >"${work}/scale.rows" <<'PY'
import json, sys
lines = [l for l in open(sys.argv[1]) if l.startswith("{")]
if not lines:
    sys.exit("designer-scale.sh gave no result")
for r in json.loads(lines[-1])["runs"]:
    own = r.get("designer_own") or {}
    g = lambda k: "-" if r.get(k) is None else r[k]
    print("|".join(str(v) for v in (
        "{:,}".format(r["spheres"]), g("position_updates_per_s"),
        "-" if own.get("generations_per_s") is None else "%.1f" % own["generations_per_s"],
        g("distinct_frames_per_s"), g("input_to_screen_ms"), g("undo_ms"), g("redo_ms"),
        g("rss_before_mib"), g("rss_after_mib"), g("memory_ratio"), g("open_first_frame_ms"),
        g("open_longest_stall_ms"), sum(1 for v in r["targets"].values() if v), len(r["targets"]))))
PY
    tables+=("## The designer at scale" "" "\`bash tests/bench/designer-scale.sh --json\`: a floor of N spheres, one (\"ball 0\") G-moved by one xdotool process at 60 Hz (240 moves), confirmed, undone and redone, then 100 more confirmed moves; ffmpeg x11grab records a region around it. Updates/s on screen: distinct frames whose ball moved; the designer's own: \`--measure-drag\` generations_per_s. Undo/redo: key to the ball where it belongs on screen. Memory: VmRSS before and after the 100 moves. Open: launch to the first frame showing the ball; stall: the longest \`_NET_WM_PING\` answer meanwhile. Targets (issue 34, at 100,000): >= 30 updates/s and distinct frames/s, undo/redo <= 50 ms, memory <= 1.5x, first frame <= 3 s, no stall over 100 ms." "")
    tables+=("| spheres | updates/s on screen | the designer's own updates/s | distinct frames/s | input to screen ms | undo ms | redo ms | memory before MiB | after 100 moves MiB | ratio | open to first frame ms | longest stall ms | targets met |" "|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    while IFS='|' read -r n ups own fps lat undo redo before after ratio open stall met of; do
        tables+=("| ${n} | ${ups} | ${own} | ${fps} | ${lat} | ${undo} | ${redo} | ${before} | ${after} | ${ratio} | ${open} | ${stall} | ${met} of ${of} |")
        [[ "${n}" == 100,000 ]] && headline+=("| ${scale_what} | **${ups} updates/s**, ${fps} distinct frames/s on screen, undo ${undo} ms, redo ${redo} ms, memory after 100 moves ${ratio}x, first frame ${open} ms, longest stall ${stall} ms | issue 34: >= 30/s, >= 30/s, <= 50 ms, <= 50 ms, <= 1.5x, <= 3000 ms, <= 100 ms | ${met} of ${of} targets met | \`bash tests/bench/designer-scale.sh --json\` |")
    done <"${work}/scale.rows"
    tables+=("")
fi
if [[ "${mode}" == full ]]; then
    run_stage "engine table" "${work}/engines" bash "${root}/tests/bench/engine-table.sh" 5 "${threads}"
    tables+=("## Both ray engines on every scene" "" "\`bash tests/bench/engine-table.sh 5 ${threads}\`: render time (\`--stats\` ms), median of 5 alternated runs." "")
    mapfile -t -O "${#tables[@]}" tables <"${work}/engines"
    tables+=("")

    run_stage "session frame" "${work}/session" bash "${root}/tests/bench/session-frame.sh" 15 "${threads}"
    tables+=("## A whole session frame against \`renderImage\`" "" "\`bash tests/bench/session-frame.sh 15 ${threads}\`: process CPU time, medians of 15 interleaved frames (\`raystudio-cli drag --frames 15\`)." "")
    mapfile -t -O "${#tables[@]}" tables <"${work}/session"
    tables+=("")

    run_stage "policy table" "${work}/policies" bash "${root}/tests/bench/policy-table.sh"
    tables+=("## Interaction policies" "" "\`bash tests/bench/policy-table.sh\`: the reference room's glass ball dragged in 20 steps at 1280x720, 2 threads, once per file in \`tests/bench/policies/\`." "")
    tables+=("| policy | step ms (median) | traced % (median) | refine ms | full frame ms | max difference after refining |" "|---|---|---|---|---|---|")
    mapfile -t -O "${#tables[@]}" tables < <(awk 'NR > 1 && NF == 6 {printf "| %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6}' "${work}/policies")
    tables+=("")

    run_stage "cost curve" "${work}/scaling" bash "${root}/tests/bench/scaling.sh" 3 "${threads}" "${work}/scaling.png"
    tables+=("## Cost curve" "" "\`bash tests/bench/scaling.sh 3 ${threads}\`: N random spheres on a floor and a tessellated sphere of N triangles, 1280x720, depth 3, median of 3 renders per engine." "")
    tables+=("| kind | N | embree ms | embree Mrays/s | builtin ms | builtin Mrays/s |" "|---|---|---|---|---|---|")
    mapfile -t -O "${#tables[@]}" tables < <(awk '($1 == "spheres" || $1 == "triangles") && NF == 5 {
            key = $1 " " $2; if (!(key in seen)) { order[++n] = key; seen[key] = 1 }
            ms[key, $3] = $4; mr[key, $3] = $5 }
        END { for (i = 1; i <= n; i++) { k = order[i]; split(k, p, " ")
            printf "| %s | %s | %s | %s | %s | %s |\n", p[1], p[2], ms[k, "embree"], mr[k, "embree"], ms[k, "builtin"], mr[k, "builtin"] } }' \
        "${work}/scaling")
    tables+=("")
fi

# The machine and what was built.
cpu="$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
[[ -n "${cpu}" ]] || cpu="$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
cores="$(nproc) available to this process ($(getconf _NPROCESSORS_ONLN) online)"
memory="$(awk '/^MemTotal:/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
os="$( (. /etc/os-release 2>/dev/null && echo "${PRETTY_NAME}") || uname -s), kernel $(uname -r)"
commit="$(git -C "${root}" rev-parse HEAD 2>/dev/null || echo "not a git checkout")"
describe="$(git -C "${root}" describe --always --dirty 2>/dev/null || echo "-")"
built="$("${cli}" --version 2>/dev/null | head -1)"
pkg() {  # the version of the first of these Debian packages that is installed
    local name
    for name in "$@"; do dpkg-query -W -f='${Version}' "${name}" 2>/dev/null && return; done
    echo "not installed"
}

tmp_out="${work}/RESULTS.md"
{
    echo "# Benchmark results"
    echo
    echo "Written by \`bash tests/bench/results.sh$([[ "${mode}" == full ]] && echo " --full")$([[ "${threads}" != 2 ]] && echo " --threads ${threads}")$([[ "${skip}" != "," ]] && echo " --skip ${skip:1:${#skip}-2}")\`; run it again to replace this file. Ratios compare runs interleaved on the same machine in the same minutes; absolute times move with the machine and its load."
    echo
    echo "| | |"
    echo "|---|---|"
    echo "| date | ${started}, $(($(date +%s) - start_s)) s in all |"
    echo "| commit | \`${commit}\` (\`git describe --always --dirty\`: \`${describe}\`) |"
    echo "| build | \`raystudio-cli --version\`: ${built:-?}, release preset (\`build/release\`) |"
    echo "| CPU | ${cpu:-unknown}, ${cores} |"
    echo "| memory | ${memory} |"
    echo "| OS | ${os} |"
    echo "| load average (1, 5, 15 min) | ${load_start} at the start, $(loadavg) at the end |"
    echo "| yardsticks | POV-Ray $(pkg povray), Embree $(pkg libembree3-3 libembree3), Mesa $(pkg libgl1-mesa-dri) |"
    echo "| setting | ${mode}: ${runs} interleaved runs a comparison, the designer ${designer_runs} time(s), ${threads} threads |"
    echo
    echo "## Headline"
    echo
    echo "| measure | RayStudio | yardstick | ratio | command |"
    echo "|---|---|---|---|---|"
    printf '%s\n' "${headline[@]}"
    echo
    if ((${#tables[@]})); then printf '%s\n' "${tables[@]}"; fi
    echo "## Runs"
    echo
    echo "| benchmark | command | took | load average before | after |"
    echo "|---|---|---|---|---|"
    if ((${#stage_log[@]})); then printf '%s\n' "${stage_log[@]}"; fi
} >"${tmp_out}"
mkdir -p "$(dirname "${output}")"
cp "${tmp_out}" "${output}"
echo "results.sh: wrote ${output}" >&2
