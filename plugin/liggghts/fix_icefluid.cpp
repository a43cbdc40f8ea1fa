// fix icefluid: LIGGGHTS glue around brash_core. Only translation lives here; the physics is in
// plugin/core (evaluate / advance). See fix_icefluid.h for the command syntax.
#include "fix_icefluid.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "brash/error.hpp"
#include "brash/hull/flow.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/hull/panel_flow.hpp"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace core = brash::core;

namespace brash::liggghts {
namespace {

double to_number(Error* error, const char* keyword, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') {
    const std::string msg = std::string("fix icefluid: keyword '") + keyword + "' expects a number, got '" + text + "'";
    error->all(FLERR, msg.c_str());
  }
  return v;
}

}  // namespace

FixIceFluid::FixIceFluid(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "fix icefluid requires per-atom radius and mass (atom_style granular/sphere)");
  parse(narg, arg);
  if (comm->me == 0) {  // the model the deck runs, in its log: brash-post reads it from a run without meta.json
    const std::string msg = "fix icefluid: model " + std::string(to_string(params_.model)) + ", treatment " +
                            std::string(to_string(params_.treatment)) + "\n";
    if (screen) fputs(msg.c_str(), screen);
    if (logfile) fputs(msg.c_str(), logfile);
  }

  peratom_flag = 1;
  size_peratom_cols = kOutputSize;
  peratom_freq = output_every_;  // LIGGGHTS checks that dumps ask for it at multiples of this
  restart_peratom = 1;
  create_attribute = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow/copy/exchange
  atom->add_callback(1);  // restart
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixIceFluid::~FixIceFluid() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(state_);
  memory->destroy(output_);
  memory->destroy(flow_);
  memory->destroy(flow_accel_);
}

