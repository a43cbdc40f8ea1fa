// brash_yade: Python extension module (pybind11) that brings the engine-independent fluid core
// (plugin/core, brash_core) into YADE. YADE is shipped by Debian without C++ headers, so the adapter is
// a YADE PyRunner (plugin/yade/py/brash_yade_scene.py) that reads the spheres each step and calls
// Fluid.correction() here; the physics is the same compiled code LIGGGHTS and ODE call.
//
// Also exposes the single-sphere reference integrator and the closed forms, so the YADE tests compare
// against the same oracle as the LIGGGHTS tests, in the same process.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "brash/core/fluid.hpp"
#include "brash/core/params.hpp"
#include "brash/core/reference.hpp"

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
  // (force + fluid) * scale (implicit added mass) or force + fluid (explicit / no added mass).
  // Gravity is part of `fluid` when apply_gravity is set (YADE's NewtonIntegrator.gravity must be 0).
  py::array_t<double> correction(const Array& radius, const Array& mass, const Array& pos, const Array& vel,
                                 const Array& force, double dt) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    const double* r = vec_n(radius, n, "radius");
    const double* m = vec_n(mass, n, "mass");
    const auto* x = mat_n3(pos, n, "pos");
    const auto* v = mat_n3(vel, n, "vel");
    const auto* f = mat_n3(force, n, "force");
    if (state_.size() != static_cast<std::size_t>(n)) {
      if (!state_.empty()) throw std::invalid_argument("Fluid.correction: the number of spheres changed");
      state_.assign(n, FluidState{});
      fraction_ = py::array_t<double>(n);
      ca_ = py::array_t<double>({n, py::ssize_t(3)});
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
          o[i][k] = (f[i][k] + fo.force_N[k]) * fo.scale[k] - f[i][k];
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
                                     const py::sequence& vel, const py::sequence& force, double dt) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    auto to_array = [n](const py::sequence& s, const char* name) {
      if (static_cast<py::ssize_t>(py::len(s)) != n)
        throw std::invalid_argument(std::string(name) + ": expected " + std::to_string(n) + " vectors");
      Array a({n, py::ssize_t(3)});
      auto* d = reinterpret_cast<double(*)[3]>(a.mutable_data());
      for (py::ssize_t i = 0; i < n; ++i) read3(s[i], d[i]);
      return a;
    };
    return correction(radius, mass, to_array(pos, "pos"), to_array(vel, "vel"), to_array(force, "force"), dt);
  }

  // The whole YADE step in one call (the fast path of the PyRunner): for sphere i, read
  // states[i].pos / .vel and forces.f(ids[i], True) (contacts, valid after InteractionLoop), evaluate
  // the core, and forces.addF(ids[i], correction). `states` are YADE State objects cached once (they
  // stay the live state of their bodies); radius/mass are per-sphere arrays in the same order.
  void apply(const Array& radius, const Array& mass, const py::list& states, const py::list& ids,
             const py::object& forces, double dt) {
    const py::ssize_t n = radius.ndim() == 1 ? radius.shape(0) : -1;
    if (static_cast<py::ssize_t>(py::len(states)) != n || static_cast<py::ssize_t>(py::len(ids)) != n)
      throw std::invalid_argument("Fluid.apply: radius, mass, states and ids must have the same length");
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
    const auto corr = correction(radius, mass, pos, vel, frc, dt);
    const auto* c = reinterpret_cast<const double(*)[3]>(corr.data());
    for (py::ssize_t i = 0; i < n; ++i)
      add_f(py::handle(PyList_GET_ITEM(ids.ptr(), i)), py::make_tuple(c[i][0], c[i][1], c[i][2]));
  }

  const py::array_t<double>& fraction() const { return fraction_; }
  const py::array_t<double>& ca() const { return ca_; }
  void reset() { state_.clear(); }
  std::size_t size() const { return state_.size(); }
  const FluidParams& params() const { return p_; }

 private:
  FluidParams p_;
  std::vector<FluidState> state_;
  py::array_t<double> fraction_{0}, ca_{std::vector<py::ssize_t>{0, 3}};
};

}  // namespace

PYBIND11_MODULE(brash_yade, mod) {
  mod.doc() = "brash fluid forces (buoyancy, drag, added mass) for YADE spheres, from brash_core";

  py::class_<Fluid>(mod, "Fluid")
      .def(py::init([](const std::string& model, const std::string& treatment, double cd, const std::string& drag_law,
                       double nu, const std::string& ca_table, double water_level, double water_density, double g,
                       bool apply_gravity) {
             return Fluid(make_params(model, treatment, cd, drag_law, nu, ca_table, water_level, water_density, g,
                                      apply_gravity));
           }),
           py::arg("model") = "added_mass", py::arg("treatment") = "implicit", py::arg("cd") = 0.44,
           py::arg("drag_law") = "constant", py::arg("nu") = 1.79e-6, py::arg("ca_table") = "table1",
           py::arg("water_level") = 0.0, py::arg("water_density") = 1000.0, py::arg("g") = 9.81,
           py::arg("apply_gravity") = true)
      .def("correction", &Fluid::correction, py::arg("radius"), py::arg("mass"), py::arg("pos"), py::arg("vel"),
           py::arg("force"), py::arg("dt"),
           "force to add per sphere (n,3) so the total is (force + fluid) * scale")
      .def("correction_seq", &Fluid::correction_seq, py::arg("radius"), py::arg("mass"), py::arg("pos"),
           py::arg("vel"), py::arg("force"), py::arg("dt"), "correction() for lists of Vector3-like objects")
      .def("apply", &Fluid::apply, py::arg("radius"), py::arg("mass"), py::arg("states"), py::arg("ids"),
           py::arg("forces"), py::arg("dt"),
           "read pos/vel/contact force of each sphere, add the fluid correction with forces.addF")
      .def_property_readonly("fraction", &Fluid::fraction, "submerged fraction of each sphere at the last call")
      .def_property_readonly("ca", &Fluid::ca, "added-mass coefficients (n,3) used at the last call")
      .def("reset", &Fluid::reset, "forget the per-sphere state (previous velocity)")
      .def("__len__", &Fluid::size)
      .def_property_readonly("model", [](const Fluid& f) { return to_string(f.params().model); })
      .def_property_readonly("treatment", [](const Fluid& f) { return to_string(f.params().treatment); });

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
