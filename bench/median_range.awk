# The median, smallest and largest of the numbers on its input, sorted, one a line, printed
# with printf `format` (median, low, high, count in that order); shared by bench/run.sh and
# bench/error_per_second.sh for their per-round ratios.
#   sort -g | awk -v format='%.2fx (%.2f-%.2f)' -f bench/median_range.awk
{ v[NR] = $1 }
END {
  m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
  printf format, m, v[1], v[NR], NR
}
