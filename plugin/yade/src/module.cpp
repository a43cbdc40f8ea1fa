// brash_yade: Python extension module (pybind11) that brings the engine-independent fluid core
// (plugin/core, brash_core) into YADE. YADE is shipped by Debian without C++ headers, so the adapter is
// a YADE PyRunner (plugin/yade/py/brash_yade_scene.py) that reads the spheres each step and calls
// Fluid.correction() here; the physics is the same compiled code LIGGGHTS and ODE call.
//
// Also exposes the run-time guards (Guard: brash::guard's per-piece checks and the hull penetration query)
// and the single-sphere reference integrator and the closed forms, so the YADE tests compare against the same
// oracle as the LIGGGHTS tests, in the same process.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "brash/case.hpp"
#include "brash/case_fluid.hpp"
#include "brash/core/fluid.hpp"
#include "brash/core/params.hpp"
#include "brash/core/reference.hpp"
#include "brash/run/guard.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/hull/proximity.hpp"

namespace py = pybind11;
using namespace brash::core;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

const double* vec_n(const Array& a, py::ssize_t n, const char* name) {
  if (a.ndim() != 1 || a.shape(0) != n)
    throw std::invalid_argument(std::string(name) + ": expected shape (" + std::to_string(n) + ",)");
  return a.data();
}

const double (*mat_n3(const Array& a, py::ssize_t n, const char* name))[3] {
  if (a.ndim() != 2 || a.shape(0) != n || a.shape(1) != 3)
    throw std::invalid_argument(std::string(name) + ": expected shape (" + std::to_string(n) + ", 3)");
  return reinterpret_cast<const double(*)[3]>(a.data());
}

// Three doubles out of a YADE Vector3 (or any sequence of 3 numbers). YADE's Vector3 pickles through
// __getinitargs__ (one call returning a tuple of floats: ~3x cheaper than three __getitem__ calls).
void read3(const py::handle& obj, double out[3]) {
  PyObject* t = nullptr;
  static PyObject* name = PyUnicode_InternFromString("__getinitargs__");
  if (PyObject_HasAttr(obj.ptr(), name)) t = PyObject_CallMethodNoArgs(obj.ptr(), name);
  if (t && PyTuple_Check(t) && PyTuple_GET_SIZE(t) == 3) {
    for (int k = 0; k < 3; ++k) out[k] = PyFloat_AsDouble(PyTuple_GET_ITEM(t, k));
    Py_DECREF(t);
  } else {
    Py_XDECREF(t);
    PyErr_Clear();
    for (int k = 0; k < 3; ++k) out[k] = obj[py::int_(k)].cast<double>();
  }
  if (PyErr_Occurred()) throw py::error_already_set();
}

FluidParams make_params(const std::string& model, const std::string& treatment, double cd,
                        const std::string& drag_law, double nu, const std::string& ca_table, double water_level,
                        double water_density, double g, bool apply_gravity) {
  FluidParams p;
  p.model = parse_fluid_model(model);
  p.treatment = parse_treatment(treatment);
  p.drag_coefficient = cd;
  p.drag_law = parse_drag_law(drag_law);
  p.kinematic_viscosity_m2_s = nu;
  p.ca = parse_ca_table(ca_table);
  p.water_level_m = water_level;
  p.water_density_kg_m3 = water_density;
  p.gravity_m_s2 = g;
  p.apply_gravity = apply_gravity;
  p.validate("brash_yade.Fluid");
  return p;
}

// The adapter: per-sphere fluid state lives here, indexed by the position in the arrays passed each
// step (the caller always passes the same spheres in the same order).
class Fluid {
 public:
  explicit Fluid(FluidParams p) : p_(std::move(p)) {}

