#!/usr/bin/env bash
# Installs what is missing, builds, and renders the default scene (the paper's Cornell box)
# to out/cornell-box.png. Extra arguments go to `geodesic render`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
./build/geodesic render scenes/cornell-box.json -o out/cornell-box.png "$@"
