// Volume portals (layout-format.md, "Volume portals"): their target rooms,
// overlaps between the volumes of a room, and volumes outside their room (its
// box, or its prism).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "base/user_text.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout::detail {

namespace {

// An oriented box: centre, unit axes and half extents along them.
struct OrientedBox {
    glm::dvec3 center{0.0};
    std::array<glm::dvec3, 3> axis{};
    glm::dvec3 half{0.0};
};

OrientedBox volume_box(const math::PortalRect& rect) {
    return {rect.center,
            {glm::cross(rect.up, rect.normal), rect.up, rect.normal},
            {rect.width / 2, rect.height / 2, rect.depth / 2}};
}

// A box room, or a prism room's bounding box.
OrientedBox room_box(const Room& room) {
    return {(room.min + room.max) / 2.0,
            {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)},
            (room.max - room.min) / 2.0};
}

double radius_along(const OrientedBox& box, const glm::dvec3& line) {
    double r = 0.0;
    for (int i = 0; i < 3; ++i) r += std::abs(glm::dot(box.axis[static_cast<std::size_t>(i)], line)) * box.half[i];
    return r;
}

double largest(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Whether the two closed boxes share interior: the separating-axis test on
// the 3 + 3 face axes and the 9 edge cross products. Boxes that only touch
// (within about 1e-9 of their size and place) do not overlap.
bool boxes_overlap(const OrientedBox& a, const OrientedBox& b) {
    const double tolerance =
        1e-9 * (1.0 + std::max({largest(a.center), largest(b.center), largest(a.half), largest(b.half)}));
    const glm::dvec3 between = b.center - a.center;
    const auto separates = [&](const glm::dvec3& line) {
        return std::abs(glm::dot(between, line)) >= radius_along(a, line) + radius_along(b, line) - tolerance;
    };
    for (const auto* box : {&a, &b}) {
        for (const glm::dvec3& line : box->axis) {
            if (separates(line)) return false;
        }
    }
    for (const glm::dvec3& p : a.axis) {
        for (const glm::dvec3& q : b.axis) {
            const glm::dvec3 line = glm::cross(p, q);
            const double length = glm::length(line);
            if (length < 1e-9) continue;  // parallel edges: a face axis decides
            if (separates(line / length)) return false;
        }
    }
    return true;
}

// The first portal (in file order) of each room, and the second: a volume
// that is the first portal of its target room is named only if no other is.
struct RoomPortals {
    int first = -1;
    int second = -1;
};

// The error of volume `i` whose target room holds portals: it names one.
void report_target_portals(Checker& check, std::size_t i, const PortalDraft& draft, const RoomPortals& held,
                           const std::vector<PortalDraft>& portals, const std::string& room_id) {
    const int self = static_cast<int>(i);
    const int other = held.first == self ? held.second : held.first;
    if (other >= 0) {
        const PortalDraft& p = portals[static_cast<std::size_t>(other)];
        check.error(draft.path / "target", "the room " + quote(room_id) + " has portals of its own (" +
                                               quote(p.portal.id) + ", " + p.path.display +
                                               "); a volume's target room must have none (no doors, mirrors, "
                                               "windows or volumes)");
    } else {
        check.error(draft.path / "target", "a volume cannot show its own room " + quote(room_id) +
                                               " (a volume's target room must have no portals, and the volume "
                                               "itself is one)");
    }
}

// Each volume's target, found by its room id, with no portals of its own.
void link_targets(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                  bool rooms_known) {
    const std::map<std::string, int> room_index = index_by_id(rooms);
    const std::map<std::string, int> portal_index = index_by_id(portals);
    std::vector<RoomPortals> held(rooms.size());
    for (std::size_t i = 0; i < portals.size(); ++i) {
        const int room = portals[i].portal.room;
        if (room < 0) continue;
        RoomPortals& h = held[static_cast<std::size_t>(room)];
        if (h.first < 0) {
            h.first = static_cast<int>(i);
        } else if (h.second < 0) {
            h.second = static_cast<int>(i);
        }
    }
    for (std::size_t i = 0; i < portals.size(); ++i) {
        PortalDraft& draft = portals[i];
        if (!draft.volume || !draft.target_id) continue;
        const auto it = room_index.find(*draft.target_id);
        if (it == room_index.end()) {
            if (!rooms_known) continue;
            const bool is_portal = portal_index.count(*draft.target_id) > 0;
            check.error(draft.path / "target", "no room has the id " + quote(*draft.target_id) +
                                                   (is_portal ? " (it is a portal's; a volume's target names a room)"
                                                              : " (a volume's target names a room)"));
            continue;
        }
        const RoomPortals& target = held[static_cast<std::size_t>(it->second)];
        if (target.first >= 0) {
            report_target_portals(check, i, draft, target, portals, *draft.target_id);
        } else {
            draft.target_room = it->second;
        }
    }
}

// Volumes of one room must not overlap (touching is allowed): a sweep along
// x over their bounding boxes, then the exact test. Each volume is reported
// once, at the later of the two.
void check_overlaps(Checker& check, const std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms) {
    struct Entry {
        std::size_t portal = 0;
        OrientedBox box;
        glm::dvec3 lo{0.0}, hi{0.0};
    };
    std::map<int, std::vector<Entry>> by_room;
    for (std::size_t i = 0; i < portals.size(); ++i) {
        const PortalDraft& d = portals[i];
        if (!d.volume || !d.rect_ok || d.portal.room < 0) continue;
        Entry e{i, volume_box(d.portal.rect)};
        glm::dvec3 reach(0.0);
        for (int k = 0; k < 3; ++k) reach += glm::abs(e.box.axis[static_cast<std::size_t>(k)]) * e.box.half[k];
        e.lo = e.box.center - reach;
        e.hi = e.box.center + reach;
        by_room[d.portal.room].push_back(e);
    }
    std::vector<bool> reported(portals.size(), false);
    for (auto& [room, list] : by_room) {
        std::sort(list.begin(), list.end(), [](const Entry& x, const Entry& y) { return x.lo.x < y.lo.x; });
        for (std::size_t i = 0; i < list.size(); ++i) {
            for (std::size_t j = i + 1; j < list.size() && list[j].lo.x < list[i].hi.x; ++j) {
                const std::size_t first = std::min(list[i].portal, list[j].portal);
                const std::size_t later = std::max(list[i].portal, list[j].portal);
                if (reported[later] || reported[first]) continue;
                if (list[j].lo.y >= list[i].hi.y || list[i].lo.y >= list[j].hi.y) continue;
                if (list[j].lo.z >= list[i].hi.z || list[i].lo.z >= list[j].hi.z) continue;
                if (!boxes_overlap(list[i].box, list[j].box)) continue;
                reported[later] = true;
                check.error(portals[later].path / "center",
                            "the volume overlaps the volume " + quote(portals[first].portal.id) + " (portals[" +
                                std::to_string(first) + "]) in the room " +
                                quote(rooms[static_cast<std::size_t>(room)].room.id) +
                                " (the volumes of a room must not overlap; touching is allowed)");
            }
        }
    }
}

// The convex hull of points in the plane (Andrew's monotone chain),
// counter-clockwise, without collinear points.
math::Polygon2 convex_hull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    math::Polygon2 hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k > 0 ? k - 1 : 0);
    return hull;
}

