#!/usr/bin/env bash
# Multi-rate estimation against brute force, on the main job's saved stages
# (benchmarks/multi_rate/README.md). For each road at 90 km/h, the main
# job's multi-rate estimate (the bands up to 'Spectra/Low bands up to' from a
# long run at 'Low-band time step', the bands above from the
# 2 m run at the step) against one run at the step over the low-rate run's
# whole distance ('Spectra/Low bands up to' = 0): the same road, the same
# record for the low bands, so their difference is the coarser step's alone.
# Prints, per band, both levels with their standard errors and whether they
# agree within two combined standard errors, and the contact stage's cost of
# each estimate.
#
#   bash benchmarks/multi_rate/multi_rate.sh [--quick] [--output DIR] \
#     [output directory of the main job] [program] [speed km/h] [roads]
#
# defaults: output/, $GREENTREAD_PROGRAM else build/greentread, 90,
# "road-A road-B". About 12 minutes on this 2-core machine (the brute-force
# runs are the longest). --quick makes its own stages on the coarse ring
# (common/saved_stages.sh) in DIR/stages and compares on road-A only, the
# run at the step over 1.2 m and the low-rate run over at most 3.6 m
# ('Spectra/Longest distance'), without the error bars' runs. Every run
# writes the tables as DIR/multi_rate.csv (DIR: build/benchmark-output/multi_rate).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options multi_rate.sh "$@"
set -- "${arguments[@]}"
(( $# <= 4 )) || input_error "multi_rate.sh: $# positional arguments ($*); allowed: at most 4, [main job's output] [program] [speed km/h] [roads]"
saved=${1:-output}
program_argument multi_rate.sh "${2:-}"
speed=${3:-90}
roads=${4:-road-A road-B}
check_number multi_rate.sh speed "$speed" number
# The quick run's shorter records.
shorter=()
if $quick; then
  roads=${4:-road-A}
  shorter=(--set "Rolling/Distance=1.2" --set "Spectra/Longest distance=3.6" --set "Error bars/Estimates=")
  saved=$output/stages
  make_quick_stages "$saved"
fi
[[ -n "${roads// /}" ]] || input_error "multi_rate.sh: roads = '$roads'; allowed: one or more roads, e.g. \"road-A road-B\""
check_saved_stages multi_rate.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Seconds of the contact runs of a log (the lines "<run>: 44.4 s, 8.53 ms per step").
run_seconds() {
  grep -oE '^    [^ ]+: [0-9.]+ s, [0-9.]+ ms per step' "$work/$1.log" |
    awk '{s += $2} END {printf "%.0f", s}'
}

csv=$work/table.csv
echo "road,speed_kmh,quantity,band_Hz,multi_rate_dB,multi_rate_standard_error_dB,from_time_step_us,from_record_m,one_rate_dB,one_rate_standard_error_dB,difference_dB,difference_over_combined_standard_error,within_2_combined_standard_errors,low_rate_distance_m,multi_rate_contact_s,one_rate_contact_s" > "$csv"
for road in $roads; do
  common=(--set "Road texture/Roads=$road" --set "Rolling/Speeds (kph)=$speed" "${shorter[@]}")
  run_saved "multi_$road" "${common[@]}"
  low=$(grep -oE "run [^ ]+_low-rate: V0 = [0-9.]+ km/h, dt = [0-9.]+ us, [0-9.]+ m, [0-9]+ steps" \
          "$work/multi_$road.log" | head -1)
  if [[ -z "$low" ]]; then
    echo "multi_rate.sh: the main job planned no low-rate run for $road at $speed km/h" >&2
    exit 1
  fi
  distance=$(awk '{print $(NF - 3)}' <<< "$low")
  run_saved "brute_$road" "${common[@]}" --set "Spectra/Low bands up to=0" \
    --set "Rolling/Distance=$distance"
  t_multi=$(run_seconds "multi_$road")
  t_brute=$(run_seconds "brute_$road")
  echo
  echo "$road at $speed km/h: the multi-rate estimate (${low#run }; and 2 m at the step)"
  echo "against one run at the step over $distance m; contact runs $t_multi s against $t_brute s" \
       "($(awk -v a="$t_multi" -v b="$t_brute" 'BEGIN{printf "%.0f", 100 * a / b}')% of the cost)"
  echo
  for quantity in spectra spectra_force; do
    echo "$quantity.csv (dB; the standard errors are one standard error):"
    echo
    echo "| band [Hz] | multi-rate | from | one rate | difference | within 2 combined SE |"
    echo "| --- | --- | --- | --- | --- | --- |"
    awk -F, -v csv="$csv" -v prefix="$road,$speed,$quantity" \
        -v suffix="$distance,$t_multi,$t_brute" '
      FNR == 1 { file++ }
      /^[a-zA-Z0-9_.\/-]+,[0-9.]+,[0-9]/ {
        key = $3
        if (file == 1) { m[key] = $4; ms[key] = $5; step[key] = $7; rec[key] = $8; order[++n] = key }
        else { b[key] = $4; bs[key] = $5 }
      }
      END {
        worst = 0; missed = 0
        for (i = 1; i <= n; i++) {
          k = order[i]
          d = m[k] - b[k]; ad = d < 0 ? -d : d
          se = sqrt(ms[k] * ms[k] + bs[k] * bs[k])
          ok = ad <= 2 * se ? "yes" : "no"
          if (ok == "no") missed++
          if (ad / se > worst) worst = ad / se
          printf "| %g | %.2f +- %.2f | %.0f us, %.2f m | %.2f +- %.2f | %+.2f | %s |\n",
                 k, m[k], ms[k], step[k], rec[k], b[k], bs[k], d, ok
          printf "%s,%g,%.6f,%.6f,%g,%g,%.6f,%.6f,%.6f,%.6f,%s,%s\n", prefix, k, m[k], ms[k], step[k],
                 rec[k], b[k], bs[k], d, ad / se, ok, suffix >> csv
        }
        printf "\nbands outside two combined standard errors: %d; largest difference %.2f combined standard errors\n\n", missed, worst
      }' "$work/multi_$road/$quantity.csv" "$work/brute_$road/$quantity.csv"
  done
done
write_csv "$output/multi_rate.csv" < "$csv"
