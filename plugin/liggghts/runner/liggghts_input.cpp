// LIGGGHTS scene for a case. Material types: 1 ice, 2 hull, 3 channel walls.
#include "liggghts_input.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "brash/case_fluid.hpp"
#include "brash/core/far_field.hpp"
#include "brash/run/guard.hpp"
#include "icefluid_arguments.h"

namespace brash::liggghts {

Box scene_box(const Case& c, double hull_x_min_m, double hull_x_max_m, double hull_z_min_m, double hull_z_max_m,
              double duration_s) {
  // The same domain every engine's box guard uses (an atom leaving it would be lost; thermo_modify lost error
  // and fix brash/guard stop the run).
  const auto d = guard::domain_box(c, hull_x_min_m, hull_x_max_m, hull_z_min_m, hull_z_max_m, duration_s);
  return Box{d[0], d[1], d[2], d[3], d[4], d[5]};
}

std::vector<Sphere> half_channel_spheres(const std::vector<Sphere>& spheres) {
  std::vector<Sphere> out;
  for (const auto& p : spheres)
    if (p.y_m >= 0.5 * p.diameter_m) out.push_back(p);
  return out;
}

hull::Mesh half_hull(const hull::Mesh& mesh) {
  // Each triangle clipped against y >= 0 (Sutherland-Hodgman): 0, 3 or 4 corners, fanned into triangles.
  hull::Mesh out;
  for (const auto& f : mesh.faces) {
    std::vector<Eigen::Vector3d> poly;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& a = mesh.vertices[f[k]];
      const Eigen::Vector3d& b = mesh.vertices[f[(k + 1) % 3]];
      if (a.y() >= 0) poly.push_back(a);
      if ((a.y() >= 0) != (b.y() >= 0)) {
        Eigen::Vector3d p = a + (b - a) * (a.y() / (a.y() - b.y()));
        p.y() = 0;
        poly.push_back(p);
      }
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      const Eigen::Vector3d e1 = poly[k] - poly[0], e2 = poly[k + 1] - poly[0];
      if (e1.cross(e2).norm() < 1e-14) continue;  // sliver on the plane
      const int n = static_cast<int>(out.vertices.size());
      out.vertices.push_back(poly[0]);
      out.vertices.push_back(poly[k]);
      out.vertices.push_back(poly[k + 1]);
      out.faces.push_back({n, n + 1, n + 2});
    }
  }
  return out;
}

std::string data_file(const std::vector<Sphere>& spheres, const Box& box, double ice_density_kg_m3, int atom_types) {
  std::string s = fmt::format(
      "brash channel packing\n\n{} atoms\n{} atom types\n\n{:.9g} {:.9g} xlo xhi\n{:.9g} {:.9g} ylo yhi\n"
      "{:.9g} {:.9g} zlo zhi\n\nAtoms\n\n",
      spheres.size(), atom_types, box.xlo, box.xhi, box.ylo, box.yhi, box.zlo, box.zhi);
  s.reserve(s.size() + spheres.size() * 80);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const auto& p = spheres[i];
    s += fmt::format("{} 1 {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", i + 1, p.diameter_m, ice_density_kg_m3, p.x_m,
                     p.y_m, p.z_m);
  }
  return s;
}

