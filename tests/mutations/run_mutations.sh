#!/usr/bin/env bash
# Deliberate bugs, each kept as a patch with the test that must catch it:
#
#   bash tests/mutations/run_mutations.sh [BUILD_DIR] [NAME ...]
#
# For each tests/mutations/NAME.patch (all of them without NAME), applies
# it to the work tree, builds BUILD_DIR (default build/), runs the ctest
# its first line names ("# test: <ctest name>") and restores the tree,
# whatever happened. A mutation is caught when that test fails. The tree
# must be clean where a patch applies (the script refuses otherwise), and
# the build is rebuilt at the end, so that it is the tree's again. Prints
# one line per mutation and exits with the number of mutations missed.
# Each takes a rebuild of the library (2 to 4 minutes on 2 cores).
set -uo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:-$top/build}" && pwd)" || exit 2
shift $(($# > 0 ? 1 : 0))
cd "$top"
names=("$@")
if ((${#names[@]} == 0)); then
  for p in tests/mutations/*.patch; do names+=("$(basename "$p" .patch)"); done
fi
missed=0
restore() {
  git apply -R "$1" 2> /dev/null || true
}
for name in "${names[@]}"; do
  patch="tests/mutations/$name.patch"
  if [[ ! -f "$patch" ]]; then
    echo "run_mutations.sh: no mutation '$name' (tests/mutations/$name.patch)" >&2
    exit 2
  fi
  test_name="$(sed -n 's/^# test: //p' "$patch" | head -1)"
  what="$(sed -n 's/^# what: //p' "$patch" | head -1)"
  if [[ -z "$test_name" ]] || ! git apply --check "$patch" 2> /dev/null; then
    echo "run_mutations.sh: $patch names no test, or does not apply to this tree" >&2
    exit 2
  fi
  git apply "$patch"
  trap 'restore "$patch"' EXIT INT TERM
  if ! cmake --build "$build" -j2 > "$build/mutation_$name.log" 2>&1; then
    result="caught (the build fails)"
  elif (cd "$build" && ctest -R "^${test_name}\$" > "$build/mutation_${name}_test.log" 2>&1); then
    result="MISSED: $test_name passed"
    missed=$((missed + 1))
  else
    result="caught by $test_name"
  fi
  restore "$patch"
  trap - EXIT INT TERM
  echo "$name ($what): $result"
done
cmake --build "$build" -j2 > "$build/mutation_restore.log" 2>&1 ||
  echo "run_mutations.sh: the rebuild of the restored tree failed: $build/mutation_restore.log" >&2
exit "$missed"
