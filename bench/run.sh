#!/usr/bin/env bash
# Throughput of Geodesic on the bundled Cornell box (512x512, depth 5) for each tracing back end,
# and, with --with-cycles, Blender Cycles (CPU, 2 threads) on the same scene in the same run,
# with the ratio. --with-cycles installs Debian's blender package if it is missing.
#   bash bench/run.sh [--with-cycles] [--spp N]
set -euo pipefail
cd "$(dirname "$0")/.."
with_cycles=0
spp=64
while [ $# -gt 0 ]; do
  case "$1" in
    --with-cycles) with_cycles=1 ;;
    --spp) spp="$2"; shift ;;
    *) echo "bench/run.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done

bash scripts/build.sh >/dev/null
scene=scenes/cornell-box.json
geodesic=$(./build/bench/geodesic_bench "$scene" --spp "$spp" --repeat 3 | tee /dev/stderr)

if [ "$with_cycles" = 1 ]; then
  if ! command -v blender >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends blender >/dev/null
  fi
  cycles=$(blender -b --factory-startup -P bench/cycles_cornell.py -- "$scene" "$spp" \
             "${TMPDIR:-/tmp}/geodesic-cycles-baseline.png" 2>/dev/null | grep '^cycles:' | tee /dev/stderr)
  best=$(echo "$geodesic" | awk '/M paths\/s/ && $2 > b { b = $2 } END { print b }')
  base=$(echo "$cycles" | sed -E 's/.*: ([0-9.]+) M paths\/s/\1/')
  awk -v g="$best" -v c="$base" \
    'BEGIN { printf "geodesic (best back end) / cycles: %.2fx (%.3f vs %.3f M paths/s)\n", g / c, g, c }'
fi
