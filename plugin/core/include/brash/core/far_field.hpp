// The far-field rule, coded once for every engine that idles far ice (LIGGGHTS' fix brash/farfield,
// brash-ode's --cull): which pieces are idle (not integrated: an immovable obstacle to active pieces) and
// when an idle piece wakes. docs/performance.md ("far field") measures what it saves and what it costs.
//
// Window: with the hull moving along +x, a piece more than `ahead` ahead of the bow or more than `behind`
// behind the stern is outside it; brash-ode can also bound it across the channel (beside the hull).
// The window alone is not enough when the ship's push travels further than `ahead` through the ice: the idle
// ice is then a wall that jams the pushed bed (biased high: docs/performance.md, "The idle far field"). The wake
// rule lets the push through:
//   - by force (F > 0): an idle piece wakes as soon as the horizontal force on it (from active neighbours:
//     idle pieces get no gravity or fluid force) exceeds F;
//   - by neighbour speed (V > 0): an idle piece wakes as soon as an active piece touching it moves faster
//     than V (a resting bed stays idle, where the force rule wakes it through its resting contacts);
//   - by push front (brash-ode; front speed U > 0): ahead of the bow nothing wakes: the window's front lies
//     `ahead` beyond the bow and beyond the foremost active piece moving ahead (+x) faster than U, and never
//     recedes, and the bed ahead is idle from the first update on, moving or not, so the push
//     meets active ice instead of a wall (on rigid contacts the pushed ice shows the push neither as its
//     speed at the wall nor as a force apart from its resting load); beside the hull and behind the stern, by
//     force;
//   - at a membership update a piece inside the window is active; ahead of the bow a piece keeps its state
//     (one the push has reached stays active: re-freezing slow pieces of a loaded bed would jam it again);
//     behind the stern, beside the hull and at a run's first update a piece is idle once no faster than V (at
//     the first update ahead of the window, by push front, always).
#pragma once
#include <limits>

#include "brash/core/params.hpp"
#include "brash/far_field_options.hpp"

namespace brash::core {

struct FarFieldWindow {
  double lo_x_m = 0, hi_x_m = 0;  // stern - behind, bow + ahead
  double centre_y_m = 0;          // the hull's centre line
  double half_width_m = std::numeric_limits<double>::infinity();  // |y - centre| beyond this: beside
};

// The window for the hull's extent along x now (stern <= bow) and the active distances behind and ahead.
constexpr FarFieldWindow far_field_window(double stern_x_m, double bow_x_m, double behind_m, double ahead_m) {
  FarFieldWindow w;
  w.lo_x_m = stern_x_m - behind_m;
  w.hi_x_m = bow_x_m + ahead_m;
  return w;
}

enum class FarFieldZone { Inside, Ahead, Behind, Beside };

// Ahead and behind take precedence over beside (their rules differ; the window is x first).
FarFieldZone far_field_zone(const FarFieldWindow& w, double x_m, double y_m);

struct WakeRule {
  double force_N = 0;    // by force (by push front: beside and behind): wake when the horizontal force exceeds
                         // this; 0: never (the window alone)
  double speed_m_s = 0;  // where the speed decides (see above): idle once |v| <= this; by neighbour speed also:
                         // wake when a touching active piece is faster than this (0: never)
  WakeBy by = WakeBy::Force;
  double front_speed_m_s = 0;  // by push front: the front follows the pieces moving ahead faster than this
                               // (0: no rule)
  bool enabled() const {
    switch (by) {
      case WakeBy::Force: return force_N > 0;
      case WakeBy::NeighbourSpeed: return speed_m_s > 0;
      case WakeBy::PushFront: return front_speed_m_s > 0;
    }
    return false;
  }
  bool reads_force() const { return by != WakeBy::NeighbourSpeed && force_N > 0; }
  bool reads_neighbour_speed() const { return by == WakeBy::NeighbourSpeed && speed_m_s > 0; }
  bool front_follows_push() const { return by == WakeBy::PushFront && front_speed_m_s > 0; }
};

// The case file's form (speedups.farfield_wake_force_weight): a fraction of the weight of a piece of the
// mean diameter.
double wake_force_N(double weight_fraction, double mean_diameter_m, double ice_density_kg_m3,
                    double gravity_m_s2);

// Does an idle piece with this horizontal force on it wake now? (by force: |F_h| > F; by push front also, but only
// in `zone` Beside or Behind; never otherwise)
bool wakes(const WakeRule& rule, double fx_N, double fy_N, FarFieldZone zone = FarFieldZone::Beside);

// The window's front with the push front (WakeBy::PushFront): `ahead` beyond the bow and beyond the foremost
// active piece moving ahead faster than the front speed (-infinity: none), never behind the previous front.
double push_front_x(double bow_x_m, double foremost_moving_x_m, double previous_front_x_m, double ahead_m);

// Does an idle piece touching a piece with this velocity wake now? (by neighbour speed: |v| > V; never
// otherwise). An idle neighbour has v = 0, so the caller need not know whether the neighbour is active.
bool wakes_by_neighbour(const WakeRule& rule, const Vec3& neighbour_velocity_m_s);

// Do two spheres touch (centre distance below the sum of the radii)?
constexpr bool touching(double dx_m, double dy_m, double dz_m, double r1_m, double r2_m) {
  const double reach = r1_m + r2_m;
  return dx_m * dx_m + dy_m * dy_m + dz_m * dz_m < reach * reach;
}

// Membership at an update: is the piece idle afterwards? `first_update`: the run's first (fix brash/farfield
// also counts a resumed run's first; brash-ode restores the idle set exactly from its restart file). Ahead of
// the window a piece keeps its state, except at the first update, where it is idle when no faster than the
// wake speed, or by push front always.
bool idle_after_update(const WakeRule& rule, FarFieldZone zone, bool was_idle, bool first_update,
                       const Vec3& velocity_m_s);

// The moving window (speedups.window, fix brash/window): only the ice around the hull is in the scene. The
// undisturbed bed ahead is held out until the front reaches it, and the ice far behind the stern is removed.
struct MovingWindow {
  double remove_below_x_m = 0;  // a piece behind this leaves the scene for good
  double insert_below_x_m = 0;  // a held-out piece before this enters the scene (at rest, where it was)
};

// The window now: the front lies `ahead` beyond the bow and beyond the foremost piece that moves faster than the
// wake speed (the push: moving ice never meets the edge of the held-out bed), and never recedes (a piece that
// entered the scene stays); pieces more than `behind` behind the stern leave. No moving piece: -infinity.
MovingWindow moving_window(double stern_x_m, double bow_x_m, double foremost_moving_x_m, double previous_front_x_m,
                           double behind_m, double ahead_m);

}  // namespace brash::core
