// The force of the water's own acceleration on a piece, coded once for every engine: evaluate() (fluid.hpp, the
// reference for ODE, YADE and the reference integrator) and the array kernel (LIGGGHTS) both take it from here.
//
// A piece in water that accelerates (Du/Dt, earth frame: the flow around the hull moves with the ship) feels the
// pressure gradient that accelerates that water, rho V_s Du/Dt (Froude-Krylov), and its added mass reacts to the
// acceleration relative to the water: with the drag on the relative velocity (Eq. 1),
//     m a = F_other + F_drag(v - U_flow) + rho V_s (1 + C_a) Du/Dt - rho C_a V_s a,
// the Morison form, or Maxey & Riley's (1983, Phys. Fluids 26) without the Basset history and Faxen terms. Per
// axis with C_a of Table 1 (0 for the model without added mass: the pressure gradient alone). The implicit
// treatment moves -m_a a to the left, (m + m_a) a = F_other + F_drag + this force (added_mass.hpp); the explicit
// one keeps -m_a a with the lagged a. In still water (Du/Dt = 0) the force is 0 and the model is the paper's.
#pragma once

namespace brash::core {

// rho V_s (1 + C_a) Du/Dt along one axis: displaced_water_kg = rho V_s.
constexpr double flow_acceleration_force_N(double displaced_water_kg, double ca, double flow_acceleration_m_s2) {
  return displaced_water_kg * (1.0 + ca) * flow_acceleration_m_s2;
}

}  // namespace brash::core