  // radius (n), mass (n), pos/vel/force (n,3): force = every other force YADE holds for the sphere
  // (contacts). Returns the force to add with O.forces.addF so that the sphere's total becomes
  // (force + m g_engine + fluid) * scale (implicit added mass) or force + m g_engine + fluid (explicit / no
  // added mass), g_engine being the gravity NewtonIntegrator adds as an acceleration itself (zero when the
  // fluid applies gravity): the engine's gravity is one of the "other" forces the scale acts on, as in the
  // core's reference integrator (engine_gravity), and the correction takes m g_engine back out.
  py::array_t<double> correction(const Array& radius, const Array& mass, const Array& pos, const Array& vel,
                                 const Array& force, double dt, const std::array<double, 3>& engine_gravity) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    const double* r = vec_n(radius, n, "radius");
    const double* m = vec_n(mass, n, "mass");
    const auto* x = mat_n3(pos, n, "pos");
    const auto* v = mat_n3(vel, n, "vel");
    const auto* f = mat_n3(force, n, "force");
    check_engine_gravity(engine_gravity);
    const double* ge = engine_gravity.data();
    if (state_.size() != static_cast<std::size_t>(n)) {
      if (!state_.empty())
        throw std::invalid_argument("Fluid.correction: the number of spheres changed (" +
                                    std::to_string(state_.size()) + " -> " + std::to_string(n) +
                                    "): call remap() when spheres come or go");
      resize(n);
    }
    py::array_t<double> out({n, py::ssize_t(3)});
    auto* o = reinterpret_cast<double(*)[3]>(out.mutable_data());
    double* fr = fraction_.mutable_data();
    auto* ca = reinterpret_cast<double(*)[3]>(ca_.mutable_data());
    {
      py::gil_scoped_release nogil;
      for (py::ssize_t i = 0; i < n; ++i) {
        const Vec3 vi(v[i][0], v[i][1], v[i][2]);
        const FluidOutput fo = evaluate(p_, Sphere{r[i], m[i], Vec3(x[i][0], x[i][1], x[i][2]), vi}, state_[i], dt);
        for (int k = 0; k < 3; ++k) {
          const double other = f[i][k] + m[i] * ge[k];
          o[i][k] = scaled_total_force(other, fo.force_N[k], fo.scale[k]) - other;
          ca[i][k] = fo.ca[k];
        }
        fr[i] = fo.immersion.fraction;
        state_[i] = advance(state_[i], vi);
      }
    }
    return out;
  }

  // Same, for callers that hold YADE Vector3 objects (anything indexable by 0..2): lists of length n.
  py::array_t<double> correction_seq(const Array& radius, const Array& mass, const py::sequence& pos,
                                     const py::sequence& vel, const py::sequence& force, double dt,
                                     const std::array<double, 3>& engine_gravity) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    auto to_array = [n](const py::sequence& s, const char* name) {
      if (static_cast<py::ssize_t>(py::len(s)) != n)
        throw std::invalid_argument(std::string(name) + ": expected " + std::to_string(n) + " vectors");
      Array a({n, py::ssize_t(3)});
      auto* d = reinterpret_cast<double(*)[3]>(a.mutable_data());
      for (py::ssize_t i = 0; i < n; ++i) read3(s[i], d[i]);
      return a;
    };
    return correction(radius, mass, to_array(pos, "pos"), to_array(vel, "vel"), to_array(force, "force"), dt,
                      engine_gravity);
  }

  // The whole YADE step in one call (the fast path of the PyRunner): for sphere i, read
  // states[i].pos / .vel and forces.f(ids[i], True) (contacts, valid after InteractionLoop), evaluate
  // the core, and forces.addF(ids[i], correction). `states` are YADE State objects cached once (they
  // stay the live state of their bodies); radius/mass are per-sphere arrays in the same order.
  // engine_gravity: NewtonIntegrator.gravity (see correction()). bodies: the spheres' cached Body objects or
  // None; YADE sets the id of an erased body to -1, so a body whose id is no longer ids[i] is gone: then
  // nothing is applied and the positions of the gone spheres are returned (the caller drops them with
  // remap() and calls again). Returns None otherwise.
  py::object apply(const Array& radius, const Array& mass, const py::list& states, const py::list& ids,
                   const py::object& forces, double dt, const std::array<double, 3>& engine_gravity,
                   const py::object& bodies) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    if (static_cast<py::ssize_t>(py::len(states)) != n || static_cast<py::ssize_t>(py::len(ids)) != n)
      throw std::invalid_argument("Fluid.apply: radius, mass, states and ids must have the same length");
    if (!bodies.is_none()) {
      const py::list bl = bodies.cast<py::list>();
      if (static_cast<py::ssize_t>(py::len(bl)) != n)
        throw std::invalid_argument("Fluid.apply: bodies and ids must have the same length");
      const py::str s_id("id");
      py::list gone;
      for (py::ssize_t i = 0; i < n; ++i) {
        const long id = py::handle(PyList_GET_ITEM(bl.ptr(), i)).attr(s_id).cast<long>();
        if (id != py::handle(PyList_GET_ITEM(ids.ptr(), i)).cast<long>()) gone.append(i);
      }
      if (py::len(gone) > 0) return gone;
    }
    Array pos({n, py::ssize_t(3)}), vel({n, py::ssize_t(3)}), frc({n, py::ssize_t(3)});
    auto* x = reinterpret_cast<double(*)[3]>(pos.mutable_data());
    auto* v = reinterpret_cast<double(*)[3]>(vel.mutable_data());
    auto* f = reinterpret_cast<double(*)[3]>(frc.mutable_data());
    const py::str s_pos("pos"), s_vel("vel");
    const py::object get_f = forces.attr("f"), add_f = forces.attr("addF");
    const py::bool_ sync(true);
    for (py::ssize_t i = 0; i < n; ++i) {
      const py::handle st = PyList_GET_ITEM(states.ptr(), i);
      read3(st.attr(s_pos), x[i]);
      read3(st.attr(s_vel), v[i]);
      read3(get_f(py::handle(PyList_GET_ITEM(ids.ptr(), i)), sync), f[i]);
    }
    const auto corr = correction(radius, mass, pos, vel, frc, dt, engine_gravity);
    const auto* c = reinterpret_cast<const double(*)[3]>(corr.data());
    for (py::ssize_t i = 0; i < n; ++i)
      add_f(py::handle(PyList_GET_ITEM(ids.ptr(), i)), py::make_tuple(c[i][0], c[i][1], c[i][2]));
    return py::none();
  }

  // The spheres changed: sphere i of the new order is old sphere old_index[i] (its state kept), or new (-1:
  // no previous velocity yet).
  void remap(const std::vector<long>& old_index) {
    std::vector<FluidState> next(old_index.size());
    for (std::size_t i = 0; i < old_index.size(); ++i) {
      const long k = old_index[i];
      if (k >= 0) {
        if (static_cast<std::size_t>(k) >= state_.size())
          throw std::invalid_argument("Fluid.remap: old index " + std::to_string(k) + " out of range (" +
                                      std::to_string(state_.size()) + " spheres)");
        next[i] = state_[k];
      }
    }
    state_ = std::move(next);
    resize_outputs(static_cast<py::ssize_t>(state_.size()));
  }

  // The per-sphere state for a restart: previous velocities (n,3) and whether each has one (n).
  py::tuple get_state() const {
    const auto n = static_cast<py::ssize_t>(state_.size());
    py::array_t<double> v({n, py::ssize_t(3)});
    py::array_t<bool> has(n);
    auto* vd = reinterpret_cast<double(*)[3]>(v.mutable_data());
    bool* hd = has.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) vd[i][k] = state_[i].velocity_prev_m_s[k];
      hd[i] = state_[i].has_prev;
    }
    return py::make_tuple(v, has);
  }

  void set_state(const Array& velocity_prev, const py::array_t<bool, py::array::c_style | py::array::forcecast>& has_prev) {
    const py::ssize_t n = has_prev.ndim() == 1 ? has_prev.shape(0) : -1;
    if (n < 0) throw std::invalid_argument("Fluid.set_state: has_prev: expected shape (n,)");
    const auto* v = mat_n3(velocity_prev, n, "velocity_prev");
    const bool* h = has_prev.data();
    state_.assign(n, FluidState{});
    for (py::ssize_t i = 0; i < n; ++i) state_[i] = FluidState{Vec3(v[i][0], v[i][1], v[i][2]), h[i]};
    resize_outputs(n);
  }

  // Who applies gravity, and g (also the buoyancy's): the adapter follows NewtonIntegrator.gravity with it.
  void configure_gravity(double g, bool apply_gravity) {
    FluidParams p = p_;
    p.gravity_m_s2 = g;
    p.apply_gravity = apply_gravity;
    p.validate("brash_yade.Fluid.configure_gravity");
    p_ = std::move(p);
  }

  const py::array_t<double>& fraction() const { return fraction_; }
  const py::array_t<double>& ca() const { return ca_; }
  void reset() { state_.clear(); }
  std::size_t size() const { return state_.size(); }
  const FluidParams& params() const { return p_; }

 private:
  void resize(py::ssize_t n) {
    state_.assign(n, FluidState{});
    resize_outputs(n);
  }
  void resize_outputs(py::ssize_t n) {
    fraction_ = py::array_t<double>(n);
    ca_ = py::array_t<double>({n, py::ssize_t(3)});
    std::fill_n(fraction_.mutable_data(), n, 0.0);
    std::fill_n(ca_.mutable_data(), 3 * n, 0.0);
  }
  // Gravity added by the integrator: none, or along -z (buoyancy acts along +z) with the fluid's g, and never
  // on top of the fluid's own gravity.
  void check_engine_gravity(const std::array<double, 3>& g) const {
    if (g[0] == 0 && g[1] == 0 && g[2] == 0) return;
    if (p_.apply_gravity)
      throw std::invalid_argument("brash_yade.Fluid: the integrator applies gravity and so does the fluid "
                                  "(apply_gravity): gravity would count twice");
    if (g[0] != 0 || g[1] != 0 || !(g[2] < 0))
      throw std::invalid_argument(fmt_vec("brash_yade.Fluid: engine gravity (", g) +
                                  ") must point along -z (buoyancy acts along +z)");
    if (std::abs(-g[2] - p_.gravity_m_s2) > 1e-12 * p_.gravity_m_s2)
      throw std::invalid_argument(fmt_vec("brash_yade.Fluid: engine gravity (", g) + ") differs from the fluid's g = " +
                                  std::to_string(p_.gravity_m_s2) + " m/s^2 (buoyancy would not balance the weight)");
  }
  static std::string fmt_vec(const std::string& head, const std::array<double, 3>& g) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.9g, %.9g, %.9g", g[0], g[1], g[2]);
    return head + buf;
  }

  FluidParams p_;
  std::vector<FluidState> state_;
  py::array_t<double> fraction_{0}, ca_{std::vector<py::ssize_t>{0, 3}};
};

