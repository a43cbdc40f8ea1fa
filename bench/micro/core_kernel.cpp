// Micro-benchmarks of the core's per-piece costs (Google Benchmark): the fluid kernel per model and treatment,
// the immersion of a sphere and the hull-flow table lookup. `make bench` prints them in its summary
// (docs/performance.md "Plugin overhead and postprocessor throughput"); alone:
//   build/bin/bench-core-kernel --benchmark_min_time=0.2
// items/s is pieces per second: its inverse is the cost of one piece in one step.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "brash/core/hull_flow.hpp"
#include "brash/core/immersion.hpp"
#include "brash/core/kernel.hpp"

namespace {

using brash::core::FluidModel;
using brash::core::Treatment;
using brash::core::Vec3;

constexpr std::size_t kPieces = 8192;  // a quick-case-sized scene: the arrays stay in the L2 cache

// A floating bed: pieces of the paper case's size around the waterline, drifting at a few cm/s.
struct Bed {
  std::vector<double> r, m, x, v, f, state;
  explicit Bed(std::size_t n) : r(n), m(n), x(3 * n), v(3 * n), f(3 * n), state(n * brash::core::kStateStride) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      r[i] = 0.0088 * (1.0 + 0.05 * u(rng));
      m[i] = 900.0 * 4.18879 * r[i] * r[i] * r[i];
      x[3 * i] = 7.0 * u(rng), x[3 * i + 1] = 1.1 * u(rng), x[3 * i + 2] = 0.8 * r[i] * u(rng);
      for (int k = 0; k < 3; ++k) v[3 * i + k] = 0.05 * u(rng);
    }
  }
  brash::core::KernelArrays arrays() {
    brash::core::KernelArrays a;
    a.n = r.size(), a.radius_m = r.data(), a.mass_kg = m.data(), a.x_m = x.data(), a.v_m_s = v.data();
    a.f_N = f.data(), a.state = state.data();
    return a;
  }
};

void Kernel(benchmark::State& st, FluidModel model, Treatment treatment) {
  Bed bed(kPieces);
  brash::core::FluidParams p;
  p.model = model, p.treatment = treatment;
  const auto a = bed.arrays();
  for (auto _ : st) {
    std::fill(bed.f.begin(), bed.f.end(), 0.0);
    brash::core::apply_kernel(p, a, 1e-4, false);
    benchmark::DoNotOptimize(bed.f.data());
  }
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * kPieces));
}
BENCHMARK_CAPTURE(Kernel, both_implicit, FluidModel::Both, Treatment::Implicit);
BENCHMARK_CAPTURE(Kernel, both_explicit, FluidModel::Both, Treatment::Explicit);
BENCHMARK_CAPTURE(Kernel, drag, FluidModel::Drag, Treatment::Implicit);
BENCHMARK_CAPTURE(Kernel, added_mass_implicit, FluidModel::AddedMass, Treatment::Implicit);

void Immersion(benchmark::State& st) {
  Bed bed(kPieces);
  for (auto _ : st) {
    double sum = 0;
    for (std::size_t i = 0; i < kPieces; ++i) sum += brash::core::immersion(bed.r[i], bed.x[3 * i + 2], 0.0).volume_m3;
    benchmark::DoNotOptimize(sum);
  }
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * kPieces));
}
BENCHMARK(Immersion);

// The table of a hull-sized box at the engines' spacing (draft / 8); the field's values do not change the cost.
void FlowTableLookup(benchmark::State& st) {
  Bed bed(kPieces);
  const auto field = [](const Vec3& p) { return Vec3(0.1 * p.x(), 0.05 * p.y(), 0.01 * p.z()); };
  const brash::core::FlowTable table(field, Vec3(-8.0, 0.0, -0.5), Vec3(8.0, 1.2, 0.0), 0.05, true);
  for (auto _ : st) {
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < kPieces; ++i) sum += table.at(Vec3(bed.x[3 * i], bed.x[3 * i + 1], bed.x[3 * i + 2]));
    benchmark::DoNotOptimize(sum);
  }
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * kPieces));
}
BENCHMARK(FlowTableLookup);

