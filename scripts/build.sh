#!/usr/bin/env bash
# Configures and builds Geodesic into build/ (Release with debug info).
#   build.sh            everything: the daemon, the test suites and the benchmarks
#   build.sh --daemon   the `geodesic` executable only (scripts/run.sh, docker/Dockerfile)
set -euo pipefail
cd "$(dirname "$0")/.."
daemon_only=OFF
case "${1:-}" in
  "") ;;
  --daemon) daemon_only=ON ;;
  *) echo "usage: build.sh [--daemon]" >&2; exit 2 ;;
esac
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGEODESIC_DAEMON_ONLY=$daemon_only >/dev/null
if [ $daemon_only = ON ]; then
  cmake --build build -j "$(nproc)" --target geodesic
else
  cmake --build build -j "$(nproc)"
fi
