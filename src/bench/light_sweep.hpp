// The lighting sweeps of `impossible bench` (issue 27): the same layout under
// the fixed light and with N lights in every room, the light depth, and the
// shadow maps' size, each measured in one run against the tracer.
#pragma once

#include "layout/layout.hpp"

namespace impossible::bench {

// The layout under "lighting": "lights" with `n` lights in every room (its
// own lights replaced): point lights on a grid 0.8 of the way up each room,
// kept 15 % of the room's size from its walls, white, their intensities
// summing to 4 per room so that a frame's brightness does not depend on n.
// n < 0: the layout under the fixed light (its lights dropped). A prism
// room (layout-format.md, "Rooms of any shape") keeps the grid's lights
// that stand inside its floor (farther than 5 cm from its walls), their
// intensities summing to 4.
layout::Layout with_lights(const layout::Layout& layout, int n);

// Whether a point lies in the room: its box, or over a prism's floor
// farther than `margin` from its walls (and within its height).
bool inside_floor(const layout::Room& room, const glm::dvec3& p, double margin = 0.05);

}  // namespace impossible::bench
