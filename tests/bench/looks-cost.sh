#!/usr/bin/env bash
# What patterns, textures and the sky cost: each scene against the same scene in flat colours,
# alternated runs, medians and their ratio from one run.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/bench/looks-cost.sh [--povray] [RUNS] [THREADS]

Renders each scene in RUNS (default 5) processes, alternating A B A B, THREADS (default 2)
threads. Each process is \`raystudio-cli bench --baseline-only --repeat 3\` and gives the median of its three
baseline renders (loading excluded): the texture cache warm, as in the designer, where tiles
stay cached from frame to frame. Prints one line per pair:

  classic   scenes/classic.scene.json (checkered floor, glass and mirror balls, HDR sky)
            against the same scene with each checker replaced by its mean colour and the
            sky by the background colour
  textured  the reference room with a 4096 x 4096 image texture on every material
            (8-bit PNG, made here with oiiotool) against the reference room as it is
  one-texel the reference room with a 1 x 1 image on every material against the room as it
            is: what texturing costs before any texel comes from memory (texture
            coordinates, footprints, the filter's arithmetic, colours per point), the floor
            under the textured line

With --povray (needs Debian's povray), POV-Ray 3.7 renders the twins of the same pairs
(tests/oracle/scene_to_pov.py; one sample a pixel, its own "Trace Time") alternated the same
way, for an independent tracer's price of the same looks:

  povray-classic    the classic pair
  povray-textured   the reference room with the 4096 x 4096 image on every material but the
                    glass (a textured glass's filtered shadow has no POV-Ray twin), against
                    the room as it is; textured-opaque is RayStudio's time for that pair

Each line: name, flat median ms, patterned median ms, ratio (patterned / flat).
Needs a release build (bash packaging/setup.sh test), python3 and oiiotool (Debian's
openimageio-tools).
USAGE
}
povray=0
args=()
for a in "$@"; do
    case "${a}" in
        -h | --help) usage; exit 0 ;;
        --povray) povray=1 ;;
        *) args+=("${a}") ;;
    esac
done
runs="${args[0]:-5}"
threads="${args[1]:-2}"
((${#args[@]} <= 2)) || { usage >&2; exit 2; }
[[ "${runs}" =~ ^[1-9][0-9]*$ && "${threads}" =~ ^[1-9][0-9]*$ ]] || { usage >&2; exit 2; }
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${root}/build/release/app/raystudio-cli"
[[ -x "${cli}" ]] || { echo "looks-cost.sh: ${cli} not built (bash packaging/setup.sh test)" >&2; exit 1; }
command -v oiiotool >/dev/null 2>&1 || { echo "looks-cost.sh: oiiotool not found (apt-get install openimageio-tools)" >&2; exit 1; }
if ((povray)); then
    command -v povray >/dev/null 2>&1 || { echo "looks-cost.sh: povray not found (apt-get install povray)" >&2; exit 1; }
fi
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT

# A 4096 x 4096 8-bit texture with detail at every scale: a colour ramp under noise.
oiiotool --pattern fill:topleft=0.9,0.2,0.1:topright=0.1,0.8,0.2:bottomleft=0.1,0.2,0.9:bottomright=0.9,0.9,0.2 4096x4096 3 \
    --pattern noise:type=uniform:min=0.7:max=1 4096x4096 3 --mul -d uint8 -o "${work}/big.png"
oiiotool --pattern constant:color=0.6,0.5,0.4 1x1 3 -d uint8 -o "${work}/one.png"

python3 - "${root}" "${work}" <<'PY'
import json, os, sys
root, work = sys.argv[1], sys.argv[2]
scenes = os.path.join(root, "scenes")

def load(name):
    with open(os.path.join(scenes, name)) as f:
        return json.load(f)

def save(doc, name):
    # Paths in the copies are absolute: they live in a scratch folder.
    with open(os.path.join(work, name), "w") as f:
        json.dump(doc, f, indent=1)

classic = load("classic.scene.json")
if "environment" in classic:
    classic["environment"]["file"] = os.path.join(scenes, classic["environment"]["file"])
save(classic, "classic.scene.json")
flat = json.loads(json.dumps(classic))
flat.pop("environment", None)
for m in flat["materials"]:
    c = m.get("color")
    if isinstance(c, dict) and "checker" in c:
        a, b = c["checker"]
        m["color"] = [(x + y) / 2 for x, y in zip(a, b)]
save(flat, "classic-flat.scene.json")

room = load("reference-room.scene.json")
save(room, "room.scene.json")
textured = json.loads(json.dumps(room))
textured["version"] = 2
for m in textured["materials"]:
    m["color"] = {"texture": os.path.join(work, "big.png"), "scale": [2, 2]}
save(textured, "room-textured.scene.json")
one = json.loads(json.dumps(room))
one["version"] = 2
for m in one["materials"]:
    m["color"] = {"texture": os.path.join(work, "one.png")}
save(one, "room-one-texel.scene.json")
opaque = json.loads(json.dumps(room))
opaque["version"] = 2
for m in opaque["materials"]:
    if m.get("transparency", 0) == 0:
        m["color"] = {"texture": os.path.join(work, "big.png"), "scale": [2, 2]}
save(opaque, "room-textured-opaque.scene.json")
PY

median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
render_ms() {  # scene
    "${cli}" bench "$1" --baseline-only --repeat 3 --threads "${threads}" | awk '$1 == "baseline" {print $3}'
}
# POV-Ray's own trace time of the twin of a scene, in ms (1280x720, one sample a pixel).
povray_ms() {  # scene
    local pov="${1%.scene.json}.pov"
    [[ -f "${pov}" ]] || python3 "${root}/tests/oracle/scene_to_pov.py" "$1" "${pov}" --width 1280 --height 720
    povray +W1280 +H720 -D -A "+WT${threads}" "+O${work}/pov.png" "${pov}" >"${work}/pov.log" 2>&1 ||
        { cat "${work}/pov.log" >&2; exit 1; }
    sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "${work}/pov.log" | awk '{print $1 * 1000}'
}
pair() {  # name flat patterned [timer]
    local timer="${4:-render_ms}"
    : >"${work}/a" >"${work}/b"
    for ((i = 1; i <= runs; i++)); do
        "${timer}" "$2" >>"${work}/a"
        "${timer}" "$3" >>"${work}/b"
    done
    local a b
    a="$(median <"${work}/a")"
    b="$(median <"${work}/b")"
    printf '%-9s flat %8.1f ms   patterned %8.1f ms   ratio %5.2f\n' "$1" "${a}" "${b}" \
        "$(awk -v a="${a}" -v b="${b}" 'BEGIN{print b/a}')"
}
echo "looks-cost: 1280x720, ${threads} threads, median of ${runs} alternated runs"
pair classic "${work}/classic-flat.scene.json" "${work}/classic.scene.json"
pair textured "${work}/room.scene.json" "${work}/room-textured.scene.json"
pair one-texel "${work}/room.scene.json" "${work}/room-one-texel.scene.json"
if ((povray)); then
    pair textured-opaque "${work}/room.scene.json" "${work}/room-textured-opaque.scene.json"
    pair povray-classic "${work}/classic-flat.scene.json" "${work}/classic.scene.json" povray_ms
    pair povray-textured "${work}/room.scene.json" "${work}/room-textured-opaque.scene.json" povray_ms
fi
