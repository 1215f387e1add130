#!/usr/bin/env bash
# Remakes every figure that README.md, doc/ and benchmarks/ show, from the runs
# that make them, with the program and benchmarks of BUILD_DIR:
#
#   bash doc/figures/make_figures.sh [--scenes-only] [BUILD_DIR] [MAIN_JOB_OUTPUT]
#
# --scenes-only remakes the figures of scenes alone (those README.md and doc/
# show; about 20 minutes on 2 cores, most of it the main job), not the
# benchmarks' (their READMEs show them): after a change to the program that
# moves no benchmark's reference numbers (tests/layout/check_figures.sh).
# BUILD_DIR (default build/) holds greentread and the benchmarks.
# MAIN_JOB_OUTPUT is the output folder of a main job run by this build
# (build/greentread writes output/); without it the main job is run here.
# The converged_ring figure comes from that benchmark's output
# (build/benchmark-output/converged_ring); the benchmark is run when its output
# is missing or was made by another build (it takes over an hour on 2 cores).
#
# Every PNG records the revision of the program that made it (its 'parameters'
# text chunk). A figure made by another revision than this build's is refused,
# and the script stops: rebuild, or remake the run, first. Commit the code
# before making the figures, so that the revision they record names it.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
benchmarks=true
if [[ "${1:-}" == --scenes-only ]]; then
  benchmarks=false
  shift
fi
build="$(cd "${1:-$top/build}" && pwd)"
main_out="${2:-}"
figures="$top/doc/figures"
program="$build/greentread"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$top"

# The revision of this build, as --version prints it: "greentread 0.1.0 (abc1234, Release)".
revision="$("$program" --version | sed -n '1s/^greentread [^ ]* (\([^,]*\),.*/\1/p')"
if [[ -z "$revision" || "$revision" == *-dirty || "$revision" == unknown ]]; then
  echo "make_figures.sh: $program was built from revision '${revision:-?}'; build it from a" \
       "committed tree, so that the figures name the code that made them" >&2
  exit 1
fi

# recorded <png>: the revision its 'parameters' chunk names ("" if none).
recorded() {
  grep -a -o -m1 'greentread [0-9.]* ([^)]*)' "$1" | head -1 | sed 's/.*(\(.*\))$/\1/' || true
}
# place <destination> <file written by the run>: copies a figure made by this build.
place() {
  local made
  made="$(recorded "$2")"
  if [[ "$made" != "$revision" ]]; then
    echo "make_figures.sh: $2 was made by revision '${made:-none recorded}', not by this" \
         "build's '$revision': refused for $1" >&2
    exit 1
  fi
  cp "$2" "$top/$1"
  echo "$1 <- $2 ($revision)"
}

# The ring's Green's functions (Figure A.9).
"$program" prm/tyre_green.prm --set "Output directory=$tmp/tyre_green" > /dev/null
place doc/figures/green_functions.png "$tmp/tyre_green/green_functions.png"

# The main job (Section 5).
if [[ -z "$main_out" ]]; then
  main_out="$tmp/main_job"
  "$program" --set "Output directory=$main_out"
fi
place doc/figures/spectra_road-A.png "$main_out/spectra_road-A.png"
place doc/figures/rolling_resistance.png "$main_out/rolling_resistance.png"

# The sound of the main job's tyre (prm/tyre_sound.prm): its Green's functions
# and modes are the main job's (the same parameters, so the same stage keys),
# reused from its output.
mkdir -p "$tmp/tyre_sound"
cp "$main_out/green_functions.h5" "$main_out/modal_model.h5" "$tmp/tyre_sound/"
"$program" prm/tyre_sound.prm --set "Output directory=$tmp/tyre_sound" > /dev/null
place doc/figures/sound_road-A_70kmh.png "$tmp/tyre_sound/sound_road-A_70kmh.png"

# The patterned tyre beside the slick one (prm/tyre_pattern.prm), on the main
# job's Green's functions and modes likewise.
mkdir -p "$tmp/tyre_pattern"
cp "$main_out/green_functions.h5" "$main_out/modal_model.h5" "$tmp/tyre_pattern/"
"$program" prm/tyre_pattern.prm --set "Output directory=$tmp/tyre_pattern" > /dev/null
place doc/figures/pattern_force_70kmh.png "$tmp/tyre_pattern/spectra_force_70kmh.png"

if ! $benchmarks; then
  bash "$top/tests/layout/check_figures.sh" "$top" "$program"
  exit
fi

# The 1-DoF scene's time step study (Section 3).
"$build/benchmarks/sdof_convergence" --output "$tmp/sdof_convergence" > /dev/null
place benchmarks/sdof_convergence/sdof_convergence.png "$tmp/sdof_convergence/sdof_convergence.png"

# The horn effect of the main job's tyre (about 4 minutes on 2 cores).
"$build/benchmarks/horn_effect" --output "$tmp/horn_effect" > /dev/null
place benchmarks/horn_effect/horn_effect.png "$tmp/horn_effect/horn_effect.png"

# The sound of the main job's tyre for white-noise forces (about 12 minutes on 2 cores).
"$build/benchmarks/tyre_sound" --output "$tmp/tyre_sound" > /dev/null
place benchmarks/tyre_sound/tyre_sound.png "$tmp/tyre_sound/tyre_sound.png"

# The default section against the one twice as fine.
converged_out="$build/benchmark-output/converged_ring"
converged="$converged_out/converged_ring_road-A_90kmh.png"
if [[ ! -f "$converged" || "$(recorded "$converged")" != "$revision" ]]; then
  # Its default section's stages are the main job's: copied, they are reused
  # (a saved stage is keyed on the code that made it, so a stale one is not).
  mkdir -p "$converged_out/default"
  cp "$main_out"/*.h5 "$converged_out/default/"
  if [[ -d "$main_out/coarser_section" ]]; then
    cp -r "$main_out/coarser_section" "$converged_out/default/"
  fi
  echo "== running build/benchmarks/converged_ring (about an hour on 2 cores)"
  "$build/benchmarks/converged_ring" --output "$converged_out"
fi
place benchmarks/converged_ring/converged_ring_road-A_90kmh.png "$converged"

# Every figure of doc/figures/figures.list, each from this build's revision
# (the code behind them is committed, so they are current once committed).
bash "$top/tests/layout/check_figures.sh" "$top" "$program"
