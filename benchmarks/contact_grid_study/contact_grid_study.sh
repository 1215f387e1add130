#!/usr/bin/env bash
# The contact grid's convergence study (benchmarks/contact_grid_study/README.md):
# road-A and road-B at 90 km/h over 1.2 m on the main job's saved stages, the
# Green's functions' 10 x 12 rectangles split into s x s contact rectangles
# ('Contact grid/Subdivisions'), and the paper's sub-grid rule 'point' beside
# the default 'envelope' on the coarsest and a fine grid. For each grid: the
# run time, the points in contact, the mean force, and the largest band-level
# difference (100 Hz to 5 kHz) of the stress at the patch centre (the mean over
# the reporting cell) and of the total force against the next finer grid and
# the finest, and the rolling resistance's coefficient with its standard
# error, the scene's contact grid error bar on it and its distance from the
# finest grid's; then both spectra band by band on the two finest grids.
#
#   bash benchmarks/contact_grid_study/contact_grid_study.sh [--quick] [--output DIR] \
#     [main job's output] [program] [runs directory] [subdivisions...]
#
# defaults: output/, $GREENTREAD_PROGRAM else build/greentread, a temporary
# directory removed at the end, and subdivisions 1 2 4 8 12 16. --quick makes
# its own stages on the coarse ring (common/saved_stages.sh) in DIR/stages and
# rolls road-A only on subdivisions 1 2 4 (the rule 'point' on 1 and 2).
# Every run writes both tables as DIR/contact_grid_study.csv (DIR:
# build/benchmark-output/contact_grid_study): the rows 'grids' of the first,
# the rows 'bands' of the second (one per grid, road and band); a figure a
# row does not have is 'none'. Every run uses the matrix-free solver
# ('Contact grid/Solver' = projected CG; SOLVER=pivoting in the environment
# for the dense one, up to s = 8), which gives the same levels as pivoting to
# 2e-5 dB (benchmarks/contact_solvers/README.md). About 30 minutes on 2 cores (each run also
# checks the reused modal model against the Green's functions, about 40 s).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options contact_grid_study.sh "$@"
set -- "${arguments[@]}"
saved=${1:-output}
program_argument contact_grid_study.sh "${2:-}"
keep=${3:-}
shift $(( $# < 3 ? $# : 3 ))
grids=("$@")
roads=(road-A road-B)
if $quick; then
  (( ${#grids[@]} > 0 )) || grids=(1 2 4)
  roads=(road-A)
  saved=$output/stages
  make_quick_stages "$saved"
fi
(( ${#grids[@]} > 0 )) || grids=(1 2 4 8 12 16)
for s in "${grids[@]}"; do check_number contact_grid_study.sh subdivisions "$s" integer; done
solver=${SOLVER:-projected CG}
[[ "$solver" == "projected CG" || "$solver" == pivoting ]] ||
  input_error "contact_grid_study.sh: SOLVER = '$solver'; allowed: 'projected CG' (the default) or pivoting"
check_saved_stages contact_grid_study.sh
if [[ -n "$keep" ]]; then
  work=$keep
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi

# run NAME ARGS...: both roads at 90 km/h over 1.2 m on a fresh copy of the saved stages.
run() {
  echo "  running $1 ..." >&2
  run_saved "$1" --set "Road texture/Roads=$(IFS=,; echo "${roads[*]}" | sed 's/,/, /g')" --set "Rolling/Speeds (kph)=90" \
    --set "Rolling/Distance=1.2" --set "Contact grid/Solver=$solver" "${@:2}"
}

# The figures of road $2 in run $1: seconds|ms per step|points in contact|mean
# force|the stress's highest band and centroid|the force's highest band.
figures() {
  awk -v road="$2" '
    { on = index($0, "    " road "_90kmh: ") == 1 }   # a run prints its lines with its name first
    on && /mean total force/ {
      match($0, /mean total force [0-9.]+/); force = substr($0, RSTART + 17, RLENGTH - 17)
      match($0, /points in contact [0-9]+% to [0-9]+%/); contact = substr($0, RSTART + 18, RLENGTH - 18)
    }
    on && / ms per step/ { seconds = $2; ms = $4 }
    index($0, "  " road " at 90 km/h: stress highest band") == 1 {
      match($0, /stress highest band [0-9]+ Hz \([0-9.-]+ dB\), spectral centroid [0-9]+ Hz/)
      stress = substr($0, RSTART + 20, RLENGTH - 20)
      sub(/ Hz \(/, " Hz, ", stress); sub(/\), spectral centroid /, "; centroid ", stress)
      match($0, /force highest band [0-9]+ Hz/); peak = substr($0, RSTART + 19, RLENGTH - 19)
    }
    END { printf "%s|%s|%s|%s|%s|%s", seconds, ms, contact, force, stress, peak }' "$work/$1.log"
}

# Largest |level difference| [dB] between runs $1 and $2, road $3, spectrum
# kind $4 (spectrum_ or spectrum_force_), and the band where it is.
difference() {
  awk -F, '
    FNR == 1 { file++ }
    /^[0-9]/ { if (file == 1) a[$1] = $6; else b[$1] = $6 }
    END {
      worst = 0; at = 0
      for (f in a) if (f in b) {
        d = a[f] - b[f]; if (d < 0) d = -d
        if (d > worst) { worst = d; at = f }
      }
      printf "%.6f %d", worst, at
    }' "$work/$1/$4$3_90kmh.csv" "$work/$2/$4$3_90kmh.csv"
}
# The rolling resistance of road $2 in run $1, from its run of the plan at
# the finest step: "C_RR se grid_error" (the scene's contact grid error bar;
# none where the grid has no coarser level).
resistance() {
  awk -F, -v road="$2" '
    !/^#/ && $1 == road && $5 == "plan" && (dt == "" || $6 < dt) {
      dt = $6; c = $14; se = $15; e = ($17 == "" ? "none" : $17)
    }
    END { printf "%s %s %s", c, se, e }' "$work/$1/rolling_resistance.csv"
}
# A coefficient in 1e-3 to three digits, or none.
milli() { [[ "$1" == none ]] && echo "" || awk -v c="$1" 'BEGIN { printf "%.3g", 1e3 * c }'; }
# A difference as the table gives it: "0.12 (800 Hz)".
shown() { [[ -z "$1" ]] || awk -v d="${1% *}" -v at="${1#* }" 'BEGIN { printf "%.2f (%d Hz)", d, at }'; }
# A difference as the CSV gives it: "0.123456,800", or "none,none".
fields() { if [[ -z "$1" ]]; then echo "none,none"; else echo "${1/ /,}"; fi; }

spacing() { awk -v s="$1" 'BEGIN { printf "%.2f x %.2f", 6 / s, 6.6667 / s }'; }

for s in "${grids[@]}"; do
  run "grid_$s" --set "Contact grid/Subdivisions=$s"
done
finest=${grids[-1]}
fine_rule=${grids[-2]:-$finest}
run point_1 --set "Contact grid/Subdivisions=1" --set "Road texture/Between points=point"
run "point_$fine_rule" --set "Contact grid/Subdivisions=$fine_rule" --set "Road texture/Between points=point"

echo "Contact grid: $(echo "${roads[*]}" | sed 's/ / and /') at 90 km/h over 1.2 m (3125 steps of 15.36 us); levels 100 Hz to 5 kHz; solver: $solver"
echo "| grid (s) | contact rectangle [mm] | points | road | run time [s] | per step [ms] | points in contact | mean force [N] | stress: highest band, centroid | largest difference to the next finer grid [dB] | to the finest | force: highest band | to the next finer grid [dB] | to the finest | C_RR [1e-3] | its standard error | the scene's contact grid error bar | C_RR to the finest |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
row() {
  local label=$1 name=$2 s=$3 next=$4 road=$5
  IFS='|' read -r seconds ms contact force stress peak <<< "$(figures "$name" "$road")"
  local sn="" sf="" fn="" ff=""
  if [[ -n "$next" ]]; then
    sn=$(difference "$name" "$next" "$road" spectrum_)
    fn=$(difference "$name" "$next" "$road" spectrum_force_)
  fi
  if [[ "$name" != "grid_$finest" ]]; then
    sf=$(difference "$name" "grid_$finest" "$road" spectrum_)
    ff=$(difference "$name" "grid_$finest" "$road" spectrum_force_)
  fi
  local rr_c rr_se rr_e rr_finest rr_to
  read -r rr_c rr_se rr_e <<< "$(resistance "$name" "$road")"
  read -r rr_finest _ <<< "$(resistance "grid_$finest" "$road")"
  rr_to=$(awk -v a="$rr_c" -v b="$rr_finest" 'BEGIN { d = a - b; printf "%.6g", d < 0 ? -d : d }')
  [[ "$name" == "grid_$finest" ]] && rr_to=none
  echo "| $label | $(spacing "$s") | $(( 120 * s * s )) | $road | $seconds | $ms | $contact | $force | $stress | $(shown "$sn") | $(shown "$sf") | $peak | $(shown "$fn") | $(shown "$ff") | $(milli "$rr_c") | $(milli "$rr_se") | $(milli "$rr_e") | $(milli "$rr_to") |"
  # "1000 Hz, 59.7 dB; centroid 1005 Hz" and "3% to 5%" as numbers.
  local band level centroid
  read -r band level centroid <<< "$(sed 's/ Hz, / /; s/ dB; centroid / /; s/ Hz$//' <<< "$stress")"
  echo "grids,$s,$rule,$(( 120 * s * s )),$road,$seconds,$ms,$(sed 's/% to /,/; s/%$//' <<< "$contact"),$force,$band,$level,$centroid,$(fields "$sn"),$(fields "$sf"),${peak% Hz},$(fields "$fn"),$(fields "$ff"),none,none,none,$rr_c,$rr_se,$rr_e,$rr_to" >> "$work/table.csv"
}
echo "table,grid,rule,points,road,run_time_s,ms_per_step,contact_min_pct,contact_max_pct,mean_force_N,stress_highest_band_Hz,stress_highest_dB,stress_centroid_Hz,stress_to_next_dB,stress_to_next_band_Hz,stress_to_finest_dB,stress_to_finest_band_Hz,force_highest_band_Hz,force_to_next_dB,force_to_next_band_Hz,force_to_finest_dB,force_to_finest_band_Hz,band_Hz,stress_dB,force_dB,rr_coefficient,rr_coefficient_se,rr_grid_error,rr_to_finest" > "$work/table.csv"
for road in "${roads[@]}"; do
  for i in "${!grids[@]}"; do
    s=${grids[$i]}
    next=""
    (( i + 1 < ${#grids[@]} )) && next="grid_${grids[$((i + 1))]}"
    rule=envelope row "$s" "grid_$s" "$s" "$next" "$road"
  done
  rule=point row "1, point" point_1 1 "" "$road"
  rule=point row "$fine_rule, point" "point_$fine_rule" "$fine_rule" "" "$road"
done

echo
echo "Band levels on the two finest grids (s = $fine_rule and $finest): stress at the patch centre [dB re 100 Pa], total force [dB re 1 N]"
header="| band [Hz] |"
grep -E '^[0-9]' "$work/grid_$fine_rule/spectrum_${roads[0]}_90kmh.csv" | cut -d, -f1 > "$work/column_0"
columns=("$work/column_0")
for road in "${roads[@]}"; do
  header+=" $road stress s=$fine_rule | s=$finest | $road force s=$fine_rule | s=$finest |"
  for kind in spectrum_ spectrum_force_; do
    for s in "$fine_rule" "$finest"; do
      columns+=("$work/column_${#columns[@]}")
      grep -E '^[0-9]' "$work/grid_$s/$kind${road}_90kmh.csv" | cut -d, -f6 > "${columns[-1]}"
    done
  done
done
echo "$header"
echo "| --- |$(printf ' --- |%.0s' $(seq 1 $(( 4 * ${#roads[@]} ))))"
paste -d, "${columns[@]}" |
  awk -F, '{ printf "| %s |", $1; for (i = 2; i <= NF; ++i) printf " %.1f |", $i; printf "\n" }'
for road in "${roads[@]}"; do
  for s in "$fine_rule" "$finest"; do
    paste -d, <(grep -E '^[0-9]' "$work/grid_$s/spectrum_${road}_90kmh.csv" | cut -d, -f1,6) \
      <(grep -E '^[0-9]' "$work/grid_$s/spectrum_force_${road}_90kmh.csv" | cut -d, -f6) |
      awk -F, -v s="$s" -v road="$road" '{ printf "bands,%s,envelope,%d,%s%s,%s,%.6f,%.6f,none,none,none,none\n", s, 120 * s * s, road, ",none,none,none,none,none,none,none,none,none,none,none,none,none,none,none,none,none", $1, $2, $3 }' \
      >> "$work/table.csv"
  done
done
write_csv "$output/contact_grid_study.csv" < "$work/table.csv"
