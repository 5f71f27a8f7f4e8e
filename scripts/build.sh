#!/usr/bin/env bash
# Configures and builds Geodesic into build/ (-O2).
#   build.sh            everything: the daemon, the test suites and the benchmarks, with line
#                       tables (-g1: backtraces and profiles name lines; full -g, which also
#                       describes variables, takes a fifth more compile time on the network layer)
#   build.sh --daemon   the `geodesic` executable only (scripts/run.sh, docker/Dockerfile): the
#                       same -O2 code without debug information, which a 2-core machine spends a
#                       quarter of the compile on (135 s -> 102 s) and the image strips anyway
set -euo pipefail
cd "$(dirname "$0")/.."
daemon_only=OFF
type=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
case "${1:-}" in
  "") ;;
  --daemon) daemon_only=ON type=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG") ;;
  *) echo "usage: build.sh [--daemon]" >&2; exit 2 ;;
esac
cmake -S . -B build -G Ninja "${type[@]}" -DGEODESIC_DAEMON_ONLY=$daemon_only >/dev/null
if [ $daemon_only = ON ]; then
  cmake --build build -j "$(nproc)" --target geodesic
else
  cmake --build build -j "$(nproc)"
fi
