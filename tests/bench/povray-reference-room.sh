#!/usr/bin/env bash
# Times POV-Ray 3.7 on the reference room (1280x720, no antialiasing, 2 threads): our yardstick.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/povray-reference-room.sh [RUNS]

Renders the POV-Ray twin of scenes/reference-room.scene.json (written by
tests/oracle/scene_to_pov.py) RUNS times (default 5) with
  povray +W1280 +H720 -D -A +WT2
and prints each wall time and the median in milliseconds. Needs the Debian 'povray' package.
Antialiasing is off with -A: POV-Ray 3.7 rejects "+A0" as an option, and +A<threshold> would
turn antialiasing on.
USAGE
}

if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then
    usage
    exit 0
fi
runs="${1:-5}"
[[ "${runs}" =~ ^[1-9][0-9]*$ ]] || { usage >&2; exit 2; }
command -v povray >/dev/null 2>&1 || {
    echo "povray-reference-room.sh: povray not found (apt-get install povray)" >&2
    exit 1
}

script_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
scene="${work}/reference-room.pov"
python3 "${script_dir}/../oracle/scene_to_pov.py" "${script_dir}/../../scenes/reference-room.scene.json" \
    "${scene}" --width 1280 --height 720

times=()
for ((i = 1; i <= runs; i++)); do
    start="$(date +%s%N)"
    if ! povray +W1280 +H720 -D -A +WT2 "+O${work}/reference-room.png" "${scene}" \
        >"${work}/povray.log" 2>&1; then
        echo "povray failed; its log:" >&2
        cat "${work}/povray.log" >&2
        exit 1
    fi
    end="$(date +%s%N)"
    ms=$(((end - start) / 1000000))
    times+=("${ms}")
    echo "run ${i}: ${ms} ms"
done

# Wall time includes parsing and writing the PNG, as a user of either program would see it.
mapfile -t sorted < <(printf '%s\n' "${times[@]}" | sort -n)
if ((runs % 2 == 1)); then
    median="${sorted[runs / 2]}"
else
    median=$(((sorted[runs / 2 - 1] + sorted[runs / 2]) / 2))
fi
echo "median of ${runs} runs: ${median} ms"
