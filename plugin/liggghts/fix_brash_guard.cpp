// fix brash/guard: see fix_brash_guard.h. Each rank finds its first offending atom (lowest id); the
// lowest id over all ranks is reported by every rank through the same error->all message.
#include "fix_brash_guard.h"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "atom.h"
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
  nevery = static_cast<int>(cfg_.every);
}

int FixBrashGuard::setmask() { return END_OF_STEP; }

void FixBrashGuard::init() { check_timestep(); }

void FixBrashGuard::setup(int) { check_atoms(); }

void FixBrashGuard::end_of_step() { check_atoms(); }

void FixBrashGuard::check_timestep() {
  if (!cfg_.youngs_modulus_pa) return;
  const double e = *cfg_.youngs_modulus_pa, nu = cfg_.poisson_ratio;
  // Smallest Rayleigh time over the group (per atom r and rho unless overridden).
  double local[2] = {std::numeric_limits<double>::infinity(), 0.0};  // T_R, atom id
  double rr = 0, rho = 0;
  if (cfg_.r_min_m && cfg_.density_kg_m3) {
    local[0] = rayleigh_time_s(*cfg_.r_min_m, *cfg_.density_kg_m3, e, nu);
  } else {
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(atom->mask[i] & groupbit)) continue;
      const double r = cfg_.r_min_m ? *cfg_.r_min_m : atom->radius[i];
      const double d = cfg_.density_kg_m3 ? *cfg_.density_kg_m3
                                          : atom->rmass[i] / (4.0 / 3.0 * kPi * std::pow(atom->radius[i], 3));
      const double t = rayleigh_time_s(r, d, e, nu);
      if (t < local[0]) local[0] = t, local[1] = static_cast<double>(atom->tag[i]);
    }
  }
  struct {
    double t;
    int rank;
  } in{local[0], comm->me}, out{};
  MPI_Allreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  if (!std::isfinite(out.t)) return;  // no atoms yet
  double info[3] = {local[1], 0, 0};
  if (comm->me == out.rank && !(cfg_.r_min_m && cfg_.density_kg_m3)) {
    // describe the atom that set the limit
    for (int i = 0; i < atom->nlocal; ++i)
      if (static_cast<double>(atom->tag[i]) == local[1]) {
        rr = cfg_.r_min_m ? *cfg_.r_min_m : atom->radius[i];
        rho = cfg_.density_kg_m3 ? *cfg_.density_kg_m3 : atom->rmass[i] / (4.0 / 3.0 * kPi * std::pow(atom->radius[i], 3));
        info[1] = rr, info[2] = rho;
      }
  } else if (cfg_.r_min_m && cfg_.density_kg_m3) {
    info[1] = *cfg_.r_min_m, info[2] = *cfg_.density_kg_m3;
  }
  MPI_Bcast(info, 3, MPI_DOUBLE, out.rank, world);
  const double dt = update->dt;
  if (dt > cfg_.max_dt_fraction * out.t) {
    const std::string who = (cfg_.r_min_m && cfg_.density_kg_m3) ? std::string("rmin/density")
                                                                 : fmt::format("atom {:.0f}", info[0]);
    const std::string msg = fmt::format(
        "fix brash/guard: step {}: {}: timestep {:g} s is too large for the contact stiffness: {:.0f} % of the "
        "Rayleigh time {:.4g} s (r = {:g} m, rho = {:g} kg/m^3, E = {:g} Pa, nu = {:g}); limit {:.0f} %, use dt <= {:.4g} s",
        update->ntimestep, who, dt, 100 * dt / out.t, out.t, info[1], info[2], e, nu, 100 * cfg_.max_dt_fraction,
        cfg_.max_dt_fraction * out.t);
    error->all(FLERR, msg.c_str());
  }
}

void FixBrashGuard::check_atoms() {
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const int nlocal = atom->nlocal;
  // First offending atom on this rank (lowest id) and its cause.
  double worst_tag = std::numeric_limits<double>::infinity();
  std::string cause;
  static const char* const kAxis[3] = {"x", "y", "z"};
  for (int i = 0; i < nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double tag = static_cast<double>(atom->tag[i]);
    if (tag >= worst_tag) continue;
    std::string c;
    for (int k = 0; k < 3 && c.empty(); ++k) {
      if (!std::isfinite(x[i][k])) c = fmt::format("non-finite position: {} = {}", kAxis[k], x[i][k]);
      else if (!std::isfinite(v[i][k])) c = fmt::format("non-finite velocity: v{} = {}", kAxis[k], v[i][k]);
      else if (!std::isfinite(f[i][k])) c = fmt::format("non-finite force: f{} = {}", kAxis[k], f[i][k]);
    }
    if (c.empty() && cfg_.box) {
      const auto& b = *cfg_.box;
      for (int k = 0; k < 3 && c.empty(); ++k) {
        if (x[i][k] < b[2 * k])
          c = fmt::format("left the box: {} = {:.6g} < {}lo = {:.6g} (m)", kAxis[k], x[i][k], kAxis[k], b[2 * k]);
        else if (x[i][k] > b[2 * k + 1])
          c = fmt::format("left the box: {} = {:.6g} > {}hi = {:.6g} (m)", kAxis[k], x[i][k], kAxis[k], b[2 * k + 1]);
      }
    }
    if (c.empty() && cfg_.z_max_m && x[i][2] > *cfg_.z_max_m)
      c = fmt::format("above zmax: z = {:.6g} > {:.6g} m (jumped out of the water)", x[i][2], *cfg_.z_max_m);
    if (c.empty() && cfg_.ke_max_J) {
      const double m = atom->rmass_flag ? atom->rmass[i] : atom->mass[atom->type[i]];
      double ke = 0.5 * m * (v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
      if (atom->omega_flag && atom->radius_flag) {
        const double* w = atom->omega[i];
        ke += 0.5 * 0.4 * m * atom->radius[i] * atom->radius[i] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      }
      if (ke > *cfg_.ke_max_J)
        c = fmt::format("runaway kinetic energy: {:.4g} J > ke_max = {:.4g} J (|v| = {:.4g} m/s)", ke, *cfg_.ke_max_J,
                        std::sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]));
    }
    if (!c.empty()) worst_tag = tag, cause = std::move(c);
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
