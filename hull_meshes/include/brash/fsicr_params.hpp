// Hull parameters of the FSICR channel-resistance formula (see docs/fsicr.md).
// Measured on the hull STL by brash_hull (hull_meshes/), consumed by the FSICR formula (postproc/).
#pragma once

namespace brash {

struct FsicrParams {
  double L_m = 0;          // length between perpendiculars
  double B_m = 0;          // maximum breadth at the waterline
  double T_m = 0;          // draught
  double alpha_deg = 0;    // waterline angle at B/4
  double phi1_deg = 90;    // stem rake at the centreline (90 for a bulbous bow)
  double phi2_deg = 0;     // bow rake (buttock angle) at B/4
  double psi_deg = 0;      // flare angle, atan(tan(phi2)/sin(alpha))
  double L_par_m = 0;      // parallel mid-body length at the waterline
  double L_bow_m = 0;      // bow length at the waterline
  double A_wf_m2 = 0;      // waterline area of the bow (L_bow part)
};

}  // namespace brash
