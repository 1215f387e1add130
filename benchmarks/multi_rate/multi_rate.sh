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
#   bash benchmarks/multi_rate/multi_rate.sh [output directory of the main job] [program] [speed km/h] [roads]
#
# defaults: output/, build/greentread, 90, "road-A road-B". About 12 minutes
# on this 2-core machine (the brute-force runs are the longest).
set -euo pipefail

saved=${1:-output}
program=${2:-build/greentread}
speed=${3:-90}
roads=${4:-road-A road-B}
source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
check_saved_stages multi_rate.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Seconds of the contact runs of a log (the lines "<run>: 44.4 s, 8.53 ms per step").
run_seconds() {
  grep -oE '^    [^ ]+: [0-9.]+ s, [0-9.]+ ms per step' "$work/$1.log" |
    awk '{s += $2} END {printf "%.0f", s}'
}

for road in $roads; do
  common=(--set "Road texture/Roads=$road" --set "Rolling/Speeds (kph)=$speed")
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
    awk -F, '
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
        }
        printf "\nbands outside two combined standard errors: %d; largest difference %.2f combined standard errors\n\n", missed, worst
      }' "$work/multi_$road/$quantity.csv" "$work/brute_$road/$quantity.csv"
  done
done
