// A runtime's visibility mask (OpenXR's xrGetVisibilityMaskKHR) turned into
// the visible area the renderers mask by (math/hidden_area.hpp): a line loop
// or visible triangles in the eye's tangent space (the plane z = -1, x right,
// y up: the point (x, y) is the direction (x, y, -1)), mapped into the
// normalised image through the eye's angles and clipped to the image.
// docs/headsets.md, "Visibility masks".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "math/polygon.hpp"
#include "math/projection.hpp"

namespace impossible::math {

// The point of the normalised image (u from 0 at the left edge to 1 at the
// right, v from 0 at the top to 1 at the bottom) that looks along the
// tangent-space direction (t.x, t.y, -1) of an eye with angles `fov`:
// u = (x - tan left) / (tan right - tan left), v = (tan up - y) / (tan up - tan down).
glm::dvec2 tangent_to_image(const FovTangents& tangents, const glm::dvec2& t);

// `visible` ∩ the image [0, 1] × [0, 1]. A polygon inside the image (its
// corners within [0, 1]) comes back unchanged, bit for bit; one reaching past
// the image is clipped (Sutherland and Hodgman), its new corners clamped into
// [0, 1] and repeated corners dropped. Fewer than 3 corners, or no area: no
// part of it lies inside the image.
Polygon2 clip_to_image(const Polygon2& visible);

// The outline of the union of triangles `indices` (three a triangle) over
// `vertices`: one simple polygon, or the problem and the triangle it is
// found at. Vertices with equal coordinates are one vertex (a runtime may
// repeat them), so the triangles must meet edge to edge: each edge is shared
// by at most two triangles lying on its two sides, and the edges used once
// form one loop. Not accepted: a degenerate triangle (collinear corners), an
// index past the vertices, triangles that overlap, meet at a T-junction, or
// whose union has a hole or several pieces.
struct OutlineProblem {
    std::size_t triangle = 0;  // index of the triangle (of the first index: 3 × triangle)
    std::string message;
};
struct MeshOutline {
    Polygon2 outline;
    std::optional<OutlineProblem> problem;
};
MeshOutline triangles_outline(const std::vector<glm::dvec2>& vertices, const std::vector<std::uint32_t>& indices);

}  // namespace impossible::math
