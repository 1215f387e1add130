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
#   bash benchmarks/contact_solvers/contact_solvers.sh [main job's output] [program] [subdivisions...]
#
# defaults: output/, build/greentread, subdivisions 4 8. About 8 minutes on
# this 2-core machine (pivoting at 7680 points is most of it).
set -euo pipefail

saved=${1:-output}
program=${2:-build/greentread}
shift $(( $# < 2 ? $# : 2 ))
grids=("$@")
(( ${#grids[@]} > 0 )) || grids=(4 8)
source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
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
          printf "%.2g", worst }' "$work/$1/$4$3_90kmh.csv" "$work/$2/$4$3_90kmh.csv"
}

# Both roads at 90 km/h over 1.2 m, one run each at the scene's step: no
# low-rate run and no error bars' runs, so that each road has one time per step.
single=(--set "Road texture/Roads=road-A, road-B" --set "Rolling/Speeds (kph)=90"
        --set "Rolling/Distance=1.2" --set "Spectra/Low bands up to=0" --set "Error bars/Estimates=")

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

echo "Contact solvers: road-A and road-B at 90 km/h over 1.2 m (3125 steps), on the main job's saved stages"
echo "| points | road | pivoting [ms per step] | projected CG on the whole grid [ms per step] | projected CG on the candidate set [ms per step] | the candidate set at tolerance 1e-10 [ms per step] | stress: largest band difference from pivoting, whole grid / candidate set / candidate set at 1e-10 [dB] | force: the same [dB] |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for s in "${grids[@]}"; do
  for road in road-A road-B; do
    p="s${s}_pivoting" w="s${s}_projected_CG_on_the_whole_grid" c="s${s}_projected_CG" t="s${s}_projected_CG_1e-10"
    echo "| $(( 120 * s * s )) | $road | $(per_step $p $road) | $(per_step $w $road) | $(per_step $c $road) | $(per_step $t $road) | $(difference $p $w $road spectrum_) / $(difference $p $c $road spectrum_) / $(difference $p $t $road spectrum_) | $(difference $p $w $road spectrum_force_) / $(difference $p $c $road spectrum_force_) / $(difference $p $t $road spectrum_force_) |"
  done
done