namespace {

// fix property/global lines of the material types: 1 ice, 2 hull, 3 channel walls (4: the symmetry plane y = 0,
// frictionless against ice, with speedups.symmetry_y)
std::string material_lines(const Case& c, bool symmetry_y) {
  const auto& f = c.friction;
  const double e = c.contact.restitution;
  std::string s;
  if (!symmetry_y) {
    s += fmt::format(
        "fix m1 all property/global youngsModulus peratomtype {0:g} {0:g} {0:g}\n"
        "fix m2 all property/global poissonsRatio peratomtype {1:g} {1:g} {1:g}\n"
        "fix m3 all property/global coefficientRestitution peratomtypepair 3 {2:g} {2:g} {2:g} {2:g} {2:g} {2:g} {2:g} "
        "{2:g} {2:g}\n"
        "fix m4 all property/global coefficientFriction peratomtypepair 3 {3:g} {4:g} {5:g} {4:g} {4:g} {4:g} {5:g} "
        "{4:g} {5:g}\n",
        c.contact.youngs_modulus_pa, c.contact.poisson_ratio, e, f.ice_ice, f.ice_hull, f.ice_wall);
  } else {  // type 4 = the symmetry plane y = 0: frictionless against ice
    s += fmt::format(
        "fix m1 all property/global youngsModulus peratomtype {0:g} {0:g} {0:g} {0:g}\n"
        "fix m2 all property/global poissonsRatio peratomtype {1:g} {1:g} {1:g} {1:g}\n"
        "fix m3 all property/global coefficientRestitution peratomtypepair 4 {2:g} {2:g} {2:g} {2:g} {2:g} {2:g} {2:g} "
        "{2:g} {2:g} {2:g} {2:g} {2:g} {2:g} {2:g} {2:g} {2:g}\n"
        "fix m4 all property/global coefficientFriction peratomtypepair 4 {3:g} {4:g} {5:g} 0 {4:g} {4:g} {4:g} 0 "
        "{5:g} {4:g} {5:g} 0 0 0 0 0\n",
        c.contact.youngs_modulus_pa, c.contact.poisson_ratio, e, f.ice_ice, f.ice_hull, f.ice_wall);
  }
  // rolling resistance (contact.rolling_friction): every pair of ice, hull and walls alike, none on the symmetry
  // plane (a mirror, as its friction); without it the deck is the one of the model without rolling resistance
  if (const double mu_r = c.contact.rolling_friction; mu_r != 0)
    s += symmetry_y ? fmt::format("fix m5 all property/global coefficientRollingFriction peratomtypepair 4 {0:g} {0:g} "
                                  "{0:g} 0 {0:g} {0:g} {0:g} 0 {0:g} {0:g} {0:g} 0 0 0 0 0\n",
                                  mu_r)
                    : fmt::format("fix m5 all property/global coefficientRollingFriction peratomtypepair 3 {0:g} {0:g} "
                                  "{0:g} {0:g} {0:g} {0:g} {0:g} {0:g} {0:g}\n",
                                  mu_r);
  return s;
}

}  // namespace

std::string granular_model(const Case& c) {
  // rolling_friction cdt: LIGGGHTS' constant directional torque, M_r = -mu_r R_eff |F_n| w_r / |w_r| (w_r the
  // relative rotation without its part along the normal; R_eff = R_i R_j / (R_i + R_j), a wall's contact R_i)
  return c.contact.rolling_friction != 0 ? "model hertz tangential history rolling_friction cdt"
                                         : "model hertz tangential history";
}

std::string contact_lines(const Case& c, bool symmetry_y) {
  return material_lines(c, symmetry_y) + "pair_style gran " + granular_model(c) + "\npair_coeff * *\n";
}

namespace {

// the scene's opening lines up to and including read_data (or read_restart)
std::string opening_lines(const Case& c, const std::string& read_line, int ranks) {
  // Spatial sort of the atoms every 1000 steps, bins of half the neighbour cutoff (LAMMPS' default size, given
  // explicitly: the default is derived from a cutoff that is 0 while the box is empty). Pair and neighbour loops
  // then walk memory in order: ~2.2x faster on the paper scene (docs/performance.md "Atom sorting").
  const double sort_bin_m = max_radius_m(c) + 0.5 * c.speedups.neighbor_skin_d * c.ice.diameter_mean_m;
  std::string s = fmt::format(
      "atom_style granular\natom_modify map array sort 1000 {:.6g}\nboundary f f f\nnewton off\n", sort_bin_m);
  s += "communicate single vel yes\nunits si\n";
  // LIGGGHTS refuses E < 5 MPa in SI units unless told otherwise; softer ice is a legitimate speed knob (the
  // time-step guard still checks dt against the Rayleigh time of the softer contact).
  if (c.contact.youngs_modulus_pa < 5.0e6) s += "soft_particles yes\n";
  s += ranks > 1 ? "processors 1 * 1\n" : "";
  return s + read_line + "\n";
}

// the channel's walls of the walls' material (type 3): at y = +-width/2 (at y = 0 the symmetry plane, type 4,
// instead of the one at -width/2) and, with end walls, at x = 0 and x = length
std::string wall_lines(const Case& c, bool symmetry_y, bool end_walls) {
  const std::string wall = "wall/gran " + granular_model(c) + " primitive";
  std::string s =
      symmetry_y ? fmt::format("fix sides all {} type 4 yplane 0\n", wall)
                 : fmt::format("fix sides all {} type 3 yplane {:.9g}\n", wall, -0.5 * c.channel.width_m);
  s += fmt::format("fix sides2 all {} type 3 yplane {:.9g}\n", wall, 0.5 * c.channel.width_m);
  // the hull's mesh is not a particle: it passes through the end walls
  if (end_walls)
    s += fmt::format("fix end0 all {0} type 3 xplane 0\nfix end1 all {0} type 3 xplane {1:.9g}\n", wall,
                     c.channel.length_m);
  return s;
}

// fix brash/guard's common arguments (no newline): every check but the hull's (brash::guard, docs/stability.md)
std::string guard_command(const Case& c, const guard::Limits& lim) {
  const auto& gb = *lim.box;
  return fmt::format(
      "fix guard all brash/guard every {} box {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} zmax {:.9g} "
      "ke_max {:.6g} youngs {:g} poisson {:g} max_dt_fraction {:g}",
      c.guards.every_steps, gb[0], gb[1], gb[2], gb[3], gb[4], gb[5], *lim.z_max_m, *lim.ke_max_J,
      c.contact.youngs_modulus_pa, c.contact.poisson_ratio, kMaxTimestepOverRayleigh);
}

}  // namespace

