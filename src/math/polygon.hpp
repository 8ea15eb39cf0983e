// Simple polygons on the floor plane (pure 2D geometry, no GL, no I/O).
//
// A floor point is glm::dvec2 (x, z): the layout's x and z in metres. A
// polygon is its corners in order, either winding, without repeating the
// first corner at the end. "Simple" means no two edges meet except adjacent
// edges at their shared corner, and no corner repeats.
//
// Clipping is Sutherland and Hodgman's (1974, "Reentrant polygon clipping",
// CACM 17(1)): clipping any polygon by a convex one gives a polygon whose area
// is exactly the area of the intersection (possibly with zero-width bridges,
// which add no area), which is all the area-based tests below need.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace impossible::math {

using Polygon2 = std::vector<glm::dvec2>;

// Twice the signed area is the shoelace sum; positive counter-clockwise in
// (x, z) axes drawn with x right and z up.
double signed_area(const Polygon2& poly);
double area(const Polygon2& poly);  // |signed_area|

// The four corners of an axis-aligned rectangle, counter-clockwise.
Polygon2 rectangle(const glm::dvec2& min, const glm::dvec2& max);

// Inside or on the boundary (within `tolerance` of an edge).
bool contains(const Polygon2& poly, const glm::dvec2& p, double tolerance = 1e-9);

// Distance from p to the nearest edge (0 on the boundary).
double distance_to_boundary(const Polygon2& poly, const glm::dvec2& p);
double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

// Whether the closed segments ab and cd share a point.
bool segments_intersect(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d);

// What makes a polygon not simple, or nothing. `corner` is the index of the
// corner (or of the first corner of the edge) the problem is found at.
struct PolygonProblem {
    int corner = 0;
    std::string message;
};
std::optional<PolygonProblem> simple_polygon_problem(const Polygon2& poly);

// The part of `subject` inside the convex polygon `convex` (either winding).
Polygon2 clip_to_convex(const Polygon2& subject, const Polygon2& convex);

// Area of the intersection of any polygon with a convex one.
double intersection_area(const Polygon2& poly, const Polygon2& convex);

// Whether the convex polygon lies inside `poly`: its area outside `poly` is
// at most `tolerance` m².
bool convex_inside(const Polygon2& convex, const Polygon2& poly, double tolerance = 1e-9);

// Whether the whole segment ab lies inside `poly` (edges included).
bool segment_inside(const Polygon2& poly, const glm::dvec2& a, const glm::dvec2& b, double tolerance = 1e-9);

}  // namespace impossible::math
