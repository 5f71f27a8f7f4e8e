#!/usr/bin/env bash
# Lints the deployment files: docker/Dockerfile with dockerfile-utils (the
# linter of VS Code's Docker support), docker/compose.yaml with dclint (the Compose
# specification's schema and its best practices, warnings fail too), and validates
# proto/openapi.json against the OpenAPI 3.1 schema. The linters are pinned in
# tests/web/package.json; scripts/install-deps.sh installs them. And deploy/kubernetes/*.yaml
# against the Kubernetes API schemas (tests/deploy/lint_kubernetes.mjs).
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

# Two rules are off on purpose: a top-level `name:` breaks docker-compose 1.29 (Debian's) and is
# ignored by podman-compose, and `image:` beside `build:` lets a compose `up` use an image
# already built (tests/deploy/compose_test.sh) instead of building it again.
"$bin/dclint" "$repo/docker/compose.yaml" "$repo/docker/compose.gpu.yaml" --max-warnings 0 \
  --disable-rule require-project-name-field --disable-rule no-build-and-image || status=1
echo "lint: docker/compose.yaml and compose.gpu.yaml checked"

# deploy/kubernetes against the Kubernetes API's schemas (kubernetes-models, offline).
node "$repo/tests/deploy/lint_kubernetes.mjs" "$repo"/deploy/kubernetes/*.yaml || status=1

out=$("$bin/validate-api" "$repo/proto/openapi.json" 2>&1) || status=1
if ! grep -q '"valid": true' <<<"$out"; then echo "$out"; status=1; fi
echo "lint: proto/openapi.json $(grep -q '"valid": true' <<<"$out" && echo valid || echo invalid)"
exit "$status"
