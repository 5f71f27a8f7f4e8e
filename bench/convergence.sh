#!/usr/bin/env bash
# Error against run time for the bundled scenes (docs/benchmarks.md, "Convergence"): for each
# scene, a cached high-sample reference, then the true and the estimated relative RMSE against
# seconds of rendering, as CSV and as a log-log PNG (gnuplot; Debian's gnuplot-nox is installed
# if missing), and one table row per scene.
#   bash bench/convergence.sh [--size WxH] [--time S] [--ref-spp N] [--ref-time S] [--build DIR]
#                             [SCENE.json...]
# Defaults: every scenes/*.json at 64x64 (each scene's own depth), 30 s of rendering per scene,
# references of 65536 spp or 90 s, whichever comes first; build dir build.
# Output in BUILD/bench-convergence/, references cached in BUILD/bench-cache/ under a hash of
# the scene file, these settings and the git-tracked renderer sources (shaders/, server/render,
# server/geometry, server/scene), so a changed renderer renders new references.
set -euo pipefail
cd "$(dirname "$0")/.."
size=64x64
seconds=30
ref_spp=65536
ref_seconds=90
build=build
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="$2"; shift ;;
    --time) seconds="$2"; shift ;;
    --ref-spp) ref_spp="$2"; shift ;;
    --ref-time) ref_seconds="$2"; shift ;;
    --build) build="$2"; shift ;;
    -*) echo "bench/convergence.sh: unknown argument $1" >&2; exit 2 ;;
    *) scenes+=("$1") ;;
  esac
  shift
done
[ ${#scenes[@]} -gt 0 ] || scenes=(scenes/*.json)
width=${size%x*}
height=${size#*x}

if ! command -v gnuplot >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gnuplot-nox \
    >/dev/null
fi
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target geodesic_convergence >/dev/null
bin=$build/bench/geodesic_convergence
out=$build/bench-convergence
cache=$build/bench-cache
mkdir -p "$out" "$cache"

renderer_sources=(shaders server/render server/geometry server/scene)
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  list_sources() { git ls-files -z "${renderer_sources[@]}"; }
else  # a source tarball: every file there
  list_sources() { find "${renderer_sources[@]}" -type f -print0 | sort -z; }
fi
renderer_hash=$(list_sources | xargs -0 cat | sha256sum | cut -c1-16)

plot() {  # plot NAME: $out/NAME.csv -> $out/NAME.png
  # The y axis goes down to the 1 % line at least, and below the lowest error measured.
  local ymin
  ymin=$(awk -F, 'BEGIN { m = 0.005 }
                  NR > 1 { for (i = 4; i <= 5; i++) if ($i > 0 && $i < m) m = $i }
                  END { print m / 1.5 }' "$out/$1.csv")
  gnuplot <<EOF
set terminal pngcairo size 800,560 noenhanced font "sans,11"
set output "$out/$1.png"
set datafile separator ","
set key autotitle columnhead top right
set logscale xy
set yrange [$ymin:*]
set grid xtics ytics mxtics mytics
set format y "%g"
set title "$1: relative RMSE against run time ($size, lavapipe)"
set xlabel "seconds of rendering"
set ylabel "relative RMS error (luminance)"
plot "$out/$1.csv" using 1:4 with linespoints pt 7 ps 0.6 lw 2 title "true (vs reference)", \
     "" using 1:(\$5 > 0 ? \$5 : NaN) with linespoints pt 6 ps 0.6 lw 1.5 \
       title "estimated (even/odd halves)", \
     "" using 1:6 with lines dt 2 lw 1.5 lc rgb "gray40" title "ideal t^(-1/2)", \
     0.05 with lines dt 3 lc rgb "black" title "5 %", \
     0.01 with lines dt 3 lc rgb "black" title "1 %"
EOF
}

header=--header
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  settings="$width $height $ref_spp $ref_seconds $renderer_hash"
  key=$( (cat "$scene"; echo "$settings") | sha256sum | cut -c1-16)
  "$bin" "$scene" --reference "$cache/$name-$key.exr" --csv "$out/$name.csv" \
    --width "$width" --height "$height" --ref-spp "$ref_spp" --ref-time "$ref_seconds" \
    --time "$seconds" $header
  header=
  if [ "$(wc -l < "$out/$name.csv")" -gt 1 ]; then plot "$name"; fi  # noise-free: no series
done
echo "CSV and PNG per scene in $out/"
