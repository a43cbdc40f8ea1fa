#!/usr/bin/env bash
# install_test.sh SOURCE_DIR BUILD_DIR CMAKE CXX: the installed tree is relocatable and works on its own.
#  1. cmake --install BUILD_DIR --prefix <tmp>/prefix; the layout of docs/guide.md "Install" is there;
#  2. no installed file contains the source or the build folder's path, and no link points into them;
#  3. from a folder outside the repository, with `env -i` (no variable pointing into the source or build tree):
#     brash-liggghts-run on <prefix>/share/brash/cases/jbc_narrow for 0.05 s on 1 rank -> meta.json complete and
#     report.json; brash-case new (default template from the data folder); brash-hull jbc (default data folder);
#     a wrong BRASH_DATA_DIR gives an error naming it; the steps of docs/own_hull.md and a derived installed case as
#     a user who cannot write the install;
#  4. find_package(brash) in a tiny CMake project: configure, build, run a program linking brash::core.
set -u
src=$(cd "${1:?usage: install_test.sh SOURCE_DIR BUILD_DIR CMAKE CXX}" && pwd -P)
build=$(cd "${2:?}" && pwd -P)
cmake_exe=${3:?}
cxx=${4:?}
tmp=$(mktemp -d /tmp/brash-install-test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# 1. install
if ! "$cmake_exe" --install "$build" --prefix "$prefix" > "$tmp/install.log" 2>&1; then
  cat "$tmp/install.log"; echo "FAIL: cmake --install"; exit 1
fi
for f in bin/brash-liggghts bin/brash-liggghts-run bin/brash-post bin/brash-case bin/brash-pack bin/brash-hull \
         bin/brash-study bin/brash-study-report \
         share/brash/cases/jbc_narrow/case.yaml share/brash/cases/jbc_ia_5kn/case.yaml \
         share/brash/hull_meshes/jbc_panamax_model.stl share/brash/hull_meshes/data/jbc_offsets_1to40.csv \
         share/brash/study/smoke.yaml share/brash/study_report/templates/study.md.tmpl \
         share/brash/examples/channel/in.channel share/brash/examples/channel/hull_barge.stl \
         share/brash/examples/floating_sphere/in.floating_sphere share/brash/examples/yade/floating_spheres.py \
         share/doc/brash/fix_icefluid.txt include/brash/paths.hpp include/brash/core/fluid.hpp \
         lib/libbrash_core.a lib/cmake/brash/brashConfig.cmake lib/cmake/brash/brashTargets.cmake; do
  [ -f "$prefix/$f" ] || bad "not installed: $f"
done
[ -n "$(find "$prefix/share/brash/cases" -path '*/generated/*' -print -quit)" ] && bad "a generated packing was installed"
if command -v yade > /dev/null && [ -e "$build/bin/brash-yade-run" ]; then
  for f in bin/brash-yade-run lib/brash/python/brash_yade_scene.py lib/brash/python/brash_yade_adapter.py; do
    [ -f "$prefix/$f" ] || bad "not installed: $f"
  done
  ls "$prefix"/lib/brash/python/brash_yade*.so > /dev/null 2>&1 || bad "not installed: the brash_yade module"
fi
echo "installed $(find "$prefix" -type f | wc -l) files into $prefix"

# 2. no source or build path in any installed file (binaries included), no link
links=$(find "$prefix" -type l)
[ -z "$links" ] || bad "links in the install: $links"
for path in "$src" "$build"; do
  while IFS= read -r -d '' f; do
    n=$(grep -c -a -F "$path" "$f")
    [ "$n" -eq 0 ] || bad "$f contains $path ($n lines)"
  done < <(find "$prefix" -type f -print0)
done
nbin=$(find "$prefix/bin" -type f | wc -l)
[ "$nbin" -ge 8 ] || bad "only $nbin executables in $prefix/bin"

# 3. a run from the prefix, outside the repository, with a bare environment
work=$tmp/work
mkdir -p "$work" "$tmp/home"
bare() { (cd "$work" && env -i PATH=/usr/bin:/bin HOME="$tmp/home" "$@"); }
bare "$prefix/bin/brash-liggghts-run" "$prefix/share/brash/cases/jbc_narrow" --duration 0.05 --np 1 \
  --out "$work/run" > "$tmp/run.log" 2>&1
rc=$?
[ $rc -eq 0 ] || { tail -n 30 "$tmp/run.log"; bad "brash-liggghts-run exited $rc"; }
if [ -f "$work/run/meta.json" ]; then
  grep -Eq '"status": *"complete"' "$work/run/meta.json" || bad "meta.json status is not complete"
  grep -Eq '"git_commit": *"([0-9a-f]{40}|unknown)"' "$work/run/meta.json" || bad "meta.json git_commit: not a commit"
  grep -Fq "$prefix/share/brash/hull_meshes/jbc_panamax_model.stl" "$work/run/case.yaml" ||
    bad "the run's hull is not the installed one: $(grep -F 'file:' "$work/run/case.yaml")"
else
  bad "no meta.json in $work/run"
fi
[ -f "$work/run/report.json" ] || bad "no report.json in $work/run"
for f in .lock engine.pid; do [ -e "$work/run/$f" ] && bad "the finished run folder keeps $f"; done

bare "$prefix/bin/brash-case" new installed_case --cases-dir "$work/cases" > "$tmp/case.log" 2>&1 ||
  { cat "$tmp/case.log"; bad "brash-case new with the default template"; }
[ -f "$work/cases/installed_case/case.yaml" ] || bad "brash-case new wrote no case.yaml"
bare "$prefix/bin/brash-hull" jbc --out "$work/jbc.stl" --lpp 7.0 > "$tmp/hull.log" 2>&1 ||
  { cat "$tmp/hull.log"; bad "brash-hull jbc with the default data folder"; }
cmp -s "$work/jbc.stl" "$prefix/share/brash/hull_meshes/jbc_panamax_model.stl" ||
  bad "brash-hull jbc from the install differs from the installed model hull"
mkdir -p "$tmp/empty"
bare env BRASH_DATA_DIR="$tmp/empty" "$prefix/bin/brash-case" new other --cases-dir "$work/cases" > "$tmp/nodata.log" 2>&1
rc=$?
[ $rc -eq 2 ] || bad "brash-case new with an empty BRASH_DATA_DIR exited $rc, expected 2"
grep -q 'BRASH_DATA_DIR' "$tmp/nodata.log" && grep -qF "$tmp/empty" "$tmp/nodata.log" ||
  bad "the missing-template message names neither BRASH_DATA_DIR nor the folder: $(cat "$tmp/nodata.log")"

# 3b. the docs' first steps (docs/own_hull.md "In five commands", a derived installed case) as a user who cannot
# write the install: "nobody" when the test runs as root, else the install made read-only.
uwork=$tmp/user
mkdir -p "$uwork"
if [ "$(id -u)" -eq 0 ]; then
  chmod 755 "$tmp"
  chown 65534:65534 "$uwork"
  as_user() { (cd "$uwork" && env -i PATH=/usr/bin:/bin HOME="$uwork" \
                 setpriv --reuid=65534 --regid=65534 --clear-groups "$@"); }
else
  chmod -R a-w "$prefix"
  trap 'chmod -R u+w "$prefix"; rm -rf "$tmp"' EXIT
  as_user() { (cd "$uwork" && env -i PATH=/usr/bin:/bin HOME="$uwork" "$@"); }
fi
as_user touch "$prefix/share/brash/cases/probe" 2> /dev/null && bad "the install is writable by the user of step 3b"
hull=$prefix/share/brash/hull_meshes/jbc_panamax_model.stl
as_user "$prefix/bin/brash-hull" check "$hull" --draft 0.4125 > "$tmp/check.json" 2> "$tmp/check.log" ||
  { cat "$tmp/check.log"; bad "own_hull.md: brash-hull check"; }
as_user "$prefix/bin/brash-case" new my_ship --hull "$hull" --draft 0.4125 --scale 30 --speed 0.45 --duration 20 \
  > "$tmp/new.log" 2>&1 || { cat "$tmp/new.log"; bad "own_hull.md: brash-case new --hull"; }
if [ -x "$prefix/bin/brash-ode" ]; then
  # the quick look, shortened from --duration 2 to a few steps
  as_user "$prefix/bin/brash-ode" cases/my_ship --duration 0.02 --no-progress > "$tmp/ode.log" 2>&1 ||
    { tail -n 20 "$tmp/ode.log"; bad "own_hull.md: brash-ode cases/my_ship"; }
  grep -Eq '"status": *"complete"' "$uwork"/runs/my_ship-ode-*/meta.json 2> /dev/null ||
    bad "own_hull.md: the ODE quick look left no complete run in runs/"
  # a variant of an installed case with the same ice: its packing is made in its own folder, not the install's
  as_user "$prefix/bin/brash-case" derive "$prefix/share/brash/cases/jbc_narrow" --set friction.ice_hull=0.2 \
    --out variant > "$tmp/derive.log" 2>&1 || { cat "$tmp/derive.log"; bad "brash-case derive of an installed case"; }
  as_user "$prefix/bin/brash-ode" variant --duration 0.02 --no-progress > "$tmp/variant.log" 2>&1 ||
    { tail -n 20 "$tmp/variant.log"; bad "brash-ode on a case derived from an installed case"; }
  [ -f "$uwork/variant/generated/packing.csv" ] || bad "the derived case's packing is not in its own folder"
fi

# 4. find_package(brash) from a tiny project
proj=$tmp/consumer
mkdir -p "$proj"
cat > "$proj/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(consumer LANGUAGES CXX)
find_package(brash 0.1 REQUIRED)
add_executable(consumer main.cpp)
target_link_libraries(consumer PRIVATE brash::core)
CMAKE
cat > "$proj/main.cpp" <<'CPP'
#include <brash/core/immersion.hpp>
#include <brash/core/params.hpp>
#include <brash/paths.hpp>
#include <iostream>
int main() {
  const bool drag = brash::core::parse_fluid_model("drag") == brash::FluidModel::Drag;  // compiled in brash_core
  std::cout << (drag ? "drag " : "? ") << brash::core::immersion(0.5, 0.0, 0.0).fraction << " "
            << brash::paths::data_dir().string() << "\n";
}
CPP
if "$cmake_exe" -S "$proj" -B "$proj/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
     > "$tmp/consumer.log" 2>&1 && "$cmake_exe" --build "$proj/build" >> "$tmp/consumer.log" 2>&1; then
  out=$(env -i PATH=/usr/bin:/bin BRASH_DATA_DIR="$prefix/share/brash" "$proj/build/consumer")
  [ "$out" = "drag 0.5 $prefix/share/brash" ] || bad "the consumer printed '$out'"
else
  tail -n 30 "$tmp/consumer.log"; bad "find_package(brash) project did not configure or build"
fi

[ $fail -eq 0 ] && echo "PASS: installed tree in $prefix is relocatable and works"
exit $fail
