// Triangulation of a plane polygon with holes, for the faces of prism rooms
// (floor and ceiling, and walls with holes that are not upright in them):
// the GLU tessellator (libglu1-mesa, gluNewTess), on the CPU, no GL context.
// docs/choices.md says why that library.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>

namespace impossible::scene {

// A polygon's triangles: indices into `points`, which holds the contours'
// points in order, contour after contour, and then any point the
// tessellator had to add where edges cross or meet (none for a polygon whose
// holes lie inside it without touching it or each other).
struct Tessellation {
    std::vector<glm::dvec2> points;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise, no slivers (polygon_tess.cpp)
    int added = 0;                              // points added by the tessellator
};

// The region inside contours[0] (the outline) and outside every other contour
// (its holes), each contour in either winding. Points between two corners on
// an edge are kept as vertices of the triangles. Empty when the tessellator
// reports an error: with these callbacks, only for a coordinate beyond
// GLU_TESS_MAX_COORD (1e150), far past the loader's limits.
Tessellation tessellate(const std::vector<std::vector<glm::dvec2>>& contours);

}  // namespace impossible::scene
