/* fix icefluid: fluid forces on floating ice spheres (buoyancy, drag, added mass) from brash_core.

   fix ID group-ID icefluid keyword value ...

   keywords (all optional; defaults in brackets):
     model        drag | added_mass | both                 [both]
     treatment    implicit | explicit                      [implicit]
     cd           drag coefficient C_D                      [brash::kDefaultDragCoefficient]
     drag_law     constant | schiller_naumann              [constant]
     nu           kinematic viscosity (m^2/s)              [brash::kDefaultKinematicViscosity_m2_s]
     ca           table1 | text | uniform VALUE            [table1]
     water_level  z of the free surface (m)                [0]
     water_density rho_w (kg/m^3)                          [1000]
     flow         vx vy vz, flow velocity (m/s)            [0 0 0]
     hull_flow    FILE x0 y0 z0 speed: instead of `flow`, the water's flow around a hull (thin-ship double
                  body, plugin/core hull_flow.hpp): the hull mesh FILE, or a flow table FILE.bin that the
                  runner computed (thin-ship or panel flow, brash/hull/panel_flow.hpp); its frame's origin
                  in the scene at t = 0 and its speed along x (the hull moves with t = step * dt, as fix
                  move/mesh linear from step 0). The drag acts on the velocity relative to the water,
                  and the table's Du/Dt adds the pressure-gradient force and the added mass's reaction
                  to the relative acceleration, rho V_s (1 + Ca) Du/Dt (brash/core/flow_acceleration.hpp)
                  [none]
     g            gravity magnitude for buoyancy (m/s^2)   [9.81]
     gravity      no | yes: also apply -m g here (then do not use fix gravity)  [no]
     output_every N: fill the per-atom output only every N steps (dump interval)  [1]

   Must be the last POST_FORCE fix (checked at init): the implicit treatment scales the sum of every
   other force. Per-atom output (dump f_ID[1..5]): submerged fraction, Ca_x, Ca_y, Ca_z, active (1 in the fix's
   group, 0 outside it: idle far-field ice, with its real submerged fraction and Ca 0).
   Doc: plugin/liggghts/doc/fix_icefluid.txt
*/
#pragma once

#include "brash/core/hull_flow.hpp"
#include "brash/core/kernel.hpp"
#include "brash/core/params.hpp"
#include "fix.h"

namespace brash::liggghts {

class FixIceFluid : public LAMMPS_NS::Fix {
 public:
  FixIceFluid(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixIceFluid() override;

  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  int pack_restart(int i, double* buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int) override { return kStateSize + 1; }
  int maxsize_restart() override { return kStateSize + 1; }
  double memory_usage();

  const brash::core::FluidParams& params() const { return params_; }

 private:
  // Per-atom state carried across steps, migration and restart: the core kernel's layout (kernel.hpp).
  static constexpr int kStateSize = brash::core::kStateStride;
  static constexpr int kOutputSize = brash::core::kOutputStride;  // submerged fraction, Ca x, y, z, active

  void compute(bool replay);
  void parse(int narg, char** arg);

  brash::core::FluidParams params_;
  // hull_flow: the table in the hull frame (water level at z = 0) and where that frame is at t = 0
  brash::core::FlowTable hull_flow_;
  brash::core::Vec3 hull_flow_origin_m_ = brash::core::Vec3::Zero();
  double hull_flow_speed_m_s_ = 0.0;
  double** flow_ = nullptr;  // per-atom flow velocity of this step (not carried: a function of x and t)
  double** flow_accel_ = nullptr;  // per-atom Du/Dt of that flow, earth frame (the same)
  int output_every_ = 1;  // per-atom output is only needed on dump steps
  double** state_ = nullptr;
  double** output_ = nullptr;
};

}  // namespace brash::liggghts
