#!/usr/bin/env bash
# RayStudio set-up for a fresh Debian 12 machine: install build dependencies, build, then run or test.
set -euo pipefail

readonly DEFAULT_SCENE="scenes/reference-room.scene.json"
# Fuzzing: seconds per target for `fuzz` without an argument, and in `test` (CI).
readonly DEFAULT_FUZZ_SECONDS=300
readonly CI_FUZZ_SECONDS=30
# The mutations `test` runs: tests/mutation/run-mutations.sh's --quick list, for --help.
quick_mutations() {
    bash "$(dirname "${BASH_SOURCE[0]}")/../tests/mutation/run-mutations.sh" --quick --list \
        2>/dev/null | cut -d ' ' -f 1 | xargs | fold -s -w 62 | sed -e 's/ *$//' -e 's/^/                  /'
}

# Everything the build, the tests and the designer need, as Debian 12 names them.
readonly REQUIRED_PACKAGES=(
    build-essential cmake ninja-build pkg-config git file
    qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev libgl-dev libqt6svg6
    libglm-dev libopenimageio-dev openimageio-tools libassimp-dev libtbb-dev libembree-dev
    nlohmann-json3-dev libgtest-dev googletest
    # The formatting check (the tree follows .clang-format) and the mutation check's patches.
    clang-format patch
    xvfb xauth mesa-utils libgl1-mesa-dri
    # The fuzz preset: Debian's clang and its libFuzzer/sanitizer runtimes.
    clang-14 libclang-rt-14-dev
    povray python3
    slurm-wlm munge
)

