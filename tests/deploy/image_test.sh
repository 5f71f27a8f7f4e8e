#!/usr/bin/env bash
# docker/Dockerfile for real, with podman: base images made locally (base_image.sh), the image
# built (--format docker keeps the HEALTHCHECK), then one container with a token and a volume:
# the HEALTHCHECK passes (`podman healthcheck run`: without systemd podman never runs it by
# itself), /api needs the token (401), a WebSocket gets a JPEG frame, a job's PNG comes back,
# `podman restart` keeps the job, a job killed with the daemon (kill -9) resumes from its
# checkpoint, the daemon runs as uid/gid 10001, the binary is stripped, the image holds the
# libraries NVIDIA's Vulkan driver loads, and the image is under 1 GB (its size is printed). Then docker/compose.yaml with podman-compose.
# Exits 77 (skipped), saying so, only when podman cannot start a container on this machine.
# Needs root (rootful podman, debootstrap).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
here="$repo/tests/deploy"
. "$here/podman_env.sh"
image=${GEODESIC_TEST_IMAGE:-localhost/geodesic:test}
name=geodesic-test-$$
token=$(od -An -N16 -tx1 /dev/urandom | tr -d ' \n')
tmp=$(mktemp -d)
cleanup() {
  command podman rm -f -t 5 "$name" >/dev/null 2>&1 || true
  command podman volume rm -f "$name" >/dev/null 2>&1 || true
  [ ! -f "$tmp/compose-up" ] || (cd "$repo/docker" && GEODESIC_TOKEN=$token podman-compose \
    -p "$name-compose" -f compose.yaml down -v >/dev/null 2>&1) || true
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 143' TERM INT  # timeout(1): clean up too
fail() { echo "image test: FAILED: $*" >&2; command podman logs --tail 30 "$name" >&2 2>/dev/null || true; exit 1; }
if ! why=$(podman_ok); then
  echo "image test: SKIPPED: the container engine cannot start here: $why"
  exit 77
fi
# GEODESIC_IMAGE_PREBUILT=1: probe an image already built as $image (a rerun of the probes).
[ "${GEODESIC_IMAGE_PREBUILT:-0}" = 1 ] || bash "$here/base_image.sh"
if ! command podman run --rm "${PODMAN_RUN_OPTS[@]}" debian:bookworm true >"$tmp/probe" 2>&1; then
  echo "image test: SKIPPED: podman cannot run a container here: $(head -c 300 "$tmp/probe")"
  exit 77
fi
t0=$(date +%s)
# --no-cache: every layer is built again, apt included, so the time printed is the image's build
# from nothing but the base images (the goal: under 10 min on 2 cores).
[ "${GEODESIC_IMAGE_PREBUILT:-0}" = 1 ] || command podman build --no-cache --runtime runc --format docker -f "$repo/docker/Dockerfile" -t "$image" \
  "${PODMAN_ULIMITS[@]}" "$repo" >"$tmp/build.log" 2>&1 || { tail -40 "$tmp/build.log"; fail "podman build"; }
[ "${GEODESIC_IMAGE_PREBUILT:-0}" = 1 ] || echo "image test: built $image from nothing but the base images in $(( $(date +%s) - t0 )) s"
size=$(command podman image inspect "$image" --format '{{.Size}}')
echo "image test: image size $((size / 1000000)) MB"
[ "$size" -lt 1000000000 ] || fail "the image is $((size / 1000000)) MB, not under 1 GB"
healthcheck=$(command podman image inspect "$image" --format '{{.HealthCheck}}')
[[ "$healthcheck" == *healthz* ]] || fail "the image has no HEALTHCHECK ($healthcheck)"

# What NVIDIA's Vulkan driver loads besides itself (docker/compose.gpu.yaml; the toolkit mounts
# the driver, not these): without libEGL it creates no instance and the daemon finds no device.
libs=$(command podman run --rm "${PODMAN_RUN_OPTS[@]}" --entrypoint /sbin/ldconfig "$image" -p) ||
  fail "ldconfig -p in the image"
for lib in libEGL.so.1 libGLdispatch.so.0 libX11.so.6 libXext.so.6; do
  grep -q "$lib " <<<"$libs" || fail "the image lacks $lib, which NVIDIA's Vulkan driver loads"
done

port=$(( 20000 + RANDOM % 20000 ))
command podman run -d --name "$name" "${PODMAN_RUN_OPTS[@]}" -e GEODESIC_TOKEN="$token" \
  -v "$name:/data" -p "127.0.0.1:$port:8080" "$image" >/dev/null 2>"$tmp/run.err" ||
  fail "podman run: $(cat "$tmp/run.err")"  # (without systemd it also complains of no health timers)
base="http://127.0.0.1:$port"
# Waits (bounded) for the container's own HEALTHCHECK to pass.
wait_healthy() {
  local t=$(date +%s)
  for _ in $(seq 150); do
    command podman healthcheck run "$name" >/dev/null 2>&1 && { echo "image test: healthy after $(( $(date +%s) - t )) s ($1)"; return 0; }
    sleep 2
  done
  fail "no healthy container within 300 s ($1)"
}
wait_healthy start

code=$(curl -s -o /dev/null -w '%{http_code}' "$base/api/jobs")
[ "$code" = 401 ] || fail "/api/jobs without the token answered $code, not 401"
python3 "$here/ws_frame.py" 127.0.0.1 "$port" "$token" 180 || fail "no JPEG over the WebSocket"

auth=(-H "Authorization: Bearer $token")
reply=$(curl -s "${auth[@]}" -w '\n%{http_code}' -X POST "$base/api/jobs" \
  -d '{"scene": "cornell-box", "width": 64, "height": 48, "spp": 4, "formats": ["png"]}')
[ "$(tail -n1 <<<"$reply")" = 202 ] || fail "POST /api/jobs: $reply"
id=$(head -n1 <<<"$reply" | sed -n 's/.*"id":\([0-9]*\).*/\1/p')
[ -n "$id" ] || fail "no job id in $reply"
state=""
for _ in $(seq 150); do
  state=$(curl -s "${auth[@]}" "$base/api/jobs/$id" | sed -n 's/.*"state":"\([a-z]*\)".*/\1/p')
  [ "$state" = done ] && break
  [ "$state" = failed ] && fail "job $id failed"
  sleep 2
done
[ "$state" = done ] || fail "job $id is '$state' after 300 s"
code=$(curl -s "${auth[@]}" -o "$tmp/job.png" -w '%{http_code}' "$base/api/jobs/$id/result.png")
[ "$code" = 200 ] && [ "$(head -c 8 "$tmp/job.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] ||
  fail "result.png: HTTP $code, not a PNG"
echo "image test: job $id done, its PNG fetched ($(stat -c %s "$tmp/job.png") bytes)"

[ "$(command podman exec "$name" id -u)" = 10001 ] && [ "$(command podman exec "$name" id -g)" = 10001 ] ||
  fail "the daemon's user is $(command podman exec "$name" id)"
uids=$(command podman exec "$name" sh -c 'grep -E "^(Uid|Gid):" /proc/1/status' | awk '{print $2}' | sort -u)
[ "$uids" = 10001 ] || fail "process 1 runs as $uids, not 10001"
command podman cp "$name:/opt/geodesic/build/geodesic" "$tmp/geodesic"
if readelf -S "$tmp/geodesic" | grep -q '\.debug_info\|\.symtab'; then fail "the binary is not stripped"; fi
echo "image test: uid/gid 10001, binary stripped ($(( $(stat -c %s "$tmp/geodesic") / 1000000 )) MB)"

command podman restart -t 10 "$name" >/dev/null 2>"$tmp/run.err" || fail "podman restart: $(cat "$tmp/run.err")"
wait_healthy restart
state=$(curl -s "${auth[@]}" "$base/api/jobs/$id" | sed -n 's/.*"state":"\([a-z]*\)".*/\1/p')
[ "$state" = done ] || fail "after the restart job $id is '$state'"
cmp -s <(curl -s "${auth[@]}" "$base/api/jobs/$id/result.png") "$tmp/job.png" || fail "the PNG changed across the restart"
echo "image test: job $id and its PNG survived podman restart"

# kill -9 in the middle of a job: the next start resumes it from its checkpoint (made every
# 10 s), the sample count going on from there.
job_field() { sed -n "s/.*\"$1\":\([0-9a-z]*\).*/\1/p"; }
reply=$(curl -s "${auth[@]}" -w '\n%{http_code}' -X POST "$base/api/jobs" \
  -d '{"scene": "cornell-box", "width": 64, "height": 48, "seconds": 3600, "formats": ["png"]}')
[ "$(tail -n1 <<<"$reply")" = 202 ] || fail "POST /api/jobs: $reply"
long=$(head -n1 <<<"$reply" | job_field id)
checkpoint=0
for _ in $(seq 60); do
  checkpoint=$(curl -s "${auth[@]}" "$base/api/jobs/$long" | job_field checkpoint_samples)
  [ "${checkpoint:-0}" -gt 0 ] && break
  sleep 2
done
[ "${checkpoint:-0}" -gt 0 ] || fail "job $long made no checkpoint in 120 s"
command podman kill -s KILL "$name" >/dev/null 2>"$tmp/run.err" || fail "podman kill: $(cat "$tmp/run.err")"
command podman start "$name" >/dev/null 2>"$tmp/run.err" || fail "podman start: $(cat "$tmp/run.err")"
wait_healthy "after kill -9"
samples=0
for _ in $(seq 60); do
  status=$(curl -s "${auth[@]}" "$base/api/jobs/$long")
  state=$(sed -n 's/.*"state":"\([a-z]*\)".*/\1/p' <<<"$status")
  samples=$(job_field samples <<<"$status")
  [ "$state" = running ] && [ "${samples:-0}" -gt "$checkpoint" ] && break
  sleep 2
done
[ "$state" = running ] && [ "${samples:-0}" -gt "$checkpoint" ] ||
  fail "after kill -9 job $long is '$state' at ${samples:-?} spp (its checkpoint had $checkpoint)"
echo "image test: kill -9 with job $long checkpointed at $checkpoint spp; resumed, now $samples spp"
curl -s "${auth[@]}" -X DELETE "$base/api/jobs/$long" >/dev/null
command podman rm -f -t 5 "$name" >/dev/null 2>&1

bash "$here/compose_test.sh" "$image" "$token" "$tmp" "$name-compose"
echo "image test: passed"
