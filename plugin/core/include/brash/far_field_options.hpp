// The far-field wake rule's choice, one definition for the core (brash/core/far_field.hpp), the case file
// (speedups.farfield_wake_by) and the engines (fix brash/farfield, brash-ode --cull).
#pragma once
#include <string_view>

namespace brash {

// What wakes an idle piece (docs/performance.md, "The idle far field"):
//   Force: the horizontal force on it exceeds a fraction of a piece's weight. Idle-idle contacts are not
//     computed, so a resting piece next to active ones feels an unbalanced force and wakes: on a bed at rest
//     the wake runs through the whole bed.
//   NeighbourSpeed: an active piece touching it moves faster than the wake speed. A resting bed stays idle;
//     the push wakes the ice it moves.
//   PushFront: ahead of the bow no wake: the window's front follows the push (it lies the window's distance
//     ahead of the foremost piece moving ahead faster than the front speed, and never recedes; the bed ahead
//     is idle from the start), so the push always meets active ice; beside the hull and behind the stern, by
//     force.
enum class WakeBy { Force, NeighbourSpeed, PushFront };

constexpr std::string_view to_string(WakeBy w) {
  switch (w) {
    case WakeBy::Force: return "force";
    case WakeBy::NeighbourSpeed: return "neighbour_speed";
    case WakeBy::PushFront: return "push_front";
  }
  return "force";
}

}  // namespace brash
