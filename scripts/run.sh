#!/usr/bin/env bash
# Installs what is missing, builds, and starts the render daemon on the default scene (the
# paper's Cornell box): open http://127.0.0.1:8080/ in a browser. Extra arguments go to
# `geodesic serve` (e.g. --host 0.0.0.0 --port 9000 --device nvidia). Only what building and
# running the daemon needs is installed, and only the daemon is built (scripts/test.sh does all).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --build
bash scripts/build.sh --daemon
exec ./build/geodesic serve "$@"
