#!/usr/bin/env bash
# `setup.sh test` (CI's command) must fail when a stage's build fails. Each stage runs as
# `stage || status=$?`, where bash ignores `set -e`, so a failed build used to leave stale
# or missing tests that ctest then "passed" ("No tests were found!!!" exits 0).
#
#   bash tests/packaging/setup_stages_test.sh SETUP_SH
#
# Runs a copy of SETUP_SH in a scratch tree with cmake, ctest and dpkg-query replaced by
# stand-ins that record their calls: the build of one stage (tsan, then asan) fails, and
# the script must exit non-zero naming that stage without running the later ones.
set -euo pipefail
setup="$1"
scratch="$(mktemp -d)"
trap 'rm -rf "${scratch}"' EXIT

mkdir -p "${scratch}/repo/packaging" "${scratch}/bin" "${scratch}/repo/build/release" \
    "${scratch}/repo/build/fuzz/tests/fuzz" "${scratch}/repo/tests/cluster"
printf 'exit 0\n' >"${scratch}/repo/tests/cluster/slurm_farm_test.sh"  # A farm that works.
cp "${setup}" "${scratch}/repo/packaging/setup.sh"
touch "${scratch}/repo/build/release/CMakeCache.txt" "${scratch}/repo/build/release/build.ninja"
for target in scene_reader mesh_loader; do  # Fuzzers that find nothing.
    printf '#!/bin/sh\nexit 0\n' >"${scratch}/repo/build/fuzz/tests/fuzz/${target}_fuzz"
    chmod +x "${scratch}/repo/build/fuzz/tests/fuzz/${target}_fuzz"
done
cat >"${scratch}/bin/cmake" <<'STUB'
#!/bin/sh
echo "cmake $*" >>"${STAGES_LOG}"
case "$*" in *"--build --preset ${FAILING_BUILD}"*) exit 7 ;; esac
exit 0
STUB
cat >"${scratch}/bin/ctest" <<'STUB'
#!/bin/sh
echo "ctest $*" >>"${STAGES_LOG}"
exit 0
STUB
printf '#!/bin/sh\necho installed\n' >"${scratch}/bin/dpkg-query"
chmod +x "${scratch}/bin/"*

fail=0
check() {  # check STAGE MESSAGE LATER: LATER is the next stage's first call
    local stage="$1" message="$2" later="$3" status=0
    : >"${scratch}/log"
    env PATH="${scratch}/bin:${PATH}" STAGES_LOG="${scratch}/log" FAILING_BUILD="${stage}" \
        bash "${scratch}/repo/packaging/setup.sh" test >"${scratch}/out" 2>&1 || status=$?
    if ((status == 0)); then
        echo "FAIL: setup.sh test exited 0 although the ${stage} build failed" >&2
        fail=1
    elif ! grep -q "${message}" "${scratch}/out"; then
        echo "FAIL: a failed ${stage} build did not say '${message}':" >&2
        cat "${scratch}/out" >&2
        fail=1
    elif grep -q -e "ctest --preset ${stage}" -e "${later}" "${scratch}/log"; then
        echo "FAIL: after the failed ${stage} build, its tests or a later stage ran:" >&2
        cat "${scratch}/log" >&2
        fail=1
    else
        echo "ok: a failed ${stage} build fails setup.sh test (exit ${status})"
    fi
}
check tsan "ThreadSanitizer tests failed" "cmake --preset fuzz"
check asan "ASan + UBSan tests failed" "ctest --preset release"
exit "${fail}"
