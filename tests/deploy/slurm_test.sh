#!/usr/bin/env bash
# deploy/slurm on a one-node Slurm cluster this test starts and stops itself (Debian's Slurm
# 22.05 and munge): a render split 4 ways by submit.sh (an sbatch array and an afterok merge)
# must merge to the same image as one render of all the samples, and a failing part must
# cancel the merge (--kill-on-invalid-dep) rather than leave it pending. Then the daemon with
# --jobs-backend slurm: a REST job (another camera, two formats) comes back through the API as
# the same image as one local render, a job for a time is refused (400 naming the field), a
# cancelled job leaves the cluster's queue, and a job submitted before the daemon restarts is
# finished after it. Every daemon started
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

# The daemon handing its REST jobs to the cluster.
port=$((port + 2))
while ss -ltn | grep -q ":$port "; do port=$((port + 1)); done
api=http://127.0.0.1:$port/api/jobs
serve() {
  "$bin" serve --port "$port" --data "$tmp/data" --jobs-backend slurm --slurm-parts 3 \
    >>"$tmp/daemon.log" 2>&1 &
  daemon=$!
  pids+=("$daemon")
  for _ in $(seq 100); do curl -sf "http://127.0.0.1:$port/healthz" >/dev/null && return; sleep 0.2; done
  cat "$tmp/daemon.log" >&2; echo "slurm test: the daemon did not serve" >&2; exit 1
}
# Waits (bounded) for job $1 to reach state $2; prints its status.
wait_state() {
  local deadline=$(( $(date +%s) + 240 )) status
  while status=$(curl -sf "$api/$1") && ! grep -q "\"state\":\"$2\"" <<<"$status"; do
    grep -q '"state":"\(failed\|cancelled\|done\)"' <<<"$status" && break
    [ "$(date +%s)" -lt "$deadline" ] || break
    sleep 0.5
  done
  grep -q "\"state\":\"$2\"" <<<"$status" ||
    { echo "$status"; cat "$tmp/daemon.log"; echo "slurm test: job $1 is not $2" >&2; exit 1; }
  echo "$status"
}
serve
# A camera other than the scene's (a turn about y by 0.1), as a frame message gives it.
camera='[0.9950041652780258,0,0.09983341664682815,0, 0,1,0,0, -0.09983341664682815,0,0.9950041652780258,0, 0,0,0,1]'
job='{"scene":"cornell-box","width":32,"height":24,"max_depth":2,"spp":12,"formats":["exr","png"],"camera":'"$camera"'}'
t0=$(date +%s)
id=$(curl -sf -X POST -H 'Content-Type: application/json' -d "$job" "$api" | sed -n 's/.*"id":\([0-9]*\).*/\1/p')
[ -n "$id" ] || { cat "$tmp/daemon.log"; echo "slurm test: the job was not accepted" >&2; exit 1; }
status=$(wait_state "$id" done)
echo "slurm test: a REST job rendered by the cluster in $(( $(date +%s) - t0 )) s"
grep -q '"samples":12' <<<"$status" || { echo "$status"; echo "slurm test: not 12 samples" >&2; exit 1; }
curl -sf "$api/$id/result.exr" -o "$tmp/job.exr"
curl -sf "$api/$id/result.png" -o "$tmp/job.png"
[ "$(head -c 4 "$tmp/job.png" | tail -c 3)" = PNG ] || { echo "slurm test: result.png is no PNG" >&2; exit 1; }
"$bin" render "$scene" "${options[@]}" --spp 12 -o "$tmp/local.exr" \
  --camera "$(tr -d '[] ' <<<"$camera")" >/dev/null
idiff -fail 1e-5 -failpercent 0 -warn 1e-5 "$tmp/job.exr" "$tmp/local.exr" ||
  { echo "slurm test: the cluster's job differs from one local render" >&2; exit 1; }
if idiff -fail 1e-5 -failpercent 0 "$tmp/job.exr" "$tmp/one.exr" >/dev/null; then
  echo "slurm test: the job's camera was not applied" >&2; exit 1
fi

# A time cannot be split into parts beforehand: refused, naming the field.
code=$(curl -s -o "$tmp/refused.json" -w '%{http_code}' -X POST -H 'Content-Type: application/json' \
  -d '{"scene":"cornell-box","seconds":5}' "$api")
[ "$code" = 400 ] && grep -q '"seconds: ' "$tmp/refused.json" ||
  { echo "$code $(cat "$tmp/refused.json")"; echo "slurm test: a job for a time was not refused" >&2; exit 1; }

# Cancelled: its Slurm jobs leave the queue and its folder goes.
big='{"scene":"cornell-box","width":256,"height":256,"spp":3000,"formats":["exr"]}'
id=$(curl -sf -X POST -H 'Content-Type: application/json' -d "$big" "$api" | sed -n 's/.*"id":\([0-9]*\).*/\1/p')
wait_state "$id" running >/dev/null
for _ in $(seq 50); do [ -f "$tmp/data/jobs/$id/slurm.json" ] && break; sleep 0.2; done
read -r parts merge < <(sed 's/.*"parts_job":"\([0-9]*\)","merge_job":"\([0-9]*\)".*/\1 \2/' "$tmp/data/jobs/$id/slurm.json")
curl -sf -X DELETE "$api/$id" | grep -q '"state":"cancelled"' || { echo "slurm test: no cancel" >&2; exit 1; }
wait_jobs 60 "$parts" "$merge"
for _ in $(seq 50); do [ ! -d "$tmp/data/jobs/$id" ] && break; sleep 0.2; done
[ ! -d "$tmp/data/jobs/$id" ] || { echo "slurm test: the cancelled job's folder stayed" >&2; exit 1; }
echo "slurm test: a cancelled job left the cluster's queue"

# Submitted, then the daemon stops (SIGTERM) and starts again: the job is picked up and done.
# An inline document this time, naming a mesh among the bundled scenes' files.
job='{"scene":'"$(cat "$repo/scenes/mesh-demo.json")"',"width":32,"height":24,"max_depth":2,"spp":12,"formats":["exr"]}'
id=$(curl -sf -X POST -H 'Content-Type: application/json' -d "$job" "$api" | sed -n 's/.*"id":\([0-9]*\).*/\1/p')
for _ in $(seq 100); do [ -f "$tmp/data/jobs/$id/slurm.json" ] && break; sleep 0.1; done
cp "$tmp/data/jobs/$id/slurm.json" "$tmp/submitted.json"
kill "$daemon"
timeout 60 tail --pid="$daemon" -f /dev/null
serve
wait_state "$id" done >/dev/null
curl -sf "$api/$id/result.exr" -o "$tmp/resumed.exr"
"$bin" render "$repo/scenes/mesh-demo.json" "${options[@]}" --spp 12 -o "$tmp/mesh.exr" >/dev/null
idiff -fail 1e-5 -failpercent 0 -warn 1e-5 "$tmp/resumed.exr" "$tmp/mesh.exr" ||
  { echo "slurm test: the job resumed after a restart differs" >&2; exit 1; }
cmp -s "$tmp/data/jobs/$id/slurm.json" "$tmp/submitted.json" ||
  { echo "slurm test: the restarted daemon submitted the job again" >&2; exit 1; }
echo "slurm test: a job submitted before a restart was finished after it"
echo "slurm test: passed in $(( $(date +%s) - start )) s"
