// fix brash/guard: see fix_brash_guard.h. Each rank finds its first offending atom (lowest id); the
// lowest id over all ranks is reported by every rank through the same error->all message.
#include "fix_brash_guard.h"

#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "atom.h"
#include "brash/hull/mesh.hpp"
#include "comm.h"
#include "error.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace brash::liggghts {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

FixBrashGuard::FixBrashGuard(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  std::vector<std::string> args;
  for (int i = 3; i < narg; ++i) args.emplace_back(arg[i]);
  try {
    cfg_ = parse_guard_args(args);
  } catch (const brash::InputError& e) {
    error->all(FLERR, e.what());
  }
  if (cfg_.youngs_modulus_pa && !(atom->radius_flag && atom->rmass_flag) && !(cfg_.r_min_m && cfg_.density_kg_m3))
    error->all(FLERR, "fix brash/guard: the time-step check needs per-atom radius and mass, or rmin and density");
  if (!cfg_.hull_file.empty()) {
    if (!atom->radius_flag)
      error->all(FLERR, "fix brash/guard: the hull check needs per-atom radii (atom_style granular)");
    try {
      const brash::hull::Mesh mesh = brash::hull::read_mesh(cfg_.hull_file);
      hull_ = std::make_unique<brash::hull::Proximity>(mesh);
    } catch (const std::exception& e) {
      error->all(FLERR, fmt::format("fix brash/guard: hull {}: {}", cfg_.hull_file, e.what()).c_str());
    }
    if (!hull_->closed())
      error->all(FLERR, fmt::format(
                            "fix brash/guard: hull {} is not a closed surface: the hull check needs the full "
                            "closed hull (inside/outside), not a band or half of it",
                            cfg_.hull_file)
                            .c_str());
  }
  nevery = static_cast<int>(cfg_.every);
}

int FixBrashGuard::setmask() { return END_OF_STEP; }

void FixBrashGuard::init() { check_timestep(); }

void FixBrashGuard::setup(int) { check_atoms(); }

void FixBrashGuard::end_of_step() { check_atoms(); }

void FixBrashGuard::check_timestep() {
  if (!cfg_.youngs_modulus_pa) return;
  const double e = *cfg_.youngs_modulus_pa, nu = cfg_.poisson_ratio;
  // Smallest Rayleigh time over the group (per atom r and rho unless overridden), with the atom id, r and rho
  // that set it (info: id, r, rho; id 0 when rmin and density are both given).
  double t_min = std::numeric_limits<double>::infinity();
  double info[3] = {0, 0, 0};
  if (cfg_.r_min_m && cfg_.density_kg_m3) {
    t_min = guard::rayleigh_time_s(*cfg_.r_min_m, *cfg_.density_kg_m3, e, nu);
    info[1] = *cfg_.r_min_m, info[2] = *cfg_.density_kg_m3;
  } else {
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(atom->mask[i] & groupbit)) continue;
      const double r = cfg_.r_min_m ? *cfg_.r_min_m : atom->radius[i];
      const double rho = cfg_.density_kg_m3 ? *cfg_.density_kg_m3
                                            : atom->rmass[i] / (4.0 / 3.0 * kPi * std::pow(atom->radius[i], 3));
      const double t = guard::rayleigh_time_s(r, rho, e, nu);
      if (t < t_min) t_min = t, info[0] = static_cast<double>(atom->tag[i]), info[1] = r, info[2] = rho;
    }
  }
  struct {
    double t;
    int rank;
  } in{t_min, comm->me}, out{};
  MPI_Allreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  if (!std::isfinite(out.t)) return;  // no atoms yet
  MPI_Bcast(info, 3, MPI_DOUBLE, out.rank, world);
  if (const auto cause = guard::check_timestep(update->dt, info[1], info[2], e, nu, cfg_.max_dt_fraction)) {
    const std::string who = (cfg_.r_min_m && cfg_.density_kg_m3) ? std::string("rmin/density")
                                                                 : fmt::format("atom {:.0f}", info[0]);
    const std::string msg = fmt::format("fix brash/guard: step {}: {}: {}", update->ntimestep, who, *cause);
    error->all(FLERR, msg.c_str());
  }
}

void FixBrashGuard::check_atoms() {
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const int nlocal = atom->nlocal;
  guard::Limits limits;
  limits.box = cfg_.box;
  limits.z_max_m = cfg_.z_max_m;
  limits.ke_max_J = cfg_.ke_max_J;
  guard::HullNow hull;
  if (hull_) {
    // The hull frame moves at constant velocity from time 0: t = step * dt, as brash-liggghts-run's
    // fix move/mesh moves the mesh from step 0 (its time and the mesh nodes are restored by read_restart, and
    // so is the step counter, so the two agree after a resume too).
    const double t = static_cast<double>(update->ntimestep) * update->dt;
    limits.max_hull_penetration_d = cfg_.max_penetration;
    hull.proximity = hull_.get();
    for (int k = 0; k < 3; ++k) hull.origin_m[k] = cfg_.hull_origin_m[k] + cfg_.hull_velocity_m_s[k] * t;
  }
  // First offending atom on this rank (lowest id) and its cause.
  double worst_tag = std::numeric_limits<double>::infinity();
  std::string cause;
  for (int i = 0; i < nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double tag = static_cast<double>(atom->tag[i]);
    if (tag >= worst_tag) continue;
    guard::Piece p;
    p.x_m = Eigen::Vector3d(x[i][0], x[i][1], x[i][2]);
    p.v_m_s = Eigen::Vector3d(v[i][0], v[i][1], v[i][2]);
    p.force_N = Eigen::Vector3d(f[i][0], f[i][1], f[i][2]);
    if (atom->omega_flag)
      p.omega_rad_s = Eigen::Vector3d(atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]);
    p.radius_m = atom->radius_flag ? atom->radius[i] : 0.0;
    p.mass_kg = atom->rmass_flag ? atom->rmass[i] : atom->mass[atom->type[i]];
    if (auto c = guard::check_piece(p, limits, hull_ ? &hull : nullptr))
      worst_tag = tag, cause = std::move(*c);
  }
  struct {
    double tag;
    int rank;
  } in{worst_tag, comm->me}, out{};
  MPI_Allreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  if (!std::isfinite(out.tag)) return;
  // The owning rank sends the cause text to everyone (error->all prints it once, from rank 0).
  int len = comm->me == out.rank ? static_cast<int>(cause.size()) : 0;
  MPI_Bcast(&len, 1, MPI_INT, out.rank, world);
  cause.resize(static_cast<std::size_t>(len));
  MPI_Bcast(cause.data(), len, MPI_CHAR, out.rank, world);
  const std::string msg =
      fmt::format("fix brash/guard: step {}: atom {:.0f}: {}", update->ntimestep, out.tag, cause);
  error->all(FLERR, msg.c_str());
}

}  // namespace brash::liggghts
