#!/usr/bin/env bash
# The discretisation error bars against the truth, on the main job's saved
# stages (benchmarks/error_bars/README.md). For each case, one run with the
# error bars (analysis/error_bars.h: one other level per discretisation, the
# step halved and the subdivisions halved, the difference scaled by the
# order) against runs refined further in each discretisation on the same
# road from the same start: the time step a quarter, 'Contact
# grid/Subdivisions' doubled, 'Geometry/Mesh size' halved (the 4 mm
# section, whose stages $FINER_SECTION holds), 'Patch model/Mode cutoff' at
# 10 kHz (whose modes $FINER_CUTOFF holds). The runs are single-rate ('Spectra/Low
# bands up to' = 0) and as long as the estimates' window (4 Fourier lines in
# the 250 Hz band, 69 ms, or the texture file's length), so that each level
# and its estimate cover the same record. Prints per band the estimate and
# the measured difference |L - L_refined| and their ratio, from 250 Hz (the
# bands the estimates cover), the bands within a factor 2, and the ratio of
# the rms over the bands (a single band's difference can pass through zero).
#
#   [FINER_SECTION=DIR] [FINER_CUTOFF=DIR] [COARSER_CUTOFF=DIR] bash benchmarks/error_bars/error_bars.sh \
#     [--quick] [--output DIR] [output directory of the main job] [program] [cases] [discretisations]
#
# cases: any of "default texture-file load section" (default: the first three):
#   default       road-A at 90 km/h, 600 N (the main job's first road)
#   texture-file  the worked example's texture file (make_example_road, 1 mm
#                 grid, 0.8 m) at 50 km/h
#   load          road-B at 50 km/h under 900 N
#   section       another tyre section, road-A at 70 km/h under 600 N: a
#                 185/65 R13 on a 5 in rim (tread 185 mm wide, section 195 mm
#                 wide and 120.25 mm high), its tread surface falling 3 mm from
#                 the crown to the tread's edges ('Crown drop', a constant of
#                 the .geo through 'Geometry/Other constants'); the settings
#                 are $section_geometry below. It was not one of the three
#                 cases that chose the ring section's order. Its stages are
#                 not the main job's: it runs alone, the first positional
#                 argument the output directory of a run of the program with
#                 $section_geometry and the default 'Error bars/Estimates',
#                 and FINER_SECTION (and FINER_CUTOFF, COARSER_CUTOFF) made
#                 with $section_geometry too (benchmarks/error_bars/README.md
#                 gives the commands).
# discretisations: any of "time_step contact_grid mode_cutoff ring_section"
#   (default: the first two, which need only the main job's stages).
#   mode_cutoff needs FINER_CUTOFF: the output directory of a run of the
#   program with 'Patch model/Mode cutoff' = 10000 on a copy of the main
#   job's green_functions.h5 ('Error bars/Estimates' empty and one short
#   run, as benchmarks/error_bars/README.md gives it: about 5 minutes). With
#   COARSER_CUTOFF, the same with 'Mode cutoff' = 6000, each case also rolls
#   at 6 kHz with its own estimate (from 4.5 kHz), and the script prints how
#   the levels converge over 4.5, 6, 8 and 10 kHz, and the estimate a
#   third level would give (the observed ratio of successive differences).
#   ring_section needs FINER_SECTION: the output directory of a run with
#   'Geometry/Mesh size' = 0.004 (the same way: about 20 minutes), and the
#   main job's output must hold its coarser_section/ (the default 'Error
#   bars/Estimates' saves it).
# About 30 minutes on this 2-core machine for the first two (the refined
# grid, 16 subdivisions on 30,720 points, is most of it), 5 for the other two.
# The program: the second positional argument, else $GREENTREAD_PROGRAM, else
# build/greentread.
#
# --quick makes its own stages on the coarse ring (common/saved_stages.sh) in
# DIR/stages, and those of the mode cut-off's refined level (5 kHz against
# the ring's 4 kHz, as 10 kHz against the default 8 kHz) in DIR/finer_cutoff;
# its cases default to 'default' and its discretisations to "time_step
# contact_grid mode_cutoff", the contact grid refined from 2 to 4
# subdivisions (ring_section and COARSER_CUTOFF are not allowed with it).
# Every run writes the tables as DIR/error_bars.csv (DIR:
# build/benchmark-output/error_bars): the rows 'band', one per band, and
# 'rms', the line under each table; a figure a row does not have is 'none'.
set -euo pipefail
# The case 'section''s tyre: every run of it, and the runs that make its
# stages, take these settings (the stages are keyed on them).
section_geometry=(--set "Geometry/Tread width=0.185" --set "Geometry/Section width=0.195"
                  --set "Geometry/Section height=0.12025" --set "Geometry/Rim width=0.127"
                  --set "Geometry/Other constants=Crown drop=0.003")

