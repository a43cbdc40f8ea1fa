// Out-of-line array loop over spheres (kept out of the header so adapters share one compiled loop).
#include "brash/core/fluid.hpp"

namespace brash::core {

void apply_to_arrays(const FluidParams& p, std::size_t n, const double* radius_m, const double* mass_kg,
                     const double (*x_m)[3], const double (*v_m_s)[3], double (*f_N)[3], FluidState* state,
                     double dt_s, const int* mask) {
  for (std::size_t i = 0; i < n; ++i) {
    if (mask && !mask[i]) continue;
    Sphere s;
    s.radius_m = radius_m[i];
    s.mass_kg = mass_kg[i];
    s.position_m = Vec3(x_m[i][0], x_m[i][1], x_m[i][2]);
    s.velocity_m_s = Vec3(v_m_s[i][0], v_m_s[i][1], v_m_s[i][2]);
    const FluidOutput out = evaluate(p, s, state[i], dt_s);
    for (int k = 0; k < 3; ++k) f_N[i][k] = scaled_total_force(f_N[i][k], out.force_N[k], out.scale[k]);
    state[i] = advance(state[i], s.velocity_m_s);
  }
}

}  // namespace brash::core
