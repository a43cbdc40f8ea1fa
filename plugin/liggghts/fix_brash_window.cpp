// fix brash/window: the moving window. See fix_brash_window.h for the command and the rules.
#include "fix_brash_window.h"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "atom.h"
#include "atom_vec.h"
#include "brash/core/far_field.hpp"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_brash_exit.h"
#include "fix_support.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace brash::liggghts {
namespace {

constexpr double kNoFront = -std::numeric_limits<double>::infinity();

// The fixes of a style, by index in the fix list (-1: none).
int fix_index(Modify* modify, const char* style) {
  for (int i = 0; i < modify->nfix; i++)
    if (std::strcmp(modify->fix[i]->style, style) == 0) return i;
  return -1;
}

}  // namespace

FixBrashWindow::FixBrashWindow(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg), front_x_m_(kNoFront) {
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, fmt::format("fix brash/window: keyword '{}' needs a value", key).c_str());
    const double v = keyword_number(error, "brash/window", key, arg[iarg + 1]);
    if (track_.take(key, v)) continue;
    if (key == "every") {
      if (v < 1 || v != std::floor(v) || v > 1e9)
        error->all(FLERR, "fix brash/window: 'every' must be an integer >= 1");
      every_ = static_cast<int>(v);
    } else if (key == "ahead") {
      ahead_ = v, have_ahead_ = true;
    } else if (key == "behind") {
      behind_ = v, have_behind_ = true;
    } else if (key == "moving_speed") {
      moving_speed_ = v;
    } else {
      error->all(FLERR, fmt::format(
                            "fix brash/window: unknown keyword '{}' (expected every, ahead, behind, hull_x0, "
                            "speed, bow_offset, stern_offset, moving_speed)",
                            key)
                            .c_str());
    }
  }
  if (!(have_ahead_ && have_behind_ && track_.complete()))
    error->all(
        FLERR,
        "fix brash/window: keywords ahead, behind, hull_x0, speed, bow_offset and stern_offset are required");
  if (!(ahead_ > 0) || !(behind_ > 0))
    error->all(FLERR, "fix brash/window: 'ahead' and 'behind' must be > 0");
  if (!(moving_speed_ > 0)) error->all(FLERR, "fix brash/window: 'moving_speed' must be > 0");
  if (track_.stern_offset_m > track_.bow_offset_m)
    error->all(FLERR, "fix brash/window: stern_offset must be <= bow_offset");
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR, "fix brash/window requires atom_style granular/sphere (radius, mass, omega)");
  if (!atom->tag_enable) error->all(FLERR, "fix brash/window requires atom ids");
  force_reneighbor = 1;
  next_reneighbor = -1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

int FixBrashWindow::setmask() {
  return PRE_EXCHANGE;
}

// Fix brash/exit counts the atoms from its own set-up on and fix brash/farfield's marks are by local index:
// both must act before this fix at each build.
void FixBrashWindow::init() {
  const int me = fix_index(modify, style), exit = fix_index(modify, "brash/exit"),
            farfield = fix_index(modify, "brash/farfield");
  if (exit > me || farfield > me)
    error->all(FLERR, "fix brash/window: define it after fix brash/exit and fix brash/farfield");
  exit_ = exit >= 0 ? static_cast<FixBrashExit*>(modify->fix[exit]) : nullptr;
}

brash::core::MovingWindow FixBrashWindow::window_now(double t_s) const {
  double foremost_local = kNoFront, foremost = kNoFront;
  double** x = atom->x;
  double** v = atom->v;
  const double v2 = moving_speed_ * moving_speed_;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2] > v2)
      foremost_local = std::max(foremost_local, x[i][0]);
  MPI_Allreduce(&foremost_local, &foremost, 1, MPI_DOUBLE, MPI_MAX, world);
  return brash::core::moving_window(track_.stern_x_m(t_s), track_.bow_x_m(t_s), foremost, front_x_m_, behind_,
                                    ahead_);
}

// A run's set-up: hold out what lies beyond the front (once: a resumed run has its list from the restart
// file).
void FixBrashWindow::setup_pre_exchange() {
  const double t = static_cast<double>(update->ntimestep) * update->dt;
  front_x_m_ = window_now(t).insert_below_x_m;
  if (!holding_started_) {
    hold_out_beyond(front_x_m_);
    holding_started_ = true;  // a second `run` in the same input keeps the list
  }
  next_update_ = update->ntimestep;
  pre_exchange();
}

void FixBrashWindow::pre_exchange() {
  if (update->ntimestep >= next_update_) {
    const brash::core::MovingWindow window = window_now(static_cast<double>(update->ntimestep) * update->dt);
    front_x_m_ = window.insert_below_x_m;
    const long long removed = remove_behind(window.remove_below_x_m);
    const long long inserted = insert_before(front_x_m_);
    atoms_changed(inserted, removed);
    next_update_ = update->ntimestep + every_;
  }
  next_reneighbor = next_update_;
}

