#!/usr/bin/env bash
# A whole session frame against a renderImage frame, scene by scene: one table.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/session-frame.sh [FRAMES] [THREADS]

For each scene, runs raystudio-cli drag (a short drag of one object, 4 steps) with --frames
FRAMES (default 15) and THREADS (default 2) threads, and prints as a Markdown table what it
reports of whole frames: FRAMES session frames (camera nudges that re-trace every pixel)
interleaved with as many renderImage frames of the same scene and size, the median CPU time
of each (the process's, all threads), their ratio, and what the session adds per pixel.
Scenes: scenes/*.scene.json, then the generated ones of tests/bench/make-bench-scenes.py
(room plus a box, room with a 16-sample sphere light, 1,000 spheres, a 1,000,000-triangle
mesh). Needs a release build (bash packaging/setup.sh test).
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi
frames="${1:-15}"
threads="${2:-2}"
[[ "${frames}" =~ ^[1-9][0-9]*$ && "${threads}" =~ ^[1-9][0-9]*$ ]] || { usage >&2; exit 2; }
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${root}/build/release/app/raystudio-cli"
[[ -x "${cli}" ]] || { echo "session-frame.sh: ${cli} not built" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python3 "${root}/tests/bench/make-bench-scenes.py" "${work}" --max-spheres 1000 --max-triangles 1000000

# Each scene with the object dragged and where to (its centre moved a little; the session
# frames come after the drag, in the scene as the drag left it). No target: the sphere's
# centre, 0.3 along x.
runs=(
    "${root}/scenes/reference-room.scene.json|blue ball|0.3,1.0,-4.6"
    "${root}/scenes/glass-and-mirrors.scene.json|gold ball|2.6,0.5,-1.0"
    "${root}/scenes/mesh.scene.json|red ball|-2.2,0.6,0.9"
    "${root}/scenes/soft-shadows.scene.json|small ball|1.0,0.4,1.4"
    "${work}/room-box.scene.json|blue ball|0.3,1.0,-4.6"
    "${work}/room-sphere-light.scene.json|blue ball|0.3,1.0,-4.6"
    "${work}/spheres-1000.scene.json|ball 1|"
    "${work}/mesh-1000000.scene.json|mesh|1.5,1.2,0"
)

printf '| scene (1280x720, %d threads, medians of %d) | session frame CPU ms | renderImage CPU ms | ratio | session adds, ns a pixel |\n' \
    "${threads}" "${frames}"
printf '|---|---|---|---|---|\n'
for run in "${runs[@]}"; do
    IFS='|' read -r scene object to <<<"${run}"
    if [[ -z "${to}" ]]; then
        to="$(python3 -c 'import json, sys
o = [o for o in json.load(open(sys.argv[1]))["objects"] if o["name"] == sys.argv[2]][0]
print("%g,%g,%g" % (o["center"][0] + 0.3, o["center"][1], o["center"][2]))' "${scene}" "${object}")"
    fi
    "${cli}" drag "${scene}" --object "${object}" --to "${to}" --steps 4 --threads "${threads}" \
        --frames "${frames}" --json |
        python3 -c 'import json, sys
d = json.load(sys.stdin)
s, r = d["session_frame_cpu_ms"], d["render_image_cpu_ms"]
print("| %s | %.2f | %.2f | %.3f | %.1f |" % (sys.argv[1], s, r, s / r,
      (s - r) * 1e6 / d["steps"][0]["total_pixels"]))' "$(basename "${scene}" .scene.json)"
done
