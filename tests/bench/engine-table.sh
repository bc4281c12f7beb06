#!/usr/bin/env bash
# Both ray engines on every bundled scene and on the generated benchmark scenes: one table.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/engine-table.sh [RUNS] [THREADS]

Renders each scene RUNS times (default 5) with raystudio-cli render --stats, alternating
--engine embree and --engine builtin, THREADS (default 2) threads, and prints the median
"ms" (tracing only, loading excluded) of each as a Markdown table with their ratio.
Scenes: scenes/*.scene.json, then the generated ones of tests/bench/make-bench-scenes.py
(room plus a box, room with a 16-sample sphere light, 1,000 and 100,000 spheres, a
1,000,000-triangle mesh). Needs a release build (bash packaging/setup.sh test).
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi
runs="${1:-5}"
threads="${2:-2}"
[[ "${runs}" =~ ^[1-9][0-9]*$ && "${threads}" =~ ^[1-9][0-9]*$ ]] || { usage >&2; exit 2; }
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${root}/build/release/app/raystudio-cli"
[[ -x "${cli}" ]] || { echo "engine-table.sh: ${cli} not built" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python3 "${root}/tests/bench/make-bench-scenes.py" "${work}" --max-spheres 100000 --max-triangles 1000000

median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
render_ms() {  # scene engine
    "${cli}" render "$1" -o "${work}/out.exr" --threads "${threads}" --stats --engine "$2" |
        sed -n 's/.*"ms": \([0-9.]*\),.*/\1/p'
}

scenes=("${root}"/scenes/*.scene.json "${work}/room-box.scene.json" "${work}/room-sphere-light.scene.json"
        "${work}/spheres-1000.scene.json" "${work}/spheres-100000.scene.json"
        "${work}/mesh-1000000.scene.json" "${work}/mesh-1000000-primary.scene.json")
printf '| scene (1280x720, %d threads) | embree ms | builtin ms | builtin / embree |\n' "${threads}"
printf '|---|---|---|---|\n'
for scene in "${scenes[@]}"; do
    : >"${work}/e" >"${work}/b"
    for ((i = 1; i <= runs; i++)); do
        render_ms "${scene}" embree >>"${work}/e"
        render_ms "${scene}" builtin >>"${work}/b"
    done
    e="$(median <"${work}/e")"; b="$(median <"${work}/b")"
    printf '| %s | %.1f | %.1f | %.2f |\n' "$(basename "${scene}" .scene.json)" "${e}" "${b}" \
        "$(awk -v a="${b}" -v c="${e}" 'BEGIN{print a/c}')"
done
