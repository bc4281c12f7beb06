#!/usr/bin/env bash
# setup.sh's stages, with stand-ins for the tools they call: `setup.sh test` (CI's command)
# must fail when a stage's build fails, when the formatting check fails (before building
# anything) and when the mutation check fails; format-check, format and mutate run alone.
# Each stage runs as `stage || status=$?`, where bash ignores `set -e`, so a failed build
# used to leave stale or missing tests that ctest then "passed" ("No tests were found!!!"
# exits 0).
#
#   bash tests/packaging/setup_stages_test.sh SETUP_SH
#
# Runs a copy of SETUP_SH in a scratch tree with cmake, ctest, dpkg-query, git, clang-format
# and the mutation script replaced by stand-ins that record their calls.
set -euo pipefail
setup="$1"
scratch="$(mktemp -d)"
trap 'rm -rf "${scratch}"' EXIT

mkdir -p "${scratch}/repo/packaging" "${scratch}/bin" "${scratch}/repo/build/release" \
    "${scratch}/repo/build/fuzz/tests/fuzz" "${scratch}/repo/tests/cluster" \
    "${scratch}/repo/tests/mutation"
printf 'exit 0\n' >"${scratch}/repo/tests/cluster/slurm_farm_test.sh"  # A farm that works.
# A mutation check that records its arguments and exits with MUTATIONS_STATUS.
printf 'echo "mutations${*:+ $*}" >>"${STAGES_LOG}"\nexit "${MUTATIONS_STATUS:-0}"\n' \
    >"${scratch}/repo/tests/mutation/run-mutations.sh"
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
# A checkout of two C++ files and a new one not yet added (git lists it with --others, and
# with --exclude-standard only if it is not ignored).
cat >"${scratch}/bin/git" <<'STUB'
#!/bin/sh
case "$1" in
    rev-parse) exit 0 ;;
    ls-files)
        printf 'render/a.cpp\0render/b.h\0'
        case "$*" in *--others*) printf 'render/c.cpp\0' ;; esac ;;
    *) echo "git stand-in: unexpected git $*" >&2; exit 2 ;;
esac
STUB
# clang-format: UNFORMATTED names the file --dry-run --Werror finds unformatted.
cat >"${scratch}/bin/clang-format" <<'STUB'
#!/bin/sh
echo "clang-format $*" >>"${STAGES_LOG}"
[ "$1" = --version ] && { echo "clang-format stand-in"; exit 0; }
if [ "$1" = --dry-run ] && [ -n "${UNFORMATTED}" ]; then
    echo "${UNFORMATTED}:3:1: error: code should be clang-formatted [-Wclang-format-violations]" >&2
    exit 1
fi
exit 0
STUB
printf '#!/bin/sh\necho installed\n' >"${scratch}/bin/dpkg-query"
chmod +x "${scratch}/bin/"*

fail=0
status=0
# run_setup ARGS...: runs the copy with the stand-ins; its output in out, the calls in log.
run_setup() {
    status=0
    : >"${scratch}/log"
    env PATH="${scratch}/bin:${PATH}" STAGES_LOG="${scratch}/log" \
        FAILING_BUILD="${FAILING_BUILD:-none}" UNFORMATTED="${UNFORMATTED:-}" \
        MUTATIONS_STATUS="${MUTATIONS_STATUS:-0}" \
        bash "${scratch}/repo/packaging/setup.sh" "$@" >"${scratch}/out" 2>&1 || status=$?
}
flunk() {
    echo "FAIL: $*" >&2
    echo "--- output:" >&2
    cat "${scratch}/out" >&2
    echo "--- calls:" >&2
    cat "${scratch}/log" >&2
    fail=1
}

check_failed_build() {  # check_failed_build STAGE MESSAGE LATER: LATER is the next stage's first call
    local stage="$1" message="$2" later="$3"
    FAILING_BUILD="${stage}" run_setup test
    if ((status == 0)); then
        flunk "setup.sh test exited 0 although the ${stage} build failed"
    elif ! grep -q "${message}" "${scratch}/out"; then
        flunk "a failed ${stage} build did not say '${message}'"
    elif grep -q -e "ctest --preset ${stage}" -e "${later}" -e "^mutations" "${scratch}/log"; then
        flunk "after the failed ${stage} build, its tests or a later stage ran"
    else
        echo "ok: a failed ${stage} build fails setup.sh test (exit ${status})"
    fi
}
check_failed_build tsan "ThreadSanitizer tests failed" "cmake --preset fuzz"
check_failed_build asan "ASan + UBSan tests failed" "ctest --preset release"

