#!/usr/bin/env bash
# Does the rolling resistance the texture adds converge with the time step,
# at what order, and how far from its limit is the scene's step (one road
# sample)? The same road and record at steps of several road samples down to
# a fraction of one (the error against the step), each with its time per
# step (the cost).
#
# Each run rolls road-A and road-B side by side at 70 km/h over 2 m, one
# rate, no error bars' runs, on a copy of the main job's saved stages; only
# 'Time stepping/Time step' changes, as FACTORS times the scene's own step
# (one road sample: 19.7 us at 70 km/h). For each road and step: C_RR with
# its standard error (rolling_resistance.csv), its change from the next finer
# step, the order three successive steps show, and the time per step; then
# the finest two steps' Richardson extrapolation at the finest order shown,
# and how far the scene's step lies from it.
#
#   bash benchmarks/rolling_resistance/rolling_resistance.sh [--quick] [--output DIR] \
#        [main job's output] [program] [factors...]
#
# Defaults: output build/greentread 4 2 1 0.5 0.25 0.125 (the factors from
# coarse to fine, each half the one before). --quick makes its own stages on
# the coarse ring (common/saved_stages.sh) in DIR/stages and rolls 1.2 m at
# factors 2 1 0.5. Every run writes the table of the power into the
# structure as DIR/rolling_resistance.csv and that of the tread's losses as
# DIR/rolling_resistance_tread.csv (DIR: build/benchmark-output/rolling_resistance).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options rolling_resistance.sh "$@"
set -- "${arguments[@]}"
saved=${1:-output}
program_argument rolling_resistance.sh "${2:-}"
shift $(( $# < 2 ? $# : 2 ))
factors=("$@")
distance=2
if $quick; then
  (( ${#factors[@]} > 0 )) || factors=(2 1 0.5)
  distance=1.2
  saved=$output/stages
  make_quick_stages "$saved"
fi
(( ${#factors[@]} > 0 )) || factors=(4 2 1 0.5 0.25 0.125)
for f in "${factors[@]}"; do check_number rolling_resistance.sh factor "$f" number; done
(( ${#factors[@]} >= 3 )) ||
  input_error "rolling_resistance.sh: give three factors or more (an order needs three steps)"
awk 'BEGIN { for (i = 2; i < ARGC; i++) if (ARGV[i] * 2 != ARGV[i - 1] + 0) exit 1 }' "${factors[@]}" ||
  input_error "rolling_resistance.sh: factors '${factors[*]}'; allowed: from coarse to fine, each half the one before"
[[ " ${factors[*]} " == *" 1 "* ]] ||
  input_error "rolling_resistance.sh: factors '${factors[*]}'; allowed: 1 (the scene's step) among them"
check_saved_stages rolling_resistance.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

common=(--set "Road texture/Roads=road-A, road-B" --set "Rolling/Speeds (kph)=70"
  --set "Rolling/Distance=$distance" --set "Spectra/Low bands up to=0" --set "Error bars/Estimates=")

# The scene's own step ('auto'), then the others as multiples of it.
echo "  running the scene's step ..." >&2
run_saved f1 "${common[@]}"
scene_dt=$(awk -F, '!/^#/ && $1 == "road-A" { print $6 * 1e-6; exit }' "$work/f1/rolling_resistance.csv")
for f in "${factors[@]}"; do
  [[ $f == 1 ]] && continue
  dt=$(awk -v f="$f" -v h="$scene_dt" 'BEGIN { printf "%.8g", f * h }')
  echo "  running $f times the scene's step ($dt s) ..." >&2
  run_saved "f$f" "${common[@]}" --set "Time stepping/Time step=$dt"
done

# The scene's error bar on its step: the level at half the step over its
# short window ('Error bars/Estimates' = time step).
echo "  running the scene's step with its time step's error bar ..." >&2
run_saved estimate "${common[@]}" --set "Error bars/Estimates=time step"

# ms per step of run $2 in log $1.
per_step() {
  awk -v run="$2" 'index($0, "    " run "_70kmh:") == 1 && / ms per step/ { print $4; exit }' \
    "$work/$1.log"
}

# One part of the rolling resistance: its table on screen and in $3.
# $1: the part's column offset in the scene's rolling_resistance.csv (0 the
# structure's columns, 12 the tread's), $2 its name.
tabulate() {
  local off=$1
  echo "Rolling resistance ($2) against the time step: road-A and road-B at 70 km/h over $distance m, on the $($quick && echo "coarse ring's" || echo "main job's") saved stages"
  echo "road,factor,dt_us,coefficient,coefficient_se,ms_per_step,step_error" > "$work/runs.csv"
  for road in road-A road-B; do
    # The scene's error bar, on its run of the plan.
    estimate=$(awk -F, -v road="$road" -v off="$off" '!/^#/ && $1 == road && $5 == "plan" { print $(16 + off); exit }' \
      "$work/estimate/rolling_resistance.csv")
    [[ -n "$estimate" ]] ||
      { echo "rolling_resistance.sh: the scene gave $road no time step's error bar" >&2; exit 1; }
    for f in "${factors[@]}"; do
      awk -F, -v road="$road" -v f="$f" -v off="$off" -v ms="$(per_step "f$f" "$road")" \
        -v e="$([[ $f == 1 ]] && echo "$estimate" || echo n/a)" \
        '!/^#/ && $1 == road { printf "%s,%s,%s,%s,%s,%s,%s\n", road, f, $6, $(14 + off), $(15 + off), ms, e; exit }' \
        "$work/f$f/rolling_resistance.csv" >> "$work/runs.csv"
    done
  done

  # Per road: each step's change from the next finer, the order three
  # successive steps show (log2 of the ratio of their changes, the factors
  # halve), and from the finest two at the finest order shown the
  # extrapolated limit and each step's distance from it.
  awk -F, '
    NR == 1 { next }
    { n[$1]++; k = n[$1]; f[$1, k] = $2; dt[$1, k] = $3; c[$1, k] = $4; se[$1, k] = $5; ms[$1, k] = $6; e[$1, k] = $7
      if (!(($1) in seen)) { seen[$1] = 1; roads[++nr] = $1 } }
    END {
      print "road,factor,dt_us,coefficient,coefficient_se,change_from_finer,observed_order,from_limit_percent,ms_per_step,step_error,step_error_over_distance"
      for (r = 1; r <= nr; r++) {
        road = roads[r]; m = n[road]
        for (k = 1; k < m; k++) d[k] = c[road, k + 1] - c[road, k]
        p = "n/a"
        for (k = 1; k + 1 < m; k++) {
          o[k] = (d[k] * d[k + 1] > 0) ? log(d[k] / d[k + 1]) / log(f[road, k] / f[road, k + 1]) : "n/a"
          p = o[k]
        }
        # The limit from the finest two at the finest order shown.
        if (p != "n/a" && p > 0) {
          ratio = f[road, m - 1] / f[road, m]
          limit = c[road, m] + d[m - 1] / (ratio ^ p - 1)
        } else limit = "n/a"
        for (k = 1; k <= m; k++) {
          change = (k < m) ? sprintf("%.6e", d[k]) : "n/a"
          order = (k + 1 < m && o[k] != "n/a") ? sprintf("%.3f", o[k]) : "n/a"
          away = (limit != "n/a") ? sprintf("%.2f", 100 * (c[road, k] - limit) / limit) : "n/a"
          # The error bar of the scene against the distance from the limit.
          over = (e[road, k] != "n/a" && limit != "n/a") ? sprintf("%.3f", e[road, k] / sqrt((c[road, k] - limit) ^ 2)) : "n/a"
          printf "%s,%s,%s,%.6e,%.6e,%s,%s,%s,%s,%s,%s\n", road, f[road, k], dt[road, k], c[road, k], se[road, k], change, order, away, ms[road, k], e[road, k], over
        }
      }
    }' "$work/runs.csv" > "$work/table.csv"

  echo "| road | road samples per step | dt [us] | C_RR [1e-3] | its standard error [1e-3] | change to the next finer step [1e-3] | order shown with the next two | from the extrapolated limit [%] | the scene's time step error bar [1e-3] | it over the distance from the limit | ms per step |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  awk -F, 'NR > 1 {
      printf "| %s | %.3g | %.4g | %.4g | %.2g | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, 1e3 * $4, 1e3 * $5,
        ($6 == "n/a") ? "" : sprintf("%.3g", 1e3 * $6), ($7 == "n/a") ? "" : $7, $8,
        ($10 == "n/a") ? "" : sprintf("%.3g", 1e3 * $10), ($11 == "n/a") ? "" : $11, $9 }' "$work/table.csv"
  write_csv "$output/$3" < "$work/table.csv"
}

tabulate 0 "into the structure" rolling_resistance.csv
echo
tabulate 12 "the tread's losses" rolling_resistance_tread.csv