std::string input_script(const Case& c, const Box& box, const SceneOptions& opt) {
  const double dt = c.run.timestep_s;
  const long steps = std::lround(opt.duration_s / dt);
  const long out_every = std::max(1L, std::lround(c.run.output_interval_s / dt));
  const long dump_every = std::max(1L, std::lround(c.run.dump_interval_s / dt));
  const long thermo_every = std::max(1L, steps / 200);
  std::string s;
  s += "# brash: LIGGGHTS scene written by brash-liggghts-run for case " + c.name + "\n";
  s += opening_lines(c, opt.restart_file.empty() ? "read_data packing.data" : "read_restart " + opt.restart_file,
                     opt.ranks);
  // speedups (docs/performance.md): idle far-field ice lives in group `idle`, the rest in `active`
  const auto& sp = c.speedups;
  const std::string moving = sp.farfield ? "active" : "all";
  if (sp.farfield) s += "group active type 1\ngroup idle subtract all all\n";
  const double skin_m = sp.neighbor_skin_d * c.ice.diameter_mean_m;
  s += fmt::format("neighbor {:.6g} bin\nneigh_modify delay 0{}\n", skin_m,
                   sp.farfield ? " exclude group idle idle" : "");
  s += contact_lines(c, sp.symmetry_y);
  s += fmt::format("timestep {:.9g}\n", dt);
  // Hull: STL frame has the keel at z = 0 and x = 0 at the aft perpendicular.
  const double hull_x0 = c.hull.start_x_m;
  // curvature_tolerant: the lofted JBC has a few slivers (smallest angle 0.23 deg, at the stem and stern post) below
  // LIGGGHTS' default acceptance angle (0.256 deg); they are valid triangles, so warn instead of refusing the mesh.
  s += fmt::format("fix hull all mesh/surface/stress file {} type 2 move {:.9g} 0 {:.9g} curvature_tolerant yes "
                   "reference_point 0 0 0\n",
                   opt.hull_file, hull_x0, -c.hull.draft_m);
  // store_force_contact_stress: each hull contact's force and contact vector, per piece, for fix brash/hullsplit;
  // store_force: the hull's force on each piece (f_force_hullwall), for the snapshots (brash-post's contact pressure)
  s += "fix hullwall all wall/gran " + granular_model(c) +
       " mesh n_meshes 1 meshes hull store_force yes store_force_contact_stress yes\n";
  s += wall_lines(c, sp.symmetry_y, c.channel.ends == ChannelEnds::Walls);
  s += fmt::format("fix mv all move/mesh mesh hull linear {:.9g} 0 0\n", c.ship.speed_m_s);
  if (sp.farfield) {
    // the wake rule (docs/performance.md, "far field"): by force, a fraction of the mean piece's weight; or by
    // the speed of a touching active piece
    std::string wake;
    if (sp.farfield_wake_by == WakeBy::NeighbourSpeed) {
      wake = fmt::format(" wake_neighbour_speed {:.9g}", sp.farfield_wake_speed_m_s);
    } else if (const double wake_force_N = core::wake_force_N(sp.farfield_wake_force_weight, c.ice.diameter_mean_m,
                                                              c.ice.density_kg_m3, c.water.gravity_m_s2);
               wake_force_N > 0) {
      wake = fmt::format(" wake_force {:.9g} wake_speed {:.9g}", wake_force_N, sp.farfield_wake_speed_m_s);
    }
    const std::string beside =
        sp.farfield_beside_m ? fmt::format(" beside {:.9g}", opt.hull_half_beam_m + *sp.farfield_beside_m) : "";
    s += fmt::format(
        "fix farfield all brash/farfield every {} ahead {:.9g} behind {:.9g}{} hull_x0 {:.9g} speed {:.9g} "
        "bow_offset {:.9g} stern_offset {:.9g}{} active active idle idle\n",
        sp.farfield_every_steps, sp.farfield_ahead_m, sp.farfield_behind_m, beside, hull_x0, c.ship.speed_m_s,
        opt.hull_x_max_m, opt.hull_x_min_m, wake);
  }
  s += fmt::format("fix integr {} nve/sphere\n", moving);
  s += fmt::format("fix grav {} gravity {:.9g} vector 0 0 -1\n", moving, c.water.gravity_m_s2);
  s += "fix ts all check/timestep/gran 1000 0.1 0.1\n";
  // run-time guards (END_OF_STEP, reads only; brash::guard, docs/stability.md): NaN/Inf, atoms about to leave
  // the box or jumping far above the water, runaway kinetic energy (largest sphere at 20x ship speed, at least
  // 5 m/s), dt vs contact stiffness, and penetration into the full closed hull (frame origin at
  // (start_x, 0, -draft) at t = 0, moving with the ship like fix mv)
  const auto lim = guard::limits_for_case(c, {box.xlo, box.xhi, box.ylo, box.yhi, box.zlo, box.zhi});
  const auto& gb = *lim.box;
  s += guard_command(c, lim);
  if (lim.max_hull_penetration_d && !opt.guard_hull_file.empty())
    s += fmt::format(" hull {} {:.9g} 0 {:.9g} {:.9g} 0 0 max_penetration {:g}", opt.guard_hull_file, hull_x0,
                     -c.hull.draft_m, c.ship.speed_m_s, *lim.max_hull_penetration_d);
  s += "\n";
  // pieces leaving through the channel's open ends (beyond the box's x-ends, away from the hull) are removed,
  // one neighbour skin inside the guard's x range so that they go before the guard sees them
  // (fix_brash_exit.h)
  s += fmt::format("fix exit all brash/exit xlo {:.9g} xhi {:.9g}\n", gb[0] + skin_m, gb[1] - skin_m);
  // the moving window (docs/performance.md): after fix exit and fix farfield, whose bookkeeping it updates; its
  // front leads the far field's moving ice by the same speed
  if (sp.moving_window)
    s += fmt::format("fix window all brash/window every {} ahead {:.9g} behind {:.9g} hull_x0 {:.9g} speed {:.9g} "
                     "bow_offset {:.9g} stern_offset {:.9g} moving_speed {:.9g}\n",
                     sp.farfield_every_steps, sp.moving_window_ahead_m, sp.moving_window_behind_m, hull_x0,
                     c.ship.speed_m_s, opt.hull_x_max_m, opt.hull_x_min_m, sp.farfield_wake_speed_m_s);
  // fluid forces last: implicit added mass scales the sum of all other forces
  s += fmt::format(
      "fix fl {} icefluid {} output_every {}{}\n", moving, icefluid_arguments(brash::fluid_params(c)), dump_every,
      // the flow around the hull: the full hull, its frame's origin at t = 0 and speed, as fix hull above
      c.fluid.hull_flow != HullFlow::None
          ? fmt::format(" hull_flow {} {:.9g} 0 {:.9g} {:.9g}", opt.flow_hull_file, hull_x0, -c.hull.draft_m,
                        c.ship.speed_m_s)
          : std::string());
  s += fmt::format("variable t equal step*dt\n");
  // the hull force split (brash/core/hull_split.hpp): fx by region and by mechanism from the hull's contacts,
  // the whole ship's with speedups.symmetry_y (twice the half hull's, as hfx below)
  const auto& hr = opt.hull_regions;
  s += fmt::format("fix split all brash/hullsplit mesh hull hull_x0 {:.9g} speed {:.9g} par_aft {:.9g} par_fwd {:.9g} "
                   "scale {}\n",
                   hull_x0, c.ship.speed_m_s, hr.x_par_aft_m, hr.x_par_fwd_m, sp.symmetry_y ? 2 : 1);
  const std::string split = " f_split[1] f_split[2] f_split[3] f_split[4] f_split[5]";
  if (sp.symmetry_y) {  // the whole ship: twice the half hull's fx, fz; fy = 0 by symmetry
    s += "variable hfx equal 2*f_hull[1]\nvariable hfy equal 0\nvariable hfz equal 2*f_hull[3]\n";
    s += fmt::format("fix hf all ave/time {0} 1 {0} v_t v_hfx v_hfy v_hfz{1} file hull_force.raw\n", out_every, split);
  } else {
    s += fmt::format("fix hf all ave/time {0} 1 {0} v_t f_hull[1] f_hull[2] f_hull[3]{1} file hull_force.raw\n",
                     out_every, split);
  }
  s += fmt::format(
      "dump parts all custom {} particles/dump.*.txt id x y z radius vx vy vz f_fl[1] f_fl[2] f_fl[3] f_fl[4] "
      "f_fl[5] f_force_hullwall[1] f_force_hullwall[2] f_force_hullwall[3]\n",
      dump_every);
  s += "dump_modify parts pad 10\n";
  if (opt.restart_every_steps > 0)
    s += fmt::format("restart {} restart/a.restart restart/b.restart\n", opt.restart_every_steps);
  // with the moving window, the pieces held out; with the far field, the last column is the number of idle
  // pieces (log.txt: how far the disturbance reached). lost ignore: fix brash/exit removes pieces and checks for lost atoms itself (LIGGGHTS' `lost
  // error` counts against the run's initial number after a read_restart: fix_brash_exit.cpp)
  s += fmt::format(
      "thermo_style custom step v_t atoms ke f_hull[1] cpu{}{}\nthermo {}\nthermo_modify norm no lost ignore\n",
      sp.moving_window ? " f_window[1]" : "", sp.farfield ? " f_farfield[1]" : "", thermo_every);
  s += fmt::format("run {}{}\n", steps, opt.restart_file.empty() ? "" : " upto");  // upto: to the same end step
  s += "write_restart restart/final.restart\n";
  return s;
}

