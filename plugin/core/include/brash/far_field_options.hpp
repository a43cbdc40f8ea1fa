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
enum class WakeBy { Force, NeighbourSpeed };

constexpr std::string_view to_string(WakeBy w) { return w == WakeBy::Force ? "force" : "neighbour_speed"; }

}  // namespace brash
