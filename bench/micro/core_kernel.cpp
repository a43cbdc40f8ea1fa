// Micro-benchmarks of the core's per-piece costs (Google Benchmark): the fluid kernel per model and treatment,
// the immersion of a sphere and the hull-flow table lookup. `make bench` prints them in its summary
// (docs/performance.md "Plugin overhead and postprocessor throughput"); alone:
//   build/bin/bench-core-kernel --benchmark_min_time=0.2
// items/s is pieces per second: its inverse is the cost of one piece in one step.
#include <benchmark/benchmark.h>

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

}  // namespace

BENCHMARK_MAIN();
