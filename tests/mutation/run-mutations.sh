#!/usr/bin/env bash
# Mutation check: puts deliberate bugs into the source one at a time, rebuilds what the tests
# that should catch each one need, runs only those tests and says whether they failed
# ("caught") or not ("MISSED"). Every mutation must be caught: a missed one is a weak test.
#
# Each mutation is a patch file next to this script, tests/mutation/NAME.patch: a few lines
# saying what behaviour it breaks and which tests must catch it, then a unified diff with
# context. A patch that no longer applies exactly (the code it breaks was moved or rewritten)
# is an error naming the mutation, never a silent skip: refresh the patch against the new code.
set -euo pipefail

# The subset `setup.sh test` (CI) runs: mutations of a source file that rebuilds in a few
# seconds, caught by tests that run in seconds (about 2 minutes in all on two cores). The
# others rebuild most of the engine (whitted.h, trace_kernel.cpp, light_sampling.cpp: 1-2
# minutes each) and run with `setup.sh mutate`. setup.sh --help shows this list.
readonly QUICK=(dirty-footprint refit-parent-box stale-tile tonemap-reinhard
    deferred-shadows-dropped interleave-one-half box-proxy-kept asset-material-rough-metal-mirror
    asset-light-own-position asset-camera-gltf-position-twice frame-shader-aces
    snapshot-highlight-cutoff cost-tree-levels dirty-light-radius)

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "${here}/../.." && pwd)"
build="${root}/build/release"

usage() {
    cat <<USAGE
Usage: bash tests/mutation/run-mutations.sh [--quick] [--build DIR] [--list] [NAME...]

Applies each mutation (tests/mutation/NAME.patch; all of them by default) to the source,
rebuilds the test targets it names in the release build (or DIR), runs the tests that must
catch it and restores the source (also on Ctrl+C or an error). Before the first mutation
the same tests run on the unmutated tree: they must pass, and each filter must name a test.

  --quick       only the subset CI runs (setup.sh test): ${QUICK[*]}
  --build DIR   the configured CMake build folder (default build/release)
  --list        print the mutations with what each breaks, and exit

Prints a table: mutation, file, result (caught / MISSED / does not apply / does not
compile), seconds of rebuild and of testing. Exits non-zero if any mutation was missed,
no longer applies or does not compile, or a catching test fails without a mutation.
CMAKE_BUILD_PARALLEL_LEVEL limits the build jobs.

Mutation file format: lines of prose (the first says what breaks), then one or more
  Catch: TARGET GTEST_FILTER   a gtest executable built by TARGET, run with that filter
  Catch: ctest REGEX           ctest -R REGEX (add Build: TARGET... for what it needs)
then the unified diff (--- a/FILE, +++ b/FILE), applied with patch -p1 --fuzz=0.
USAGE
}

die() {
    printf 'run-mutations.sh: error: %s\n' "$*" >&2
    exit 1
}

quick=0
list=0
selected=()
while (($#)); do
    case "$1" in
        -h | --help)
            usage
            exit 0
            ;;
        --quick) quick=1 ;;
        --list) list=1 ;;
        --build)
            (($# >= 2)) || die "--build needs a folder"
            build="$(cd "$2" && pwd)" || die "--build: no folder $2"
            shift
            ;;
        -*) die "unknown option '$1' (see --help)" ;;
        *) selected+=("$1") ;;
    esac
    shift
done
((quick)) && selected+=("${QUICK[@]}")