# Everything passes: the formatting is checked before any build, the quick mutations run
# after the suite, and the run passes.
run_setup test
if ((status != 0)); then
    flunk "setup.sh test failed although every stage passed"
elif ! sed -n '/^clang-format --dry-run --Werror/,$p' "${scratch}/log" | grep -q '^cmake' ||
    sed -n '/^clang-format --dry-run --Werror/q;p' "${scratch}/log" | grep -q '^cmake'; then
    flunk "the formatting was not checked before the builds"
elif ! grep -q -- '--dry-run --Werror render/a.cpp render/b.h render/c.cpp' "${scratch}/log"; then
    flunk "the formatting check did not take the files git tracks and the new ones"
elif ! sed -n '/^ctest --preset release/,$p' "${scratch}/log" | grep -qx 'mutations --quick'; then
    flunk "setup.sh test did not run the quick mutations after the test suite"
else
    echo "ok: setup.sh test checks the formatting first and runs the quick mutations last"
fi

# An unformatted file fails setup.sh test before anything is built, naming the file.
UNFORMATTED=render/b.h run_setup test
if ((status == 0)); then
    flunk "setup.sh test exited 0 with an unformatted file"
elif ! grep -q 'render/b.h' "${scratch}/out" || grep -q 'render/a.cpp' "${scratch}/out"; then
    flunk "the failed formatting check did not name render/b.h (and only it)"
elif grep -q -e '^cmake' -e '^ctest' -e '^mutations' "${scratch}/log"; then
    flunk "setup.sh test built or tested after the formatting check failed"
else
    echo "ok: an unformatted file fails setup.sh test before any build (exit ${status})"
fi

# A missed mutation fails setup.sh test.
MUTATIONS_STATUS=1 run_setup test
if ((status == 0)); then
    flunk "setup.sh test exited 0 although the mutation check failed"
elif ! grep -q 'mutation check failed' "${scratch}/out"; then
    flunk "a failed mutation check did not say 'mutation check failed'"
else
    echo "ok: a failed mutation check fails setup.sh test (exit ${status})"
fi

# format-check alone: fails naming the file, passes when all are formatted, builds nothing.
UNFORMATTED=render/a.cpp run_setup format-check
if ((status == 0)) || ! grep -q 'render/a.cpp' "${scratch}/out"; then
    flunk "setup.sh format-check did not fail naming render/a.cpp"
else
    run_setup format-check
    if ((status != 0)) || grep -q -e '^cmake' -e '^ctest' "${scratch}/log"; then
        flunk "setup.sh format-check failed on formatted files, or built something"
    else
        echo "ok: setup.sh format-check fails naming the unformatted file, passes on formatted ones"
    fi
fi

# format rewrites the files git tracks, and new ones, in place, and builds nothing.
run_setup format
if ((status != 0)) || ! grep -qx 'clang-format -i render/a.cpp render/b.h render/c.cpp' "${scratch}/log" ||
    grep -q -e '^cmake' -e '^ctest' "${scratch}/log"; then
    flunk "setup.sh format did not run clang-format -i on the tracked and new files alone"
else
    echo "ok: setup.sh format runs clang-format -i on the files git tracks and new ones"
fi

# mutate builds the release tree, then runs the named mutations; their failure is its own.
run_setup mutate stale-tile schlick-r0
if ((status != 0)); then
    flunk "setup.sh mutate failed although the mutation check passed"
elif ! grep -q 'cmake --build --preset release' "${scratch}/log" ||
    [[ "$(tail -n 1 "${scratch}/log")" != "mutations stale-tile schlick-r0" ]]; then
    flunk "setup.sh mutate did not build the release tree and then run the named mutations"
else
    MUTATIONS_STATUS=3 run_setup mutate
    if ((status == 0)) || [[ "$(tail -n 1 "${scratch}/log")" != "mutations" ]]; then
        flunk "setup.sh mutate (all mutations) did not fail when the mutation check failed"
    else
        echo "ok: setup.sh mutate builds, runs the named (or all) mutations and fails with them"
    fi
fi
run_setup mutate 'stale-tile;true'
if ((status == 0)) || grep -q '^mutations' "${scratch}/log"; then
    flunk "setup.sh mutate took a name that is not a mutation's"
else
    echo "ok: setup.sh mutate refuses a name that is not a mutation's"
fi
exit "${fail}"
