// The hot loop over an engine's particle arrays: the same physics as evaluate() (fluid.hpp, the
// readable reference), specialised per fluid model and treatment so that the per-sphere work is a
// few dozen flops with no allocation, no strings and no Eigen temporaries. Tests check it against
// evaluate() to round-off.
//
// Arrays are row-major and contiguous (LIGGGHTS' double** point at one block: pass x[0]).
// Per-sphere state, kStateStride doubles owned by the engine (migrates and goes into restarts; a new
// sphere's row must be all zero):
//   [0..2] velocity used at the last evaluation (x, y only with drag or explicit)
//   [3] 0 never evaluated, 1 evaluated, 2 evaluated and the last evaluation saw a reversal (one store
//       for both flags)   [4] 0 (the reversal flag of the older layout, still read on replay so that
//       older restart files continue exactly)   [5..7] acceleration used by the explicit treatment
// With `replay` (start of a run), spheres that have a state re-evaluate their last step from it
// (same position, same velocity, same reversal and acceleration) and keep the state: a restarted
// run continues exactly like an uninterrupted one.
#pragma once
#include <cstddef>

#include "brash/core/params.hpp"

namespace brash::core {

inline constexpr int kStateStride = 8;
// Per-sphere output: submerged fraction, Ca_x, Ca_y, Ca_z, active (1 integrated, 0 outside the mask: idle far-field
// ice, whose submerged fraction is its real one and whose Ca is 0, as no fluid force acts on it)
inline constexpr int kOutputStride = 5;

struct KernelArrays {
  std::size_t n = 0;
  const double* radius_m = nullptr;
  const double* mass_kg = nullptr;
  const double* x_m = nullptr;    // n x 3
  const double* v_m_s = nullptr;  // n x 3
  double* f_N = nullptr;          // n x 3: every other force on entry, the total on exit
  const double* flow_m_s = nullptr;  // n x 3: each sphere's flow velocity (drag: u = v - flow), or null for
                                     // the uniform FluidParams::flow_velocity_m_s
  const double* flow_acceleration_m_s2 = nullptr;  // n x 3: each sphere's Du/Dt of that flow
                                                   // (flow_acceleration.hpp), or null for the uniform
                                                   // FluidParams::flow_acceleration_m_s2
  double* state = nullptr;        // n x kStateStride
  double* output = nullptr;       // n x kOutputStride, or null (filled by a pass after the forces)
  const int* mask = nullptr;      // null = all spheres; else sphere i is used if mask[i] & groupbit
  int groupbit = 0;
};

void apply_kernel(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay);

}  // namespace brash::core