// Whether the volume's box shares interior with a prism room: the part of
// the box between the floor and the ceiling (each moved in by the
// tolerance, so a box that only touches them stays out), seen from above,
// overlaps the floor polygon by more than a sliver.
bool volume_meets_prism(const OrientedBox& box, const Room& room) {
    const double tolerance = 1e-9 * (1.0 + std::max(largest(box.center), largest(box.half)));
    const double y0 = room.min.y + tolerance, y1 = room.max.y - tolerance;
    std::array<glm::dvec3, 8> corner{};
    for (std::size_t i = 0; i < 8; ++i) {
        corner[i] = box.center;
        for (std::size_t a = 0; a < 3; ++a) {
            corner[i] +=
                box.axis[a] * (((i >> a) & 1u) != 0 ? box.half[static_cast<int>(a)] : -box.half[static_cast<int>(a)]);
        }
    }
    std::vector<glm::dvec2> points;
    for (std::size_t i = 0; i < 8; ++i) {
        const glm::dvec3& p = corner[i];
        if (p.y >= y0 && p.y <= y1) points.push_back({p.x, p.z});
        for (std::size_t a = 0; a < 3; ++a) {  // the edges from corner i to a corner further along one axis
            const std::size_t j = i | (1u << a);
            if (j == i) continue;
            const glm::dvec3& q = corner[j];
            for (const double y : {y0, y1}) {
                if ((p.y - y) * (q.y - y) < 0.0) {
                    const glm::dvec3 m = p + (q - p) * ((y - p.y) / (q.y - p.y));
                    points.push_back({m.x, m.z});
                }
            }
        }
    }
    if (points.size() < 3) return false;
    const math::Polygon2 hull = convex_hull(points);
    if (hull.size() < 3) return false;
    return math::intersection_area(room.floor, hull) > tolerance * (1.0 + std::sqrt(math::area(hull)));
}

// A volume wholly outside its room's box (or prism) is seen from nowhere in
// the room: a warning (partly outside is fine: it shows its target through
// the walls).
void warn_outside(Checker& check, const std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms) {
    for (const PortalDraft& d : portals) {
        if (!d.volume || !d.rect_ok || d.portal.room < 0) continue;
        const RoomDraft& room = rooms[static_cast<std::size_t>(d.portal.room)];
        if (!room.shape_ok) continue;
        const OrientedBox box = volume_box(d.portal.rect);
        const bool meets =
            boxes_overlap(box, room_box(room.room)) && (!is_prism(room.room) || volume_meets_prism(box, room.room));
        if (meets) continue;
        check.warning(d.path / "center", "the volume lies wholly outside its room " + quote(room.room.id) +
                                             ", so nothing in the room is seen through it");
    }
}

}  // namespace

void link_volumes(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                  bool rooms_known) {
    link_targets(check, portals, rooms, rooms_known);
    check_overlaps(check, portals, rooms);
    warn_outside(check, portals, rooms);
}

}  // namespace impossible::layout::detail
