#!/usr/bin/env bash
# The discretisation error bars against the truth, on the main job's saved
# stages (doc/benchmarks.md, error_bars.sh). For each case, one run with the
# error bars (analysis/error_bars.h: one other level per discretisation, the
# step halved and the subdivisions halved, the difference scaled by the
# order) against runs refined further in each discretisation on the same
# road from the same start: the time step a quarter, 'Contact
# grid/Subdivisions' doubled, 'Geometry/Mesh size' halved (the 4 mm
# section, whose stages FINER_SECTION holds). The runs are single-rate ('Spectra/Low
# bands up to' = 0) and as long as the estimates' window (4 Fourier lines in
# the 250 Hz band, 69 ms, or the texture file's length), so that each level
# and its estimate cover the same record. Prints per band the estimate and
# the measured difference |L - L_refined| and their ratio, from 250 Hz (the
# bands the estimates cover), the bands within a factor 2, and the ratio of
# the rms over the bands (a single band's difference can pass through zero).
#
#   bash benchmarks/error_bars.sh [output directory of the main job] [program] [cases] [discretisations] [FINER_SECTION]
#
# cases: any of "default texture-file load" (default: all three):
#   default       road-A at 90 km/h, 600 N (the main job's first road)
#   texture-file  the worked example's texture file (make_example_road, 1 mm
#                 grid, 0.8 m) at 50 km/h
#   load          road-B at 50 km/h under 900 N
# discretisations: any of "time_step contact_grid ring_section" (default:
#   the first two). ring_section needs FINER_SECTION: the output directory
#   of a run of the program with 'Geometry/Mesh size' = 0.004 (every other
#   default, 'Error bars/Estimates' empty: about 30 minutes), whose stages
#   the refined runs reuse; the main job's output must hold its
#   coarser_section/ (the default 'Error bars/Estimates' saves it).
# About 30 minutes on this 2-core machine (the refined grid, 16 subdivisions
# on 30,720 points, is most of it).
set -euo pipefail

saved=${1:-output}
program=${2:-build/greentread}
cases=${3:-default texture-file load}
discretisations=${4:-time_step contact_grid}
finer_section=${5:-}
source "$(dirname "${BASH_SOURCE[0]}")/saved_stages.sh"
check_saved_stages error_bars.sh
if [[ " $discretisations " == *" ring_section "* ]]; then
  if [[ -z "$finer_section" || ! -f "$finer_section/green_functions.h5" ]]; then
    echo "error_bars.sh: ring_section needs FINER_SECTION (argument 5), the output of a run" \
         "with 'Geometry/Mesh size' = 0.004; '$finer_section' holds no green_functions.h5" >&2
    exit 1
  fi
  if [[ ! -f "$saved/coarser_section/green_functions.h5" ]]; then
    echo "error_bars.sh: '$saved' holds no coarser_section/: run the main job with the" \
         "default 'Error bars/Estimates' first" >&2
    exit 1
  fi
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
make_road=$(dirname "$program")/benchmarks/make_example_road
[[ -x "$make_road" ]] || make_road=$(dirname "$program")/../benchmarks/make_example_road

# The record of 4 lines in the 250 Hz band [s].
window=$(awk 'BEGIN { c = 1000 * 10^(-6/10); printf "%.6f", 4 / (c * (10^(1/20) - 10^(-1/20))) }')

