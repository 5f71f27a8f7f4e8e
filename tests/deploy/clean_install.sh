#!/usr/bin/env bash
# The README's install step on a clean tree: the repository's files (tracked and new, nothing
# ignored: no build/, no node_modules) copied to a temporary directory, where
# scripts/install-deps.sh must succeed in each mode (all, --build for the image's build stage,
# --runtime for its last stage), install the npm tools into that tree, and leave a tree that
# CMake configures. Needs root, as the script does.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT

(cd "$repo" && git ls-files -z --cached --others --exclude-standard) |
  while IFS= read -r -d '' file; do
    [ -e "$repo/$file" ] || continue  # deleted in the working tree
    mkdir -p "$tree/$(dirname "$file")"
    cp -p "$repo/$file" "$tree/$file"
  done
[ ! -e "$tree/tests/web/node_modules" ] || { echo "clean install: the copy is not clean" >&2; exit 1; }

cd "$tree"
for mode in --runtime --build ""; do
  echo "clean install: scripts/install-deps.sh $mode"
  bash scripts/install-deps.sh $mode
done
for tool in playwright-core dclint dockerfile-utils validate-api; do
  [ -x "tests/web/node_modules/.bin/$tool" ] || { echo "clean install: no $tool after npm ci" >&2; exit 1; }
done
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
[ -f build/build.ninja ] || { echo "clean install: CMake wrote no build.ninja" >&2; exit 1; }
echo "clean install: passed"
