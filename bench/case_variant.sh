# shellcheck shell=bash
# Sourced by the bench scripts that run a case with some keys changed.
#   case_variant BIN BASE OUT_DIR "section.key=value,section.key=value..."
# writes OUT_DIR/case.yaml: the case BASE (folder or case.yaml) with those keys set, through `BIN/brash-case derive`
# (checked by the case loader; it keeps BASE's packing unless a key the packing depends on changes:
# docs/case_format.md, "Variants of a case"). A piece of the list without '=' continues the value before it, so a
# list value keeps its comma: run.window_s=[0.0,3.0]. An empty list writes a plain copy.
case_variant() {
  local bin="$1" base="$2" dir="$3" piece
  local -a pieces=() sets=()
  IFS=, read -r -a pieces <<< "$4"
  for piece in "${pieces[@]}"; do
    if [[ "$piece" == *=* || ${#sets[@]} -eq 0 ]]; then sets+=(--set "$piece"); else sets[-1]+=",$piece"; fi
  done
  "$bin/brash-case" derive "$base" "${sets[@]}" --out "$dir" --force > /dev/null
}

# case_variant_same_packing BIN BASE OUT_DIR "edits": the same on BASE's packing whatever the edits, as a paired
# comparison needs (both sides on one bed: an edit of the ice, e.g. its density, changes the scene, not the bed).
case_variant_same_packing() {
  local pack
  pack="$("$1/brash-case" get "$2" ice.packing_file)" || return
  case_variant "$1" "$2" "$3" "ice.packing_file=$pack${4:+,$4}"
}
