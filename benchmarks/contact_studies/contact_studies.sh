#!/usr/bin/env bash
# The contact scene's time-step study and its stiff and extreme cases, on the
# main job's saved stages (benchmarks/contact_studies/README.md: the tables "Time step"
# and "Stiff and extreme cases"). Each run reuses green_functions.h5 and the
# patch model from a copy of the main job's output directory, so only the
# rolling is timed.
#
#   bash benchmarks/contact_studies/contact_studies.sh [output directory of the main job] [program]
#
# defaults: output/ and build/greentread. The runs go to a temporary directory,
# removed at the end. About 27 minutes on this 2-core machine with the default
# patch model and contact grid (the ring's modes on 7680 contact points by
# projected CG: 7 to 11 ms per step, and about 40 s per run for the check of
# the reused model against the Green's functions).
set -euo pipefail

saved=${1:-output}
program=${2:-build/greentread}
source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
check_saved_stages contact_studies.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One run at one rate, without the error bars' runs: these studies compare
# single runs ('Spectra/Low bands up to' = 0, 'Error bars/Estimates' empty).
run() { run_saved "$@" --set "Spectra/Low bands up to=0" --set "Error bars/Estimates="; }

# The numbers of one run: seconds, points in contact, mean force, steps not
# converged, largest penetration.
summary() {
  local log=$work/$1.log
  local seconds contact force failed pen
  seconds=$(grep -oE '^    ([^ ]+: )?[0-9.]+ s, [0-9.]+ ms per step' "$log" | tail -1 |
            awk '{print $(NF - 5)}')
  contact=$(grep -oE 'points in contact [0-9]+% to [0-9]+%' "$log" | tail -1 | sed 's/points in contact //')
  force=$(grep -oE 'mean total force [0-9.]+ N \(static [0-9.e+-]+ N\)' "$log" | tail -1 |
          sed 's/mean total force //')
  failed=$(grep -oE 'did not converge: [0-9]+' "$log" | tail -1 | awk '{print $4}')
  pen=$(grep -oE "largest penetration at a step's end [0-9.e+-]+ m" "$log" | tail -1 | awk '{print $7}')
  echo "$seconds|$contact|$force|$failed|$pen"
}

# Largest |level difference| [dB] of run $1 against run $2, over bands up to
# $3 Hz, and over every band both have (with the highest band compared).
band_difference() {
  awk -F, -v top="$3" '
    FNR == 1 { file++ }
    /^[0-9]/ { if (file == 1) a[$1] = $6; else b[$1] = $6 }
    END {
      low = 0; all = 0; highest = 0
      for (f in a) if (f in b) {
        d = a[f] - b[f]; if (d < 0) d = -d
        if (f + 0 <= top && d > low) low = d
        if (d > all) all = d
        if (f + 0 > highest) highest = f + 0
      }
      printf "%.2f|%.2f (top band %d Hz)", low, all, highest
    }' "$work/$1"/spectrum_road-A_*kmh.csv "$work/$2"/spectrum_road-A_*kmh.csv
}

v=25           # m/s: 90 km/h
sample=0.000384 # m: Road texture/Spacing's default, the step of Time step = auto
common=(--set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=90" --set "Rolling/Distance=1.2288")

echo "Time step: road-A at 90 km/h over 1.2288 m (3200 road samples: every dt below a whole number of steps, every record 49.15 ms), band levels against dt = 1/20 of a road sample"
echo "| dt | road samples per step | run time [s] | steps not converged | max level difference, bands to 1 kHz [dB] | all bands [dB] |"
echo "| --- | --- | --- | --- | --- | --- |"
run reference "${common[@]}" --set "Time stepping/Time step=$(awk -v s=$sample -v v=$v 'BEGIN{printf "%.6e", s/v/20}')"
for factor in 20 5 2 1 0.5 0.2; do
  name=dt_$factor
  if [[ $factor == 1 ]]; then
    run "$name" "${common[@]}"
  else
    run "$name" "${common[@]}" --set "Time stepping/Time step=$(awk -v s=$sample -v v=$v -v f=$factor 'BEGIN{printf "%.6e", s/v*f}')"
  fi
  IFS='|' read -r seconds _ _ failed _ <<< "$(summary "$name")"
  dt=$(awk -v s=$sample -v v=$v -v f=$factor 'BEGIN{printf "%.3g us", 1e6*s/v*f}')
  echo "| $dt | $factor | $seconds | $failed | $(band_difference "$name" reference 1000) |"
done
IFS='|' read -r seconds _ _ failed _ <<< "$(summary reference)"
echo "| $(awk -v s=$sample -v v=$v 'BEGIN{printf "%.3g us", 1e6*s/v/20}') (reference) | 0.05 | $seconds | $failed | | |"

echo
echo "Stiff and extreme cases: 2 m each unless said; the saved stages reused"
echo "| case | points in contact | mean force (static) | steps not converged | largest penetration [m] | run time [s] |"
echo "| --- | --- | --- | --- | --- | --- |"
case_row() {
  local label=$1 name=$2
  IFS='|' read -r seconds contact force failed pen <<< "$(summary "$name")"
  echo "| $label | $contact | $force | $failed | $pen | $seconds |"
}
run rough --set "Road texture/Roads=sinusoid" --set "Road/Sinusoid/Amplitude=0.003" \
  --set "Road/Sinusoid/Wavelength=0.05" --set "Rolling/Speeds (kph)=90"
case_row "very rough: sinusoid, 3 mm amplitude, 5 cm wavelength, 90 km/h" rough
run fast --set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=130"
case_row "130 km/h, road-A" fast
run light_A --set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=90" --set "Rolling/Static load=0.01"
case_row "barely touching: 0.01 N, road-A, 90 km/h" light_A
run light_B --set "Road texture/Roads=road-B" --set "Rolling/Speeds (kph)=90" --set "Rolling/Static load=0.01"
case_row "barely touching: 0.01 N, road-B, 90 km/h" light_B
case_row "dt = 20 road samples (307 us), road-A, 90 km/h, 1.2288 m" dt_20
case_row "dt = 1/20 road sample (0.768 us), road-A, 90 km/h, 1.2288 m" reference
