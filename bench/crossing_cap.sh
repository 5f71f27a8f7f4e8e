#!/usr/bin/env bash
# What the crossing cap costs in pixels and in time: renders a quotient scene at its own
# max_crossings and at each CAP given (default 32 48 64), same seed, same samples, as the PNGs a
# user sees (8-bit sRGB at the scene's exposure), and prints for each cap the share of pixels
# whose code differs from the highest cap's in any channel (idiff), the mean radiance and the
# paths/s. A geodesic given up at the cap returns as if it met nothing (docs/numerics.md).
#   bench/crossing_cap.sh SCENE.json [--size N] [CAP...]
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
bin=${GEODESIC_BIN:-$repo/build/geodesic}
scene=$(realpath "${1:?usage: crossing_cap.sh SCENE.json [--size N] [CAP...]}")
shift
size=128
if [ "${1:-}" = --size ]; then size=$2; shift 2; fi
caps=("$@")
[ ${#caps[@]} -gt 0 ] || caps=(32 48 64)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
own=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["manifold"].get("max_crossings", 16))' "$scene")
all=("$own" "${caps[@]}")
top=${all[-1]}
for cap in "${all[@]}"; do
  # The scene with its cap changed, beside the original so its relative files still resolve.
  copy=$(dirname "$scene")/.crossing-cap-$$-$cap.json
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); d["manifold"]["max_crossings"]=int(sys.argv[2]); json.dump(d,open(sys.argv[3],"w"))' \
    "$scene" "$cap" "$copy"
  "$bin" render "$copy" -o "$tmp/$cap.png" --width "$size" --height "$size" \
    --report "$tmp/$cap.json" >"$tmp/$cap.log" 2>&1 || { rm -f "$copy"; cat "$tmp/$cap.log"; exit 1; }
  rm -f "$copy"
done
printf '%-28s %5s %14s %10s %10s\n' scene cap 'px changed' 'M paths/s' truncated
for cap in "${all[@]}"; do
  changed=$(idiff -fail 0.0019 -failpercent 100 "$tmp/$cap.png" "$tmp/$top.png" 2>/dev/null |
            sed -n 's/.*pixels (\([0-9.e+-]*\)%) over.*/\1/p' | head -n1 || true)
  rate=$(sed -n 's/.* \([0-9.]*\) M paths\/s.*/\1/p' "$tmp/$cap.log")
  truncated=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["truncated_geodesics"])' "$tmp/$cap.json")
  printf '%-28s %5s %13s%% %10s %10s\n' "$(basename "$scene" .json)" "$cap" "${changed:-0}" "$rate" "$truncated"
done