void FixIceFluid::parse(int narg, char** arg) {
  std::string hull_flow_file;
  try {
    for (int iarg = 3; iarg < narg;) {
      const std::string key = arg[iarg];
      auto need = [&](int n) {
        if (iarg + n >= narg) {
          const std::string msg = "fix icefluid: keyword '" + key + "' needs " + std::to_string(n) + " value(s)";
          error->all(FLERR, msg.c_str());
        }
      };
      auto num = [&](int k) { return to_number(error, key.c_str(), arg[iarg + k]); };
      if (key == "model") {
        need(1), params_.model = core::parse_fluid_model(arg[iarg + 1]), iarg += 2;
      } else if (key == "treatment") {
        need(1), params_.treatment = core::parse_treatment(arg[iarg + 1]), iarg += 2;
      } else if (key == "cd") {
        need(1), params_.drag_coefficient = num(1), iarg += 2;
      } else if (key == "drag_law") {
        need(1), params_.drag_law = core::parse_drag_law(arg[iarg + 1]), iarg += 2;
      } else if (key == "nu") {
        need(1), params_.kinematic_viscosity_m2_s = num(1), iarg += 2;
      } else if (key == "ca") {
        need(1);
        if (std::strcmp(arg[iarg + 1], "uniform") == 0) {
          need(2), params_.ca = core::CaTable::uniform(num(2)), iarg += 3;
        } else {
          params_.ca = core::parse_ca_table(arg[iarg + 1]), iarg += 2;
        }
      } else if (key == "water_level") {
        need(1), params_.water_level_m = num(1), iarg += 2;
      } else if (key == "water_density") {
        need(1), params_.water_density_kg_m3 = num(1), iarg += 2;
      } else if (key == "flow") {
        need(3), params_.flow_velocity_m_s = core::Vec3(num(1), num(2), num(3)), iarg += 4;
      } else if (key == "hull_flow") {
        need(5);
        const std::string file = arg[iarg + 1];
        hull_flow_origin_m_ = core::Vec3(num(2), num(3), num(4));
        hull_flow_speed_m_s_ = num(5);
        hull_flow_file = file, iarg += 6;
      } else if (key == "g") {
        need(1), params_.gravity_m_s2 = num(1), iarg += 2;
      } else if (key == "output_every") {
        need(1);
        const double n = num(1);
        if (!(n >= 1) || n != static_cast<int>(n)) error->all(FLERR, "fix icefluid: output_every must be an integer >= 1");
        output_every_ = static_cast<int>(n), iarg += 2;
      } else if (key == "gravity") {
        need(1);
        const std::string v = arg[iarg + 1];
        if (v != "yes" && v != "no") error->all(FLERR, "fix icefluid: keyword 'gravity' expects yes or no");
        params_.apply_gravity = v == "yes", iarg += 2;
      } else {
        const std::string msg = "fix icefluid: unknown keyword '" + key +
                                "' (expected model, treatment, cd, drag_law, nu, ca, water_level, "
                                "water_density, flow, hull_flow, g, gravity, output_every)";
        error->all(FLERR, msg.c_str());
      }
    }
    params_.validate("fix icefluid");
    if (!hull_flow_file.empty()) {
      if (!params_.flow_velocity_m_s.isZero())
        error->all(
            FLERR,
            "fix icefluid: 'flow' and 'hull_flow' exclude each other (the hull's flow is in still water)");
      if (!params_.has_drag())
        error->all(FLERR, "fix icefluid: 'hull_flow' acts through the drag, and model added_mass has none");
      // Every rank builds the same table from the same file (deterministic): no communication,
      // rank-independent. The mesh reader's and the table's errors name the file or the problem, not the fix.
      try {
        // a .bin file: a table the runner computed (brash::hull_flow_table, thin-ship or panel flow)
        if (hull_flow_file.size() > 4 && hull_flow_file.compare(hull_flow_file.size() - 4, 4, ".bin") == 0) {
          auto table = brash::hull::read_flow_table(hull_flow_file);
          if (!table) throw brash::InputError(hull_flow_file + ": not a readable brash flow table");
          hull_flow_ = std::move(*table);
        } else {
          const brash::hull::Mesh mesh = brash::hull::read_mesh(hull_flow_file);
          hull_flow_ = brash::hull::thin_ship_flow(mesh, params_.water_level_m - hull_flow_origin_m_.z(),
                                                   hull_flow_speed_m_s_);
        }
      } catch (const brash::InputError& e) {
        const std::string msg = std::string("fix icefluid: ") + e.what();
        error->all(FLERR, msg.c_str());
      }
      if (comm->me == 0) {
        const auto n = hull_flow_.nodes();
        const std::string msg = "fix icefluid: hull flow from " + hull_flow_file + ": " +
                                std::to_string(n.prod()) + " table nodes, largest flow speed " +
                                std::to_string(hull_flow_.max_speed_m_s()) + " m/s (ship " +
                                std::to_string(hull_flow_speed_m_s_) + " m/s)\n";
        if (screen) fputs(msg.c_str(), screen);
        if (logfile) fputs(msg.c_str(), logfile);
      }
    }
  } catch (const brash::InputError& e) {
    error->all(FLERR, e.what());
  }
}

int FixIceFluid::setmask() { return POST_FORCE; }

void FixIceFluid::init() {
  // Implicit added mass scales the sum of all other forces: nothing may add force after us.
  const int me = modify->find_fix(id);
  for (int i = me + 1; i < modify->nfix; i++) {
    if (modify->fmask[i] & POST_FORCE) {
      const std::string msg = std::string("fix icefluid must be the last post_force fix, but fix ") +
                              modify->fix[i]->id + " (" + modify->fix[i]->style +
                              ") comes after it: define fix icefluid last";
      error->all(FLERR, msg.c_str());
    }
  }
  if (std::strstr(update->integrate_style, "respa")) error->all(FLERR, "fix icefluid does not support run_style respa");
  if (params_.apply_gravity && modify->find_fix_style("gravity", 0))
    error->all(FLERR, "fix icefluid: 'gravity yes' together with fix gravity would apply gravity twice");
}

void FixIceFluid::setup(int) {
  // Forces at the start of a run feed the first half kick. A sphere with history (continued run or
  // restart) replays its last evaluation at this same position (see kernel.hpp), so a restarted run
  // continues exactly like an uninterrupted one.
  compute(true);
}

void FixIceFluid::post_force(int) { compute(false); }

