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
#   bash benchmarks/realisations/realisations.sh [output directory of the main job] [program] [road] [speed] [N] [distance]
#
# defaults: output/, build/greentread, road-A, 90, 10, 2. About 10 minutes
# on this 2-core machine (two runs at a time).
set -euo pipefail

saved=${1:-output}
program=${2:-build/greentread}
road=${3:-road-A}
speed=${4:-90}
n=${5:-10}
distance=${6:-2}
source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
check_saved_stages realisations.sh
(( n >= 3 )) || { echo "realisations.sh: N = $n; allowed: 3 or more realisations" >&2; exit 1; }

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
for quantity in spectra spectra_force; do
  echo
  echo "$quantity.csv (dB):"
  echo
  echo "| band [Hz] | mean level | spread (standard deviation) | standard error (rms of the records') | spread / standard error |"
  echo "| --- | --- | --- | --- | --- |"
  awk -F, '
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
      }
      printf "\nspread / standard error from %.2f to %.2f; %d of %d bands within a factor 1.5\n", low, high, within, m
    }' "$work"/seed_*/"$quantity.csv"
done