# ---- The mutation files -------------------------------------------------------------------
# describe FILE: sets m_what (first line), m_files (the files the diff changes), m_catch
# (the Catch: lines), m_build (the targets to rebuild).
describe() {
    local file="$1" line in_diff=0
    m_what="" m_files=() m_catch=() m_build=()
    while IFS= read -r line; do
        if [[ "${line}" == "--- "* ]]; then in_diff=1; fi
        if ((in_diff)); then
            [[ "${line}" == "+++ b/"* ]] && m_files+=("${line#+++ b/}")
            continue
        fi
        case "${line}" in
            "Catch: "*) m_catch+=("${line#Catch: }") ;;
            "Build: "*) read -r -a more <<<"${line#Build: }" && m_build+=("${more[@]}") ;;
            "") ;;
            *) [[ -n "${m_what}" ]] || m_what="${line}" ;;
        esac
    done <"${file}"
    local c target
    for c in "${m_catch[@]}"; do
        target="${c%% *}"
        [[ "${target}" == ctest ]] || m_build+=("${target}")
    done
    ((${#m_files[@]})) || die "${file}: no '+++ b/FILE' line: not a unified diff"
    ((${#m_catch[@]})) || die "${file}: no 'Catch:' line naming the tests that must catch it"
}

names=()
for file in "${here}"/*.patch; do
    [[ -e "${file}" ]] || continue
    name="$(basename "${file}" .patch)"
    if ((${#selected[@]})) && [[ " ${selected[*]} " != *" ${name} "* ]]; then continue; fi
    names+=("${name}")
done
for name in "${selected[@]}"; do
    [[ -f "${here}/${name}.patch" ]] || die "no mutation '${name}' (tests/mutation/${name}.patch)"
done
((${#names[@]})) || die "no mutations in ${here}"

if ((list)); then
    for name in "${names[@]}"; do
        describe "${here}/${name}.patch"
        printf '%-30s %s (%s)\n' "${name}" "${m_what}" "${m_files[*]}"
    done
    exit 0
fi

command -v patch >/dev/null 2>&1 || die "the patch program is needed (Debian: apt-get install patch)"
[[ -f "${build}/build.ninja" || -f "${build}/Makefile" ]] ||
    die "${build} is not a configured build (run: bash packaging/setup.sh test, or cmake --preset release)"

# ---- Running the catching tests -----------------------------------------------------------
log="$(mktemp -d)"
# run_catch SPEC LOGFILE: runs one Catch: line; returns the tests' exit status. A test that
# hangs past 10 minutes counts as a failure (timeout's 124).
run_catch() {
    local spec="$1" out="$2" target filter binary
    target="${spec%% *}"
    filter="${spec#* }"
    if [[ "${target}" == ctest ]]; then
        timeout 1800 ctest --test-dir "${build}" -R "${filter}" --no-tests=error \
            --output-on-failure >"${out}" 2>&1
        return
    fi
    binary="$(find "${build}" -type f -name "${target}" -perm -u+x -print -quit)"
    [[ -n "${binary}" ]] || {
        echo "no executable ${target} under ${build}" >"${out}"
        return 1
    }
    timeout 600 "${binary}" --gtest_filter="${filter}" >"${out}" 2>&1
}

# Names of the tests a run's log says failed (gtest's or ctest's summary).
failed_tests() {
    sed -n -e 's/^\[  FAILED  \] \([^ ,]*\.[^ ,]*\).*/\1/p' \
        -e 's/^ *[0-9]* - \(.*\) (Failed\|Timeout\|SEGFAULT\|Subprocess aborted).*/\1/p' "$1" |
        sort -u
}

build_targets() {  # build_targets LOGFILE TARGET...
    local out="$1"
    shift
    cmake --build "${build}" --target "$@" >"${out}" 2>&1
}

# ---- Restoring the source -----------------------------------------------------------------
backup="${log}/backup"
mutated=()
restore() {
    local f
    for f in "${mutated[@]}"; do cp "${backup}/${f}" "${root}/${f}"; done
    mutated=()
}
on_exit() {
    local status=$?
    if ((${#mutated[@]})); then
        restore
        echo "run-mutations.sh: interrupted; the source is restored (the next build recompiles it)" >&2
    fi
    exit "${status}"
}
trap on_exit EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

# ---- The unmutated tree: its catching tests must pass ---------------------------------------
# A mutation already in the source (a run killed with SIGKILL) would make every result a lie.
for name in "${names[@]}"; do
    if patch -p1 --reverse --forward --fuzz=0 --batch --dry-run -s -d "${root}" -i "${here}/${name}.patch" \
        >/dev/null 2>&1; then
        die "the source holds mutation ${name} already (an interrupted run?); undo it with:
    patch -p1 --reverse -d '${root}' -i '${here}/${name}.patch'"
    fi
done
all_targets=()
for name in "${names[@]}"; do
    describe "${here}/${name}.patch"
    all_targets+=("${m_build[@]}")
done
mapfile -t all_targets < <(printf '%s\n' "${all_targets[@]}" | sort -u)
echo "==> building the unmutated test targets: ${all_targets[*]}" >&2
build_targets "${log}/baseline.build" "${all_targets[@]}" ||
    die "the unmutated tree does not build (${log}/baseline.build)"
echo "==> running every catching test on the unmutated tree" >&2
declare -A baseline_done=()
for name in "${names[@]}"; do
    describe "${here}/${name}.patch"
    for spec in "${m_catch[@]}"; do
        [[ -z "${baseline_done[${spec}]:-}" ]] || continue
        baseline_done["${spec}"]=1
        out="${log}/baseline.$((${#baseline_done[@]}))"
        run_catch "${spec}" "${out}" ||
            die "'${spec}' (mutation ${name}) fails without any mutation, see ${out}:
$(failed_tests "${out}" | head -n 5)"
        if [[ "${spec%% *}" != ctest ]] && ! grep -q '^\[  PASSED  \] [1-9]' "${out}"; then
            die "'${spec}' (mutation ${name}) runs no test: its filter names none"
        fi
    done
done

# ---- One mutation at a time ---------------------------------------------------------------
results=()
bad=0
for name in "${names[@]}"; do
    patchfile="${here}/${name}.patch"
    describe "${patchfile}"
    files="${m_files[*]}"
    if ! patch -p1 --forward --fuzz=0 --batch --dry-run -d "${root}" -i "${patchfile}" \
        >"${log}/${name}.apply" 2>&1; then
        printf 'run-mutations.sh: MUTATION %s NO LONGER APPLIES to %s: the code it breaks was moved or changed; refresh tests/mutation/%s.patch\n' \
            "${name}" "${files}" "${name}" >&2
        sed 's/^/    /' "${log}/${name}.apply" >&2
        results+=("| ${name} | ${files} | does not apply | | | |")
        bad=1
        continue
    fi
    for f in "${m_files[@]}"; do
        mkdir -p "$(dirname "${backup}/${f}")"
        cp "${root}/${f}" "${backup}/${f}"
    done
    mutated=("${m_files[@]}")
    patch -p1 --forward --fuzz=0 --batch -s -d "${root}" -i "${patchfile}" >>"${log}/${name}.apply" 2>&1 ||
        die "mutation ${name}: the patch applied in a dry run but not for real"

    echo "==> ${name}: building ${m_build[*]}" >&2
    start=${SECONDS}
    if ! build_targets "${log}/${name}.build" "${m_build[@]}"; then
        restore
        echo "run-mutations.sh: mutation ${name} does not compile (${log}/${name}.build)" >&2
        results+=("| ${name} | ${files} | does not compile | $((SECONDS - start)) | | |")
        bad=1
        continue
    fi
    built=$((SECONDS - start))
    echo "==> ${name}: testing" >&2
    start=${SECONDS}
    failed=()
    k=0
    for spec in "${m_catch[@]}"; do
        k=$((k + 1))
        out="${log}/${name}.test${k}"
        status=0
        run_catch "${spec}" "${out}" || status=$?
        if ((status != 0)); then
            mapfile -t names_failed < <(failed_tests "${out}")
            ((${#names_failed[@]})) || names_failed=("${spec} (exit status ${status})")
            failed+=("${names_failed[@]}")
        fi
    done
    tested=$((SECONDS - start))
    restore
    if ((${#failed[@]})); then
        results+=("| ${name} | ${files} | caught: ${#failed[@]} failed | ${built} | ${tested} | $(printf '%s ' "${failed[@]:0:3}")|")
    else
        results+=("| ${name} | ${files} | MISSED | ${built} | ${tested} | $(printf '%s; ' "${m_catch[@]}")|")
        bad=1
    fi
    echo "${results[-1]}" >&2
done

echo "==> rebuilding the unmutated tree" >&2
build_targets "${log}/final.build" "${all_targets[@]}" ||
    die "the restored tree does not build (${log}/final.build)"
echo "| mutation | file | result | build s | test s | failing tests (or the catching tests, if missed) |"
echo "|---|---|---|---|---|---|"
printf '%s\n' "${results[@]}"
if ((bad)); then
    echo "run-mutations.sh: some mutations were missed, no longer apply or do not compile (above; logs in ${log})" >&2
    exit 1
fi
rm -rf "${log}"
echo "==> every mutation was caught" >&2
