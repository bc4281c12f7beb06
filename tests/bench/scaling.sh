#!/usr/bin/env bash
# The cost curve: N-sphere scenes (N = 10 ... 100,000) and meshes of 1e3 ... 1e6 triangles,
# ms and Mrays/s per N for each engine, and a plot of it.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/scaling.sh [RUNS] [THREADS] [PLOT.png]

For every generated scene (tests/bench/make-bench-scenes.py) and both engines, the median of
RUNS (default 3) raystudio-cli render --stats runs at THREADS (default 2) threads: prints
"kind N engine ms mrays_per_s" lines, and with gnuplot installed (apt-get install
gnuplot-nox) draws PLOT.png (default build/release/scaling.png).
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi
runs="${1:-3}"
threads="${2:-2}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
plot="${3:-${root}/build/release/scaling.png}"
[[ "${runs}" =~ ^[1-9][0-9]*$ && "${threads}" =~ ^[1-9][0-9]*$ ]] || { usage >&2; exit 2; }
cli="${root}/build/release/app/raystudio-cli"
[[ -x "${cli}" ]] || { echo "scaling.sh: ${cli} not built" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python3 "${root}/tests/bench/make-bench-scenes.py" "${work}"

median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
measure() {  # kind n scene
    for engine in embree builtin; do
        : >"${work}/ms" >"${work}/mr"
        for ((i = 1; i <= runs; i++)); do
            "${cli}" render "$3" -o "${work}/out.exr" --threads "${threads}" --stats --engine "${engine}" >"${work}/s.json"
            sed -n 's/.*"ms": \([0-9.]*\),.*/\1/p' "${work}/s.json" >>"${work}/ms"
            sed -n 's/.*"mrays_per_s": \([0-9.]*\)}.*/\1/p' "${work}/s.json" >>"${work}/mr"
        done
        printf '%s %s %s %s %s\n' "$1" "$2" "${engine}" "$(median <"${work}/ms")" "$(median <"${work}/mr")"
    done
}
{
    for n in 10 100 1000 10000 100000; do measure spheres "${n}" "${work}/spheres-${n}.scene.json"; done
    for n in 1000 10000 100000 1000000; do measure triangles "${n}" "${work}/mesh-${n}.scene.json"; done
} | tee "${work}/data.txt"
if command -v gnuplot >/dev/null 2>&1; then
    for k in spheres triangles; do
        for e in embree builtin; do awk -v k="$k" -v e="$e" '$1==k && $3==e {print $2, $4}' "${work}/data.txt" >"${work}/${k}-${e}.dat"; done
    done
    gnuplot <<GP
set terminal pngcairo size 900,420 font ",10"
set output "${plot}"
set multiplot layout 1,2 title "RayStudio render time, 1280x720, depth 3, ${threads} threads"
set logscale x
set xlabel "spheres"; set ylabel "ms"; set key top left
plot "${work}/spheres-embree.dat" w lp t "embree", "${work}/spheres-builtin.dat" w lp t "builtin (thesis BVH)"
set xlabel "mesh triangles"
plot "${work}/triangles-embree.dat" w lp t "embree", "${work}/triangles-builtin.dat" w lp t "builtin (thesis BVH)"
unset multiplot
GP
    echo "plot: ${plot}"
else
    echo "scaling.sh: gnuplot not found, no plot (apt-get install gnuplot-nox)" >&2
fi
