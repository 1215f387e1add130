#!/usr/bin/env bash
# Remakes the figures of README.md, doc/ and benchmarks/ from the runs that make them.
#
#   bash doc/figures/make_figures.sh [BUILD_DIR] [MAIN_JOB_OUTPUT]
#
# BUILD_DIR (default build/) holds greentread and the benchmarks.
# MAIN_JOB_OUTPUT is the output folder of a finished main job (build/greentread
# writes output/); without it the main job is run here (about 13 minutes on 2 cores).
# QUICK=1 keeps green_functions.png instead of running the tyre-green scene
# (its 257 lines take 5 to 12 minutes).
# The benchmarks' figures are kept in their folders, benchmarks/<name>/.
# converged_ring_road-A_90kmh.png comes from the converged_ring benchmark's
# output (build/benchmark-output/converged_ring, about 70 minutes to make); it is
# copied when that output exists and kept as it is otherwise.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:-$top/build}" && pwd)"
main_out="${2:-}"
figures="$top/doc/figures"
program="$build/greentread"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$top"

# figure <file in doc/figures> <file written by the run>
figure() { cp "$2" "$figures/$1"; echo "doc/figures/$1 <- $2"; }
# benchmark_figure <benchmark> <file in benchmarks/<benchmark>> <file written by the run>
benchmark_figure() { cp "$3" "$top/benchmarks/$1/$2"; echo "benchmarks/$1/$2 <- $3"; }

# The 1-DoF scene (Section 3) and its time step study.
"$program" prm/sdof_kinematic.prm --set "Output directory=$tmp/sdof_kinematic" > /dev/null
figure sdof_kinematic.png "$tmp/sdof_kinematic/time_history.png"
"$program" prm/sdof_penalty_1e8.prm --set "Output directory=$tmp/sdof_penalty_1e8" > /dev/null
figure sdof_penalty_1e8.png "$tmp/sdof_penalty_1e8/time_history.png"
"$build/benchmarks/sdof_convergence" --output "$tmp/sdof_convergence" > /dev/null
benchmark_figure sdof_convergence sdof_convergence.png "$tmp/sdof_convergence/sdof_convergence.png"

# LSCE identification of the shipped FRF (Appendix A, Figure A.10).
"$program" prm/identify.prm --set "Output directory=$tmp/identify" > /dev/null
figure identification_example.png "$tmp/identify/identification_worst.png"

# The tyre section (Section 4) and the ring's Green's functions (Figure A.9).
"$program" prm/geometry_study.prm --set "Output directory=$tmp/geometry_study" > /dev/null
figure tyre_section.png "$tmp/geometry_study/section.png"
if [[ "${QUICK:-0}" != 1 ]]; then
  "$program" prm/tyre_green.prm --set "Output directory=$tmp/tyre_green" > /dev/null
  figure green_functions.png "$tmp/tyre_green/green_functions.png"
else
  echo "doc/figures/green_functions.png kept (QUICK=1)"
fi

# The main job (Section 5).
if [[ -z "$main_out" ]]; then
  main_out="$tmp/main_job"
  "$program" --set "Output directory=$main_out"
fi
figure spectra_road-A.png "$main_out/spectra_road-A.png"
figure history_road-A_90kmh.png "$main_out/history_road-A_90kmh.png"

converged="$build/benchmark-output/converged_ring/converged_ring_road-A_90kmh.png"
if [[ -f "$converged" ]]; then
  benchmark_figure converged_ring converged_ring_road-A_90kmh.png "$converged"
else
  echo "benchmarks/converged_ring/converged_ring_road-A_90kmh.png kept: run build/benchmarks/converged_ring first"
fi
