#!/usr/bin/env bash
# docker/compose.yaml with Debian's podman-compose (1.0): `up` starts the one lavapipe service
# from the image tests/deploy/image_test.sh built, its HEALTHCHECK passes, /api answers with the
# token, then `down -v`. podman-compose runs plain `podman`, so runc and the ulimits come from a
# containers.conf of this test's own (CONTAINERS_CONF).
#   compose_test.sh IMAGE TOKEN TMPDIR PROJECT
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
image=$1 token=$2 tmp=$3 project=$4
command -v podman-compose >/dev/null || { echo "compose test: podman-compose missing: run scripts/install-deps.sh" >&2; exit 1; }
cat > "$tmp/containers.conf" <<'CONF'
[containers]
default_ulimits = ["nofile=20000:20000", "nproc=32768:32768"]
[engine]
runtime = "runc"
CONF
export CONTAINERS_CONF=$tmp/containers.conf GEODESIC_IMAGE=$image GEODESIC_TOKEN=$token
export GEODESIC_HOST_PORT=$(( 20000 + RANDOM % 20000 ))
compose() { (cd "$repo/docker" && podman-compose -p "$project" -f compose.yaml "$@"); }
touch "$tmp/compose-up"
compose up -d >"$tmp/compose.log" 2>&1 || { cat "$tmp/compose.log"; echo "compose test: up failed" >&2; exit 1; }
containers=$(podman ps --filter "label=io.podman.compose.project=$project" --format '{{.Names}}')
[ "$(wc -l <<<"$containers")" = 1 ] || { echo "compose test: started '$containers', not one service" >&2; exit 1; }
for _ in $(seq 150); do
  podman healthcheck run "$containers" >/dev/null 2>&1 && break
  sleep 2
done
podman healthcheck run "$containers" >/dev/null || { podman logs --tail 20 "$containers"; echo "compose test: not healthy" >&2; exit 1; }
code=$(curl -s -o /dev/null -w '%{http_code}' -H "Authorization: Bearer $token" "http://127.0.0.1:$GEODESIC_HOST_PORT/api/jobs")
[ "$code" = 200 ] || { echo "compose test: /api/jobs answered $code" >&2; exit 1; }
compose down -v >>"$tmp/compose.log" 2>&1
rm -f "$tmp/compose-up"
echo "compose test: podman-compose up: one healthy service ($containers), /api/jobs 200; down -v"
