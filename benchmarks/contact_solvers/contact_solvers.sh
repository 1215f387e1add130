#!/usr/bin/env bash
# The contact grid's solvers side by side ('Contact grid/Solver'):
# warm-started block principal pivoting on the formed N x N compliances (the
# reference, exact to round-off) against the matrix-free projected CG (MPRGP,
# the tread's layer by FFT) on the whole grid and on the candidate set (the
# points the road would be inside, checked on the whole grid: the default),
# on the main job's saved stages: road-A and road-B
# at 90 km/h over 1.2 m on 4 x 4 and 8 x 8 subdivisions (1920 and 7680
# points). For each run: the time per step and, for projected CG, the largest
# band-level difference (100 Hz to 5 kHz) from pivoting, stress and force.
# The candidate set runs twice: at the default 'Contact grid/Tolerance'
# (1e-6) and at 1e-10, the tolerance before it.
#
#   bash benchmarks/contact_solvers/contact_solvers.sh [--quick] [--output DIR] \
#     [main job's output] [program] [subdivisions...]
#
# defaults: output/, $GREENTREAD_PROGRAM else build/greentread, subdivisions
# 4 8. About 8 minutes on this 2-core machine (pivoting at 7680 points is
# most of it). --quick makes its own stages on the coarse ring
# (common/saved_stages.sh) in DIR/stages and compares the solvers on road-A
# only, on subdivisions 2 and 4 (480 and 1920 points), at 3 road samples per
# step (1042 steps). Every run writes the
# table as DIR/contact_solvers.csv (DIR: build/benchmark-output/contact_solvers).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options contact_solvers.sh "$@"
set -- "${arguments[@]}"
saved=${1:-output}
program_argument contact_solvers.sh "${2:-}"
shift $(( $# < 2 ? $# : 2 ))
grids=("$@")
roads=(road-A road-B)
step=()
if $quick; then
  (( ${#grids[@]} > 0 )) || grids=(2 4)
  roads=(road-A)
  step=(--set "Time stepping/Time step=4.608e-05")
  saved=$output/stages
  make_quick_stages "$saved"
fi
(( ${#grids[@]} > 0 )) || grids=(4 8)
for s in "${grids[@]}"; do check_number contact_solvers.sh subdivisions "$s" integer; done
check_saved_stages contact_solvers.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# ms per step of road $2 in run $1.
per_step() {
  # A run prints its lines with its name first: "    road-A_90kmh: 64.6 s, 20.7 ms per step".
  awk -v road="$2" 'index($0, "    " road "_") == 1 && / ms per step/ { print $4; exit }' \
    "$work/$1.log"
}

# Largest |level difference| [dB] between runs $1 and $2, road $3, spectrum kind $4.
difference() {
  awk -F, 'FNR == 1 { file++ }
    /^[0-9]/ { if (file == 1) a[$1] = $6; else b[$1] = $6 }
    END { worst = 0; for (f in a) if (f in b) { d = a[f] - b[f]; if (d < 0) d = -d; if (d > worst) worst = d }
          printf "%.6e", worst }' "$work/$1/$4$3_90kmh.csv" "$work/$2/$4$3_90kmh.csv"
}

# Both roads at 90 km/h over 1.2 m, one run each at the scene's step: no
# low-rate run and no error bars' runs, so that each road has one time per step.
single=(--set "Road texture/Roads=$(IFS=,; echo "${roads[*]}" | sed 's/,/, /g')" --set "Rolling/Speeds (kph)=90"
        --set "Rolling/Distance=1.2" --set "Spectra/Low bands up to=0" --set "Error bars/Estimates="
        "${step[@]}")

for s in "${grids[@]}"; do
  for solver in pivoting "projected CG on the whole grid" "projected CG"; do
    name="s${s}_${solver// /_}"
    echo "  running $name ..." >&2
    run_saved "$name" "${single[@]}" --set "Contact grid/Subdivisions=$s" \
      --set "Contact grid/Solver=$solver"
  done
  # The candidate set at the tolerance before 1e-6 was the default.
  echo "  running s${s}_projected_CG_1e-10 ..." >&2
  run_saved "s${s}_projected_CG_1e-10" "${single[@]}" --set "Contact grid/Subdivisions=$s" \
    --set "Contact grid/Tolerance=1e-10"
done

# Two significant digits, as the table gives a difference.
g2() { awk -v x="$1" 'BEGIN { printf "%.2g", x }'; }

echo "Contact solvers: $(echo "${roads[*]}" | sed 's/ / and /') at 90 km/h over 1.2 m ($($quick && echo 1042 || echo 3125) steps), on the $($quick && echo "coarse ring's" || echo "main job's") saved stages"
echo "| points | road | pivoting [ms per step] | projected CG on the whole grid [ms per step] | projected CG on the candidate set [ms per step] | the candidate set at tolerance 1e-10 [ms per step] | stress: largest band difference from pivoting, whole grid / candidate set / candidate set at 1e-10 [dB] | force: the same [dB] |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
echo "points,road,pivoting_ms_per_step,whole_grid_ms_per_step,candidate_set_ms_per_step,candidate_set_1e-10_ms_per_step,stress_whole_grid_dB,stress_candidate_set_dB,stress_candidate_set_1e-10_dB,force_whole_grid_dB,force_candidate_set_dB,force_candidate_set_1e-10_dB" > "$work/table.csv"
for s in "${grids[@]}"; do
  for road in "${roads[@]}"; do
    p="s${s}_pivoting" w="s${s}_projected_CG_on_the_whole_grid" c="s${s}_projected_CG" t="s${s}_projected_CG_1e-10"
    times=("$(per_step $p $road)" "$(per_step $w $road)" "$(per_step $c $road)" "$(per_step $t $road)")
    stress=("$(difference $p $w $road spectrum_)" "$(difference $p $c $road spectrum_)" "$(difference $p $t $road spectrum_)")
    force=("$(difference $p $w $road spectrum_force_)" "$(difference $p $c $road spectrum_force_)" "$(difference $p $t $road spectrum_force_)")
    echo "| $(( 120 * s * s )) | $road | ${times[0]} | ${times[1]} | ${times[2]} | ${times[3]} | $(g2 "${stress[0]}") / $(g2 "${stress[1]}") / $(g2 "${stress[2]}") | $(g2 "${force[0]}") / $(g2 "${force[1]}") / $(g2 "${force[2]}") |"
    echo "$(( 120 * s * s )),$road,$(IFS=,; echo "${times[*]},${stress[*]},${force[*]}")" >> "$work/table.csv"
  done
done
write_csv "$output/contact_solvers.csv" < "$work/table.csv"
