#!/usr/bin/env bash
# Mutation check, run by hand: applies deliberate bugs one at a time to the source, rebuilds
# the test binaries in build/release, runs the unit, image and POV-Ray oracle tests and shows
# which of them fail. Every mutation must make some test fail ("caught"). The source is
# restored after each mutation (also on Ctrl+C), and the binaries rebuilt at the end.
set -euo pipefail

usage() {
    cat <<USAGE
Usage: bash tests/mutation/run-mutations.sh [NAME...]

Mutations (all by default):
  phong-sign      the Phong term reflects L with the wrong sign (light_sampling.cpp)
  schlick-r0      Schlick's R0 is ((1 - ior) / (2 + ior))^2 (whitted.h)
  no-shadow-ray   shadow rays are not traced: every light sample counts as visible (trace_kernel.cpp)
  short-footprint a dirty footprint one pixel short on the right (dirty_region.cpp): the
                  footprint's one-pixel margin and the mask's growth to the 8 neighbours
                  both used up, so the marked set misses the last column the object covers
  stale-tile      a tile traced for an older generation is written to the frame (session_tiles.cpp)
Needs a configured release build (bash packaging/setup.sh test); the oracle tests need povray.
Prints one line per mutation: caught (N tests failed, the first few named) or MISSED.
Takes 2-6 minutes per mutation on two cores (a rebuild of what the file touches, then the tests).
USAGE
}
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then usage; exit 0; fi

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${root}/build/release"
[[ -f "${build}/build.ninja" ]] || { echo "run-mutations.sh: ${build} is not configured" >&2; exit 1; }

# name|file|exact text|replacement
mutations=(
    "phong-sign|render/integrator/light_sampling.cpp|glm::dot(2.0f * s.nl * n - s.dir, toViewer)|glm::dot(2.0f * s.nl * n + s.dir, toViewer)"
    "schlick-r0|render/integrator/whitted.h|float r0 = (1.0f - ior) / (1.0f + ior);|float r0 = (1.0f - ior) / (2.0f + ior);"
    "no-shadow-ray|render/integrator/trace_kernel.cpp|            scene_.engine().anyHit(ws.shadowBatch(area), ws.occluded.data());|            std::fill(ws.occluded.begin(), ws.occluded.end(), uint8_t(0));"
    "short-footprint|render/session/dirty_region.cpp|r.x1 = std::min(camera.width(), int(std::floor(maxX)) + 2);|r.x1 = std::min(camera.width(), int(std::floor(maxX)) - 1);"
    "stale-tile|render/session/session_tiles.cpp|        if (generation_.load() != plan.generation) return;  // Never write a stale tile.|        // (mutation: the generation check is gone)"
)

targets=(raystudio_unit_tests raystudio_image_tests)
binaries=("${build}/tests/raystudio_unit_tests" "${build}/tests/raystudio_image_tests")
if [[ -f "${build}/tests/oracle/CTestTestfile.cmake" ]]; then
    targets+=(raystudio_oracle_tests)
    binaries+=("${build}/tests/oracle/raystudio_oracle_tests")
fi

backup=""
restore() {
    if [[ -n "${backup}" ]]; then
        cp "${backup}" "${root}/${current_file}"
        rm -f "${backup}"
        backup=""
    fi
}
trap 'restore' EXIT INT TERM

selected=("$@")
log="$(mktemp -d)"
results=()
for entry in "${mutations[@]}"; do
    IFS='|' read -r name current_file from to <<<"${entry}"
    if ((${#selected[@]})) && [[ " ${selected[*]} " != *" ${name} "* ]]; then continue; fi
    backup="$(mktemp)"
    cp "${root}/${current_file}" "${backup}"
    python3 - "${root}/${current_file}" "${from}" "${to}" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
if text.count(old) != 1:
    sys.exit("run-mutations.sh: %s: the text to mutate occurs %d times" % (path, text.count(old)))
open(path, "w").write(text.replace(old, new))
PY
    echo "==> ${name}: building" >&2
    if ! cmake --build "${build}" -j "${CMAKE_BUILD_PARALLEL_LEVEL:-1}" --target "${targets[@]}" >"${log}/${name}.build" 2>&1; then
        results+=("| ${name} | does not compile | |")
        restore
        continue
    fi
    echo "==> ${name}: testing" >&2
    failed=()
    for bin in "${binaries[@]}"; do
        "${bin}" >"${log}/${name}.$(basename "${bin}")" 2>&1 || true
        mapfile -t names < <(sed -n 's/^\[  FAILED  \] \([^ ,]*\.[^ ,]*\).*/\1/p' "${log}/${name}.$(basename "${bin}")" | sort -u)
        failed+=("${names[@]}")
    done
    restore
    if ((${#failed[@]})); then
        results+=("| ${name} | caught: ${#failed[@]} tests fail | $(printf '%s ' "${failed[@]:0:4}")|")
    else
        results+=("| ${name} | MISSED | |")
    fi
    echo "${results[-1]}" >&2
done
echo "==> rebuilding the unmutated tree" >&2
cmake --build "${build}" -j "${CMAKE_BUILD_PARALLEL_LEVEL:-1}" --target "${targets[@]}" >"${log}/final.build" 2>&1
echo "| mutation | result | first failing tests |"
echo "|---|---|---|"
printf '%s\n' "${results[@]}"
echo "(logs in ${log})" >&2
