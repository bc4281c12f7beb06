#!/usr/bin/env bash
# The thesis's chapter 4.2 cost table for interaction policies: one drag per policy file.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/policy-table.sh [OBJECT] [TO] [STEPS]

Drags OBJECT (default "glass ball") of scenes/reference-room.scene.json to TO (default
0.3,1.0,-4.6) in STEPS (default 20) steps with raystudio-cli drag, once per policy in
tests/bench/policies/, and prints median step time, traced fraction, refinement time and
the refined frame's difference to a full render (1280x720, 2 threads).
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi
object="${1:-glass ball}"
to="${2:-0.3,1.0,-4.6}"
steps="${3:-20}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${root}/build/release/app/raystudio-cli"
[[ -x "${cli}" ]] || { echo "policy-table.sh: ${cli} not built" >&2; exit 1; }

printf '%-20s %10s %10s %10s %10s %10s\n' policy step_ms traced_% refine_ms full_ms max_diff
for policy in "${root}"/tests/bench/policies/*.json; do
    json="$("${cli}" drag "${root}/scenes/reference-room.scene.json" --object "${object}" --to "${to}" \
        --steps "${steps}" --threads 2 --policy "${policy}" --json)"
    python3 - "$(basename "${policy}" .json)" "${json}" <<'PY'
import json, sys
name, d = sys.argv[1], json.loads(sys.argv[2])
print(f"{name:<20} {d['step_ms_median']:10.2f} {100 * d['traced_fraction_median']:10.2f} "
      f"{d['refine_ms']:10.2f} {d['full_frame_ms']:10.2f} {d['final_max_abs_diff']:10.2g}")
PY
done
