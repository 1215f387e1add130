# Shared by the contact scene's studies (contact_studies.sh,
# contact_grid_study.sh): rolling runs of the program on copies of a main
# job's saved stages. Sourced with $saved (the main job's output directory),
# $program and $work (where the runs go) set.

# check_saved_stages SCRIPT: refuse a missing saved stage or program, naming SCRIPT.
check_saved_stages() {
  if [[ ! -f "$saved/green_functions.h5" ]]; then
    echo "$1: '$saved' holds no green_functions.h5: run the main job first" \
         "(build/greentread writes output/)" >&2
    exit 1
  fi
  if [[ ! -x "$program" ]]; then
    echo "$1: program '$program' not found or not executable" >&2
    exit 1
  fi
}

# run_saved NAME ARGS...: one run of the program with ARGS on a fresh copy of
# the saved stages (those of $saved, and of its coarser_section/ if there);
# its screen output goes to $work/NAME.log and its outputs to $work/NAME/.
# Fails unless both stages (the Green's functions and the patch model) were
# reused. `saved=DIR run_saved ...` takes another directory's stages. Every
# run rolls its planned record ('Spectra/Extend runs' = false): the studies
# compare runs over the same road and record.
run_saved() {
  local name=$1
  shift
  mkdir -p "$work/$name"
  cp "$saved"/green_functions.h5 "$work/$name"/
  cp "$saved"/*_model.h5 "$work/$name"/ 2>/dev/null || true
  # The error bars' coarser section, if the main job saved its stages.
  [[ -d "$saved/coarser_section" ]] && cp -r "$saved/coarser_section" "$work/$name"/
  "$program" --set "Output directory=$work/$name" --set "Rolling/Frames=1" \
    --set "Spectra/Extend runs=false" "$@" \
    > "$work/$name.log" 2>&1 || { echo "run $name failed:"; tail -5 "$work/$name.log"; exit 1; }
  if (( $(grep -c "Reusing" "$work/$name.log") < 2 )); then
    echo "run $name did not reuse both saved stages (the Green's functions and the patch model):" >&2
    grep -i "reus\|stage" "$work/$name.log" >&2 || true
    exit 1
  fi
}
