# Shared by the contact scene's script studies (contact_grid_study.sh,
# contact_solvers.sh, contact_studies.sh, error_bars.sh, multi_rate.sh,
# realisations.sh, rolling_resistance.sh, tread_pattern.sh): their options,
# and rolling runs of the program on copies of saved stages, the main job's
# or, with --quick, a coarse ring's that the script makes itself. A script
# sources this file, calls parse_options with its arguments, and sets $saved
# (the stages' directory), $program and $work (where the runs go) before it
# calls run_saved.

# input_error MESSAGE: print MESSAGE and exit with status 2, the status of bad
# input (CONTRIBUTING.md).
input_error() {
  echo "$1" >&2
  exit 2
}

# parse_options SCRIPT ARGS...: reads the options, which come before the
# positional arguments:
#   --quick       the check of the study's code on a coarse ring ($quick = true);
#   --output DIR  where the CSV (and with --quick the stages) go ($output;
#                 default build/benchmark-output/SCRIPT, SCRIPT without .sh).
# The positional arguments are left in the array $arguments; an unknown option
# exits 2.
parse_options() {
  local script=$1
  shift
  quick=false
  output=build/benchmark-output/${script%.sh}
  while (( $# > 0 )); do
    case $1 in
      --quick) quick=true; shift ;;
      --output)
        [[ $# -ge 2 && -n "$2" ]] ||
          input_error "$script: option --output needs a directory (--output DIR)"
        output=$2
        shift 2 ;;
      --output=*) output=${1#--output=}; shift ;;
      --) shift; break ;;
      -*) input_error "$script: unknown option '$1'; allowed: --quick, --output DIR (before the positional arguments)" ;;
      *) break ;;
    esac
  done
  [[ -n "$output" ]] || input_error "$script: option --output needs a directory (--output DIR)"
  arguments=("$@")
  mkdir -p "$output"
  # With --quick, every run of the program starts from these settings (the
  # run's own --set options follow them, so a study may change one).
  if $quick; then
    quick_settings=("${quick_ring[@]}")
  else
    quick_settings=()
  fi
}

# The --quick runs' coarse ring, as converged_ring --quick has it: a
# quadratic 32 mm section, the Green's functions up to 2 kHz every 500 Hz
# and the ring's modes up to 4 kHz, whose stages take seconds; and 2 x 2
# contact rectangles per Green's-function rectangle (480 points) unless a
# study sets its own. Its numbers check the studies' code, not the tyre's
# convergence.
quick_ring=(--set "Geometry/Mesh size=0.032" --set "Geometry/Element degree=2"
            --set "Green's functions/Maximum frequency=2000"
            --set "Green's functions/Frequency step=500"
            --set "Patch model/Mode cutoff=4000" --set "Contact grid/Subdivisions=2")

# program_argument SCRIPT VALUE: the program, VALUE (a positional argument)
# else $GREENTREAD_PROGRAM else build/greentread, into $program; exits 2 unless
# it is an executable file.
program_argument() {
  program=${2:-${GREENTREAD_PROGRAM:-build/greentread}}
  [[ -f "$program" && -x "$program" ]] ||
    input_error "$1: program '$program' (the second positional argument, else GREENTREAD_PROGRAM, else build/greentread) is not an executable file"
}

# check_number SCRIPT WHAT VALUE KIND: exit 2 unless VALUE is a KIND
# ('integer': a whole number >= 1; 'number': a positive decimal number).
check_number() {
  if [[ $4 == integer ]]; then
    [[ "$3" =~ ^[1-9][0-9]*$ ]] || input_error "$1: $2 = '$3'; allowed: a whole number >= 1"
  elif ! [[ "$3" =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] ||
       ! awk -v x="$3" 'BEGIN { exit !(x + 0 > 0) }'; then
    input_error "$1: $2 = '$3'; allowed: a positive number"
  fi
}

# check_saved_stages SCRIPT: refuse a missing saved stage, naming SCRIPT.
check_saved_stages() {
  if [[ ! -f "$saved/green_functions.h5" ]]; then
    input_error "$1: '$saved' (the first positional argument, the main job's output directory) holds no green_functions.h5: run the main job first (build/greentread writes output/), or give --quick"
  fi
}

# make_quick_stages DIR [ARGS...]: one run of the program on the coarse ring
# that writes the saved stages into DIR (those already there and valid are
# reused), with ARGS after the ring's settings; the rolling is the least the
# scene allows (road-A at 90 km/h over 1.1 m, one rectangle per Green's
# function, 0.1 ms steps). Its screen output goes to DIR.log.
make_quick_stages() {
  local dir=$1
  shift
  mkdir -p "$dir"
  echo "  making the coarse ring's stages in $dir ..." >&2
  "$program" --set "Output directory=$dir" "${quick_ring[@]}" \
    --set "Road texture/Roads=road-A" --set "Rolling/Speeds (kph)=90" \
    --set "Rolling/Distance=1.1" --set "Contact grid/Subdivisions=1" \
    --set "Time stepping/Time step=1e-4" --set "Spectra/Low bands up to=0" \
    --set "Error bars/Estimates=" --set "Spectra/Extend runs=false" --set "Rolling/Frames=1" \
    "$@" > "$dir.log" 2>&1 ||
    { echo "the run that makes the stages in $dir failed:" >&2; tail -5 "$dir.log" >&2; exit 1; }
}

# run_saved NAME ARGS...: one run of the program with ARGS on a fresh copy of
# the saved stages (those of $saved, and of its coarser_section/ if there);
# its screen output goes to $work/NAME.log and its outputs to $work/NAME/.
# Fails unless both stages (the Green's functions and the patch model) were
# reused. `saved=DIR run_saved ...` takes another directory's stages. Every
# run rolls its planned record ('Spectra/Extend runs' = false): the studies
# compare runs over the same road and record. With --quick, the coarse ring's
# settings come first.
run_saved() {
  local name=$1
  shift
  mkdir -p "$work/$name"
  cp "$saved"/green_functions.h5 "$work/$name"/
  cp "$saved"/*_model.h5 "$work/$name"/ 2>/dev/null || true
  # The error bars' coarser section, if the main job saved its stages.
  [[ -d "$saved/coarser_section" ]] && cp -r "$saved/coarser_section" "$work/$name"/
  "$program" "${quick_settings[@]}" --set "Output directory=$work/$name" --set "Rolling/Frames=1" \
    --set "Spectra/Extend runs=false" "$@" \
    > "$work/$name.log" 2>&1 || { echo "run $name failed:"; tail -5 "$work/$name.log"; exit 1; }
  if (( $(grep -c "Reusing" "$work/$name.log") < 2 )); then
    echo "run $name did not reuse both saved stages (the Green's functions and the patch model):" >&2
    grep -i "reus\|stage" "$work/$name.log" >&2 || true
    exit 1
  fi
}

# write_csv FILE: standard input (a header line, then rows) written to FILE
# through a temporary file, so that no half-written CSV is left.
write_csv() {
  cat > "$1.tmp"
  mv "$1.tmp" "$1"
  echo "wrote $1" >&2
}
