#!/usr/bin/env bash
# RayStudio (primary rays + Lambert shading, the whole trace path) against Embree 3's
# rtcIntersect1 alone on the same camera rays of a 1,000,000-triangle mesh.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/compare-embree.sh [RUNS] [THREADS] [TRIANGLES]

Builds tests/bench/embree-primary.cpp (a few lines of Embree, no shading) into a temporary
folder, generates mesh-TRIANGLES-primary (default 1000000; tests/bench/make-bench-scenes.py),
and alternates RUNS (default 7) timings of Embree's rtcIntersect1 over the 1280x720 camera
rays with raystudio-cli render --stats (depth 0, no shadows: camera rays, hits, Lambert
shading, image) at THREADS (default 2) threads. Prints the medians and their ratio.
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi
runs="${1:-7}"
threads="${2:-2}"
triangles="${3:-1000000}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${root}/build/release/app/raystudio-cli"
[[ -x "${cli}" ]] || { echo "compare-embree.sh: ${cli} not built" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python3 "${root}/tests/bench/make-bench-scenes.py" "${work}" --max-spheres 10 --max-triangles "${triangles}"
# The release preset's optimisation flags (CMAKE_BUILD_TYPE Release: -O3 -DNDEBUG), so neither
# side is built with less; the yardstick's time is Embree's library code either way.
c++ -O3 -DNDEBUG -std=c++17 -o "${work}/embree-primary" "${root}/tests/bench/embree-primary.cpp" -lembree3 -ltbb

median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
: >"${work}/em" >"${work}/rs"
for ((i = 1; i <= runs; i++)); do
    # Embree's first run includes its warm-up; take the second of each pair.
    "${work}/embree-primary" "${work}/mesh-${triangles}.obj" "${threads}" 2 | tail -1 | awk '{print $1}' >>"${work}/em"
    "${cli}" render "${work}/mesh-${triangles}-primary.scene.json" -o "${work}/rs.exr" --threads "${threads}" \
        --stats | sed -n 's/.*"ms": \([0-9.]*\),.*/\1/p' >>"${work}/rs"
done
em="$(median <"${work}/em")"; rs="$(median <"${work}/rs")"
printf '%d-triangle mesh, 1280x720 primary rays, %d threads, median of %d interleaved runs\n' \
    "${triangles}" "${threads}" "${runs}"
# Other work on the machine skews both sides; the load average says how much there was.
printf '  load average before %s, after %s\n' "${load_before}" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '  Embree rtcIntersect1 alone   %8.1f ms\n' "${em}"
printf '  RayStudio, shaded image      %8.1f ms   (Embree / RayStudio = %.2f)\n' "${rs}" \
    "$(awk -v a="${em}" -v b="${rs}" 'BEGIN{print a/b}')"
