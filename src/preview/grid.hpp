// The physical-boundary grid: like a headset's guardian, the walls of the
// play area appear as a grid when the head comes within kGridDistance of an
// edge, more opaque the closer it is. Drawn over the scene (no depth test)
// for one eye, in physical coordinates seen by the physical eye: the same
// picture as the play area mapped by W and seen by the virtual eye.
#pragma once

#include "layout/layout.hpp"
#include "math/pose.hpp"
#include "preview/overlay.hpp"

namespace impossible::preview {

inline constexpr double kGridDistance = 0.5;  // m from an edge
inline constexpr double kGridSpacing = 0.25;  // m between grid lines
inline constexpr double kGridHeight = 2.5;    // m, top of the walls

// Opacity of the wall at distance d (negative outside): 0 at kGridDistance
// and beyond, rising to 1 at the edge and outside.
float grid_alpha(double distance);

// Appends the near walls' grid lines, in clip space of `projection · view(eye)`.
// Returns the number of walls drawn.
int add_boundary_grid(OverlayBatch& batch, const layout::PlayArea& area, const math::dvec3& physical_head,
                      const math::Eye& physical_eye, const math::dmat4& projection);

}  // namespace impossible::preview
