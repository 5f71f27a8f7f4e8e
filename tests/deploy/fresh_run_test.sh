#!/usr/bin/env bash
# The README's run command as a new user runs it on a fresh Debian 12 machine: a bare container
# from the locally made base image (base_image.sh) with only the repository's files (tracked
# and new, nothing ignored), `bash scripts/run.sh` until the daemon answers /healthz, then a
# WebSocket JPEG frame. Prints the times (the README's figure). Exits 77 (skipped), saying so,
# only when podman cannot start a container here. Needs root.
#   fresh_run_test.sh [TIMEOUT_SECONDS]   (default 1500)
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
here="$repo/tests/deploy"
. "$here/podman_env.sh"
limit=${1:-1500}
name=geodesic-fresh-$$
token=$(od -An -N16 -tx1 /dev/urandom | tr -d ' \n')
tmp=$(mktemp -d)
trap 'command podman rm -f -t 5 "$name" >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
trap 'exit 143' TERM INT  # timeout(1): clean up too
if ! why=$(podman_ok); then
  echo "fresh run test: SKIPPED: the container engine cannot start here: $why"
  exit 77
fi
bash "$here/base_image.sh"
(cd "$repo" && git ls-files -z --cached --others --exclude-standard |
  tar --null --ignore-failed-read -c -T - -f "$tmp/tree.tar" 2>/dev/null)
port=$(( 20000 + RANDOM % 20000 ))
start=$(date +%s)
command podman run -d --name "$name" "${PODMAN_RUN_OPTS[@]}" -p "127.0.0.1:$port:8080" \
  -v "$tmp/tree.tar:/tree.tar:ro" debian:bookworm bash -c \
  "mkdir /geodesic && tar -C /geodesic -xf /tree.tar && cd /geodesic &&
   exec bash scripts/run.sh --host 0.0.0.0 --token $token" >/dev/null
until curl -sf "http://127.0.0.1:$port/healthz" >/dev/null; do
  if [ "$(command podman inspect -f '{{.State.Running}}' "$name")" != true ]; then
    command podman logs --tail 40 "$name" >&2
    echo "fresh run test: FAILED: scripts/run.sh exited" >&2; exit 1
  fi
  if [ $(( $(date +%s) - start )) -gt "$limit" ]; then
    command podman logs --tail 20 "$name" >&2
    echo "fresh run test: FAILED: not serving after $limit s" >&2; exit 1
  fi
  sleep 5
done
serving=$(( $(date +%s) - start ))
python3 "$here/ws_frame.py" 127.0.0.1 "$port" "$token" 300 ||
  { echo "fresh run test: FAILED: no frame" >&2; exit 1; }
logs=$(command podman logs "$name" 2>&1)
grep -q "install-deps: done" <<<"$logs" || { echo "fresh run test: FAILED: install-deps did not run" >&2; exit 1; }
if command podman exec "$name" sh -c 'command -v node || command -v chromium || dpkg -s libgtest-dev' >/dev/null 2>&1; then
  echo "fresh run test: FAILED: the run command installed test-only tools" >&2; exit 1
fi
[ ! -e "$(command podman mount "$name" 2>/dev/null)/geodesic/build/tests" ] ||
  { echo "fresh run test: FAILED: the run command built the test suites" >&2; exit 1; }
echo "fresh run test: bare Debian 12 to a serving daemon in $serving s, first frame after $(( $(date +%s) - start )) s"
