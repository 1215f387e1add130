#!/usr/bin/env bash
# Fails, naming each file, when a C++ source of the repository differs from
# what clang-format makes of it with the project's .clang-format. CI runs it
# before the tests; run it yourself before a commit, or format with
#   git ls-files '*.cc' '*.h' | xargs clang-format -i
# The layout is Debian 12's clang-format (14), which scripts/setup.sh installs:
# another version may format some lines differently.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if ! command -v clang-format > /dev/null; then
  echo "check_format.sh: clang-format is not installed (apt-get install clang-format)" >&2
  exit 2
fi
bad=()
while IFS= read -r f; do
  if ! clang-format --dry-run --Werror "$f" > /dev/null 2>&1; then
    bad+=("$f")
  fi
done < <(git ls-files '*.cc' '*.h')
if (( ${#bad[@]} )); then
  echo "check_format.sh: ${#bad[@]} file(s) differ from .clang-format:" >&2
  printf '  %s\n' "${bad[@]}" >&2
  echo "format them with: clang-format -i FILE (clang-format $(clang-format --version | grep -o '[0-9][0-9.]*' | head -1))" >&2
  exit 1
fi
echo "check_format.sh: $(git ls-files '*.cc' '*.h' | wc -l) files follow .clang-format"