std::string settle_script(const Case& c, const Box& box, long chunk_steps, long max_chunks) {
  const double skin_m = c.speedups.neighbor_skin_d * c.ice.diameter_mean_m;
  std::string s = "# brash: settling deck written by brash-settle for case " + c.name + "\n";
  s += opening_lines(c, "read_data packing.data", 1);
  s += fmt::format("neighbor {:.6g} bin\nneigh_modify delay 0\n", skin_m);
  s += contact_lines(c, false);
  s += fmt::format("timestep {:.9g}\n", c.run.timestep_s);
  s += wall_lines(c, false, true);  // closed: the bed must not spread through open ends while it settles
  s += "fix integr all nve/sphere\n";
  s += fmt::format("fix grav all gravity {:.9g} vector 0 0 -1\n", c.water.gravity_m_s2);
  // Preparation only: a floating bed bobs for seconds (the fluid model's drag, quadratic in the speed, barely
  // damps mm/s motion, and it radiates no waves), so the settling adds viscous damping with a time of 0.1 s on
  // the mean piece; the run itself starts from the settled positions at rest, without it.
  const double mean_mass_kg = c.ice.density_kg_m3 * sphere_volume_m3(c.ice.diameter_mean_m);
  s += fmt::format("fix damp all viscous {:.9g}\n", mean_mass_kg / 0.1);
  s += guard_command(c, guard::limits_for_case(c, {box.xlo, box.xhi, box.ylo, box.yhi, box.zlo, box.zhi})) + "\n";
  s += fmt::format("fix fl all icefluid {} output_every {}\n", icefluid_arguments(brash::fluid_params(c)),
                   chunk_steps * max_chunks + 1);
  // the rms speed of the pieces from their translational kinetic energy (thermo evaluates c_k at each chunk's
  // last step, so the variable is current between runs)
  s += "compute k all ke\nvariable vrms equal sqrt(2*c_k/mass(all))\nvariable t equal step*dt\n";
  s += fmt::format("thermo_style custom step v_t atoms c_k v_vrms\nthermo {}\nthermo_modify norm no\n", chunk_steps);
  s += fmt::format("variable chunk loop {}\nlabel next_chunk\nrun {}\n", max_chunks, chunk_steps);
  s += "print \"brash-settle progress: t ${t} vrms ${vrms}\"\n";
  s += fmt::format("if \"${{vrms}} < {:.9g}\" then \"jump SELF settled\"\n", c.ice.settle_speed_m_s);
  s += "next chunk\njump SELF next_chunk\nlabel settled\n";
  s += "print \"brash-settle: t ${t} vrms ${vrms}\"\n";
  s += "dump final all custom 1 settled.dump id x y z radius\ndump_modify final sort id\nrun 0\n";
  return s;
}

}  // namespace brash::liggghts