void FixBrashWindow::hold_out_beyond(double front_x_m) {
  std::vector<double> mine;
  delete_local_atoms(atom, [&](int i) {
    const double* xi = atom->x[i];
    if (!(atom->mask[i] & groupbit) || xi[0] < front_x_m) return false;
    const HeldPiece p{static_cast<double>(atom->tag[i]), static_cast<double>(atom->type[i]),
                      static_cast<double>(atom->mask[i]), xi[0], xi[1], xi[2], atom->radius[i], atom->rmass[i],
                      atom->density_flag ? atom->density[i] : 0.0};
    const double* d = &p.tag;
    mine.insert(mine.end(), d, d + kDoublesPerPiece);
    return true;
  });
  const int nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  const int count = static_cast<int>(mine.size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int r = 1; r < nprocs; r++) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(displs[nprocs - 1] + counts[nprocs - 1]));
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  held_.resize(all.size() / kDoublesPerPiece);
  std::memcpy(static_cast<void*>(held_.data()), all.data(), all.size() * sizeof(double));
  // the same order on every rank, whatever the ranks held
  std::sort(held_.begin(), held_.end(), [](const HeldPiece& a, const HeldPiece& b) {
    return a.x < b.x || (a.x == b.x && a.tag < b.tag);
  });
  next_held_ = 0;
  atoms_changed(0, static_cast<long long>(held_.size()));
}

long long FixBrashWindow::insert_before(double front_x_m) {
  std::size_t end = next_held_;
  while (end < held_.size() && held_[end].x < front_x_m) ++end;
  if (end == next_held_) return 0;
  Fix** fix = modify->fix;
  for (int j = 0; j < modify->nfix; j++)
    if (fix[j]->create_attribute) fix[j]->pre_set_arrays();
  long long mine = 0;
  for (std::size_t k = next_held_; k < end; k++) {
    const HeldPiece& p = held_[k];
    double pos[3] = {p.x, p.y, p.z};
    if (!domain->is_in_subdomain(pos)) continue;
    atom->avec->create_atom(static_cast<int>(p.type), pos);
    const int m = atom->nlocal - 1;
    atom->tag[m] = static_cast<int>(p.tag);
    atom->mask[m] = static_cast<int>(p.mask);
    atom->radius[m] = p.radius;
    atom->rmass[m] = p.rmass;
    if (atom->density_flag) atom->density[m] = p.density;
    for (int d = 0; d < 3; d++) atom->v[m][d] = atom->omega[m][d] = 0.0;
    for (int j = 0; j < modify->nfix; j++)
      if (fix[j]->create_attribute) fix[j]->set_arrays(m);
    ++mine;
  }
  long long all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
  const long long expected = static_cast<long long>(end - next_held_);
  if (all != expected)
    error->all(FLERR, fmt::format("fix brash/window: step {}: {} of {} held-out piece(s) lie in no rank's "
                                  "sub-domain (outside the box?)",
                                  update->ntimestep, expected - all, expected)
                          .c_str());
  next_held_ = end;
  return all;
}

long long FixBrashWindow::remove_behind(double x_m) {
  const long long mine =
      delete_local_atoms(atom, [&](int i) { return (atom->mask[i] & groupbit) && atom->x[i][0] < x_m; });
  long long all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
  removed_ += static_cast<double>(all);
  return all;
}

// natoms and the atom map as LIGGGHTS' own insertion and deletion leave them; fix brash/exit is told.
void FixBrashWindow::atoms_changed(long long added, long long deleted) {
  if (added == 0 && deleted == 0) return;  // as many in as out still moves atoms: the map is rebuilt then too
  recount_atoms(atom, world);
  if (exit_) exit_->expect_atoms(added - deleted);
}

double FixBrashWindow::compute_vector(int i) {
  if (i == 0) return static_cast<double>(held_.size() - next_held_);
  if (i == 1) return removed_;
  return front_x_m_;
}

// Restart: front, removed, the number of pieces still held out, then those pieces.
void FixBrashWindow::write_restart(FILE* fp) {
  if (comm->me != 0) return;
  std::vector<double> list = {front_x_m_, removed_, static_cast<double>(held_.size() - next_held_)};
  for (std::size_t k = next_held_; k < held_.size(); k++) {
    const double* d = &held_[k].tag;
    list.insert(list.end(), d, d + kDoublesPerPiece);
  }
  const int size = static_cast<int>(list.size() * sizeof(double));
  std::fwrite(&size, sizeof(int), 1, fp);
  std::fwrite(list.data(), sizeof(double), list.size(), fp);
}

void FixBrashWindow::restart(char* buf) {
  double head[3];
  std::memcpy(head, buf, sizeof(head));
  front_x_m_ = head[0];
  removed_ = head[1];
  held_.resize(static_cast<std::size_t>(head[2]));
  std::memcpy(static_cast<void*>(held_.data()), buf + sizeof(head), held_.size() * sizeof(HeldPiece));
  next_held_ = 0;
  holding_started_ = true;
}

}  // namespace brash::liggghts
