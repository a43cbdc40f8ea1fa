// fix brash/hullsplit: see fix_brash_hullsplit.h.
#include "fix_brash_hullsplit.h"

#include <fmt/format.h>
#include <mpi.h>

#include <string>

#include "atom.h"
#include "error.h"
#include "fix_contact_property_atom_wall.h"
#include "fix_mesh_surface.h"
#include "fix_support.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace brash::liggghts {

namespace {
constexpr const char* kStyle = "brash/hullsplit";
}

FixBrashHullSplit::FixBrashHullSplit(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  int given = 0;  // a bit per required keyword
  for (int i = 3; i < narg; i += 2) {
    const std::string key = arg[i];
    if (i + 1 >= narg) error->all(FLERR, fmt::format("fix {}: keyword {} needs a value", kStyle, key).c_str());
    if (key == "mesh") {
      mesh_id_ = arg[i + 1];
      given |= 1;
      continue;
    }
    const double v = keyword_number(error, kStyle, key, arg[i + 1]);
    if (key == "hull_x0") x0_m_ = v, given |= 2;
    else if (key == "speed") speed_m_s_ = v, given |= 4;
    else if (key == "par_aft") regions_.x_par_aft_m = v, given |= 8;
    else if (key == "par_fwd") regions_.x_par_fwd_m = v, given |= 16;
    else if (key == "scale") scale_ = v;
    else
      error->all(FLERR, fmt::format("fix {}: unknown keyword {} (expected mesh, hull_x0, speed, par_aft, par_fwd, "
                                    "scale)",
                                    kStyle, key)
                            .c_str());
  }
  if (given != 31)
    error->all(FLERR, fmt::format("fix {}: needs mesh MESH-ID hull_x0 X0 speed U par_aft XA par_fwd XF", kStyle).c_str());
  if (!(regions_.x_par_aft_m <= regions_.x_par_fwd_m))
    error->all(FLERR, fmt::format("fix {}: par_aft {} m is ahead of par_fwd {} m", kStyle, regions_.x_par_aft_m,
                                  regions_.x_par_fwd_m)
                          .c_str());
  vector_flag = 1;
  size_vector = static_cast<int>(core::kHullSplitParts);
  global_freq = 1;
  extvector = 1;
}

int FixBrashHullSplit::setmask() { return 0; }

void FixBrashHullSplit::init() {
  Fix* f = modify->find_fix_id(mesh_id_.c_str());
  mesh_ = f ? dynamic_cast<FixMeshSurface*>(f) : nullptr;
  if (!mesh_)
    error->all(FLERR, fmt::format("fix {}: mesh {} is not a fix mesh/surface", kStyle, mesh_id_).c_str());
  if (!mesh_->meshforceContactStress())
    error->all(FLERR, fmt::format("fix {}: the fix wall/gran of mesh {} does not store its contacts (add "
                                  "store_force_contact_stress yes)",
                                  kStyle, mesh_id_)
                          .c_str());
  summed_at_ = -1;
}

// The contacts stored by fix wall/gran this step: per piece, per touched triangle, 9 values: F on the piece
// (3), d from the contact point to the piece's centre (3), the wall's velocity there (3).
void FixBrashHullSplit::sum_contacts() {
  core::HullSplit mine{};
  if (!update->setupflag) {
    FixContactPropertyAtomWall* store = mesh_->meshforceContactStress();
    const double* const* x = atom->x;
    const int* mask = atom->mask;
    const int nlocal = atom->nlocal;
    const double hull_x_m = x0_m_ + speed_m_s_ * static_cast<double>(update->ntimestep) * update->dt;
    for (int i = 0; i < nlocal; ++i) {
      if (!(mask[i] & groupbit)) continue;
      const int n = store->n_partner(i);
      for (int k = 0; k < n; ++k) {
        const double* c = store->contacthistory(i, k);
        const double on_hull[3] = {-c[0], -c[1], -c[2]};
        core::add_contact_x(mine, regions_, x[i][0] - c[3] - hull_x_m, on_hull, c + 3);
      }
    }
  }
  MPI_Allreduce(mine.data(), split_.data(), static_cast<int>(split_.size()), MPI_DOUBLE, MPI_SUM, world);
  for (double& v : split_) v *= scale_;
  summed_at_ = update->ntimestep;
}

double FixBrashHullSplit::compute_vector(int i) {
  // every rank asks for the vector at the same point (fix ave/time, thermo): the sum is collective
  if (summed_at_ != update->ntimestep || update->setupflag) sum_contacts();
  return split_[static_cast<std::size_t>(i)];
}

}  // namespace brash::liggghts
