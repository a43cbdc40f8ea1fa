// Writes a synthetic run directory in the layout of docs/case_format.md, with known numbers, for the
// postprocessor tests. Header-only test helper.
#pragma once
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace brash::post::testing {

struct SyntheticRun {
  double duration_s = 45.0, dt_s = 0.01;
  double mean_resistance_N = 2.0;     // plateau value of -fx
  double fy_N = 0.1, fz_N = -0.5;     // plateau values of fy, fz
  double noise_N = 0.3, phi = 0.8;    // AR(1) noise on every component
  double drift_N_per_s = 0;  // resistance rising linearly after t = 15 s (a record that is not stationary)
  double gap_from_s = 0, gap_to_s = 0;  // rows strictly between them are not written (a lost attempt's rows)
  std::string status = "complete";
  bool truncated_tail = false;        // last line cut without newline
  std::vector<double> snapshot_times_s{0.0, 20.0, 40.0};
  int particles = 60;
  int exits = 0;                      // meta.json "exits" (written when > 0)
  std::string meta_extra_json;        // more meta.json keys, e.g. R"(, "early_stop": {...})"
  std::string hull_extra_yaml;        // more hull: keys, e.g. "  band_m: [0.15, 0.1]\n"
  double deep_piece_z_m = 0;          // nonzero: piece 0's centre z in the second snapshot
  bool active_column = true;          // particles files with the active column (LIGGGHTS, ODE; every 4th piece idle)
  // the hull force split's columns (fx_bow_N .. fx_tangential_N): bow 0.6 fx + a, mid 0.3 fx - a, stern 0.1 fx,
  // normal 0.8 fx + b, tangential the rest (a, b: noise of their own)
  bool split = false;
  bool split_stern_untouched = false;  // the stern touches no ice: 0 exactly, its tenth of fx on the mid-body
  std::vector<std::vector<double>> split_series;  // written values, one vector per column
  // Written values (read back by the tests).
  std::vector<double> t_s, fx_N, fy_N_series, fz_N_series;
};

// An empty folder <tmp>/brash_<suite>_<name>_<pid> for one test.
inline std::filesystem::path fresh_dir(const std::string& suite, const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / fmt::format("brash_{}_{}_{}", suite, name, ::getpid());
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// A file's bytes ("" when it cannot be read).
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline void write_text(const std::filesystem::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
}

// Case: the fsicr.md Panamax at 1:28.5 (so case dimensions * lambda = L 199.11, B 32, T 11.733) with
// every bow parameter overridden to the first worked example (R_CH = 990 kN). The hull file does not
// exist, so nothing is measured.
inline std::string synthetic_case_yaml(double window_t1_s = 40.0, const std::string& hull_extra_yaml = "") {
  return fmt::format(R"(name: synthetic
description: "postproc test"
hull:
{}  file: no_such_hull.stl
  draft_m: {}
  lpp_m: {}
  beam_m: {}
  start_x_m: -1.0
ship:
  speed_m_s: 0.482
  scale_lambda: 28.5
  ice_class: IA
channel:
  length_m: 21.0
  width_m: 2.25
fluid:
  model: added_mass
run:
  duration_s: 45.0
  window_s: [15.0, {}]
fsicr:
  alpha_deg: 25
  phi1_deg: 90
  phi2_deg: 60
  L_par_m: 100
  L_bow_m: 40
  A_wf_m2: 900
)", hull_extra_yaml, 11.733 / 28.5, 199.11 / 28.5, 32.0 / 28.5, window_t1_s);
}

inline void write_synthetic_run(const std::filesystem::path& dir, SyntheticRun& r) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "particles");
  write_text(dir / "case.yaml", synthetic_case_yaml(40.0, r.hull_extra_yaml));
  write_text(dir / "meta.json",
             fmt::format(R"({{"engine": "synthetic", "engine_version": "1.0", "fluid_model": "added_mass",
 "treatment": "implicit", "dt_s": 5e-5, "ranks": 2, "particles": {}, "wall_time_s": 123.5,
 "particle_steps": 4.2e9, "git_commit": "abc", "status": "{}", "reason": ""{}}})",
                         r.particles, r.status,
                         (r.exits > 0 ? fmt::format(", \"exits\": {}", r.exits) : "") + r.meta_extra_json));

  std::mt19937_64 rng(42);
  std::normal_distribution<double> e(0, 1);
  double nx = 0, ny = 0, nz = 0;
  const double s = r.noise_N * std::sqrt(1 - r.phi * r.phi);
  std::string csv = r.split ? "t_s,fx_N,fy_N,fz_N,fx_bow_N,fx_mid_N,fx_stern_N,fx_normal_N,fx_tangential_N\n"
                            : "t_s,fx_N,fy_N,fz_N\n";
  r.split_series.assign(r.split ? 5 : 0, {});
  const int n = static_cast<int>(std::lround(r.duration_s / r.dt_s));
  for (int i = 0; i <= n; ++i) {
    const double t = i * r.dt_s;
    const double ramp = std::min(1.0, t / 10.0);  // bow entering the ice
    nx = r.phi * nx + s * e(rng);
    ny = r.phi * ny + s * e(rng);
    nz = r.phi * nz + s * e(rng);
    if (t > r.gap_from_s + 1e-9 && t < r.gap_to_s - 1e-9) continue;
    r.t_s.push_back(t);
    r.fx_N.push_back(-(r.mean_resistance_N * ramp + r.drift_N_per_s * std::max(0.0, t - 15.0) + nx));
    r.fy_N_series.push_back(r.fy_N * ramp + ny);
    r.fz_N_series.push_back(r.fz_N * ramp + nz);
    csv += fmt::format("{},{},{},{}", t, r.fx_N.back(), r.fy_N_series.back(), r.fz_N_series.back());
    if (r.split) {
      const double fx = r.fx_N.back(), a = 0.2 * e(rng), b = 0.1 * e(rng);
      const double stern = r.split_stern_untouched ? 0.0 : 0.1 * fx;
      const double parts[5] = {0.6 * fx + a, 0.4 * fx - a - stern, stern, 0.8 * fx + b, 0.2 * fx - b};
      for (std::size_t k = 0; k < 5; ++k) {
        r.split_series[k].push_back(parts[k]);
        csv += fmt::format(",{}", parts[k]);
      }
    }
    csv += "\n";
  }
  if (r.truncated_tail) csv += fmt::format("{},-1.2", (n + 1) * r.dt_s);  // being written
  write_text(dir / "hull_force.csv", csv);

  std::string index = "step,t_s,file,hull_x_m\n";
  for (std::size_t k = 0; k < r.snapshot_times_s.size(); ++k) {
    const double t = r.snapshot_times_s[k];
    const long step = std::lround(t / 5e-5);
    const auto file = fmt::format("particles_{}.csv", step);
    index += fmt::format("{},{},{},{}\n", step, t, file, -1.0 + 0.482 * t);
    std::string p = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z";
    p += r.active_column ? ",active\n" : "\n";
    for (int i = 0; i < r.particles; ++i) {
      const double x = 0.1 * i + 0.01 * t, y = -1.0 + 0.03 * i;
      const double z = (i == 0 && k == 1 && r.deep_piece_z_m != 0) ? r.deep_piece_z_m : -0.005 * (i % 3);
      p += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}", i, x, y, z, 0.0088, 0.01 * i, 0.0, -0.001 * i,
                       0.9 + 0.001 * (i % 10), 0.5, 0.5, i % 2 ? 0.0 : 0.5);
      p += r.active_column ? fmt::format(",{}\n", i % 4 ? 1 : 0) : "\n";
    }
    write_text(dir / "particles" / file, p);
  }
  write_text(dir / "particles" / "index.csv", index);
}

// Mean of v over samples with t in [t0, t1].
inline double window_mean(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1) {
  double s = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) s += v[i], ++n;
  return s / n;
}

}  // namespace brash::post::testing
