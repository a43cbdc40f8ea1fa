#!/usr/bin/env bash
# The water's flow around the JBC model (0.482 m/s, draft 0.4125 m) from the double-body panel method beside the
# thin-ship sheet (fluid.hull_flow: panel | thin_ship, docs/physics.md "Panel flow"): ahead of the stem on the
# centre line and alongside the hull 5 cm off its side, 1 cm under the water. brash-hull flow writes the CSVs
# (the panel flow evaluated directly, the thin-ship flow from its table, zero beyond the table's box one
# breadth ahead of the stem); gnuplot draws
# docs/hull_flow_panel_vs_thin_ship.png. About a minute (four flows, the panel method solved twice).
#   bench/hull_flow_panel_vs_thin_ship.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
hull_tool="$build/bin/brash-hull"
stl="$build/hull_meshes/jbc_panamax_model.stl"
out="$here/docs/hull_flow_panel_vs_thin_ship.png"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
U=0.482 T=0.4125
x_stem=6.9975  # the stem at the waterline (brash-hull check: fsicr.x_stem_m)
half_b=0.5625
for m in panel thin_ship; do
  "$hull_tool" flow "$stl" --draft $T --speed $U --method $m --points 150 \
    --line "$(echo "$x_stem + 0.005" | bc)" 0 -0.01 "$(echo "$x_stem + 1.5" | bc)" 0 -0.01 --out "$work/ahead_$m.csv"
  "$hull_tool" flow "$stl" --draft $T --speed $U --method $m --points 300 \
    --line -0.5 "$(echo "$half_b + 0.05" | bc)" -0.01 7.7 "$(echo "$half_b + 0.05" | bc)" -0.01 \
    --out "$work/side_$m.csv"
done
gnuplot <<GP
set terminal pngcairo size 1100,800 font ",10"
set output "$out"
set datafile separator ","
set key right center
set grid
set multiplot layout 2,1 title "JBC model, U = $U m/s, draft $T m: the water's flow (still-water frame) / U, 1 cm under the water"
set title "ahead of the stem, centre line"
set xlabel "distance ahead of the stem at the waterline (m)"
set ylabel "u / U"
plot "$work/ahead_panel.csv" every ::1 using (\$2-$x_stem):(\$5/$U) w l lw 2 lc rgb "#1f77b4" t "panel u_x", \
     "$work/ahead_thin_ship.csv" every ::1 using (\$2-$x_stem):(\$5/$U) w l lw 2 dt 2 lc rgb "#d62728" t "thin-ship u_x", \
     "$work/ahead_panel.csv" every ::1 using (\$2-$x_stem):(\$8) w l lw 1 lc rgb "#1f77b4" t "panel |u - U e_x| / U", \
     "$work/ahead_thin_ship.csv" every ::1 using (\$2-$x_stem):(\$8) w l lw 1 dt 2 lc rgb "#d62728" t "thin-ship |u - U e_x| / U"
set key top center
set title "alongside, 5 cm off the widest waterline (y = B/2 + 0.05 m)"
set xlabel "x (m; aft perpendicular 0, stem $x_stem)"
plot "$work/side_panel.csv" every ::1 using 2:(\$5/$U) w l lw 2 lc rgb "#1f77b4" t "panel u_x", \
     "$work/side_thin_ship.csv" every ::1 using 2:(\$5/$U) w l lw 2 dt 2 lc rgb "#d62728" t "thin-ship u_x", \
     "$work/side_panel.csv" every ::1 using 2:(\$6/$U) w l lw 1 lc rgb "#2ca02c" t "panel u_y", \
     "$work/side_thin_ship.csv" every ::1 using 2:(\$6/$U) w l lw 1 dt 2 lc rgb "#ff7f0e" t "thin-ship u_y"
unset multiplot
GP
echo "wrote $out"
