#!/usr/bin/env bash
# The standard errors against the spread over independent realisations of a
# road, on the main job's saved stages (benchmarks/realisations/README.md).
# One road at one speed rolled on N realisations ('Road texture/Seed' = 1 to
# N: the same texture spectrum, independent textures, each from its own
# static start), one rate over 'Rolling/Distance', no error bars. Per band:
# the spread (standard deviation) of the N levels against the rms of the
# standard errors the N records predict for themselves, for the stress and
# the force; the error bars should hold the spread within a factor 1.5.
#
#   bash benchmarks/realisations/realisations.sh [--quick] [--output DIR] \
#     [output directory of the main job] [program] [road] [speed] [N] [distance]
#
# defaults: output/, $GREENTREAD_PROGRAM else build/greentread, road-A, 90,
# 10, 2. About 10 minutes on this 2-core machine (two runs at a time).
# --quick makes its own stages on the coarse ring (common/saved_stages.sh) in
# DIR/stages and rolls 4 realisations of 1.2 m (about 20 s). Every run
# writes the tables as DIR/realisations.csv (DIR: build/benchmark-output/realisations).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options realisations.sh "$@"
set -- "${arguments[@]}"
(( $# <= 6 )) || input_error "realisations.sh: $# positional arguments ($*); allowed: at most 6, [main job's output] [program] [road] [speed] [N] [distance]"
saved=${1:-output}
program_argument realisations.sh "${2:-}"
road=${3:-road-A}
speed=${4:-90}
n=${5:-10}
distance=${6:-2}
if $quick; then
  n=${5:-4}
  distance=${6:-1.2}
fi
check_number realisations.sh speed "$speed" number
check_number realisations.sh distance "$distance" number
[[ "$n" =~ ^[0-9]+$ ]] && (( n >= 3 )) ||
  input_error "realisations.sh: N = '$n'; allowed: a whole number of realisations, 3 or more"
if $quick; then
  saved=$output/stages
  make_quick_stages "$saved"
fi
check_saved_stages realisations.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for seed in $(seq 1 "$n"); do
  run_saved "seed_$seed" --set "Road texture/Roads=$road" --set "Rolling/Speeds (kph)=$speed" \
    --set "Road texture/Seed=$seed" --set "Rolling/Distance=$distance" \
    --set "Spectra/Low bands up to=0" --set "Error bars/Estimates=" &
  (( seed % 2 == 0 )) && wait
done
wait
for seed in $(seq 1 "$n"); do
  [[ -f "$work/seed_$seed/spectra.csv" ]] ||
    { echo "realisations.sh: the run of seed $seed failed:" >&2; tail -5 "$work/seed_$seed.log" >&2; exit 1; }
done

echo "$road at $speed km/h, $n realisations of $distance m ('Road texture/Seed' = 1 to $n), one rate"
csv=$work/table.csv
echo "quantity,band_Hz,mean_level_dB,spread_dB,standard_error_dB,spread_over_standard_error" > "$csv"
for quantity in spectra spectra_force; do
  echo
  echo "$quantity.csv (dB):"
  echo
  echo "| band [Hz] | mean level | spread (standard deviation) | standard error (rms of the records') | spread / standard error |"
  echo "| --- | --- | --- | --- | --- |"
  awk -F, -v csv="$csv" -v quantity="$quantity" '
    /^[a-zA-Z0-9_.\/-]+,[0-9.]+,[0-9]/ {
      k = $3; if (!(k in n)) order[++m] = k
      n[k]++; s[k] += $4; s2[k] += $4 * $4; e2[k] += $5 * $5
    }
    END {
      low = 1e9; high = 0; within = 0
      for (i = 1; i <= m; i++) {
        k = order[i]
        sd = sqrt((s2[k] - s[k] * s[k] / n[k]) / (n[k] - 1)); se = sqrt(e2[k] / n[k]); r = sd / se
        if (r < low) low = r; if (r > high) high = r
        if (r >= 1 / 1.5 && r <= 1.5) within++
        printf "| %g | %.2f | %.2f | %.2f | %.2f |\n", k, s[k] / n[k], sd, se, r
        printf "%s,%g,%.6f,%.6f,%.6f,%.6f\n", quantity, k, s[k] / n[k], sd, se, r >> csv
      }
      printf "\nspread / standard error from %.2f to %.2f; %d of %d bands within a factor 1.5\n", low, high, within, m
    }' "$work"/seed_*/"$quantity.csv"
done
write_csv "$output/realisations.csv" < "$csv"
