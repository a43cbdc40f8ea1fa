// fix brash/farfield: idle far-field ice. See fix_brash_farfield.h for the command and the hooks.
#include "fix_brash_farfield.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "brash/core/far_field.hpp"
#include "error.h"
#include "fix_support.h"
#include "force.h"
#include "group.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace brash::liggghts {
FixBrashFarfield::FixBrashFarfield(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  for (int iarg = 3; iarg < narg;) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) {
      const std::string msg = "fix brash/farfield: keyword '" + key + "' needs a value";
      error->all(FLERR, msg.c_str());
    }
    const char* val = arg[iarg + 1];
    if (key == "every") {
      const double n = keyword_number(error, "brash/farfield", key, val);
      if (n < 1 || n != std::floor(n) || n > 1e9) error->all(FLERR, "fix brash/farfield: 'every' must be an integer >= 1");
      every_ = static_cast<int>(n);
    } else if (key == "ahead") {
      ahead_ = keyword_number(error, "brash/farfield", key, val), have_ahead_ = true;
      if (ahead_ < 0) error->all(FLERR, "fix brash/farfield: 'ahead' must be >= 0");
    } else if (key == "behind") {
      behind_ = keyword_number(error, "brash/farfield", key, val), have_behind_ = true;
      if (behind_ < 0) error->all(FLERR, "fix brash/farfield: 'behind' must be >= 0");
    } else if (key == "beside") {
      beside_half_width_m_ = keyword_number(error, "brash/farfield", key, val);
      if (!(beside_half_width_m_ > 0)) error->all(FLERR, "fix brash/farfield: 'beside' must be > 0");
    } else if (HullTrack::keyword(key)) {
      track_.take(key, keyword_number(error, "brash/farfield", key, val));
    } else if (key == "wake_speed") {
      wake_speed_ = keyword_number(error, "brash/farfield", key, val);
      if (wake_speed_ < 0) error->all(FLERR, "fix brash/farfield: 'wake_speed' must be >= 0");
    } else if (key == "wake_force") {
      wake_force_ = keyword_number(error, "brash/farfield", key, val), have_wake_force_ = true;
      if (wake_force_ < 0) error->all(FLERR, "fix brash/farfield: 'wake_force' must be >= 0");
    } else if (key == "wake_neighbour_speed") {
      wake_speed_ = keyword_number(error, "brash/farfield", key, val), by_neighbour_ = true;
      if (!(wake_speed_ > 0)) error->all(FLERR, "fix brash/farfield: 'wake_neighbour_speed' must be > 0");
    } else if (key == "active") {
      active_name_ = val;
    } else if (key == "idle") {
      idle_name_ = val;
    } else {
      const std::string msg = "fix brash/farfield: unknown keyword '" + key +
                              "' (expected every, ahead, behind, beside, hull_x0, speed, bow_offset, stern_offset, "
                              "wake_speed, wake_force, wake_neighbour_speed, active, idle)";
      error->all(FLERR, msg.c_str());
    }
    iarg += 2;
  }
  if (!(have_ahead_ && have_behind_ && track_.complete()))
    error->all(FLERR,
               "fix brash/farfield: keywords ahead, behind, hull_x0, speed, bow_offset and stern_offset are required");
  if (track_.stern_offset_m > track_.bow_offset_m)
    error->all(FLERR, "fix brash/farfield: stern_offset must be <= bow_offset");
  if (by_neighbour_ && have_wake_force_)
    error->all(FLERR, "fix brash/farfield: give either wake_force (with wake_speed) or wake_neighbour_speed, not both");
  const int ia = group->find(active_name_.c_str()), ii = group->find(idle_name_.c_str());
  if (ia < 0 || ii < 0) {
    const std::string msg = "fix brash/farfield: groups '" + active_name_ + "' and '" + idle_name_ +
                            "' must exist (e.g. group " + active_name_ + " type 1; group " + idle_name_ +
                            " subtract all all)";
    error->all(FLERR, msg.c_str());
  }
  if (ia == igroup || ii == igroup || ia == ii)
    error->all(FLERR, "fix brash/farfield: the fix group, the active group and the idle group must differ");
  active_bit_ = group->bitmask[ia];
  idle_bit_ = group->bitmask[ii];
  if (!atom->omega_flag) error->all(FLERR, "fix brash/farfield requires per-atom omega (atom_style granular/sphere)");

  force_reneighbor = 1;
  next_reneighbor = -1;
  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
}

