#!/usr/bin/env bash
# A patterned tyre against the slick one on the same contact grid
# ('Tread pattern', doc/methods/contact.md#tread-patterns): the scene's
# pattern of prm/tyre_pattern.prm (three pitch lengths in a sequence of 19,
# lateral grooves 5 mm and two circumferential grooves 8 mm wide, 6 mm deep)
# and the slick tyre, rolled side by side on road-A at 70 km/h over 1.2 m, on
# the main job's saved stages, on 4 x 4 and 8 x 8 subdivisions (1920 and
# 7680 points). For each tyre and grid: the time per step, and how far its
# force band levels (100 Hz to 5 kHz) moved from the coarser grid to the
# finer, the error the grid leaves in them; and the pattern's effect, the
# largest band-level difference between the patterned and the slick tyre.
# Then, on the finest grid, the blocks' own compliance ('Tread pattern/Block
# compliance'): the patterned tyre with the endless layer instead of the
# finite blocks, and with the blocks' mesh ('Block mesh size') refined and
# coarsened by 3/2, each beside its slick run: the time the blocks' set-up
# took, the time per step, and how far the force band levels moved from the
# finite blocks on the scene's mesh. Last, the blocks' mesh over its three
# levels (rms over the force bands from 250 Hz, the bands the error bars
# cover): the moves between levels, the order they show, and the scene's
# error bar of the blocks' mesh ('Error bars/Estimates' = block mesh)
# against the move to the finer mesh.
#
#   bash benchmarks/tread_pattern/tread_pattern.sh [--quick] [--output DIR] \
#     [main job's output] [program] [subdivisions...]
#
# defaults: output/, $GREENTREAD_PROGRAM else build/greentread, subdivisions
# 4 8. --quick makes its own stages on the coarse ring
# (common/saved_stages.sh) in DIR/stages and rolls on subdivisions 2 and 4
# (480 and 1920 points) at 3 road samples per step, the blocks' mesh 4 mm
# (refined to 2.67 mm, coarsened to 6 mm). Every run writes the
# table as DIR/tread_pattern.csv (DIR: build/benchmark-output/tread_pattern).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options tread_pattern.sh "$@"
set -- "${arguments[@]}"
saved=${1:-output}
program_argument tread_pattern.sh "${2:-}"
shift $(( $# < 2 ? $# : 2 ))
grids=("$@")
step=()
block_mesh=0.002
if $quick; then
  (( ${#grids[@]} > 0 )) || grids=(2 4)
  step=(--set "Time stepping/Time step=5.926e-05")
  block_mesh=0.004
  saved=$output/stages
  make_quick_stages "$saved"
fi
(( ${#grids[@]} > 0 )) || grids=(4 8)
for s in "${grids[@]}"; do check_number tread_pattern.sh subdivisions "$s" integer; done
(( ${#grids[@]} >= 2 )) || input_error "tread_pattern.sh: give two subdivisions or more (the grid's error is their difference)"
check_saved_stages tread_pattern.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

# The pattern of prm/tyre_pattern.prm, read from it so that the two agree.
pattern=()
while IFS= read -r line; do
  pattern+=(--set "Tread pattern/$line")
done < <(awk '/^subsection Tread pattern/ { on = 1; next } on && /^end/ { on = 0 }
              on { sub(/#.*/, ""); sub(/^ *set */, ""); sub(/ *= */, "="); sub(/ *$/, ""); if ($0 != "") print }' \
           "$top/prm/tyre_pattern.prm")

# ms per step of run $2 in log $1.
per_step() {
  awk -v run="$2" 'index($0, "    " run "_70kmh:") == 1 && / ms per step/ { print $4; exit }' \
    "$work/$1.log"
}

# Seconds the finite blocks' set-up took in log $1 (0: none).
setup_time() {
  awk '/block shapes on/ { for (i = 1; i <= NF; i++) if ($i == "s)") { print $(i - 1); found = 1 } }
       END { if (!found) print 0 }' "$work/$1.log"
}

# Largest |force band-level difference| [dB] between file $1 and file $2.
difference() {
  awk -F, 'FNR == 1 { file++ }
    /^[0-9]/ { if (file == 1) a[$1] = $6; else b[$1] = $6 }
    END { worst = 0; for (f in a) if (f in b) { d = a[f] - b[f]; if (d < 0) d = -d; if (d > worst) worst = d }
          printf "%.6e", worst }' "$1" "$2"
}

common=(--set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=70"
  --set "Rolling/Distance=1.2" --set "Spectra/Low bands up to=0" --set "Error bars/Estimates="
  "${pattern[@]}" "${step[@]}" --set "Tread pattern/Block mesh size=$block_mesh")
for s in "${grids[@]}"; do
  echo "  running s$s ..." >&2
  run_saved "s$s" "${common[@]}" --set "Contact grid/Subdivisions=$s"
done
finest=${grids[-1]}
fine_mesh=$(awk -v h="$block_mesh" 'BEGIN { printf "%.6g", h * 2 / 3 }')
echo "  running the blocks' alternatives on s$finest ..." >&2
# Each beside its own slick run, as on the grids, so that its time per step
# is measured as theirs is (two runs sharing the machine).
run_saved endless "${common[@]}" --set "Contact grid/Subdivisions=$finest" \
  --set "Tread pattern/Block compliance=endless layer"
run_saved fine_blocks "${common[@]}" --set "Contact grid/Subdivisions=$finest" \
  --set "Tread pattern/Block mesh size=$fine_mesh"
coarse_mesh=$(awk -v h="$block_mesh" 'BEGIN { printf "%.6g", h * 3 / 2 }')
run_saved coarse_blocks "${common[@]}" --set "Contact grid/Subdivisions=$finest" \
  --set "Tread pattern/Block mesh size=$coarse_mesh"
# The scene's error bar of the blocks' mesh (its level on the mesh 3/2 as
# coarse), on the same record.
run_saved estimate "${common[@]}" --set "Contact grid/Subdivisions=$finest" \
  --set "Tread pattern/Compare with slick=false" --set "Error bars/Estimates=block mesh"

g2() { awk -v x="$1" 'BEGIN { printf "%.2g", x }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }

echo "Tread pattern against slick: road-A at 70 km/h over 1.2 m, on the $($quick && echo "coarse ring's" || echo "main job's") saved stages"
echo "| points | patterned [ms per step] | slick [ms per step] | ratio | patterned: largest band move to ${finest} x ${finest} [dB] | slick: the same [dB] | pattern's effect: largest band difference from slick [dB] |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
echo "points,patterned_ms_per_step,slick_ms_per_step,ratio,patterned_grid_dB,slick_grid_dB,pattern_effect_dB" > "$work/table.csv"
for s in "${grids[@]}"; do
  p=$(per_step "s$s" road-A) q=$(per_step "s$s" road-A_slick)
  fine="$work/s$finest" here="$work/s$s"
  move_p=$(difference "$here/spectrum_force_road-A_70kmh.csv" "$fine/spectrum_force_road-A_70kmh.csv")
  move_s=$(difference "$here/spectrum_force_road-A_slick_70kmh.csv" "$fine/spectrum_force_road-A_slick_70kmh.csv")
  effect=$(difference "$here/spectrum_force_road-A_70kmh.csv" "$here/spectrum_force_road-A_slick_70kmh.csv")
  echo "| $(( 120 * s * s )) | $p | $q | $(ratio "$p" "$q") | $(g2 "$move_p") | $(g2 "$move_s") | $(g2 "$effect") |"
  echo "$(( 120 * s * s )),$p,$q,$(ratio "$p" "$q"),$move_p,$move_s,$effect" >> "$work/table.csv"
done

mm() { awk -v x="$1" 'BEGIN { printf "%.3g mm", 1e3 * x }'; }
fine="$work/s$finest/spectrum_force_road-A_70kmh.csv"
echo
echo "The blocks' own compliance on $(( 120 * finest * finest )) points (the patterned tyre, each beside its slick run):"
echo "| the tread's local compliance | blocks' set-up [s] | patterned [ms per step] | ratio to the slick run beside it | largest band move from the finite blocks on $(mm "$block_mesh") [dB] |"
echo "| --- | --- | --- | --- | --- |"
echo "blocks,setup_s,patterned_ms_per_step,ratio,blocks_dB" > "$work/blocks.csv"
for case in "coarse_blocks:finite blocks, $(mm "$coarse_mesh")" "s$finest:finite blocks, $(mm "$block_mesh")" \
  "fine_blocks:finite blocks, $(mm "$fine_mesh")" "endless:endless layer"; do
  log=${case%%:*} label=${case#*:}
  p=$(per_step "$log" road-A) q=$(per_step "$log" road-A_slick)
  move=$(difference "$work/$log/spectrum_force_road-A_70kmh.csv" "$fine")
  echo "| $label | $(setup_time "$log") | $p | $(ratio "$p" "$q") | $(g2 "$move") |"
  echo "\"$label\",$(setup_time "$log"),$p,$(ratio "$p" "$q"),$move" >> "$work/blocks.csv"
done
# The blocks' mesh over its three levels, band by band from 250 Hz (the
# bands the error bars cover): the rms of the differences between
# successive levels, the order they show, and the scene's estimate of the
# middle level's error against its difference from the finest.
mesh_order=$(awk -F, -v from=250 -v ratio=1.5 'FNR == 1 { file++ }
    file == 4 && FNR == 2 { for (i = 1; i <= NF; i++) if ($i == "block_mesh_dB") column = i }
    /^[0-9]/ && $1 >= from { l[file, $1] = $6; if (file == 1) bands[$1] = 1; if (file == 4) e[$1] = $column }
    END {
      if (!column) { print "tread_pattern.sh: no block_mesh_dB column in the estimate run" > "/dev/stderr"; exit 1 }
      for (f in bands) { a = l[1, f] - l[2, f]; b = l[2, f] - l[3, f]; sa += a * a; sb += b * b; se += e[f] * e[f]; n++ }
      sa = sqrt(sa / n); sb = sqrt(sb / n); se = sqrt(se / n)
      printf "%.6e,%.6e,%.3f,%.6e,%.3f", sa, sb, log(sa / sb) / log(ratio), se, se / sb }' \
  "$work/coarse_blocks/spectrum_force_road-A_70kmh.csv" "$fine" \
  "$work/fine_blocks/spectrum_force_road-A_70kmh.csv" "$work/estimate/spectrum_force_road-A_70kmh.csv")
IFS=, read -r coarse_move fine_move observed_order estimate_rms estimate_ratio <<< "$mesh_order"
echo
echo "The blocks' mesh, force bands from 250 Hz (rms over the bands): $(mm "$coarse_mesh") to $(mm "$block_mesh") moved them $(g2 "$coarse_move") dB, $(mm "$block_mesh") to $(mm "$fine_mesh") $(g2 "$fine_move") dB: observed order $observed_order; the scene's error bar on $(mm "$block_mesh") ('Error bars/Estimates' = block mesh) $(g2 "$estimate_rms") dB, $estimate_ratio times the move to $(mm "$fine_mesh")"
# One file for the smoke test's key numbers: the grids' rows (the finite
# blocks on the scene's mesh), then the blocks' rows on the finest grid
# (n/a: a column of the other table).
{
  head -1 "$work/table.csv" | tr -d '\n'; echo ",blocks,setup_s,blocks_dB"
  for s in "${grids[@]}"; do
    grep "^$(( 120 * s * s ))," "$work/table.csv" |
      sed "s/\$/,\"finite blocks, $(mm "$block_mesh")\",$(setup_time "s$s"),n\/a/"
  done
  tail -n +2 "$work/blocks.csv" |
    awk -F'",' -v points=$(( 120 * finest * finest )) \
      '{ split($2, f, ","); print points ",n/a,n/a,n/a,n/a,n/a,n/a," $1 "\"," f[1] "," f[4] }'
  echo "$(( 120 * finest * finest )),n/a,n/a,n/a,n/a,n/a,n/a,\"the error bar of the blocks' mesh\",n/a,$estimate_rms"
} | write_csv "$output/tread_pattern.csv"
