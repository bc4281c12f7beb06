#!/usr/bin/env bash
# Integration test of `raystudio-cli farm`: a real single-node Slurm (munge, slurmctld, slurmd)
# in a temporary folder, on loopback ports, runs a 4-part job array and its merge job; the
# merged image must equal a local render bit for bit. Daemons that cannot start fail the test
# with the reason (their log); they are stopped on every exit path.
#
# usage: tests/cluster/slurm_farm_test.sh RAYSTUDIO_CLI SCENE   (as root: slurmd runs jobs as
# the submitting user and the daemons need root for that without systemd)
set -euo pipefail

readonly CLI="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
readonly SCENE="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"
readonly PARTS=4
readonly JOB_TIMEOUT_S=300   # the 4 parts and the merge, queued and run
readonly DAEMON_TIMEOUT_S=30 # each daemon up and answering
# A small but real image: supersampled, so part borders matter. RAYSTUDIO_FARM_TEST_ARGS
# replaces these options (e.g. a larger image to measure, README "Rendering on a cluster").
read -r -a RENDER_ARGS <<<"${RAYSTUDIO_FARM_TEST_ARGS:---width 320 --height 180 --supersampling 2}"
readonly RENDER_ARGS

fail() {
    printf 'slurm_farm_test: FAIL: %s\n' "$*" >&2
    exit 1
}
say() { printf 'slurm_farm_test: %s\n' "$*"; }
# Seconds (one decimal) since a `date +%s%N` reading.
seconds_since() {
    local ms=$((($(date +%s%N) - $1) / 1000000))
    printf '%d.%d' $((ms / 1000)) $((ms % 1000 / 100))
}

((EUID == 0)) || fail "needs root (slurmd starts job steps as the submitting user; no systemd here)"
for tool in munged slurmctld slurmd sbatch squeue scontrol sinfo idiff; do
    command -v "${tool}" >/dev/null 2>&1 ||
        fail "${tool} is not installed (packaging/setup.sh installs slurm-wlm and munge)"
done
[[ -x "${CLI}" ]] || fail "no raystudio-cli at ${CLI}"
[[ -f "${SCENE}" ]] || fail "no scene at ${SCENE}"

T="$(mktemp -d /tmp/raystudio-slurm.XXXXXX)"
chmod 755 "${T}"
readonly T
export SLURM_CONF="${T}/slurm.conf"

