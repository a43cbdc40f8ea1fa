#!/usr/bin/env bash
# Include arrows point down the layers of docs/architecture.md:
#   core physics (plugin/core) and statistics (stats) <- geometry (hull_meshes) <- case (case)
#   <- run (run: the run record and layout, the guards, the driver)
#   <- engines (plugin/liggghts, plugin/ode, plugin/yade) and the postprocessor (postproc), which never include
#   each other; the study (study) runs engines and the postprocessor as processes and includes neither.
# A header belongs to the component whose include/ folder holds it. Every '#include "brash/..."' or
# '<brash/...>' of a component's sources must name a header of its own component or of one it may include.
# A folder with C++ sources that is neither a component below nor a test, benchmark or example fails the check,
# so a new component has to be placed in a layer here first.
# Prints each offending line as file:line: include, exits 1 if there is one.
set -u
root=${1:?usage: check_layers.sh SOURCE_DIR}
cd "$root" || exit 2

# component -> the components it may include (the layers below it and itself)
declare -A may_include=(
  [plugin/core]="plugin/core"
  [stats]="stats"
  [hull_meshes]="plugin/core hull_meshes"
  [case]="plugin/core stats hull_meshes case"
  [run]="plugin/core stats hull_meshes case run"
  [plugin/liggghts]="plugin/core stats hull_meshes case run"
  [plugin/yade]="plugin/core stats hull_meshes case run"
  [plugin/ode]="plugin/core stats hull_meshes case run plugin/ode"
  [postproc]="plugin/core stats hull_meshes case run postproc"
  [study]="plugin/core stats hull_meshes case run study"
)
# folders with C++ sources that are not components: they may include any layer
not_components=" tests bench examples "

owner() {
  local component found
  for component in "${!may_include[@]}"; do
    for found in "$component"/include/"$1" "$component"/*/include/"$1"; do
      [[ -f $found ]] && { echo "$component"; return; }
    done
  done
  echo unknown
}

bad=0
# every folder holding C++ sources lies in a component or in a folder that is not one
while read -r dir; do
  top=${dir%%/*}
  [[ $not_components == *" $top "* ]] && continue
  [[ -v may_include[$top] ]] && continue
  second=$(cut -d/ -f1-2 <<<"$dir")
  [[ -v may_include[$second] ]] && continue
  echo "$dir: C++ sources in a folder that is no component of docs/architecture.md (add it to $0)"
  bad=1
done < <(find . \( -path ./build -o -path './build-*' -o -path ./.git -o -path ./runs \) -prune -o \
              -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -printf '%h\n' | sed 's#^\./##' | sort -u)

checked=0
for component in "${!may_include[@]}"; do
  [[ -d $component ]] || continue
  ok=" ${may_include[$component]} "
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
