#!/usr/bin/env bash
# Every figure the manual shows is from the current code (the test
# layout/figure_provenance):
#
#   bash tests/layout/check_figures.sh TOP PROGRAM
#
# TOP is the checkout (a git work tree), PROGRAM build/greentread. The figures
# are those of doc/figures/figures.list; every image that README.md, a page in
# doc/ or a benchmark's README.md shows must be in it. For each figure:
#
# - its 'parameters' text chunk names the revision that made it, from a clean
#   tree ("greentread 0.1.0 (abc1234)"), and that commit is in the history;
# - the code behind it is the same in that commit as in the work tree: a
#   change to it since makes the figure stale, even one that moves no number,
#   because no one has looked. For a scene's figure (those README.md and doc/
#   show) that is the program's code (source, include, cmake, CMakeLists.txt,
#   prm, geometry) and the files the list adds. For a benchmark's figure (its
#   README shows it) it is the benchmark's own code, the list's files: a change
#   to the program that moves the benchmark's numbers fails its test
#   benchmark-smoke/<name>, which compares them with its reference_quick.csv,
#   and the one who updates that reference remakes the figure
#   (CONTRIBUTING.md). The full runs behind those figures take over an hour;
#   they are not remade for every change to the program;
# - it was made by what the list says: a benchmark's figure names the
#   benchmark, and not its --quick run; a scene's figure names the scene, and
#   every parameter it records (but its output directory) has the value that
#   PROGRAM gives that scene now (--print-parameters=scene). An absolute path
#   is compared from its geometry/ or prm/ on, so the checkout may move.
#
# Each failure is printed; the exit status is the number of figures that
# failed (at most 100). doc/figures/make_figures.sh remakes them all.
set -uo pipefail
top="$1"
program="$2"
list="$top/doc/figures/figures.list"
program_code=(source include cmake CMakeLists.txt prm geometry)
failed=0
fail() {
  echo "figure_provenance: $*" >&2
  failed=$((failed + 1))
}

if ! git -C "$top" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  echo "figure_provenance: $top is not a git work tree: the figures' revisions cannot be" \
       "checked" >&2
  exit 100
fi

# parameters <png>: the text of its 'parameters' tEXt chunk (PNG chunks:
# length, type, data, CRC; the data is "keyword\0text").
parameters() {
  perl -e '
    open(my $f, "<:raw", $ARGV[0]) or die "cannot read $ARGV[0]\n";
    local $/; my $d = <$f>; my $i = 8;
    while ($i + 8 <= length $d) {
      my ($n, $t) = unpack("N a4", substr($d, $i, 8));
      if ($t eq "tEXt") {
        my ($k, $v) = split(/\0/, substr($d, $i + 8, $n), 2);
        if ($k eq "parameters") { print $v; exit 0; }
      }
      $i += 12 + $n;
    }' "$1"
}
# normalised: "Path = value" lines, the output directory left out and
# absolute paths cut as a scene file in prm/ names them, also inside a list:
# to their geometry/ on, and a file of prm/ to its name, relative to the
# scene's folder ("Roads = road-A, /.../prm/dense_asphalt.x3p" as
# prm/tyre_pattern.prm gives it, "dense_asphalt.x3p").
normalised() {
  grep -v '^Output directory = ' |
    sed -E 's#/[^ ,]*/prm/([^/ ,]*)#\1#g; s#/[^ ,]*/(geometry/[^/ ,]*)#\1#g'
}

declare -A listed
while read -r figure scene code; do
  [[ -z "$figure" || "$figure" == \#* ]] && continue
  listed["$figure"]=1
  png="$top/$figure"
  if [[ ! -f "$png" ]]; then
    fail "$figure is in doc/figures/figures.list but missing"
    continue
  fi
  text="$(parameters "$png")"
  header="$(head -1 <<< "$text")"
  if [[ ! "$header" =~ ^greentread\ [0-9.]+\ \(([^\)]*)\) ]]; then
    fail "$figure records no revision (its first line: '${header:-none}'): remake it"
    continue
  fi
  revision="${BASH_REMATCH[1]}"
  if [[ "$revision" == *-dirty || "$revision" == unknown ]]; then
    fail "$figure was made by a build of an uncommitted tree ('$revision'): remake it"
    continue
  fi
  if ! git -C "$top" rev-parse -q --verify "$revision^{commit}" > /dev/null; then
    fail "$figure was made by revision $revision, which is not in this history"
    continue
  fi
  paths=()
  [[ "$scene" != benchmark ]] && paths=("${program_code[@]}")
  if [[ "$code" != "-" ]]; then
    IFS=, read -r -a more <<< "$code"
    paths+=("${more[@]}")
  fi
  if ((${#paths[@]} > 0)) && ! git -C "$top" diff --quiet "$revision" -- "${paths[@]}"; then
    fail "$figure was made by revision $revision; the code behind it changed since:
$(git -C "$top" diff --stat "$revision" -- "${paths[@]}" | tail -15)
  remake it: bash doc/figures/make_figures.sh"
    continue
  fi
  if [[ "$scene" == benchmark ]]; then
    name="$(basename "$(dirname "$figure")")"
    if [[ "$header" != *"), benchmark $name"* || "$header" == *--quick* ]]; then
      fail "$figure should be from the benchmark $name's full run; it records '$header'"
    fi
    continue
  fi
  args=()
  [[ "$scene" != default ]] && args=("$top/$scene")
  current="$("$program" "${args[@]}" --print-parameters=scene)" || {
    fail "$program ${args[*]} --print-parameters=scene failed"
    continue
  }
  scene_name="$(grep '^Scene = ' <<< "$current" | sed 's/^Scene = //')"
  if [[ "$header" != *"), scene $scene_name" ]]; then
    fail "$figure records '$header'; the scene $scene is '$scene_name'"
    continue
  fi
  differences="$(tail -n +2 <<< "$text" | normalised | sort |
                 comm -23 - <(normalised <<< "$current" | sort))"
  if [[ -n "$differences" ]]; then
    fail "$figure records parameters that $scene does not give now (its value, then the scene's):
$(while IFS= read -r line; do
    echo "  $line | $(grep -F -- "${line%% = *} = " <<< "$current" | normalised | head -1)"
  done <<< "$differences")"
  fi
done < "$list"

# Every image the manual shows is listed.
while IFS= read -r page; do
  while IFS= read -r image; do
    [[ "$image" == http* ]] && continue
    path="$(realpath -m --relative-to="$top" "$(dirname "$page")/$image")"
    if [[ -z "${listed[$path]:-}" ]]; then
      fail "$(realpath --relative-to="$top" "$page") shows $image, which doc/figures/figures.list" \
           "does not list"
    fi
  done < <(grep -o '!\[[^]]*\]([^)]*)' "$page" | sed -E 's/.*\(([^) ]*).*/\1/')
done < <(ls "$top/README.md" "$top"/doc/*.md "$top"/benchmarks/*/README.md 2>/dev/null)

if ((failed == 0)); then
  echo "figure_provenance: ${#listed[@]} figures, each from the current code and scene"
fi
exit $((failed > 100 ? 100 : failed))
