#!/usr/bin/env bash
# Submits a sample-parallel render to Slurm: PARTS array tasks of SAMPLES samples each, then a
# merge job that runs only when all of them succeeded. --kill-on-invalid-dep=yes: a failed part
# cancels the merge instead of leaving it pending forever. Prints the two job ids.
#   submit.sh SCENE.json PARTS SAMPLES OUTDIR IMAGE [render options...]
# e.g. submit.sh scenes/cornell-box.json 4 256 /shared/render-1 cornell.png --width 1280 --height 960
# IMAGE may name several files, space-separated in one argument ("a.exr a.png"): one per format.
# OUTDIR must be on storage every node sees. GEODESIC_BIN: the geodesic executable (default
# `geodesic` on PATH); SBATCH_* variables and extra sbatch options (GEODESIC_SBATCH) pass through.
set -euo pipefail
if [ $# -lt 5 ]; then
  sed -n '2,10p' "$0" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
scene=$(realpath "$1") parts=$2 samples=$3 out=$4 image=$5
shift 5
[[ "$parts" =~ ^[1-9][0-9]*$ && "$samples" =~ ^[1-9][0-9]*$ ]] ||
  { echo "submit: PARTS and SAMPLES must be positive integers" >&2; exit 2; }
mkdir -p "$out"
out=$(realpath "$out")
bin=$(command -v "${GEODESIC_BIN:-geodesic}") || { echo "submit: no geodesic executable" >&2; exit 1; }
read -r -a extra <<<"${GEODESIC_SBATCH:-}"
export GEODESIC_BIN=$bin GEODESIC_SCENE=$scene GEODESIC_SAMPLES=$samples GEODESIC_OUT=$out \
  GEODESIC_IMAGE=$image GEODESIC_OPTIONS="$*"
parts_job=$(sbatch --parsable "${extra[@]}" --export=ALL --array=0-$((parts - 1)) \
  --output="$out/part-%a.log" "$here/render-part.sbatch")
parts_job=${parts_job%%;*}
merge_job=$(sbatch --parsable "${extra[@]}" --export=ALL --dependency=afterok:"$parts_job" \
  --kill-on-invalid-dep=yes --output="$out/merge.log" "$here/merge.sbatch")
echo "$parts_job ${merge_job%%;*}"
