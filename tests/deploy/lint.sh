#!/usr/bin/env bash
# Lints what CI cannot run here (no Docker engine): docker/Dockerfile with dockerfile-utils (the
# linter of VS Code's Docker support), docker/compose.yaml with dclint (the Compose
# specification's schema and its best practices, warnings fail too), and validates
# proto/openapi.json against the OpenAPI 3.1 schema. The linters are pinned in
# tests/web/package.json; scripts/install-deps.sh installs them.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
bin="$repo/tests/web/node_modules/.bin"
for tool in dockerfile-utils dclint validate-api; do
  [ -x "$bin/$tool" ] || { echo "lint: $tool is missing: run scripts/install-deps.sh" >&2; exit 1; }
done
status=0

# dockerfile-utils prints its problems and exits 0 on warnings: any output is a failure.
out=$("$bin/dockerfile-utils" lint "$repo/docker/Dockerfile" 2>&1) || status=1
if [ -n "$out" ]; then echo "$out"; status=1; fi
echo "lint: docker/Dockerfile $([ -z "$out" ] && echo clean || echo 'has problems')"

"$bin/dclint" --max-warnings 0 "$repo/docker/compose.yaml" || status=1
echo "lint: docker/compose.yaml checked"

out=$("$bin/validate-api" "$repo/proto/openapi.json" 2>&1) || status=1
if ! grep -q '"valid": true' <<<"$out"; then echo "$out"; status=1; fi
echo "lint: proto/openapi.json $(grep -q '"valid": true' <<<"$out" && echo valid || echo invalid)"
exit "$status"