// The force rule reads the step's complete forces (END_OF_STEP); the neighbour-speed rule reads velocities in
// PRE_FORCE, where every local and ghost piece has the same half-step velocity (forward communication with vel
// yes), so 1 and 2 ranks decide alike.
int FixBrashFarfield::setmask() {
  if (!wake_rule().enabled()) return PRE_EXCHANGE;
  return PRE_EXCHANGE | (by_neighbour_ ? PRE_FORCE : END_OF_STEP);
}

void FixBrashFarfield::init() {
  // the group bits were looked up at creation; a deleted group would leave stale bits
  if (group->find(active_name_.c_str()) < 0 || group->find(idle_name_.c_str()) < 0)
    error->all(FLERR, "fix brash/farfield: the active or idle group was deleted");
  if (!by_neighbour_ && wake_speed_ > 0 && wake_force_ <= 0)
    error->all(FLERR, "fix brash/farfield: wake_speed needs wake_force > 0 (the pieces the push has reached)");
  if (wake_rule().enabled() && force->newton_pair)
    error->all(FLERR,
               "fix brash/farfield: a wake rule needs 'newton off' (the force on a local atom, and every pair of a "
               "local atom, complete on its rank)");
  if (by_neighbour_ && (force->pair == nullptr || !atom->radius_flag))
    error->all(FLERR, "fix brash/farfield: wake_neighbour_speed needs a granular pair style (its neighbour list)");
}

// Before the first neighbour build of a run: membership for the current position of the hull (speed test only).
// Marks left by the previous run's last steps are used first, while their local indices still hold.
void FixBrashFarfield::setup_pre_exchange() {
  wake_marked_pieces();
  update_membership(true);
  next_update_ = update->ntimestep + every_;
  next_reneighbor = next_update_;
}

// Called only on re-neighbour steps (before exchange and borders): wakes the pieces the neighbour-speed rule
// marked, then updates the membership when a period has passed. The forced re-neighbour at next_reneighbor makes
// the update happen no later than every N steps.
void FixBrashFarfield::pre_exchange() {
  wake_marked_pieces();
  if (update->ntimestep >= next_update_) {
    update_membership(false);
    next_update_ = update->ntimestep + every_;
  }
  next_reneighbor = next_update_;
}

// By force: an idle piece pushed beyond F (horizontal force: active neighbours and walls) wakes now, integrated
// from the next step on; its pairs with idle neighbours enter the neighbour list at the next build, forced within
// kWakeBuildSteps (ghost copies get the new mask then too).
// By neighbour speed: an idle piece touched by a piece faster than V (PRE_FORCE) is marked and wakes at the next
// build (PRE_EXCHANGE), forced within kWakeBuildSteps, so that the same build lists its pairs with its idle
// neighbours: a piece of a resting bed woken without them would fall or drift within a few steps and wake its
// neighbours in turn. Until then it is an immovable neighbour, as before.
// Every rank takes the same decision on the build (Allreduce).
void FixBrashFarfield::end_of_step() { request_build(wake_pushed_pieces()); }

void FixBrashFarfield::pre_force(int) { request_build(mark_touched_by_fast_pieces()); }

void FixBrashFarfield::request_build(int any_local) {
  int any = 0;
  MPI_Allreduce(&any_local, &any, 1, MPI_INT, MPI_MAX, world);
  if (any) {
    const bigint step = update->ntimestep;
    const bigint soon = std::max(step + 1, neighbor->lastcall + kWakeBuildSteps);
    next_reneighbor = std::min(next_reneighbor, soon);
  }
}