run_case() {
  local name=$1 road=$2 speed=$3 load=$4 spacing=$5 distance=$6
  local dt
  dt=$(awk -v s="$spacing" -v v="$speed" 'BEGIN { printf "%.6e", s / (v / 3.6) }')
  local common=(--set "Road texture/Roads=$road" --set "Rolling/Speeds (kph)=$speed"
                --set "Rolling/Static load=$load" --set "Rolling/Distance=$distance"
                --set "Spectra/Low bands up to=0" --set "Time stepping/Time step=$dt")
  local estimates="" d
  for d in $discretisations; do estimates+="${estimates:+, }${d//_/ }"; done
  run_saved "${name}_estimated" "${common[@]}" --set "Error bars/Estimates=$estimates"
  [[ " $discretisations " == *" time_step "* ]] &&
    run_saved "${name}_time_step" "${common[@]}" --set "Error bars/Estimates=" \
      --set "Time stepping/Time step=$(awk -v d="$dt" 'BEGIN { printf "%.6e", d / 4 }')"
  [[ " $discretisations " == *" contact_grid "* ]] &&
    run_saved "${name}_contact_grid" "${common[@]}" --set "Error bars/Estimates=" \
      --set "Contact grid/Subdivisions=16"
  [[ " $discretisations " == *" ring_section "* ]] &&
    saved=$finer_section run_saved "${name}_ring_section" "${common[@]}" \
      --set "Error bars/Estimates=" --set "Geometry/Mesh size=0.004"
  return 0
}

compare() {
  local name=$1 title=$2
  echo
  echo "### $title"
  for quantity in spectra spectra_force; do
    for column in $discretisations; do
      local refined=$column
      echo
      echo "$quantity.csv, ${column//_/ } (dB):"
      echo
      echo "| band [Hz] | level | standard error | estimate | refined level | measured difference | estimate / measured |"
      echo "| --- | --- | --- | --- | --- | --- | --- |"
      awk -F, -v column="${column}_dB" '
        FNR == 1 { file++ }
        file == 1 && /^road,/ { for (i = 1; i <= NF; i++) if ($i == column) c = i }
        /^[a-zA-Z0-9_.\/-]+,[0-9.]+,[0-9]/ {
          key = $3
          if (file == 1) { l[key] = $4; se[key] = $5; e[key] = $c; order[++n] = key }
          else r[key] = $4
        }
        END {
          within = 0; counted = 0; se2 = 0; sm2 = 0
          for (i = 1; i <= n; i++) {
            k = order[i]
            if (k < 250) continue
            m = l[k] - r[k]; m = m < 0 ? -m : m
            if (e[k] == "" || e[k] == "nan") { printf "| %g | %.2f | %.2f | not estimated | %.2f | %.3f | |\n", k, l[k], se[k], r[k], m; continue }
            ratio = m > 0 ? e[k] / m : 0
            counted++; if (ratio >= 0.5 && ratio <= 2) within++
            se2 += e[k] * e[k]; sm2 += m * m
            printf "| %g | %.2f | %.2f | %.3f | %.2f | %.3f | %.2f |\n", k, l[k], se[k], e[k], r[k], m, ratio
          }
          printf "\nbands within a factor 2: %d of %d; rms over the bands: estimate %.3f dB, measured %.3f dB, ratio %.2f\n",
                 within, counted, sqrt(se2 / counted), sqrt(sm2 / counted), sqrt(se2 / sm2)
        }' "$work/${name}_estimated/$quantity.csv" "$work/${name}_${refined}/$quantity.csv"
    done
  done
}

for c in $cases; do
  case $c in
    default)
      run_case default road-A 90 600 3.84e-4 "$(awk -v w="$window" 'BEGIN { printf "%.4f", w * 25 }')"
      compare default "road-A at 90 km/h, 600 N" ;;
    texture-file)
      "$make_road" "$work/my_road.sdf" > /dev/null
      run_case texture "$work/my_road.sdf" 50 600 1e-3 0.64
      compare texture "the worked example's texture file (1 mm grid, 0.64 m) at 50 km/h, 600 N" ;;
    load)
      run_case load road-B 50 900 3.84e-4 "$(awk -v w="$window" 'BEGIN { printf "%.4f", w * 50 / 3.6 }')"
      compare load "road-B at 50 km/h, 900 N" ;;
    *) echo "error_bars.sh: unknown case '$c' (allowed: default, texture-file, load)" >&2; exit 1 ;;
  esac
done