stop_daemons() {
    local name pid
    for name in slurmd slurmctld munged; do
        [[ -f "${T}/${name}.pid" ]] || continue
        pid="$(cat "${T}/${name}.pid" 2>/dev/null || true)"
        [[ "${pid}" =~ ^[0-9]+$ ]] || continue
        kill "${pid}" 2>/dev/null || true
        for _ in $(seq 50); do kill -0 "${pid}" 2>/dev/null || break; sleep 0.1; done
        kill -9 "${pid}" 2>/dev/null || true
    done
}
on_exit() {
    local status=$?
    stop_daemons
    if ((status != 0)); then
        for log in "${T}"/*.log "${T}"/out/*.parts/logs/*.log; do
            [[ -f "${log}" ]] || continue
            printf '\n---- %s (last 20 lines)\n' "${log}" >&2
            tail -n 20 "${log}" >&2
        done
    fi
    rm -rf "${T}"
    exit "${status}"
}
trap on_exit EXIT
trap 'exit 130' INT TERM

# Waits up to DAEMON_TIMEOUT_S for a command to succeed, each try bounded by 5 s (a port held
# by something else may accept and never answer); fails naming what did not come up.
wait_for() {
    local what="$1"
    shift
    local deadline=$(($(date +%s) + DAEMON_TIMEOUT_S))
    while (($(date +%s) < deadline)); do
        timeout 5 "$@" >/dev/null 2>&1 && return 0
        sleep 0.2
    done
    fail "${what} did not come up within ${DAEMON_TIMEOUT_S} s (the logs follow)"
}

say "munge, slurmctld and slurmd in ${T}"
dd if=/dev/urandom of="${T}/munge.key" bs=1024 count=1 status=none
chmod 0400 "${T}/munge.key"
munged --force --socket="${T}/munge.sock" --key-file="${T}/munge.key" \
    --pid-file="${T}/munged.pid" --log-file="${T}/munged.log" --seed-file="${T}/munge.seed" ||
    fail "munged did not start (see ${T}/munged.log below)"
wait_for "munged" test -S "${T}/munge.sock"

mkdir -p "${T}/state" "${T}/spool" "${T}/out"
cat >"${SLURM_CONF}" <<CONF
ClusterName=raystudio-test
SlurmctldHost=localhost
SlurmctldPort=17817
SlurmdPort=17818
AuthType=auth/munge
AuthInfo=socket=${T}/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=${T}/state
SlurmdSpoolDir=${T}/spool
SlurmctldPidFile=${T}/slurmctld.pid
SlurmdPidFile=${T}/slurmd.pid
SlurmctldLogFile=${T}/slurmctld.log
SlurmdLogFile=${T}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
NodeName=localhost CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES State=UP MaxTime=INFINITE
CONF
slurmctld -f "${SLURM_CONF}" || fail "slurmctld did not start (see ${T}/slurmctld.log below)"
wait_for "slurmctld" scontrol ping
slurmd -f "${SLURM_CONF}" -N localhost || fail "slurmd did not start (see ${T}/slurmd.log below)"
wait_for "slurmd (node localhost idle)" bash -c "sinfo -h -n localhost -o %t | grep -qx 'idle\|mix\|alloc'"

say "submitting ${PARTS} parts"
out="${T}/out/farm.exr"
submit="$("${CLI}" farm submit "${SCENE}" -o "${out}" --parts "${PARTS}" "${RENDER_ARGS[@]}")" ||
    fail "farm submit failed"
printf '%s\n' "${submit}"
render_job="$(sed -n 's/^render job \([0-9]*\):.*/\1/p' <<<"${submit}")"
merge_job="$(sed -n 's/^merge job \([0-9]*\):.*/\1/p' <<<"${submit}")"
[[ -n "${render_job}" && -n "${merge_job}" ]] || fail "farm submit printed no job ids"

start_ns=$(date +%s%N)
deadline=$(($(date +%s) + JOB_TIMEOUT_S))
while :; do
    state="$(timeout 10 squeue -h -t all -j "${merge_job}" -o %T 2>/dev/null || true)"
    [[ "${state}" == COMPLETED || ( -z "${state}" && -f "${out}" ) ]] && break
    case "${state}" in FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY)
        fail "merge job ${merge_job} ended ${state}" ;;
    esac
    # afterok on a failed array leaves the merge job pending forever (DependencyNeverSatisfied)
    if timeout 10 squeue -h -t all -j "${merge_job}" -o %R 2>/dev/null | grep -q DependencyNeverSatisfied; then
        "${CLI}" farm status "${render_job}" >&2 || true
        fail "a render task failed; merge job ${merge_job} can never run"
    fi
    (($(date +%s) < deadline)) || fail "job did not finish within ${JOB_TIMEOUT_S} s (state '${state}')"
    sleep 0.5
done
farm_s="$(seconds_since "${start_ns}")"
"${CLI}" farm status "${render_job}" || fail "farm status ${render_job} failed"
[[ -f "${out}" ]] || fail "the merge job finished but ${out} is missing"

say "rendering the same image locally"
local_start_ns=$(date +%s%N)
"${CLI}" render "${SCENE}" -o "${T}/local.exr" "${RENDER_ARGS[@]}" || fail "local render failed"
local_s="$(seconds_since "${local_start_ns}")"
# Every pixel bit for bit (idiff with zero tolerance); the files differ only in the date
# OpenImageIO writes into an EXR header.
idiff -fail 0 -warn 0 "${out}" "${T}/local.exr" || fail "the farm's image differs from the local render"
say "PASS: ${PARTS}-part Slurm job ${render_job} + merge ${merge_job} equals the local render" \
    "(farm ${farm_s} s from submission to merged file, local render ${local_s} s)"
