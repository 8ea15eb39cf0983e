// The portal box (layout-format.md, "The portal box"): the front rectangle in
// the portal's plane facing +n, and the four side faces and the back face
// facing inwards.
//
// The front is given as a grid of points so that a portal that is a hole in a
// wall can share the wall's vertices exactly: the wall, the front and the side
// faces then meet edge to edge, with no T-junction that could leave a crack.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "math/portal.hpp"
#include "scene/mesh_writer.hpp"

namespace impossible::scene {

// points[j * cols + i], i along the portal's right (r), j along its up (u);
// the corners (0,0), (cols-1,0), (cols-1,rows-1), (0,rows-1) are the front
// corners of math::box_corners in its order. cols, rows >= 1.
struct FrontGrid {
    int cols = 0;
    int rows = 0;
    std::vector<glm::vec3> points;

    const glm::vec3& at(int i, int j) const { return points[static_cast<std::size_t>(j * cols + i)]; }
};

// The plain front of a portal: its four box corners (a 2 × 2 grid), relative
// to out's origin.
FrontGrid corner_front(const MeshWriter& out, const math::PortalRect& rect);

// Appends the box of `rect` with the given front; the back corners are
// math::box_corners' (in float, relative to out's origin). Colour
// shading::kPortalFillColor, checker 0.
PortalMesh append_portal_box(MeshWriter& out, const math::PortalRect& rect, const FrontGrid& front);

// A mirror's or window's one-sided rectangle facing +n: the front alone,
// no inner faces (layout-format.md, "Mirrors and windows").
PortalMesh append_portal_front(MeshWriter& out, const math::PortalRect& rect, const FrontGrid& front);

}  // namespace impossible::scene