usage() {
    cat <<EOF
Usage: bash packaging/setup.sh COMMAND [ARGS]

Sets up RayStudio on Debian 12: installs the missing build dependencies with apt-get
(only when some are missing), configures the release build once, builds it (incrementally
on later runs), then:

  run [SCENE]   open SCENE in the designer; without a display (or a built designer),
                render SCENE with raystudio-cli into build/release/<scene name>.png.
                SCENE defaults to ${DEFAULT_SCENE}.
  test          check the formatting (format-check), then run the session tests under
                ThreadSanitizer (build/tsan), each fuzzer (the scene reader's and the mesh
                loader's) for ${CI_FUZZ_SECONDS} s (build/fuzz), the unit and command-line tests
                under ASan + UBSan (build/asan), the whole test suite (ctest), the Slurm farm
                test (needs root) and the quick mutations (below), and exit with the status.
  format-check  check that every C++ file git tracks or would track (*.cpp, *.h, *.inl; new
                files too, not ignored ones) is formatted as .clang-format says
                (clang-format --dry-run --Werror); fails naming the files.
  format        reformat those files in place (clang-format -i).
  mutate [NAME...]
                the mutation check (tests/mutation): put each deliberate bug into the source
                in turn, rebuild the tests that must catch it in build/release, run them and
                restore the source; fails if a mutation is missed or its patch no longer
                applies. All mutations by default (about 15 minutes on two cores), or the
                NAMEd ones (bash tests/mutation/run-mutations.sh --list names them). The
                test command runs the quick ones, whose source file rebuilds in seconds and
                whose tests run in seconds (about 2 minutes on two cores):
$(quick_mutations)
  asan          build the unit and command-line tests with ASan + UBSan (build/asan) and
                run them (the ASan stage of test alone).
  fuzz [SECONDS]
                build the libFuzzer targets (tests/fuzz, clang 14, ASan + UBSan) in
                build/fuzz and run each for SECONDS (default ${DEFAULT_FUZZ_SECONDS}) on top of
                its corpus; a crash or sanitizer report fails it and leaves the input in
                build/fuzz/artifacts/.
  package       build the Debian package build/release/raystudio_<version>_<arch>.deb
                with CPack (install it with: sudo apt install ./build/release/raystudio_*.deb).
  -h, --help    show this help.

Works from any folder. Run as root, or as a user who may use sudo for apt-get.
CMAKE_BUILD_PARALLEL_LEVEL limits the number of build jobs, CTEST_PARALLEL_LEVEL the number
of tests run at once (both default to all cores).
EOF
}

# Tests at once in every ctest stage: most tests are a process that starts in a fraction of a
# second and then runs on one core, so one at a time leaves the other cores idle.
# main() has checked CTEST_PARALLEL_LEVEL.
test_jobs() {
    printf '%s' "${CTEST_PARALLEL_LEVEL:-$(nproc 2>/dev/null || echo 1)}"
}

say() { printf '==> %s\n' "$*"; }
die() {
    printf 'setup.sh: error: %s\n' "$*" >&2
    exit 1
}

# Installs only what is missing, so a second run neither needs the network nor root.
install_missing_packages() {
    if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
        say "No dpkg/apt-get here (not Debian?): skipping the package check."
        say "Make sure these (or their equivalents) are installed: ${REQUIRED_PACKAGES[*]}"
        return 0
    fi
    local missing=() pkg status
    for pkg in "${REQUIRED_PACKAGES[@]}"; do
        status="$(dpkg-query -W -f='${db:Status-Status}' "${pkg}" 2>/dev/null || true)"
        if [[ "${status}" != "installed" ]]; then
            missing+=("${pkg}")
        fi
    done
    if ((${#missing[@]} == 0)); then
        say "All ${#REQUIRED_PACKAGES[@]} required Debian packages are installed."
        return 0
    fi

    local sudo_cmd=()
    if ((EUID != 0)); then
        command -v sudo >/dev/null 2>&1 ||
            die "missing packages (${missing[*]}) and not root; run as root or install sudo"
        sudo_cmd=(sudo)
    fi
    say "Installing ${#missing[@]} missing package(s): ${missing[*]}"
    "${sudo_cmd[@]}" apt-get update
    "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
        apt-get install -y --no-install-recommends "${missing[@]}"
}

# Configures once (a reconfigure would throw away the user's cache choices), builds always.
build_release() {
    if [[ -f build/release/CMakeCache.txt && -f build/release/build.ninja ]]; then
        say "build/release is already configured; building incrementally."
    else
        say "Configuring the release build in build/release."
        cmake --preset release
    fi
    say "Building."
    cmake --build --preset release
}

# The interactive session's threading under ThreadSanitizer: its own preset and build
# folder, the render unit tests and one designer test that edits while passes and a Render
# Image job run (tests/gui/session_threads_test.cpp; the rest of the designer's tests are
# not built there).
run_thread_sanitizer_tests() {
    if [[ ! -f build/tsan/CMakeCache.txt || ! -f build/tsan/build.ninja ]]; then
        say "Configuring the ThreadSanitizer build in build/tsan."
        cmake --preset tsan || return
    fi
    say "Building the unit tests and the designer's threading test with ThreadSanitizer."
    cmake --build --preset tsan --target raystudio_unit_tests raystudio_session_threads_test || return
    say "Running the session, renderer and designer-threading tests under ThreadSanitizer."
    ctest --preset tsan --parallel "$(test_jobs)" \
        -R 'RenderSession|Renderer|Sampling|gui\.session_threads' --no-tests=error --output-on-failure
}

# ---- Fuzzing (tests/fuzz) ----------------------------------------------------------------
# The libFuzzer targets with clang 14, ASan and UBSan (the fuzz preset builds the whole render
# library with clang too). Findings go to build/fuzz/corpus (new inputs) and
# build/fuzz/artifacts (crashes); the checked-in corpus is only read.
build_fuzzers() {
    if [[ ! -f build/fuzz/CMakeCache.txt || ! -f build/fuzz/build.ninja ]]; then
        say "Configuring the fuzzing build in build/fuzz (clang 14)."
        cmake --preset fuzz || return
    fi
    say "Building the fuzz targets (and the render library) with clang 14."
    cmake --build --preset fuzz || return
}

# run_fuzzers SECONDS [TARGET...]: every target when none is named.
run_fuzzers() {
    local seconds="$1" target status=0
    shift
    local targets=("$@")
    ((${#targets[@]} > 0)) || targets=(scene_reader mesh_loader)
    build_fuzzers || return
    mkdir -p build/fuzz/artifacts
    for target in "${targets[@]}"; do
        mkdir -p "build/fuzz/corpus/${target}"
        say "Fuzzing ${target} for ${seconds} s."
        # -max_len: small files (the loaders' size guards are tested elsewhere); -timeout and
        # -rss_limit_mb: an input that runs without bound or allocates gigabytes is a finding.
        ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" \
            LSAN_OPTIONS="suppressions=tests/fuzz/lsan.supp:print_suppressions=0" \
            UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
            "build/fuzz/tests/fuzz/${target}_fuzz" -max_total_time="${seconds}" \
            -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
            -dict="tests/fuzz/${target}.dict" -artifact_prefix="build/fuzz/artifacts/${target}-" \
            "build/fuzz/corpus/${target}" "tests/fuzz/corpus/${target}" || status=$?
        if ((status != 0)); then
            printf 'setup.sh: fuzzing %s failed (exit status %d); the input is in build/fuzz/artifacts/\n' \
                "${target}" "${status}" >&2
            return "${status}"
        fi
    done
    say "Fuzzing found nothing."
}
# ---- End of fuzzing ------------------------------------------------------------------------

# ---- Formatting (.clang-format) -------------------------------------------------------------
# Every C++ file git tracks or would track (new files not yet added, not ignored ones), in one
# clang-format call; the files it would change are named.
tracked_cxx_files() {
    git rev-parse --is-inside-work-tree >/dev/null 2>&1 ||
        die "the formatting stages need a git checkout (they format the files git tracks)"
    git ls-files -z --cached --others --exclude-standard '*.cpp' '*.h' '*.inl'
}

check_format() {
    command -v clang-format >/dev/null 2>&1 || die "clang-format is not installed"
    say "Checking the formatting of the C++ files ($(clang-format --version | head -n 1))."
    local out status=0
    out="$(tracked_cxx_files | xargs -0 -r clang-format --dry-run --Werror 2>&1)" || status=$?
    if ((status == 0)); then
        say "Every C++ file is formatted as .clang-format says."
        return 0
    fi
    local files=()
    mapfile -t files < <(sed -n \
        's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<<"${out}" |
        sort -u)
    if ((${#files[@]})); then
        printf 'setup.sh: these files are not formatted as .clang-format says (fix them with: bash packaging/setup.sh format):\n' >&2
        printf '  %s\n' "${files[@]}" >&2
    else
        printf 'setup.sh: clang-format failed (exit status %d):\n%s\n' "${status}" "${out}" >&2
    fi
    return 1
}

format_sources() {
    command -v clang-format >/dev/null 2>&1 || die "clang-format is not installed"
    say "Formatting the C++ files with clang-format -i."
    tracked_cxx_files | xargs -0 -r clang-format -i
}
# ---- End of formatting ------------------------------------------------------------------------

# ---- Mutation check (tests/mutation) ---------------------------------------------------------
# run_mutations [--quick] [NAME...]: in build/release, which must be configured and built.
run_mutations() {
    say "Running the mutation check${1:+ ($*)}."
    bash tests/mutation/run-mutations.sh "$@"
}
# ---- End of the mutation check ---------------------------------------------------------------

# ---- AddressSanitizer + UndefinedBehaviorSanitizer ---------------------------------------
# The unit and command-line tests under ASan + UBSan: the asan preset without the designer
# (Qt is not instrumented, and the GUI tests run in the suite below). Tests named NAME.CASE
# are the gtest ones; the image, packaging and clang tests are left to the suite.
run_address_sanitizer_tests() {
    if [[ ! -f build/asan/CMakeCache.txt || ! -f build/asan/build.ninja ]]; then
        say "Configuring the ASan + UBSan build in build/asan."
        cmake --preset asan -DRAYSTUDIO_BUILD_UI=OFF || return
    fi
    say "Building the unit and command-line tests with ASan + UBSan."
    cmake --build --preset asan --target raystudio_unit_tests raystudio_cli_tests || return
    say "Running the unit and command-line tests under ASan + UBSan."
    ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" \
        UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
        ctest --preset asan --parallel "$(test_jobs)" -R '^[^.]+[.][^.]+$' --no-tests=error \
            --output-on-failure
}
# ---- End of ASan + UBSan ---------------------------------------------------------------------

# `raystudio-cli farm` against a real single-node Slurm (munge, slurmctld, slurmd in a
# temporary folder, loopback ports 17817/17818): a 4-part job array and its merge job must
# give the local render's pixels. Daemons that cannot start fail it, with their logs.
run_slurm_farm_test() {
    say "Running the Slurm farm integration test (tests/cluster/slurm_farm_test.sh)."
    timeout 600 bash tests/cluster/slurm_farm_test.sh build/release/app/raystudio-cli \
        scenes/reference-room.scene.json
}

# Each stage's function is called as `stage || status=$?`, where bash turns `set -e` off for
# everything inside it: a failed build would go unnoticed (its stale or missing tests then
# 'pass'). So every build step says `|| return`, and ctest treats no tests as a failure.
run_tests() {
    local status=0
    run_thread_sanitizer_tests || status=$?
    if ((status != 0)); then
        printf 'setup.sh: ThreadSanitizer tests failed (exit status %d)\n' "${status}" >&2
        return "${status}"
    fi
    # Both targets: the mesh loader's assimp runs in a child process, so the assertion in
    # Debian's assimp 5.2 that aborts on a malformed PLY (its corpus) is an error now.
    run_fuzzers "${CI_FUZZ_SECONDS}" scene_reader mesh_loader || status=$?
    if ((status != 0)); then return "${status}"; fi
    run_address_sanitizer_tests || status=$?
    if ((status != 0)); then
        printf 'setup.sh: ASan + UBSan tests failed (exit status %d)\n' "${status}" >&2
        return "${status}"
    fi
    say "Running the test suite."
    ctest --preset release --parallel "$(test_jobs)" --no-tests=error --output-on-failure || status=$?
    run_slurm_farm_test || status=$?
    if ((status != 0)); then
        printf 'setup.sh: tests failed (ctest exit status %d)\n' "${status}" >&2
        return "${status}"
    fi
    # Last: it rebuilds the unit tests of build/release once per mutation (and at its end).
    run_mutations --quick || status=$?
    if ((status == 0)); then
        say "All tests passed."
    else
        printf 'setup.sh: the mutation check failed (exit status %d)\n' "${status}" >&2
    fi
    return "${status}"
}

# The Debian package from the install rules (packaging/cpack.cmake); dpkg-shlibdeps, from
# dpkg-dev (part of build-essential), fills in the run-time dependencies.
build_package() {
    say "Building the Debian package with CPack."
    (cd build/release && cpack -G DEB)
    local deb
    deb="$(ls -t build/release/raystudio_*.deb | head -n 1)"
    say "Package written to ${PWD}/${deb}"
}

run_scene() {
    local scene="$1"
    [[ -f "${scene}" ]] || die "scene file not found: ${scene}"

    # ---- Designer hand-off ---------------------------------------------------------------
    # Once app/raystudio (the Qt designer) is built, `run` opens the scene in it. Without a
    # display the designer cannot start, so a headless machine keeps the CLI render below.
    local designer="build/release/app/raystudio"
    if [[ -x "${designer}" ]]; then
        if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
            say "Opening ${scene} in the designer."
            exec "${designer}" "${scene}"
        fi
        say "The designer is built but there is no display (DISPLAY/WAYLAND_DISPLAY unset);"
        say "rendering with raystudio-cli instead."
    fi
    # ---- End of designer hand-off --------------------------------------------------------

    local cli="build/release/app/raystudio-cli"
    [[ -x "${cli}" ]] || die "${cli} was not built"
    local name
    name="$(basename "${scene}")"
    name="${name%.json}"
    name="${name%.scene}"
    local image="build/release/${name}.png"
    say "Rendering ${scene} with raystudio-cli."
    "${cli}" render "${scene}" -o "${image}"
    say "Image written to ${PWD}/${image}"
}

main() {
    if (($# == 0)); then
        usage >&2
        exit 2
    fi
    local command="$1"
    shift
    case "${command}" in
        -h | --help | help)
            usage
            return 0
            ;;
        run)
            (($# <= 1)) || die "run takes at most one scene file (see --help)"
            ;;
        test)
            (($# == 0)) || die "test takes no arguments (see --help)"
            ;;
        package)
            (($# == 0)) || die "package takes no arguments (see --help)"
            ;;
        asan)
            (($# == 0)) || die "asan takes no arguments (see --help)"
            ;;
        format-check | format)
            (($# == 0)) || die "${command} takes no arguments (see --help)"
            ;;
        mutate)
            local name
            for name in "$@"; do
                [[ "${name}" =~ ^[a-z0-9-]+$ ]] || die "mutate: '${name}' is not a mutation name (see --help)"
            done
            ;;
        fuzz)
            (($# <= 1)) || die "fuzz takes at most a number of seconds (see --help)"
            [[ "${1:-1}" =~ ^[1-9][0-9]*$ ]] || die "fuzz: SECONDS must be a positive whole number, got '${1}'"
            ;;
        *)
            usage >&2
            die "unknown command '${command}'"
            ;;
    esac

    if [[ -n "${CTEST_PARALLEL_LEVEL:-}" && ! "${CTEST_PARALLEL_LEVEL}" =~ ^[1-9][0-9]*$ ]]; then
        die "CTEST_PARALLEL_LEVEL must be a positive whole number, got '${CTEST_PARALLEL_LEVEL}'"
    fi

    # Resolve the scene against the caller's folder before moving to the repository root.
    local scene=""
    if [[ "${command}" == run ]]; then
        scene="${1:-}"
        if [[ -n "${scene}" ]]; then
            [[ -f "${scene}" ]] || die "scene file not found: ${scene}"
            scene="$(cd "$(dirname "${scene}")" && pwd)/$(basename "${scene}")"
        fi
    fi

    local repo_root
    repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    cd "${repo_root}"
    [[ -n "${scene}" ]] || scene="${DEFAULT_SCENE}"

    install_missing_packages
    case "${command}" in
        format-check)
            check_format
            return
            ;;
        format)
            format_sources
            return
            ;;
        test) check_format || die "the formatting check failed (above); nothing was built" ;;
    esac
    [[ "${command}" == fuzz || "${command}" == asan ]] || build_release
    case "${command}" in
        run) run_scene "${scene}" ;;
        test) run_tests ;;
        package) build_package ;;
        asan) run_address_sanitizer_tests ;;
        fuzz) run_fuzzers "${1:-${DEFAULT_FUZZ_SECONDS}}" ;;
        mutate) run_mutations "$@" ;;
    esac
}

main "$@"
