// The blockers of a light image's legs (light_blockers.hpp).
#include "lights/light_blockers.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "layout/room_shape.hpp"
#include "lights/aperture_clip.hpp"
#include "math/rigid.hpp"

namespace impossible::lights {

using math::dmat4;
using math::dvec3;
using math::dvec4;

namespace {

// One leg of the image being given its blockers: the image's position in
// the leg's room's coordinates (the shadow ray's end, the light itself on
// the last leg), the light's range (0: none), and the map back to C's.
struct LbLeg {
    const BlockerSource& source;
    LightImage& image;
    int leg = 0;
    dvec3 light{0.0};
    double range = 0.0;
    dmat4 to_c{1.0};
};

// The distance from p to the rectangle (its front, depth 0).
double lb_rect_distance(const math::PortalRect& rect, const dvec3& p) {
    const dvec3 v = p - rect.center;
    const double a = std::max(std::abs(glm::dot(v, math::portal_right(rect))) - 0.5 * rect.width, 0.0);
    const double b = std::max(std::abs(glm::dot(v, rect.up)) - 0.5 * rect.height, 0.0);
    const double n = glm::dot(v, rect.normal);
    return std::sqrt(a * a + b * b + n * n);
}

// Whether a segment from a point of the room towards the light may cross
// the rectangle from its front (within the light's range): the light lies
// behind its plane or near it. The margins are far above float's rounding
// in the shader (1e-5 of the sizes; 1e-4 of the range, where the falloff's
// (d / range)⁴ is already past 1 in float), so that what is dropped is what
// the shader too finds never blocks.
bool lb_may_block(const LbLeg& leg, const math::PortalRect& rect) {
    const double margin = 1e-5 * (1.0 + glm::length(leg.light) + glm::length(rect.center));
    if (math::signed_distance(rect, leg.light) > margin) return false;
    return leg.range <= 0.0 || lb_rect_distance(rect, leg.light) < leg.range * (1.0 + 1e-4) + margin;
}

void lb_add(const LbLeg& leg, const math::PortalRect& rect, int portal, int wall = -1, int face = -1) {
    if (leg.source.cull && !lb_may_block(leg, rect)) return;
    leg.image.blockers.push_back({transform_rect(leg.to_c, rect), portal, leg.leg, wall, face});
}

// Wall i of a prism room as a rectangle (normal into the room, up +y).
math::PortalRect lb_wall_rect(const layout::Room& room, int i) {
    const layout::Wall w = layout::wall(room, i);
    const glm::dvec2 mid = 0.5 * (w.a + w.b);
    math::PortalRect rect;
    rect.center = dvec3(mid.x, 0.5 * (room.min.y + room.max.y), mid.y);
    rect.normal = dvec3(w.inward.x, 0.0, w.inward.y);
    rect.up = dvec3(0.0, 1.0, 0.0);
    rect.width = glm::length(w.b - w.a);
    rect.height = room.max.y - room.min.y;
    rect.depth = 0.0;
    return rect;
}

// The face of its room a portal is a hole in, or -1 (also for no portal).
int lb_hole_face(const BlockerSource& source, int portal) {
    return portal < 0 ? -1 : source.layout.portals[static_cast<std::size_t>(portal)].hole_face;
}

// Where a door the leg enters or leaves its room by reaches outside that
// room (a portal's rectangle may, layout-format.md, "The portal box"), the
// segment to a point of it there leaves the room first, through a face the
// tracer meets. A face plane that such a corner lies behind (by more than
// the hole rule's 1e-4 m) blocks the leg: in a convex room, or for a convex
// hull face of a prism (a floor, a ceiling, a wall that is not crossable),
// crossing the plane from inside is leaving the room. The face's rectangle
// is the whole plane for this (1e6 m), centred at the foot of the door's
// centre. Rooms whose doors stay inside them get none.
void lb_add_face_planes(const LbLeg& leg, const layout::Room& room, int room_index, int entry, int exit) {
    const BlockerSource& source = leg.source;
    const int entry_face = lb_hole_face(source, entry), exit_face = lb_hole_face(source, exit);
    constexpr double kOutside = 1e-4;
    std::vector<dvec3> corners;
    dvec3 centre(0.0);
    for (const int p : {entry, exit}) {
        if (p < 0) continue;
        const math::PortalRect& rect = source.layout.portals[static_cast<std::size_t>(p)].rect;
        const Polygon3 c = rect_polygon(rect, 0.0);
        corners.insert(corners.end(), c.begin(), c.end());
        centre = rect.center;
    }
    if (std::all_of(corners.begin(), corners.end(),
                    [&](const dvec3& c) { return layout::room_contains(room, c, kOutside); }))
        return;
    const std::vector<int>& crossable = source.crossable[static_cast<std::size_t>(room_index)];
    for (int f = 0; f < layout::face_count(room); ++f) {
        const int wall = layout::wall_of_face(room, f);
        if (wall >= 0 && std::find(crossable.begin(), crossable.end(), wall) != crossable.end()) continue;
        if (f == entry_face || f == exit_face) continue;
        const layout::FaceFrame frame = layout::face_frame(room, f);
        const bool behind = std::any_of(corners.begin(), corners.end(), [&](const dvec3& c) {
            return glm::dot(c - frame.origin, frame.normal) < -kOutside;
        });
        if (!behind) continue;
        math::PortalRect plane;
        plane.normal = frame.normal;
        plane.up = frame.t_axis;
        plane.center = centre - glm::dot(centre - frame.origin, frame.normal) * frame.normal;
        plane.width = plane.height = 1e6;
        plane.depth = 0.0;
        lb_add(leg, plane, -1, wall, f);
    }
}

// The free-standing portals of the leg's room, but for the portals the
// shadow ray enters and leaves that room by, and the walls of that room it
// may cross (a non-convex prism's), but for the walls those two portals are
// holes in (the leg only ends on them).
void lb_add_leg(const LbLeg& leg) {
    const BlockerSource& source = leg.source;
    const LightImage& image = leg.image;
    const int k = static_cast<int>(image.apertures.size());
    int entry = -1;
    if (leg.leg > 0) {
        const Aperture& in = image.apertures[static_cast<std::size_t>(leg.leg - 1)];
        entry = in.reflect ? in.portal : source.layout.portals[static_cast<std::size_t>(in.portal)].target;
    }
    const int exit = leg.leg < k ? image.apertures[static_cast<std::size_t>(leg.leg)].portal : -1;
    const int room = image.rooms[static_cast<std::size_t>(leg.leg)];
    for (const int p : source.links.room_portals[static_cast<std::size_t>(room)]) {
        const layout::Portal& portal = source.layout.portals[static_cast<std::size_t>(p)];
        if (portal.hole_face != -1 || p == entry || p == exit) continue;
        lb_add(leg, portal.rect, p);
    }
    const layout::Room& leg_room = source.layout.rooms[static_cast<std::size_t>(room)];
    const int entry_wall = layout::wall_of_face(leg_room, lb_hole_face(source, entry));
    const int exit_wall = layout::wall_of_face(leg_room, lb_hole_face(source, exit));
    for (const int w : source.crossable[static_cast<std::size_t>(room)]) {
        if (w == entry_wall || w == exit_wall) continue;
        lb_add(leg, lb_wall_rect(leg_room, w), -1, w);
    }
    lb_add_face_planes(leg, leg_room, room, entry, exit);
}

}  // namespace

void add_blockers(const BlockerSource& source, LightImage& image) {
    const layout::Light& light =
        source.layout.rooms[static_cast<std::size_t>(image.light_room)].lights[static_cast<std::size_t>(image.light)];
    for (std::size_t leg = 0; leg <= image.apertures.size(); ++leg) {
        const dmat4& to_room = image.to_room[leg];
        LbLeg l{source,
                image,
                static_cast<int>(leg),
                dvec3(to_room * dvec4(image.position, 1.0)),
                light.range,
                math::rigid_inverse(to_room)};
        lb_add_leg(l);
    }
}

}  // namespace impossible::lights
