#!/usr/bin/env bash
# deploy/slurm on a one-node Slurm cluster this test starts and stops itself (Debian's Slurm
# 22.05 and munge): a render split 4 ways by submit.sh (an sbatch array and an afterok merge)
# must merge to the same image as one render of all the samples, and a failing part must
# cancel the merge (--kill-on-invalid-dep) rather than leave it pending. Every daemon started
# here is stopped at the end; each wait is bounded. Exit 77 (ctest: skipped) with the reason
# printed when the cluster cannot start on this machine.
#   slurm_test.sh BUILD_DIR
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
bin=$(realpath "${1:?usage: slurm_test.sh BUILD_DIR}")/geodesic
[ -x "$bin" ] || { echo "slurm test: no $bin" >&2; exit 1; }
for tool in slurmctld slurmd sbatch squeue munged munge; do
  command -v "$tool" >/dev/null || { echo "slurm test: $tool missing: run scripts/install-deps.sh" >&2; exit 1; }
done
[ "$(id -u)" -eq 0 ] || { echo "slurm test: SKIPPED: needs root to start slurmd"; exit 77; }

tmp=$(mktemp -d)
chmod 755 "$tmp"
pids=()
munged_pid=""
cleanup() {
  [ -z "${SLURM_CONF:-}" ] || scancel --quiet --user=root 2>/dev/null || true
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do timeout 20 tail --pid="$pid" -f /dev/null 2>/dev/null || kill -9 "$pid" 2>/dev/null || true; done
  [ -z "$munged_pid" ] || kill "$munged_pid" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 143' TERM INT  # timeout(1): clean up too
skip() {
  echo "slurm test: SKIPPED: $1 (the Slurm split-and-merge test did not run)"
  for log in "$tmp"/*.log; do [ -f "$log" ] && { echo "--- $log"; tail -n 15 "$log"; }; done
  exit 77
}

# munge: reuse a running munged, else start one as the munge user (as its package would).
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  mkdir -p /run/munge && chown munge:munge /run/munge && chmod 755 /run/munge
  [ -f /etc/munge/munge.key ] || { echo "slurm test: no /etc/munge/munge.key" >&2; exit 1; }
  runuser -u munge -- munged --pid-file=/run/munge/munged-geodesic-test.pid || skip "munged did not start"
  munged_pid=$(cat /run/munge/munged-geodesic-test.pid)
  for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
fi

# Two free ports above the defaults, so a cluster already on this machine is left alone.
port=$(( 20000 + RANDOM % 20000 ))
while ss -ltn | grep -q ":$port \|:$((port + 1)) "; do port=$((port + 2)); done
host=$(hostname -s)
mkdir -p "$tmp/state" "$tmp/spool"
export SLURM_CONF=$tmp/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=geodesic-test
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MailProg=/bin/true
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
start=$(date +%s)
slurmctld -D -i -f "$SLURM_CONF" >"$tmp/slurmctld.log" 2>&1 & pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$tmp/slurmd.log" 2>&1 & pids+=($!)
state=""
for _ in $(seq 60); do
  state=$(timeout 5 sinfo -h -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || skip "the one-node cluster is not idle after 30 s (state '${state}')"
echo "slurm test: one-node cluster idle in $(( $(date +%s) - start )) s"

# Waits (bounded) until none of the jobs is queued or running.
wait_jobs() {
  local deadline=$(( $(date +%s) + $1 )); shift
  while [ -n "$(squeue -h -j "$1" 2>/dev/null)" ] || [ -n "$(squeue -h -j "$2" 2>/dev/null)" ]; do
    [ "$(date +%s)" -lt "$deadline" ] || { squeue; echo "slurm test: jobs $* still queued" >&2; return 1; }
    sleep 1
  done
}
scene="$repo/scenes/cornell-box.json"
options=(--width 32 --height 24 --max-depth 2)
t0=$(date +%s)
read -r parts merge < <(GEODESIC_BIN=$bin bash "$repo/deploy/slurm/submit.sh" "$scene" 4 3 "$tmp/split" merged.exr "${options[@]}")
wait_jobs 300 "$parts" "$merge"
echo "slurm test: 4 parts and the merge done in $(( $(date +%s) - t0 )) s"
[ -f "$tmp/split/merged.exr" ] || { cat "$tmp"/split/*.log >&2; echo "slurm test: no merged image" >&2; exit 1; }
grep -q '"samples": 12' "$tmp/split/merge-report.json" || { cat "$tmp/split/merge-report.json"; exit 1; }
for i in 0 1 2 3; do
  grep -q "samples \[$((i * 3)), $((i * 3 + 3)))" "$tmp/split/part-$i.log" || { cat "$tmp/split/part-$i.log"; exit 1; }
done

# One render of the same 12 samples: equal up to float round-off (summation order).
"$bin" render "$scene" "${options[@]}" --spp 12 -o "$tmp/one.exr" >/dev/null
idiff -fail 1e-5 -failpercent 0 -warn 1e-5 "$tmp/split/merged.exr" "$tmp/one.exr" ||
  { echo "slurm test: the merged image differs from one render" >&2; exit 1; }
# A different seed is a different image: the comparison can tell.
"$bin" render "$scene" "${options[@]}" --spp 12 --seed 7 -o "$tmp/other.exr" >/dev/null
if idiff -fail 1e-5 -failpercent 0 "$tmp/split/merged.exr" "$tmp/other.exr" >/dev/null; then
  echo "slurm test: another seed's image passes the comparison" >&2; exit 1
fi

# A failing part (an invalid option) must cancel the merge, not leave it pending.
read -r parts merge < <(GEODESIC_BIN=$bin bash "$repo/deploy/slurm/submit.sh" "$scene" 2 1 "$tmp/fail" merged.exr --max-depth 999)
wait_jobs 120 "$parts" "$merge"
[ ! -e "$tmp/fail/merged.exr" ] || { echo "slurm test: the merge ran after a failed part" >&2; exit 1; }
echo "slurm test: a failed part cancelled the merge"
echo "slurm test: passed in $(( $(date +%s) - start )) s"
