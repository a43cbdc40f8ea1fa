// Hydrostatics and FSICR bow parameters measured on a closed hull mesh at a given draft.
// Hull frame: x forward, y to port, keel at z = 0, waterline at z = draft.
#pragma once
#include <brash/fsicr_params.hpp>
#include <brash/hull/mesh.hpp>

namespace brash::hull {

struct Hydrostatics {
  double volume_m3 = 0;           // displaced volume below z = draft
  double cb = 0;                  // volume / (Lpp B T); Lpp = lpp_m if given, else Lwl; B = Bwl
  double lcb_x_m = 0;             // x of the centre of buoyancy (hull frame)
  double kb_m = 0;                // z of the centre of buoyancy
  double waterplane_area_m2 = 0;  // area of the section z = draft
  double lcf_x_m = 0;             // x of the centre of the waterplane
  double wetted_surface_m2 = 0;   // hull area below z = draft (waterplane not included)
  double lwl_m = 0;               // x extent of the waterline
  double bwl_m = 0;               // y extent of the waterline
};

// Exact for the piecewise-linear mesh: triangles are clipped at the waterline and integrated with the
// divergence theorem (field (0, 0, z - draft) vanishes on the waterplane, so the lid is not needed).
// Needs a closed, outward mesh for volume, LCB and waterplane area.
Hydrostatics hydrostatics(const Mesh& mesh, double draft_m, double lpp_m = 0);

// Conventions (all at the waterline z = T = draft, on the mesh; see hull_meshes/README.md):
//  - Y(x, z): half-breadth = largest |y| of the section at height z at station x.
//  - B/4 point: the most forward x where Y(x, T) >= B/4 (B = Bwl).
//  - alpha: atan(-dY/dx) there, central difference over +-dx (dx = 1 mm * Lpp / 7 m).
//  - phi2: buttock y = B/4 (most forward x with Y >= B/4) at T +- dz (dz = 5 mm * Lpp / 7 m):
//    atan(2 dz / (x(T + dz) - x(T - dz))), from the horizontal.
//  - phi1: the same with the stem (most forward x of the section); set to 90 deg when the hull has a
//    bulb (a point below T ahead of the stem at T, or a stem receding going up at T: a waterline that
//    cuts the bulb), as the FSICR rule says. The geometric value is returned by measure_fsicr_detail.
//  - psi = atan(tan(phi2) / sin(alpha)).
//  - L_par: longest run of x where Y(x, T) >= B/2 - flat_tol (flat_tol = 1e-5 B), sampled every
//    L / 70000; L_bow: from its forward end to the stem at T; A_wf: waterplane area over L_bow.
//  - L = lpp_m, B = Bwl, T = draft.
struct FsicrDetail {
  FsicrParams params;
  double phi1_geometric_deg = 0;
  bool bulbous_bow = false;
  double x_b4_m = 0;           // x of the B/4 point on the waterline
  double x_stem_m = 0;         // x of the stem at T
  double x_par_aft_m = 0, x_par_fwd_m = 0;  // parallel mid-body at T
};

FsicrDetail measure_fsicr_detail(const Mesh& mesh, double draft_m, double lpp_m);
FsicrParams measure_fsicr(const Mesh& mesh, double draft_m, double lpp_m);

}  // namespace brash::hull
