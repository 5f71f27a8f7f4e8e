#!/usr/bin/env bash
# Throughput of Geodesic on the bundled Cornell box (512x512, depth 5) for each tracing back
# end, with every path traced to full depth and with Russian roulette. With --with-cycles,
# Blender Cycles (CPU, 2 threads, no denoising, no adaptive sampling) renders the same scene in
# the same run, in the same two modes, and the ratios are printed; then the error per second
# of both on a scene they describe identically (bench/error_per_second.sh). --with-cycles
# installs Debian's blender package if it is missing.
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
best() { awk '/M paths\/s/ && $2 > b { b = $2 } END { print b }'; }

full=$(./build/bench/geodesic_bench "$scene" --spp "$spp" | tee /dev/stderr | best)
rr=$(./build/bench/geodesic_bench "$scene" --spp "$spp" --russian-roulette | tee /dev/stderr | best)

if [ "$with_cycles" = 1 ]; then
  if ! command -v blender >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends blender >/dev/null
  fi
  cycles() {
    blender -b --factory-startup -P bench/cycles_cornell.py -- "$scene" "$spp" \
      "${TMPDIR:-/tmp}/geodesic-cycles-baseline.png" 2>/dev/null | grep '^cycles:' |
      tee /dev/stderr | sed -E 's/.*: ([0-9.]+) M paths\/s/\1/'
  }
  cycles_full=$(FULL_DEPTH=1 cycles)
  cycles_rr=$(cycles)
  printf '\n%-28s %12s %12s\n' "M paths/s (512x512, depth 5)" "full depth" "roulette"
  printf '%-28s %12.3f %12.3f\n' "geodesic (best back end)" "$full" "$rr"
  printf '%-28s %12.3f %12.3f\n' "cycles (CPU, 2 threads)" "$cycles_full" "$cycles_rr"
  awk -v a="$full" -v b="$rr" -v c="$cycles_full" -v d="$cycles_rr" \
    'BEGIN { printf "%-28s %11.2fx %11.2fx\n", "geodesic / cycles", a / c, b / d }'
  echo
  bash bench/error_per_second.sh
fi
