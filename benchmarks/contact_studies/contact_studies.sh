#!/usr/bin/env bash
# The contact scene's time-step study and its stiff and extreme cases, on the
# main job's saved stages (benchmarks/contact_studies/README.md: the tables "Time step"
# and "Stiff and extreme cases"). Each run reuses green_functions.h5 and the
# patch model from a copy of the main job's output directory, so only the
# rolling is timed.
#
#   bash benchmarks/contact_studies/contact_studies.sh [--quick] [--output DIR] \
#     [output directory of the main job] [program]
#
# defaults: output/ and $GREENTREAD_PROGRAM else build/greentread. --quick
# makes its own stages on the coarse ring (common/saved_stages.sh) in
# DIR/stages; its time-step study has the reference at 1/5 of a road sample
# and the steps 20, 5, 2, 1 and 0.5 road samples, and its cases are the
# sinusoid, 130 km/h and 0.01 N on road-A, 1.6 m each. Every run writes both
# tables as DIR/contact_studies.csv (DIR: build/benchmark-output/contact_studies):
# the rows 'time step' of the first, 'case' of the second; a figure a row
# does not have is 'none'. The runs go to a temporary directory,
# removed at the end. About 27 minutes on this 2-core machine with the default
# patch model and contact grid (the ring's modes on 7680 contact points by
# projected CG: 7 to 11 ms per step, and about 40 s per run for the check of
# the reused model against the Green's functions).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options contact_studies.sh "$@"
set -- "${arguments[@]}"
(( $# <= 2 )) || input_error "contact_studies.sh: $# positional arguments ($*); allowed: at most 2, [main job's output] [program]"
saved=${1:-output}
program_argument contact_studies.sh "${2:-}"
# The reference step (this fraction of a road sample), the steps compared
# with it (in road samples), the cases' distance and their roads 'barely touching'.
fraction=20 factors=(20 5 2 1 0.5 0.2) cases_distance=2 light_roads=(road-A road-B)
if $quick; then
  fraction=5 factors=(20 5 2 1 0.5) cases_distance=1.6 light_roads=(road-A)
  saved=$output/stages
  make_quick_stages "$saved"
fi
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
      printf "%.6f|%.6f|%d", low, all, highest
    }' "$work/$1"/spectrum_road-A_*kmh.csv "$work/$2"/spectrum_road-A_*kmh.csv
}

v=25           # m/s: 90 km/h
sample=0.000384 # m: Road texture/Spacing's default, the step of Time step = auto
common=(--set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=90" --set "Rolling/Distance=1.2288")

csv=$work/table.csv
echo "table,label,dt_us,road_samples_per_step,run_time_s,steps_not_converged,difference_to_1kHz_dB,difference_all_bands_dB,top_band_Hz,contact_min_pct,contact_max_pct,mean_force_N,static_force_N,largest_penetration_m" > "$csv"
reference_dt=$(awk -v s=$sample -v v=$v -v f=$fraction 'BEGIN{printf "%.3g us", 1e6*s/v/f}')
echo "Time step: road-A at 90 km/h over 1.2288 m (3200 road samples: every dt below a whole number of steps, every record 49.15 ms), band levels against dt = 1/$fraction of a road sample"
echo "| dt | road samples per step | run time [s] | steps not converged | max level difference, bands to 1 kHz [dB] | all bands [dB] |"
echo "| --- | --- | --- | --- | --- | --- |"
run reference "${common[@]}" --set "Time stepping/Time step=$(awk -v s=$sample -v v=$v -v f=$fraction 'BEGIN{printf "%.6e", s/v/f}')"
for factor in "${factors[@]}"; do
  name=dt_$factor
  if [[ $factor == 1 ]]; then
    run "$name" "${common[@]}"
  else
    run "$name" "${common[@]}" --set "Time stepping/Time step=$(awk -v s=$sample -v v=$v -v f=$factor 'BEGIN{printf "%.6e", s/v*f}')"
  fi
  IFS='|' read -r seconds _ _ failed _ <<< "$(summary "$name")"
  dt=$(awk -v s=$sample -v v=$v -v f=$factor 'BEGIN{printf "%.3g us", 1e6*s/v*f}')
  IFS='|' read -r low all top <<< "$(band_difference "$name" reference 1000)"
  echo "| $dt | $factor | $seconds | $failed | $(printf '%.2f | %.2f (top band %d Hz)' "$low" "$all" "$top") |"
  echo "time step,dt,${dt% us},$factor,$seconds,$failed,$low,$all,$top,none,none,none,none,none" >> "$csv"
done
IFS='|' read -r seconds _ _ failed _ <<< "$(summary reference)"
echo "| $reference_dt (reference) | $(awk -v f=$fraction 'BEGIN{printf "%g", 1/f}') | $seconds | $failed | | |"
echo "time step,reference,${reference_dt% us},$(awk -v f=$fraction 'BEGIN{printf "%g", 1/f}'),$seconds,$failed,none,none,none,none,none,none,none,none" >> "$csv"

echo
echo "Stiff and extreme cases: $cases_distance m each unless said; the saved stages reused"
echo "| case | points in contact | mean force (static) | steps not converged | largest penetration [m] | run time [s] |"
echo "| --- | --- | --- | --- | --- | --- |"
case_row() {
  local label=$1 name=$2
  IFS='|' read -r seconds contact force failed pen <<< "$(summary "$name")"
  echo "| $label | $contact | $force | $failed | $pen | $seconds |"
  # "3% to 5%" and "593 N (static 600 N)" as numbers; the label without its commas.
  echo "case,${label//,/},none,none,$seconds,$failed,none,none,none,$(sed 's/% to /,/; s/%$//' <<< "$contact"),$(sed 's/ N (static /,/; s/ N)$//' <<< "$force"),$pen" >> "$csv"
}
cases=(--set "Rolling/Distance=$cases_distance")
run rough --set "Road texture/Roads=sinusoid" --set "Road/Sinusoid/Amplitude=0.003" \
  --set "Road/Sinusoid/Wavelength=0.05" --set "Rolling/Speeds (kph)=90" "${cases[@]}"
case_row "very rough: sinusoid, 3 mm amplitude, 5 cm wavelength, 90 km/h" rough
run fast --set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=130" "${cases[@]}"
case_row "130 km/h, road-A" fast
for road in "${light_roads[@]}"; do
  run "light_${road#road-}" --set "Road texture/Roads=$road" --set "Rolling/Speeds (kph)=90" \
    --set "Rolling/Static load=0.01" "${cases[@]}"
  case_row "barely touching: 0.01 N, $road, 90 km/h" "light_${road#road-}"
done
case_row "dt = 20 road samples (307 us), road-A, 90 km/h, 1.2288 m" dt_20
case_row "dt = 1/$fraction road sample ($reference_dt), road-A, 90 km/h, 1.2288 m" reference
write_csv "$output/contact_studies.csv" < "$csv"
