#include "trace/prism_faces.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "math/polygon.hpp"
#include "trace/coplanar.hpp"

namespace impossible::trace {

PrismShape prism_shape(const layout::Room& room) {
    PrismShape s;
    s.corners = room.floor;
    s.winding = math::signed_area(room.floor) > 0.0 ? 1.0 : -1.0;
    s.lo = s.hi = room.floor.front();
    double largest = 0.0;
    for (const glm::dvec2& c : room.floor) {
        s.lo = glm::min(s.lo, c);
        s.hi = glm::max(s.hi, c);
        largest = std::max({largest, std::abs(c.x), std::abs(c.y)});
    }
    s.y0 = room.min.y;
    s.y1 = room.max.y;
    s.tolerance = 1e-9 * (1.0 + largest);
    const int count = layout::face_count(room);
    for (int f = 0; f < count; ++f) {
        const layout::FaceFrame frame = layout::face_frame(room, f);
        PrismFace face;
        face.normal = frame.normal;
        face.y = f == static_cast<int>(layout::Face::Ceiling) ? s.y1 : s.y0;
        RoomFace& surface = face.surface;
        surface.face = f < 2 ? static_cast<layout::Face>(f) : layout::Face::Floor;
        surface.color = room.face_color[static_cast<std::size_t>(f)];
        surface.texture = room.face_texture[static_cast<std::size_t>(f)];
        surface.texture_size = room.texture_size;
        surface.wall = layout::wall_of_face(room, f);
        if (surface.wall >= 0) {
            surface.wall_origin = frame.origin;
            surface.wall_s_axis = frame.s_axis;
        }
        face.frame = frame;
        s.faces.push_back(std::move(face));
    }
    return s;
}

bool cuts_prism_hole(const layout::FaceFrame& face, const math::PortalRect& rect) {
    if (!(glm::dot(rect.normal, face.normal) > 0.5)) return false;  // not facing into the room
    dvec3 corners[8];
    math::box_corners(rect, corners);  // the first four are the rectangle's
    const double eps = kHolePlaneTolerance;
    for (int k = 0; k < 4; ++k) {
        if (std::abs(glm::dot(corners[k] - face.origin, face.normal)) > eps) return false;
        if (!math::contains(face.outline, layout::to_face(face, corners[k]), eps)) return false;
    }
    return true;
}

int prism_hole_face(const PrismShape& prism, const math::PortalRect& rect) {
    for (std::size_t f = 0; f < prism.faces.size(); ++f)
        if (cuts_prism_hole(prism.faces[f].frame, rect)) return static_cast<int>(f);
    return -1;
}

namespace {

// The squared distance from p to the segment ab.
double segment_distance2(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double u = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec2 q = p - (a + u * ab);
    return glm::dot(q, q);
}

}  // namespace

bool in_prism_floor(const PrismShape& prism, double x, double z) {
    const double tol = prism.tolerance;
    if (!(x >= prism.lo.x - tol && x <= prism.hi.x + tol && z >= prism.lo.y - tol && z <= prism.hi.y + tol))
        return false;
    const std::vector<glm::dvec2>& poly = prism.corners;
    const std::size_t n = poly.size();
    bool inside = false;  // even–odd crossings of a ray towards +x
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const glm::dvec2 &a = poly[i], &b = poly[j];
        if ((a.y > z) != (b.y > z) && x < a.x + (z - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    if (inside) return true;
    const glm::dvec2 p(x, z);
    for (std::size_t i = 0, j = n - 1; i < n; j = i++)
        if (segment_distance2(p, poly[j], poly[i]) <= tol * tol) return true;
    return false;
}

namespace {

// The floor and the ceiling: as a box room's, over the polygon.
void hit_floor_and_ceiling(const Scene& scene, const PrismShape& prism, const dvec3& origin, const dvec3& dir,
                           const ClipPlane& clip, PrismHit& best, Tie& best_tie) {
    for (int f = 0; f < 2; ++f) {
        const PrismFace& face = prism.faces[static_cast<std::size_t>(f)];
        const double along = dir.y;
        if (!(along * face.normal.y < 0.0)) continue;  // seen from behind, or edge-on
        const double t = (face.y - origin.y) / along;
        if (!(t > 0.0 && t < best.t)) continue;
        const dvec3 p = origin + t * dir;
        if (!in_prism_floor(prism, p.x, p.z) || !clip.keeps(p)) continue;
        best = PrismHit{f, t, hole_at(face.surface, scene, p)};
        best_tie = face_tie(scene, best.portal, dir);
    }
}

// The ray's side of a corner in (x, z): cross(dir, corner - origin).
double corner_side(const glm::dvec2& corner, const dvec3& origin, const dvec3& dir) {
    return dir.x * (corner.y - origin.z) - dir.z * (corner.x - origin.x);
}

}  // namespace

PrismHit hit_prism_faces(const Scene& scene, const PrismShape& prism, const dvec3& origin, const dvec3& dir,
                         const ClipPlane& clip, double t_limit) {
    PrismHit best{-1, t_limit, -1};
    Tie best_tie;  // a wall's hit in a door's hole loses a tie to the floor (coplanar.hpp)
    hit_floor_and_ceiling(scene, prism, origin, dir, clip, best, best_tie);
    // Wall i meets the ray's line where the line separates its corners (or
    // passes through one): the sides are computed once per corner and shared
    // by the two walls that meet there, so a ray past a corner meets one of
    // them (or both, through the corner itself) and never slips between.
    const std::vector<glm::dvec2>& c = prism.corners;
    const std::size_t n = c.size();
    const double first = corner_side(c[0], origin, dir);
    double side_b = first;
    for (std::size_t i = 0; i < n; ++i) {
        const double side_a = side_b;
        side_b = i + 1 < n ? corner_side(c[i + 1], origin, dir) : first;
        if ((side_a > 0.0 && side_b > 0.0) || (side_a < 0.0 && side_b < 0.0)) continue;
        const glm::dvec2 a = c[i];
        const glm::dvec2 e = (i + 1 < n ? c[i + 1] : c[0]) - a;
        // cross(dir, e) in (x, z); the inward normal is winding · (-e.z, e.x),
        // so the wall faces the ray when winding · cross(dir, e) > 0.
        const double across = dir.x * e.y - dir.z * e.x;
        if (!(prism.winding * across > 0.0)) continue;  // seen from behind, or edge-on
        const double t = ((a.x - origin.x) * e.y - (a.y - origin.z) * e.x) / across;
        if (!(t > 0.0 && t < search_limit(best.t, best_tie))) continue;
        const dvec3 p = origin + t * dir;
        if (!(p.y >= prism.y0 && p.y <= prism.y1) || !clip.keeps(p)) continue;
        const int face = 2 + static_cast<int>(i);
        const int portal = hole_at(prism.faces[static_cast<std::size_t>(face)].surface, scene, p);
        const Tie tie = face_tie(scene, portal, dir);
        if (best.face >= 0 && !replaces(t, tie, best.t, best_tie)) continue;
        best = PrismHit{face, t, portal};
        best_tie = tie;
    }
    if (best.face < 0) best.t = 0.0;
    return best;
}

}  // namespace impossible::trace