void FixIceFluid::compute(bool replay) {
  if (atom->nlocal == 0) return;
  core::KernelArrays a;  // LIGGGHTS' per-atom 2-d arrays are contiguous blocks: row 0 is the data
  a.n = static_cast<std::size_t>(atom->nlocal);
  a.radius_m = atom->radius;
  a.mass_kg = atom->rmass;
  a.x_m = atom->x[0];
  a.v_m_s = atom->v[0];
  a.f_N = atom->f[0];
  a.state = state_[0];
  a.output = update->ntimestep % output_every_ == 0 ? output_[0] : nullptr;
  a.mask = igroup == 0 ? nullptr : atom->mask;  // group "all": every atom, no per-atom mask test
  a.groupbit = groupbit;
  if (!hull_flow_.empty()) {
    // The hull frame (water level at z = 0) at this step; t = step * dt as fix move/mesh linear from step 0.
    const double t = static_cast<double>(update->ntimestep) * update->dt;
    const core::Vec3 frame(hull_flow_origin_m_.x() + hull_flow_speed_m_s_ * t, hull_flow_origin_m_.y(),
                           params_.water_level_m);
    const double* x = atom->x[0];
    double* fl = flow_[0];
    double* fa = flow_accel_[0];
    const int* mask = atom->mask;
    core::Vec3 u, du_dt;
    for (int i = 0; i < atom->nlocal; i++) {
      if (igroup != 0 && !(mask[i] & groupbit)) continue;  // the kernel skips them too (idle far-field ice)
      // U_flow and Du/Dt (earth frame) at the sphere: the table's values move with the hull
      hull_flow_.at(core::Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]) - frame, u, du_dt);
      fl[3 * i] = u.x(), fl[3 * i + 1] = u.y(), fl[3 * i + 2] = u.z();
      fa[3 * i] = du_dt.x(), fa[3 * i + 1] = du_dt.y(), fa[3 * i + 2] = du_dt.z();
    }
    a.flow_m_s = fl;
    // a table of the first file version (a run started before) has no Du/Dt: the drag alone sees the flow
    if (hull_flow_.has_acceleration()) a.flow_acceleration_m_s2 = fa;
  }
  core::apply_kernel(params_, a, update->dt, replay);
}

void FixIceFluid::grow_arrays(int nmax) {
  memory->grow(state_, nmax, kStateSize, "icefluid:state");
  memory->grow(output_, nmax, kOutputSize, "icefluid:output");
  if (!hull_flow_.empty()) {
    memory->grow(flow_, nmax, 3, "icefluid:flow");
    memory->grow(flow_accel_, nmax, 3, "icefluid:flow_accel");
  }
  array_atom = output_;
}

void FixIceFluid::copy_arrays(int i, int j, int) {
  for (int k = 0; k < kStateSize; k++) state_[j][k] = state_[i][k];
  for (int k = 0; k < kOutputSize; k++) output_[j][k] = output_[i][k];
}

void FixIceFluid::set_arrays(int i) {
  for (int k = 0; k < kStateSize; k++) state_[i][k] = 0.0;
  for (int k = 0; k < kOutputSize; k++) output_[i][k] = 0.0;
}

int FixIceFluid::pack_exchange(int i, double* buf) {
  for (int k = 0; k < kStateSize; k++) buf[k] = state_[i][k];
  for (int k = 0; k < kOutputSize; k++) buf[kStateSize + k] = output_[i][k];
  return kStateSize + kOutputSize;
}

int FixIceFluid::unpack_exchange(int nlocal, double* buf) {
  for (int k = 0; k < kStateSize; k++) state_[nlocal][k] = buf[k];
  for (int k = 0; k < kOutputSize; k++) output_[nlocal][k] = buf[kStateSize + k];
  return kStateSize + kOutputSize;
}

int FixIceFluid::pack_restart(int i, double* buf) {
  buf[0] = kStateSize + 1;
  for (int k = 0; k < kStateSize; k++) buf[1 + k] = state_[i][k];
  return kStateSize + 1;
}

void FixIceFluid::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;  // skip the blocks of the fixes stored before this one; each starts with its length
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < kStateSize; k++) state_[nlocal][k] = extra[nlocal][m++];
}

double FixIceFluid::memory_usage() {
  const int flow = hull_flow_.empty() ? 0 : 6;
  return double(atom->nmax) * (kStateSize + kOutputSize + flow) * sizeof(double) +
         (double(hull_flow_.values().size()) + double(hull_flow_.brick_values().size())) * sizeof(double) +
         double(hull_flow_.cell_bricks().size()) * sizeof(std::int32_t);
}

}  // namespace brash::liggghts
