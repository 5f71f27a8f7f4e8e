#!/usr/bin/env bash
# Error per second against Blender Cycles on a scene both describe identically (default
# bench/scenes/cornell-shared.json: diffuse walls with a ceiling window, a white diffuse sphere,
# a 0.95 perfect mirror sphere, a point light, 128x128, depth 5). Each renderer renders its own
# high-sample reference (another seed), the two references are compared (relMSE and mean
# radiance per channel: they must agree, or the comparison is of different scenes), then each
# renders the series of sample counts and its relMSE against its own reference, its seconds
# (Cycles: the n samples' time without scene setup, as bench/cycles_cornell.py measures) and
# relMSE x seconds are printed, with the ratio Geodesic / Cycles (below 1: Geodesic reaches an
# error sooner).
# relMSE = mean over pixels and channels of (x - r)^2 / (r^2 + 0.01) (bench/image_error.cpp).
#   bash bench/error_per_second.sh [SCENE.json] [--spp 16,64,256] [--ref-spp 4096] [--rounds R]
# --rounds (default 1): the series is rendered R times, Cycles' then Geodesic's in each round,
# and the median and range of each sample count's ratio over the rounds are printed (the
# errors are the same every round, as the seeds are: only the seconds move).
# Installs Debian's blender package if it is missing; expects the build of bench/run.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=bench/scenes/cornell-shared.json
series=16,64,256
ref_spp=4096
rounds=1
while [ $# -gt 0 ]; do
  case "$1" in
    --spp) series="$2"; shift ;;
    --ref-spp) ref_spp="$2"; shift ;;
    --rounds) rounds="$2"; shift ;;
    -*) echo "bench/error_per_second.sh: unknown argument $1" >&2; exit 2 ;;
    *) scene="$1" ;;
  esac
  shift
done
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "bench/error_per_second.sh: --rounds must be a positive integer" >&2; exit 2; }
if ! command -v blender >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends blender >/dev/null
fi
[ -x build/geodesic ] && [ -x build/bench/geodesic_image_error ] || bash scripts/build.sh >/dev/null
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cycles() { blender -b --factory-startup -P bench/cycles_cornell.py -- "$@" 2>/dev/null; }
seconds_of() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["seconds"])' "$1"; }
field() { awk -v k="$1" '$1 == k { $1 = ""; print substr($0, 2) }'; }

echo "references: $ref_spp spp each, seed 7 ($scene)" >&2
build/geodesic render "$scene" --spp "$ref_spp" --seed 7 -o "$out/geodesic-ref.exr" >/dev/null
cycles "$scene" "$ref_spp" "$out/cycles-ref.exr" 7 >/dev/null
agreement=$(build/bench/geodesic_image_error "$out/geodesic-ref.exr" "$out/cycles-ref.exr")
echo "reference means (r g b), geodesic / cycles: $(field means <<<"$agreement")"
echo "relMSE of one reference against the other: $(field relmse <<<"$agreement")"

printf '\n%5s %6s %11s %8s %11s   %11s %8s %11s   %8s\n' round spp "geo relMSE" "s" "relMSE*s" \
  "cyc relMSE" "s" "relMSE*s" "geo/cyc"
for ((r = 1; r <= rounds; ++r)); do
  cycles "$scene" "$series" "$out" 1 | grep '^cycles-render:' > "$out/cycles.txt"
  for n in ${series//,/ }; do
    build/geodesic render "$scene" --spp "$n" --seed 1 -o "$out/geodesic-$n.exr" \
      --report "$out/geodesic-$n.json" >/dev/null
    g_err=$(build/bench/geodesic_image_error "$out/geodesic-$n.exr" "$out/geodesic-ref.exr" | field relmse)
    g_s=$(seconds_of "$out/geodesic-$n.json")
    c_s=$(awk -v n="$n" '$2 == n { print $3 }' "$out/cycles.txt")
    c_err=$(build/bench/geodesic_image_error "$out/cycles-$n.exr" "$out/cycles-ref.exr" | field relmse)
    awk -v r="$r" -v n="$n" -v ge="$g_err" -v gs="$g_s" -v ce="$c_err" -v cs="$c_s" 'BEGIN {
      printf "%5d %6d %11.3e %8.3f %11.3e   %11.3e %8.3f %11.3e   %7.2fx\n",
             r, n, ge, gs, ge * gs, ce, cs, ce * cs, (ge * gs) / (ce * cs) }' | tee -a "$out/rows.txt"
  done
done
if [ "$rounds" -gt 1 ]; then
  for n in ${series//,/ }; do
    format="$(printf '%6d' "$n") spp: relMSE x s, geodesic / cycles, median %.2fx (%.2f-%.2f)"
    awk -v n="$n" '$2 == n { sub("x", "", $NF); print $NF }' "$out/rows.txt" | sort -g |
      awk -v format="$format over %d rounds\n" -f bench/median_range.awk
  done
fi