void FixBrashFarfield::wake_marked_pieces() {
  if (marked_.empty()) return;
  int* mask = atom->mask;
  const int n = std::min(atom->nlocal, static_cast<int>(marked_.size()));
  for (int i = 0; i < n; i++)
    if (marked_[i] && (mask[i] & idle_bit_)) mask[i] = (mask[i] | active_bit_) & ~idle_bit_;
  marked_.assign(marked_.size(), 0);
}

int FixBrashFarfield::wake_pushed_pieces() {
  double** f = atom->f;
  int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  const brash::core::WakeRule rule = wake_rule();
  int woke = 0;
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & idle_bit_) && brash::core::wakes(rule, f[i][0], f[i][1])) {
      mask[i] = (mask[i] | active_bit_) & ~idle_bit_;
      woke = 1;
    }
  return woke;
}

// The pair style's half list (newton off: a pair with a ghost is listed on both ranks, so each local piece sees
// all its neighbours here; idle-idle pairs are excluded, and an idle piece has v = 0). Local indices hold until
// the next build's PRE_EXCHANGE, where the marks are used (atoms migrate and are sorted only after it).
int FixBrashFarfield::mark_touched_by_fast_pieces() {
  const NeighList* list = force->pair->list;
  double** x = atom->x;
  double** v = atom->v;
  const double* radius = atom->radius;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  if (static_cast<int>(marked_.size()) < nlocal) marked_.resize(atom->nmax, 0);
  const brash::core::WakeRule rule = wake_rule();
  auto mark_if_touched = [&](int idle, int other) {
    if (!(mask[idle] & idle_bit_) || marked_[idle]) return false;
    if (!brash::core::wakes_by_neighbour(rule, brash::core::Vec3(v[other][0], v[other][1], v[other][2])))
      return false;
    if (!brash::core::touching(x[idle][0] - x[other][0], x[idle][1] - x[other][1], x[idle][2] - x[other][2],
                               radius[idle], radius[other]))
      return false;
    marked_[idle] = 1;
    return true;
  };
  int marked = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int* jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (mark_if_touched(i, j)) marked = 1;
      if (j < nlocal && mark_if_touched(j, i)) marked = 1;
    }
  }
  return marked;
}

void FixBrashFarfield::update_membership(bool setup) {
  const double t = static_cast<double>(update->ntimestep) * update->dt;
  brash::core::FarFieldWindow window =
      brash::core::far_field_window(track_.stern_x_m(t), track_.bow_x_m(t), behind_, ahead_);
  window.half_width_m = beside_half_width_m_;
  const brash::core::WakeRule rule = wake_rule();
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  double local[2] = {0, 0};  // idle, changed
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    // the rule of brash/core/far_field.hpp; at setup (a new run, or a resumed one) its first update
    const bool was_idle = (mask[i] & idle_bit_) != 0;
    const brash::core::FarFieldZone zone = brash::core::far_field_zone(window, x[i][0], x[i][1]);
    const brash::core::Vec3 vi(v[i][0], v[i][1], v[i][2]);
    const bool idle = brash::core::idle_after_update(rule, zone, was_idle, setup, vi);
    if (idle) {
      mask[i] = (mask[i] | idle_bit_) & ~active_bit_;
      v[i][0] = v[i][1] = v[i][2] = 0;
      omega[i][0] = omega[i][1] = omega[i][2] = 0;
      local[0] += 1;
    } else {
      mask[i] = (mask[i] | active_bit_) & ~idle_bit_;
    }
    if (idle != was_idle) local[1] += 1;
  }
  double global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, world);
  n_idle_ = global[0];
  n_changed_ = global[1];
}

double FixBrashFarfield::compute_vector(int i) { return i == 0 ? n_idle_ : n_changed_; }

}  // namespace brash::liggghts