// Run-time guards (brash::guard, the checks the LIGGGHTS fix brash/guard and brash-ode call): a PyRunner
// calls check() every N iterations on the ice spheres' YADE State objects (same order as the Fluid
// adapter's).
class Guard {
 public:
  // box: (xlo, xhi, ylo, yhi, zlo, zhi) or empty; z_max / ke_max / max_hull_penetration_d: None = off;
  // hull_stl: the FULL closed hull in its STL frame ("" = no hull check), whose origin is at hull_origin at
  // t = 0 and moves at hull_velocity (the facets' velocity in the scene).
  Guard(const Array& radius, const Array& mass, const std::vector<double>& box, std::optional<double> z_max,
        std::optional<double> ke_max, std::optional<double> max_hull_penetration_d,
        const std::string& hull_stl, const std::array<double, 3>& hull_origin,
        const std::array<double, 3>& hull_velocity)
      : origin_(hull_origin[0], hull_origin[1], hull_origin[2]),
        velocity_(hull_velocity[0], hull_velocity[1], hull_velocity[2]) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    const double* r = vec_n(radius, n, "radius");
    const double* m = vec_n(mass, n, "mass");
    radius_.assign(r, r + n);
    mass_.assign(m, m + n);
    if (!box.empty()) {
      if (box.size() != 6) throw std::invalid_argument("Guard: box needs 6 values (xlo xhi ylo yhi zlo zhi)");
      limits_.box = brash::guard::Box{box[0], box[1], box[2], box[3], box[4], box[5]};
    }
    limits_.z_max_m = z_max;
    limits_.ke_max_J = ke_max;
    if (max_hull_penetration_d && !hull_stl.empty()) {
      hull_ = std::make_unique<brash::hull::Proximity>(brash::hull::read_mesh(hull_stl));
      if (!hull_->closed())
        throw std::invalid_argument("Guard: " + hull_stl +
                                    " is not a closed surface (the hull check needs the full hull)");
      limits_.max_hull_penetration_d = max_hull_penetration_d;
    }
  }

  // The stop message of the first offending sphere (lowest index), or None. `states` as for Fluid.apply.
  std::optional<std::string> check(const py::list& states, long step, double t) const {
    if (static_cast<std::size_t>(py::len(states)) != radius_.size())
      throw std::invalid_argument("Guard.check: states and radius must have the same length");
    const py::str s_pos("pos"), s_vel("vel"), s_ang("angVel");
    brash::guard::HullNow hull{hull_.get(), origin_ + velocity_ * t};
    for (std::size_t i = 0; i < radius_.size(); ++i) {
      const py::handle st = PyList_GET_ITEM(states.ptr(), static_cast<py::ssize_t>(i));
      double x[3], v[3], w[3];
      read3(st.attr(s_pos), x);
      read3(st.attr(s_vel), v);
      read3(st.attr(s_ang), w);
      brash::guard::Piece p;
      p.x_m = Vec3(x[0], x[1], x[2]);
      p.v_m_s = Vec3(v[0], v[1], v[2]);
      p.omega_rad_s = Vec3(w[0], w[1], w[2]);
      p.radius_m = radius_[i];
      p.mass_kg = mass_[i];
      if (auto cause = brash::guard::check_piece(p, limits_, hull_ ? &hull : nullptr))
        return brash::guard::stop_message(step, t, static_cast<long>(i) + 1, *cause);
    }
    return std::nullopt;
  }

  // The contact time-step check on the sphere with the smallest Rayleigh time (its own radius and density).
  std::optional<std::string> check_timestep(double dt, double youngs, double poisson,
                                            double max_fraction) const {
    std::size_t worst = 0;
    double tr_min = std::numeric_limits<double>::infinity(), rho_worst = 0;
    for (std::size_t i = 0; i < radius_.size(); ++i) {
      const double rho = mass_[i] / (4.0 / 3.0 * std::numbers::pi * std::pow(radius_[i], 3));
      const double tr = brash::guard::rayleigh_time_s(radius_[i], rho, youngs, poisson);
      if (tr < tr_min) tr_min = tr, worst = i, rho_worst = rho;
    }
    if (radius_.empty()) return std::nullopt;
    if (auto cause =
            brash::guard::check_timestep(dt, radius_[worst], rho_worst, youngs, poisson, max_fraction))
      return brash::guard::stop_message(0, 0.0, static_cast<long>(worst) + 1, *cause);
    return std::nullopt;
  }

  bool has_hull() const { return hull_ != nullptr; }

 private:
  std::vector<double> radius_, mass_;
  brash::guard::Limits limits_;
  std::unique_ptr<brash::hull::Proximity> hull_;
  Vec3 origin_, velocity_;
};

}  // namespace

