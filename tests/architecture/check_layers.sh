#!/usr/bin/env bash
# Include arrows point down the layers of docs/architecture.md:
#   core physics (plugin/core) and statistics (stats)
#   <- geometry (hull_meshes) <- case and packing (common) <- engines (plugin/liggghts, ode, yade)
#   and the postprocessor (postproc), which never include each other; the engines' run driver (plugin/driver) sits
#   below the engines; the study (study/) runs engines and the postprocessor as processes and includes neither.
# Every '#include "brash/..."' or '<brash/...>' of a component's sources must name a header of its own
# layer or of one below it. Prints each offending line as file:line: include, exits 1 if there is one.
set -u
root=${1:?usage: check_layers.sh SOURCE_DIR}
cd "$root" || exit 2

# header (as included) -> the component that owns it
owner() {
  case $1 in
    brash/core/*|brash/error.hpp|brash/fluid_options.hpp|brash/far_field_options.hpp|brash/paths.hpp) echo core ;;
    brash/stats/*) echo stats ;;
    brash/hull/*|brash/fsicr_params.hpp) echo geometry ;;
    brash/post/*) echo postproc ;;
    brash/ode/*) echo ode ;;
    brash/run/*) echo driver ;;
    brash/study/*) echo study ;;
    brash/*) [[ -f common/include/$1 ]] && echo case || echo unknown ;;
  esac
}
# component folder -> the owners it may include
allowed() {
  case $1 in
    plugin/core) echo "core" ;;
    stats) echo "stats" ;;
    hull_meshes) echo "core geometry" ;;
    common) echo "core stats geometry case" ;;
    plugin/driver) echo "core stats geometry case driver" ;;
    plugin/liggghts|plugin/yade) echo "core stats geometry case driver" ;;
    plugin/ode) echo "core stats geometry case driver ode" ;;
    postproc) echo "core stats geometry case postproc" ;;
    study) echo "core stats geometry case study" ;;
  esac
}

bad=0
checked=0
for component in plugin/core stats hull_meshes common plugin/driver plugin/liggghts plugin/ode plugin/yade postproc study; do
  [[ -d $component ]] || continue
  ok=" $(allowed "$component") "
  while IFS=: read -r file line text; do
    header=$(sed -E 's/.*[<"](brash\/[^">]+)[">].*/\1/' <<<"$text")
    layer=$(owner "$header")
    checked=$((checked + 1))
    if [[ $ok != *" $layer "* ]]; then
      echo "$file:$line: $component includes $header ($layer): an arrow pointing up or across"
      bad=1
    fi
  done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]brash/' "$component" \
             --include='*.cpp' --include='*.hpp' --include='*.h')
done
echo "$checked brash includes checked"
[[ $checked -gt 0 ]] || { echo "no includes found under $root"; exit 2; }
exit $bad
