// Object–door contact by convex clipping: the door's rectangle clipped by a
// box's six half-spaces, or each triangle clipped by the rectangle's slab
// (|x| <= w/2, |y| <= h/2, |z| <= 0 in the door's frame), all widened by the
// tolerance; whatever is left means the two meet.
#include "walk/object_meet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "math/rigid.hpp"

namespace impossible::walk {

namespace {

using math::dmat4;
using math::dvec3;
using math::dvec4;

dvec3 apply_point(const dmat4& m, const dvec3& p) { return dvec3(m * dvec4(p, 1.0)); }

// Keeps the part of the convex polygon `poly` where dot(plane, (p, 1)) >= 0
// (Sutherland–Hodgman: points on the plane stay, so touching survives).
void clip_by_plane(std::vector<dvec3>& poly, const dvec4& plane, std::vector<dvec3>& out) {
    out.clear();
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3& a = poly[i];
        const dvec3& b = poly[(i + 1) % n];
        const double da = glm::dot(dvec3(plane), a) + plane.w;
        const double db = glm::dot(dvec3(plane), b) + plane.w;
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    poly.swap(out);
}

// The six planes x >= lo.x, x <= hi.x, ... of a box, as (n, w) with
// dot(n, p) + w >= 0 inside.
std::array<dvec4, 6> box_planes(const dvec3& lo, const dvec3& hi) {
    return {dvec4(1, 0, 0, -lo.x), dvec4(-1, 0, 0, hi.x), dvec4(0, 1, 0, -lo.y),
            dvec4(0, -1, 0, hi.y), dvec4(0, 0, 1, -lo.z), dvec4(0, 0, -1, hi.z)};
}

bool clipped_nonempty(std::vector<dvec3> poly, const std::array<dvec4, 6>& planes) {
    std::vector<dvec3> scratch;
    for (const dvec4& plane : planes) {
        clip_by_plane(poly, plane, scratch);
        if (poly.empty()) return false;
    }
    return true;
}

bool box_meets_door(const ObjectSolid& box, const dmat4& to_cell, const math::PortalRect& door, double tol) {
    // The rectangle in the object's own coordinates, where the box is axis-aligned.
    const dmat4 to_object = math::rigid_inverse(to_cell);
    const dvec3 r = math::portal_right(door);
    const dvec3 u = door.up;
    const double hw = 0.5 * door.width;
    const double hh = 0.5 * door.height;
    std::vector<dvec3> rect = {
        apply_point(to_object, door.center - hw * r - hh * u), apply_point(to_object, door.center + hw * r - hh * u),
        apply_point(to_object, door.center + hw * r + hh * u), apply_point(to_object, door.center - hw * r + hh * u)};
    return clipped_nonempty(std::move(rect), box_planes(box.min - dvec3(tol), box.max + dvec3(tol)));
}

bool triangles_meet_door(const ObjectSolid& solid, const dmat4& to_cell, const math::PortalRect& door, double tol) {
    const dmat4 to_door = math::portal_frame_inverse(door) * to_cell;
    const double hw = 0.5 * door.width + tol;
    const double hh = 0.5 * door.height + tol;
    const std::array<dvec4, 6> slab = box_planes(dvec3(-hw, -hh, -tol), dvec3(hw, hh, tol));
    for (std::size_t i = 0; i + 2 < solid.triangles.size(); i += 3) {
        std::vector<dvec3> tri = {apply_point(to_door, solid.triangles[i]),
                                  apply_point(to_door, solid.triangles[i + 1]),
                                  apply_point(to_door, solid.triangles[i + 2])};
        // Most triangles lie wholly on one side of the plane or beside the rectangle.
        const auto side = [&](int axis, double limit) {
            return std::all_of(tri.begin(), tri.end(), [&](const dvec3& p) { return p[axis] > limit; }) ||
                   std::all_of(tri.begin(), tri.end(), [&](const dvec3& p) { return p[axis] < -limit; });
        };
        if (side(2, tol) || side(0, hw) || side(1, hh)) continue;
        if (clipped_nonempty(std::move(tri), slab)) return true;
    }
    return false;
}

}  // namespace

bool solid_meets_door(const ObjectSolid& solid, const dmat4& to_cell, const math::PortalRect& door) {
    const double tol = kMeetTolerance * (1.0 + glm::length(door.center));
    return solid.is_box ? box_meets_door(solid, to_cell, door, tol) : triangles_meet_door(solid, to_cell, door, tol);
}

bool solid_reaches_behind(const ObjectSolid& solid, const dmat4& to_cell, const math::PortalRect& door) {
    const double tol = kMeetTolerance * (1.0 + glm::length(door.center));
    const auto behind = [&](const dvec3& p) { return math::signed_distance(door, apply_point(to_cell, p)) < -tol; };
    if (!solid.is_box) return std::any_of(solid.triangles.begin(), solid.triangles.end(), behind);
    for (int k = 0; k < 8; ++k)
        if (behind(dvec3(k & 1 ? solid.max.x : solid.min.x, k & 2 ? solid.max.y : solid.min.y,
                         k & 4 ? solid.max.z : solid.min.z)))
            return true;
    return false;
}

}  // namespace impossible::walk
