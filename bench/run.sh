#!/usr/bin/env bash
# Throughput of Geodesic on the bundled Cornell box (512x512, depth 5) for each tracing back
# end, with every path traced to full depth and with Russian roulette. With --with-cycles,
# Blender Cycles (CPU, 2 threads, no denoising, no adaptive sampling) renders the same scene in
# the same run, in the same two modes, and the ratios are printed; then the error per second
# of both on a scene they describe identically (bench/error_per_second.sh). --with-cycles
# installs Debian's blender package if it is missing.
#   bash bench/run.sh [--with-cycles] [--spp N] [--rounds R]
# --rounds (default 3 with --with-cycles, else 1): the two renderers take turns R times, each
# round Geodesic then Cycles in each mode, and each round's ratio is printed with their median
# and range. On a shared machine whose speed drifts by tens of per cent between minutes, a ratio
# of two runs taken minutes apart measures the drift; one of a round, seconds apart, much less.
set -euo pipefail
cd "$(dirname "$0")/.."
with_cycles=0
spp=64
rounds=
while [ $# -gt 0 ]; do
  case "$1" in
    --with-cycles) with_cycles=1 ;;
    --spp) spp="$2"; shift ;;
    --rounds) rounds="$2"; shift ;;
    *) echo "bench/run.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
[ -n "$rounds" ] || rounds=$((with_cycles ? 3 : 1))
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "bench/run.sh: --rounds must be a positive integer" >&2; exit 2; }

bash scripts/build.sh >/dev/null
scene=scenes/cornell-box.json
# Each run's lines go to stderr as they come (awk writes its own fd 2: `tee /dev/stderr` would
# reopen a log file that stderr is redirected to, from its start) and its figure to stdout: that
# of the back end the daemon picks on this device (its "auto back end" line), the one a user
# gets, not the faster of the two in this run (the larger of two noisy figures leans high).
picked() {
  awk '{ print > "/dev/stderr" } /M paths\/s/ { rate[$1] = $2 } /^auto back end/ { auto = $NF }
       END { print rate[auto] }'
}
geodesic() { ./build/bench/geodesic_bench "$scene" --spp "$spp" "$@" | picked; }

if [ "$with_cycles" = 0 ]; then
  for ((r = 1; r <= rounds; ++r)); do geodesic >/dev/null; geodesic --russian-roulette >/dev/null; done
  exit 0
fi

if ! command -v blender >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends blender >/dev/null
fi
cycles() {
  blender -b --factory-startup -P bench/cycles_cornell.py -- "$scene" "$spp" \
    "${TMPDIR:-/tmp}/geodesic-cycles-baseline.png" 2>/dev/null | grep '^cycles:' |
    awk '{ print > "/dev/stderr"; print }' | sed -E 's/.*: ([0-9.]+) M paths\/s/\1/'
}
table=$(mktemp)
trap 'rm -f "$table"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  full=$(geodesic)
  cycles_full=$(FULL_DEPTH=1 cycles)
  rr=$(geodesic --russian-roulette)
  cycles_rr=$(cycles)
  echo "$r $full $cycles_full $rr $cycles_rr" >> "$table"
done
printf '\n%-6s %28s %28s\n' "round" "full depth: geo / cyc M p/s" "roulette: geo / cyc M p/s"
awk '{ printf "%-6d %9.3f / %7.3f = %5.2fx %9.3f / %7.3f = %5.2fx\n", $1, $2, $3, $2 / $3,
       $4, $5, $4 / $5 }' "$table"
# The median and range of each mode's per-round ratio.
summary() { sort -g | awk -v format='%.2fx (%.2f-%.2f)' -f bench/median_range.awk; }
printf '%-28s full depth %s, roulette %s\n' "geodesic / cycles, median" \
  "$(awk '{ print $2 / $3 }' "$table" | summary)" "$(awk '{ print $4 / $5 }' "$table" | summary)"
echo
bash bench/error_per_second.sh --rounds "$rounds"