source "$(dirname "${BASH_SOURCE[0]}")/../common/saved_stages.sh"
parse_options error_bars.sh "$@"
set -- "${arguments[@]}"
(( $# <= 4 )) || input_error "error_bars.sh: $# positional arguments ($*); allowed: at most 4, [main job's output] [program] [cases] [discretisations]"
saved=${1:-output}
program_argument error_bars.sh "${2:-}"
cases=${3:-default texture-file load}
discretisations=${4:-time_step contact_grid}
# The refined contact grid's subdivisions and the refined mode cut-off [Hz].
refined_subdivisions=16 refined_cutoff=10000
if $quick; then
  cases=${3:-default}
  discretisations=${4:-time_step contact_grid mode_cutoff}
  refined_subdivisions=4 refined_cutoff=5000
fi
for c in $cases; do
  [[ " default texture-file load section " == *" $c "* ]] ||
    input_error "error_bars.sh: case '$c' (the third positional argument); allowed: default, texture-file, load, section"
done
# The case 'section' runs alone, on stages of its own section.
if [[ " $cases " == *" section "* ]]; then
  if $quick; then
    input_error "error_bars.sh: case 'section' is not allowed with --quick (it needs stages of its own section)"
  fi
  for c in $cases; do
    [[ $c == section ]] ||
      input_error "error_bars.sh: cases = '$cases'; 'section' runs alone (its stages are not the main job's: see this script's header)"
  done
fi
allowed="time_step contact_grid mode_cutoff ring_section"
$quick && allowed="time_step contact_grid mode_cutoff"
for d in $discretisations; do
  [[ " $allowed " == *" $d "* ]] ||
    input_error "error_bars.sh: discretisation '$d' (the fourth positional argument); allowed$($quick && echo " with --quick"): ${allowed// /, }"
done
[[ -n "${cases// /}" && -n "${discretisations// /}" ]] ||
  input_error "error_bars.sh: cases = '$cases', discretisations = '$discretisations'; allowed: one or more of each"
if $quick; then
  [[ -z "${COARSER_CUTOFF:-}" ]] || input_error "error_bars.sh: COARSER_CUTOFF = '$COARSER_CUTOFF'; allowed with --quick: unset"
  saved=$output/stages
  make_quick_stages "$saved"
  if [[ " $discretisations " == *" mode_cutoff "* ]]; then
    FINER_CUTOFF=$output/finer_cutoff
    mkdir -p "$FINER_CUTOFF"
    cp "$saved/green_functions.h5" "$FINER_CUTOFF"/
    make_quick_stages "$FINER_CUTOFF" --set "Patch model/Mode cutoff=$refined_cutoff"
  fi
fi
check_saved_stages error_bars.sh
# needs_stages DISCRETISATION DIR VARIABLE: refuse a refined level without its stages.
needs_stages() {
  if [[ " $discretisations " == *" $1 "* && ( -z "$2" || ! -f "$2/green_functions.h5" ) ]]; then
    echo "error_bars.sh: $1 needs $3, the output directory of the refined level's run" \
         "(see this script's header); '$2' holds no green_functions.h5" >&2
    exit 2
  fi
}
needs_stages ring_section "${FINER_SECTION:-}" FINER_SECTION
needs_stages mode_cutoff "${FINER_CUTOFF:-}" FINER_CUTOFF
if [[ -n "${COARSER_CUTOFF:-}" && ! -f "$COARSER_CUTOFF/green_functions.h5" ]]; then
  echo "error_bars.sh: COARSER_CUTOFF='$COARSER_CUTOFF' holds no green_functions.h5:" \
       "the output directory of the run with 'Patch model/Mode cutoff' = 6000 (this script's header)" >&2
  exit 2
fi
# The mode cut-off's four levels: with mode_cutoff and COARSER_CUTOFF.
four_levels=false
[[ " $discretisations " == *" mode_cutoff "* && -n "${COARSER_CUTOFF:-}" ]] && four_levels=true
if [[ " $discretisations " == *" ring_section "* && ! -f "$saved/coarser_section/green_functions.h5" ]]; then
  echo "error_bars.sh: '$saved' holds no coarser_section/: run the main job with the" \
       "default 'Error bars/Estimates' first" >&2
  exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
make_road=$(dirname "$program")/benchmarks/make_example_road
[[ -x "$make_road" ]] || make_road=$(dirname "$program")/../benchmarks/make_example_road

# The record of 4 lines in the 250 Hz band [s].
window=$(awk 'BEGIN { c = 1000 * 10^(-6/10); printf "%.6f", 4 / (c * (10^(1/20) - 10^(-1/20))) }')

run_case() {
  local name=$1 road=$2 speed=$3 load=$4 spacing=$5 distance=$6
  shift 6
  local dt
  dt=$(awk -v s="$spacing" -v v="$speed" 'BEGIN { printf "%.6e", s / (v / 3.6) }')
  # The case's own settings (its section's), then the rolling's.
  local common=("$@" --set "Road texture/Roads=$road" --set "Rolling/Speeds (kph)=$speed"
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
      --set "Contact grid/Subdivisions=$refined_subdivisions"
  [[ " $discretisations " == *" ring_section "* ]] &&
    saved=$FINER_SECTION run_saved "${name}_ring_section" "${common[@]}" \
      --set "Error bars/Estimates=" --set "Geometry/Mesh size=0.004"
  [[ " $discretisations " == *" mode_cutoff "* ]] &&
    saved=$FINER_CUTOFF run_saved "${name}_mode_cutoff" "${common[@]}" \
      --set "Error bars/Estimates=" --set "Patch model/Mode cutoff=$refined_cutoff"
  $four_levels &&
    saved=$COARSER_CUTOFF run_saved "${name}_cutoff_6k" "${common[@]}" \
      --set "Error bars/Estimates=mode cutoff" --set "Patch model/Mode cutoff=6000"
  return 0
}

# cutoff_convergence NAME: with COARSER_CUTOFF, the mode cut-off's four levels
# (4.5, 6, 8 and 10 kHz) of case NAME: the rms over the bands from 250 Hz of
# the successive level differences, and how they fall from one step of the
# cut-off to the next. Each run's estimate is its factor (the run prints it)
# times the difference from its coarser level, so that difference is the
# estimate over the factor.
# cutoff_factor LOG: the mode cut-off estimate's factor that the run of LOG printed.
cutoff_factor() {
  local f
  f=$(sed -n "s/.*the mode cut-off's error bar:.* the estimate is \([0-9.e+-]*\) times.*/\1/p" "$1")
  [[ -n "$f" ]] || { echo "error_bars.sh: $1 prints no mode cut-off factor" >&2; exit 1; }
  echo "$f"
}

cutoff_convergence() {
  local name=$1 quantity f8 f6
  f8=$(cutoff_factor "$work/${name}_estimated.log")
  f6=$(cutoff_factor "$work/${name}_cutoff_6k.log")
  for quantity in spectra spectra_force; do
    awk -F, -v f8="$f8" -v f6="$f6" -v q="$quantity" '
      FNR == 1 { file++ }
      /^road,/ { for (i = 1; i <= NF; i++) if ($i == "mode_cutoff_dB") c[file] = i }
      /^[a-zA-Z0-9_.\/-]+,[0-9.]+,[0-9]/ && $3 >= 250 {
        if (file == 1) { l8[$3] = $4; e8[$3] = $(c[1]) }
        else if (file == 2) { e6[$3] = $(c[2]) }
        else l10[$3] = $4
      }
      END {
        for (k in l8) {
          if (e8[k] == "" || e6[k] == "" || !(k in l10)) continue
          n++; d1 += (e6[k] / f6)^2; d2 += (e8[k] / f8)^2; d3 += (l8[k] - l10[k])^2
        }
        d1 = sqrt(d1 / n); d2 = sqrt(d2 / n); d3 = sqrt(d3 / n)
        printf "%s.csv, the mode cut-off'"'"'s levels (%d bands, rms): |L4.5 - L6| %.4f dB, |L6 - L8| %.4f dB, |L8 - L10| %.4f dB; falls %.2f and %.2f times; ", q, n, d1, d2, d3, d1 / d2, d2 / d3
        printf "the estimate from the 4.5-6-8 kHz convergence, |L6 - L8| / (%.2f - 1), against |L8 - L10|: ratio %s\n", d1 / d2, (d1 > d2 ? sprintf("%.2f", d2 / (d1 / d2 - 1) / d3) : "none (no convergence)")
      }' "$work/${name}_estimated/$quantity.csv" "$work/${name}_cutoff_6k/$quantity.csv" \
         "$work/${name}_mode_cutoff/$quantity.csv"
  done
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
      awk -F, -v column="${column}_dB" -v csv="$csv" -v prefix="$name,$quantity,$column" '
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
            if (e[k] == "" || e[k] == "nan") {
              printf "| %g | %.2f | %.2f | not estimated | %.2f | %.3f | |\n", k, l[k], se[k], r[k], m
              printf "%s,band,%g,%.6f,%.6f,none,%.6f,%.6f,none,none,none\n", prefix, k, l[k], se[k], r[k], m >> csv
              continue
            }
            ratio = m > 0 ? e[k] / m : 0
            counted++; if (ratio >= 0.5 && ratio <= 2) within++
            se2 += e[k] * e[k]; sm2 += m * m
            printf "| %g | %.2f | %.2f | %.3f | %.2f | %.3f | %.2f |\n", k, l[k], se[k], e[k], r[k], m, ratio
            printf "%s,band,%g,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,none,none\n", prefix, k, l[k], se[k], e[k], r[k], m, ratio >> csv
          }
          printf "\nbands within a factor 2: %d of %d; rms over the bands: estimate %.3f dB, measured %.3f dB, ratio %.2f\n",
                 within, counted, sqrt(se2 / counted), sqrt(sm2 / counted), sqrt(se2 / sm2)
          printf "%s,rms,none,none,none,%.6f,none,%.6f,%.6f,%d,%d\n", prefix, sqrt(se2 / counted),
                 sqrt(sm2 / counted), sqrt(se2 / sm2), within, counted >> csv
        }' "$work/${name}_estimated/$quantity.csv" "$work/${name}_${refined}/$quantity.csv"
    done
  done
  if $four_levels; then
    echo
    cutoff_convergence "$name"
  fi
}

csv=$work/table.csv
echo "case,quantity,discretisation,row,band_Hz,level_dB,standard_error_dB,estimate_dB,refined_level_dB,measured_difference_dB,estimate_over_measured,bands_within_factor_2,bands_estimated" > "$csv"
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
    section)
      run_case section road-A 70 600 3.84e-4 "$(awk -v w="$window" 'BEGIN { printf "%.4f", w * 70 / 3.6 }')" \
        "${section_geometry[@]}"
      compare section "another section (185/65 R13, 3 mm crown drop): road-A at 70 km/h, 600 N" ;;
  esac
done
write_csv "$output/error_bars.csv" < "$csv"
