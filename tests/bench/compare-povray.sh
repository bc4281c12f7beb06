#!/usr/bin/env bash
# RayStudio against POV-Ray 3.7 on the reference room, interleaved runs, medians from one run.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/compare-povray.sh [RUNS] [THREADS] [SCENE.scene.json SCENE.pov]

Alternates RUNS (default 7) renders of the reference room at 1280x720 (depth 3, 1 shadow
sample, no antialiasing) by POV-Ray (the twin tests/oracle/scene_to_pov.py writes) and by
raystudio-cli (scenes/reference-room.scene.json), THREADS (default 2) threads each, and prints
medians. Another scene may be named instead; its twin is written the same way unless a .pov
is named too (make-bench-scenes.py writes spheres-N ones):
  render  POV-Ray's own "Trace Time" vs raystudio-cli --stats "ms" (loading excluded)
  wall    whole process, start to exit, image written (both)
Needs the Debian 'povray' package and a release build (bash packaging/setup.sh test).
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi
runs="${1:-7}"
threads="${2:-2}"
scene_json="${3:-}"
scene_pov="${4:-}"
[[ "${runs}" =~ ^[1-9][0-9]*$ && "${threads}" =~ ^[1-9][0-9]*$ ]] || { usage >&2; exit 2; }
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${root}/build/release/app/raystudio-cli"
command -v povray >/dev/null 2>&1 || { echo "compare-povray.sh: povray not found (apt-get install povray)" >&2; exit 1; }
[[ -x "${cli}" ]] || { echo "compare-povray.sh: ${cli} not built" >&2; exit 1; }
work="$(mktemp -d)"
scene_json="${scene_json:-${root}/scenes/reference-room.scene.json}"
trap 'rm -rf "${work}"' EXIT
if [[ -z "${scene_pov}" ]]; then
    scene_pov="${work}/twin.pov"
    python3 "${root}/tests/oracle/scene_to_pov.py" "${scene_json}" "${scene_pov}" --width 1280 --height 720
fi

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

: >"${work}/pov_trace" >"${work}/pov_wall" >"${work}/rs_render" >"${work}/rs_wall"
for ((i = 1; i <= runs; i++)); do
    t0="$(now_ms)"
    povray +W1280 +H720 -D -A "+WT${threads}" "+O${work}/pov.png" "${scene_pov}" \
        >"${work}/pov.log" 2>&1 || { cat "${work}/pov.log" >&2; exit 1; }
    t1="$(now_ms)"
    echo $((t1 - t0)) >>"${work}/pov_wall"
    sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "${work}/pov.log" | awk '{print $1 * 1000}' >>"${work}/pov_trace"
    t0="$(now_ms)"
    "${cli}" render "${scene_json}" -o "${work}/rs.png" --threads "${threads}" --stats \
        >"${work}/rs.json"
    t1="$(now_ms)"
    echo $((t1 - t0)) >>"${work}/rs_wall"
    sed -n 's/.*"ms": \([0-9.]*\),.*/\1/p' "${work}/rs.json" >>"${work}/rs_render"
done
pt="$(median <"${work}/pov_trace")"; pw="$(median <"${work}/pov_wall")"
rr="$(median <"${work}/rs_render")"; rw="$(median <"${work}/rs_wall")"
printf '%s 1280x720, %d threads, median of %d interleaved runs\n' "$(basename "${scene_json}" .scene.json)" "${threads}" "${runs}"
printf '  render  POV-Ray %8.1f ms   RayStudio %7.1f ms   speed-up %5.1fx\n' "${pt}" "${rr}" "$(awk -v a="${pt}" -v b="${rr}" 'BEGIN{print a/b}')"
printf '  wall    POV-Ray %8.1f ms   RayStudio %7.1f ms   speed-up %5.1fx\n' "${pw}" "${rw}" "$(awk -v a="${pw}" -v b="${rw}" 'BEGIN{print a/b}')"