// One fluid step of every piece in a hull's flow, as fix icefluid does it (the table lookup per piece, then the
// kernel), with the table as it was (a regular grid, U_flow only, the drag alone sees it) and as it is (nodes
// inside the hull never used, cells along it refined, Du/Dt: the water's acceleration in the force), timed
// alternately in one run; the counter `ratio` is the step's cost now over before. The hull: an ellipsoid of the
// JBC model's length, breadth and draft (a double body about the water level) in the flow of a source doublet;
// the pieces' bed of the other benchmarks lies around and across it.
void HullFlowStep(benchmark::State& st) {
  using brash::core::FlowField;
  using brash::core::FlowTable;
  Bed bed(kPieces);
  const Vec3 axes(3.5, 0.56, 0.4125);
  const auto field = [&](const Vec3& p) {
    const Vec3 q = p.cwiseQuotient(axes);
    const double r2 = std::max(q.squaredNorm(), 1e-6), r = std::sqrt(r2);
    return Vec3(0.482 * 0.5 * (3 * q.x() * q / (r2 * r2 * r) - Vec3::UnitX() / (r2 * r)));
  };
  const Vec3 lo(-8.0, 0.0, -1.5), hi(8.0, 2.0, 0.1);
  const FlowTable before(field, lo, hi, 0.4125 / 8, true);
  FlowField body;
  body.velocity = field, body.body_velocity_m_s = Vec3(0.482, 0, 0), body.acceleration = true;
  body.solid = [&](const Vec3& p) { return p.cwiseQuotient(axes).norm() < 1.0; };
  body.distance_m = [&](const Vec3& p) { return std::abs(p.cwiseQuotient(axes).norm() - 1.0) * axes.y(); };
  const FlowTable now(body, lo, hi, 0.4125 / 8, true, {0.25 * 0.4125, 0.0025 * 0.482, 16});
  std::vector<double> flow(3 * kPieces), accel(3 * kPieces);
  brash::core::FluidParams p;
  auto a = bed.arrays();
  a.flow_m_s = flow.data();
  double before_s = 0, now_s = 0;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    std::fill(bed.f.begin(), bed.f.end(), 0.0);
    for (std::size_t i = 0; i < kPieces; ++i) {
      const Vec3 u = before.at(Vec3(bed.x[3 * i], bed.x[3 * i + 1], bed.x[3 * i + 2]));
      flow[3 * i] = u.x(), flow[3 * i + 1] = u.y(), flow[3 * i + 2] = u.z();
    }
    a.flow_acceleration_m_s2 = nullptr;
    brash::core::apply_kernel(p, a, 1e-4, false);
    benchmark::DoNotOptimize(bed.f.data());
    const auto t1 = std::chrono::steady_clock::now();
    std::fill(bed.f.begin(), bed.f.end(), 0.0);
    Vec3 u, du_dt;
    for (std::size_t i = 0; i < kPieces; ++i) {
      now.at(Vec3(bed.x[3 * i], bed.x[3 * i + 1], bed.x[3 * i + 2]), u, du_dt);
      flow[3 * i] = u.x(), flow[3 * i + 1] = u.y(), flow[3 * i + 2] = u.z();
      accel[3 * i] = du_dt.x(), accel[3 * i + 1] = du_dt.y(), accel[3 * i + 2] = du_dt.z();
    }
    a.flow_acceleration_m_s2 = accel.data();
    brash::core::apply_kernel(p, a, 1e-4, false);
    benchmark::DoNotOptimize(bed.f.data());
    const auto t2 = std::chrono::steady_clock::now();
    before_s += std::chrono::duration<double>(t1 - t0).count(), now_s += std::chrono::duration<double>(t2 - t1).count();
  }
  const double steps = static_cast<double>(st.iterations()) * kPieces;
  st.counters["before_ns_per_piece"] = before_s / steps * 1e9;
  st.counters["now_ns_per_piece"] = now_s / steps * 1e9;
  st.counters["ratio"] = now_s / before_s;
  st.counters["bricks"] = static_cast<double>(now.bricks().size());
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * kPieces));
}
BENCHMARK(HullFlowStep)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