PYBIND11_MODULE(brash_yade, mod) {
  mod.doc() = "brash fluid forces (buoyancy, drag, added mass) for YADE spheres, from brash_core";
  // the core's defaults, for Python code that takes the same parameters (brash_yade_adapter.FluidAdapter)
  mod.attr("DEFAULT_CD") = brash::kDefaultDragCoefficient;
  mod.attr("DEFAULT_NU") = brash::kDefaultKinematicViscosity_m2_s;
  mod.attr("DEFAULT_WATER_DENSITY") = brash::kDefaultWaterDensity_kg_m3;
  mod.attr("DEFAULT_G") = brash::kDefaultGravity_m_s2;

  py::class_<Fluid>(mod, "Fluid")
      .def(py::init([](const std::string& model, const std::string& treatment, double cd, const std::string& drag_law,
                       double nu, const std::string& ca_table, double water_level, double water_density, double g,
                       bool apply_gravity) {
             return Fluid(make_params(model, treatment, cd, drag_law, nu, ca_table, water_level, water_density, g,
                                      apply_gravity));
           }),
           py::arg("model") = "both", py::arg("treatment") = "implicit",
           py::arg("cd") = brash::kDefaultDragCoefficient, py::arg("drag_law") = "constant",
           py::arg("nu") = brash::kDefaultKinematicViscosity_m2_s, py::arg("ca_table") = "table1",
           py::arg("water_level") = 0.0, py::arg("water_density") = brash::kDefaultWaterDensity_kg_m3,
           py::arg("g") = brash::kDefaultGravity_m_s2, py::arg("apply_gravity") = true)
      .def_static(
          "from_case",
          [](const std::string& case_file, bool apply_gravity) {
            FluidParams p = brash::fluid_params(brash::load_case(case_file));
            p.apply_gravity = apply_gravity;
            p.validate("brash_yade.Fluid.from_case(" + case_file + ")");
            return Fluid(std::move(p));
          },
          py::arg("case_file"), py::arg("apply_gravity") = true,
          "the fluid of a case.yaml (water.*, fluid.*) through brash::fluid_params, the mapping every engine uses")
      .def("correction", &Fluid::correction, py::arg("radius"), py::arg("mass"), py::arg("pos"), py::arg("vel"),
           py::arg("force"), py::arg("dt"), py::arg("engine_gravity") = std::array<double, 3>{0, 0, 0},
           "force to add per sphere (n,3) so the total is (force + m g_engine + fluid) * scale - m g_engine")
      .def("correction_seq", &Fluid::correction_seq, py::arg("radius"), py::arg("mass"), py::arg("pos"),
           py::arg("vel"), py::arg("force"), py::arg("dt"),
           py::arg("engine_gravity") = std::array<double, 3>{0, 0, 0},
           "correction() for lists of Vector3-like objects")
      .def("apply", &Fluid::apply, py::arg("radius"), py::arg("mass"), py::arg("states"), py::arg("ids"),
           py::arg("forces"), py::arg("dt"), py::arg("engine_gravity") = std::array<double, 3>{0, 0, 0},
           py::arg("bodies") = py::none(),
           "read pos/vel/contact force of each sphere, add the fluid correction with forces.addF; with bodies, "
           "returns the positions of erased spheres (and applies nothing) or None")
      .def("remap", &Fluid::remap, py::arg("old_index"),
           "new sphere order: old_index[i] = the old position of sphere i, or -1 for a new sphere")
      .def("get_state", &Fluid::get_state, "(previous velocities (n,3), has_prev (n,)) for a restart")
      .def("set_state", &Fluid::set_state, py::arg("velocity_prev"), py::arg("has_prev"),
           "restore what get_state() returned")
      .def("configure_gravity", &Fluid::configure_gravity, py::arg("g"), py::arg("apply_gravity"),
           "set g (buoyancy and weight) and whether the fluid applies the weight itself")
      .def_property_readonly("fraction", &Fluid::fraction, "submerged fraction of each sphere at the last call")
      .def_property_readonly("ca", &Fluid::ca, "added-mass coefficients (n,3) used at the last call")
      .def("reset", &Fluid::reset, "forget the per-sphere state (previous velocity)")
      .def("__len__", &Fluid::size)
      .def_property_readonly("model", [](const Fluid& f) { return to_string(f.params().model); })
      .def_property_readonly("treatment", [](const Fluid& f) { return to_string(f.params().treatment); })
      .def_property_readonly("drag_law", [](const Fluid& f) { return to_string(f.params().drag_law); })
      .def_property_readonly("cd", [](const Fluid& f) { return f.params().drag_coefficient; })
      .def_property_readonly("nu", [](const Fluid& f) { return f.params().kinematic_viscosity_m2_s; })
      .def_property_readonly("ca_table", [](const Fluid& f) { return ca_table_spelling(f.params().ca); })
      .def_property_readonly("water_level", [](const Fluid& f) { return f.params().water_level_m; })
      .def_property_readonly("water_density", [](const Fluid& f) { return f.params().water_density_kg_m3; })
      .def_property_readonly("g", [](const Fluid& f) { return f.params().gravity_m_s2; })
      .def_property_readonly("apply_gravity", [](const Fluid& f) { return f.params().apply_gravity; });

  py::class_<Guard>(mod, "Guard")
      .def(py::init<const Array&, const Array&, const std::vector<double>&, std::optional<double>,
                    std::optional<double>, std::optional<double>, const std::string&,
                    const std::array<double, 3>&, const std::array<double, 3>&>(),
           py::arg("radius"), py::arg("mass"), py::arg("box") = std::vector<double>{},
           py::arg("z_max") = py::none(), py::arg("ke_max") = py::none(),
           py::arg("max_hull_penetration_d") = py::none(), py::arg("hull_stl") = "",
           py::arg("hull_origin") = std::array<double, 3>{0, 0, 0},
           py::arg("hull_velocity") = std::array<double, 3>{0, 0, 0})
      .def("check", &Guard::check, py::arg("states"), py::arg("step"), py::arg("t"),
           "stop message 'guard: step N (t = T s): piece ID: cause' of the first offending sphere, or None")
      .def("check_timestep", &Guard::check_timestep, py::arg("dt"), py::arg("youngs"), py::arg("poisson"),
           py::arg("max_fraction"),
           "stop message when dt exceeds max_fraction of the smallest Rayleigh time, or None")
      .def_property_readonly("has_hull", &Guard::has_hull);

  // Single-sphere oracle (velocity Verlet, gravity as an engine force) and closed forms.
  py::class_<ReferenceSphere>(mod, "ReferenceSphere")
      .def(py::init([](double radius, double density, double dt, double z0, double vz0, const Fluid& fluid) {
             ReferenceSphere s;
             s.params = fluid.params();
             s.params.apply_gravity = false;  // the reference applies gravity itself (engine_gravity)
             s.radius_m = radius;
             s.density_kg_m3 = density;
             s.dt_s = dt;
             s.x_m = Vec3(0, 0, z0);
             s.v_m_s = Vec3(0, 0, vz0);
             s.setup();
             return s;
           }),
           py::arg("radius"), py::arg("density"), py::arg("dt"), py::arg("z0"), py::arg("vz0"), py::arg("fluid"))
      .def("run", &ReferenceSphere::run, py::arg("steps"))
      .def_property_readonly("t", [](const ReferenceSphere& s) { return s.t_s; })
      .def_property_readonly("z", [](const ReferenceSphere& s) { return s.x_m.z(); })
      .def_property_readonly("vz", [](const ReferenceSphere& s) { return s.v_m_s.z(); })
      .def_property_readonly("fz", [](const ReferenceSphere& s) { return s.f_N.z(); })
      .def_property_readonly("mass", &ReferenceSphere::mass_kg);

  auto an = mod.def_submodule("analytic", "closed forms of brash::core::analytic");
  an.def("rise", [](double r, double rho_i, double rho_w, double g, double cd, double ca_z) {
    const auto x = analytic::rise(r, rho_i, rho_w, g, cd, ca_z);
    return py::make_tuple(x.terminal_velocity_m_s, x.time_constant_s);
  }, "(terminal velocity, time constant) of the fully submerged rise from rest");
  an.def("heave_period", &analytic::heave_period);
  an.def("height_for_fraction", &analytic::height_for_fraction);
  an.def("sphere_volume", &analytic::sphere_volume);
}
