#!/usr/bin/env bash
# "Within 2 %" per speed-up knob: each knob as a paired-seed ensemble against the case as it is
# (bench/rank_ensemble.sh, side A = 1 rank with no edits, side B = 1 rank with the knob), then the Pareto plot
# (bench/pareto_plot.sh -> docs/performance_pareto.png). ~4 h on a quiet 2-core machine for the eight knobs at 12
# seeds (two runs at a time); finished runs are kept and skipped, so it can be stopped and started again.
#   bash bench/knob_ensembles.sh [N_SEEDS (12)] [OUT (runs/rank-ensemble: shares side A with the rank comparison)]
# env: CASE (cases/jbc_narrow), KNOBS (names below, default all), JOBS (2), BRASH_BIN.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
n_seeds="${1:-12}"
out="${2:-$here/runs/rank-ensemble}"
ff="speedups.farfield=true,speedups.farfield_ahead_m=0.3,speedups.farfield_behind_m=1.0,speedups.farfield_every_steps=100"
declare -A edits=(
  [farfield_window]="$ff,speedups.farfield_wake_force_weight=0"    # the window alone (idle ice = a wall)
  [farfield]="$ff,speedups.farfield_wake_force_weight=1e-3"        # the far field with the wake (its default)
  [farfield_neighbour]="$ff,speedups.farfield_wake_by=neighbour_speed"  # woken by a touching piece faster than 5 mm/s
  [dt_x2]="run.timestep_s=2.0e-4"                   # 16 % of the Rayleigh time (the paper case's dt is at 18 %)
  [farfield_dt_x2]="$ff,speedups.farfield_wake_force_weight=1e-3,run.timestep_s=2.0e-4"  # both together
  [symmetry_y]="speedups.symmetry_y=true"           # half channel
  # softer contacts with the step kept at 16 % of their (longer) Rayleigh time, t_R ~ E^-1/2:
  [soft_E_div4_dt_x4]="contact.youngs_modulus_pa=1.25e6,run.timestep_s=4.0e-4"
  [soft_E_div16_dt_x8]="contact.youngs_modulus_pa=3.125e5,run.timestep_s=8.0e-4"   # the paper case's default
  [soft_E_div64_dt_x16]="contact.youngs_modulus_pa=7.8125e4,run.timestep_s=1.6e-3"
)
for k in ${KNOBS:-farfield_window farfield dt_x2 farfield_dt_x2 symmetry_y soft_E_div4_dt_x4 soft_E_div16_dt_x8 soft_E_div64_dt_x16}; do
  [ -n "${edits[$k]:-}" ] || { echo "knob_ensembles: unknown knob '$k' (${!edits[*]})" >&2; exit 2; }
  echo "##### knob $k: ${edits[$k]}"
  SIDE_A=1 SIDE_B="1:${edits[$k]}" TOL_PCT=2 bash "$here/bench/rank_ensemble.sh" "$n_seeds" "$out"
done
TOL_PCT=2 bash "$here/bench/pareto_plot.sh" "$out"
