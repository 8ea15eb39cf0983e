// Rooms on the physical floor, breadth first from the start; see placement.hpp.
#include "design/placement.hpp"

#include <deque>

#include "layout/room_shape.hpp"
#include "math/rigid.hpp"

namespace impossible::design {

Placement place_rooms(const layout::Layout& layout) {
    Placement out;
    out.links = links::link_portals(layout);
    out.rooms.resize(layout.rooms.size());
    const int start = layout.start.room;
    if (start < 0 || static_cast<std::size_t>(start) >= layout.rooms.size()) return out;
    std::vector<math::dmat4> w(layout.rooms.size(), math::dmat4(1.0));  // physical → room
    out.rooms[start].reachable = true;
    std::deque<int> queue{start};
    while (!queue.empty()) {
        const int room = queue.front();
        queue.pop_front();
        out.order.push_back(room);
        for (const int p : out.links.room_portals[room]) {
            // Only doors are walked through; a window shows a room but leads nowhere.
            if (layout.portals[p].kind != layout::PortalKind::Door) continue;
            const int target = layout.portals[p].target;
            const int next = layout.portals[target].room;
            const math::dmat4 w_next = math::orthonormalize_rigid(out.links.transfer[p] * w[room]);
            RoomPlacement& placed = out.rooms[next];
            if (placed.reachable) {
                if (math::max_abs_difference(w_next, w[next]) > 1e-6) placed.inconsistent = true;
                continue;
            }
            placed.reachable = true;
            placed.parent = room;
            placed.via = p;
            placed.doors = out.rooms[room].doors + 1;
            w[next] = w_next;
            placed.to_physical = math::rigid_inverse(w_next);
            queue.push_back(next);
        }
    }
    return out;
}

glm::dvec2 to_floor(const math::dmat4& to_physical, const math::dvec3& p) {
    const math::dvec4 q = to_physical * math::dvec4(p, 1.0);
    return {q.x, q.z};
}

math::Polygon2 physical_floor(const layout::Room& room, const math::dmat4& m) {
    const double y = room.min.y;
    if (layout::is_prism(room)) {
        math::Polygon2 floor;
        for (const glm::dvec2& c : layout::floor_outline(room)) floor.push_back(to_floor(m, {c.x, y, c.y}));
        return floor;
    }
    math::Polygon2 floor = {to_floor(m, {room.min.x, y, room.min.z}), to_floor(m, {room.max.x, y, room.min.z}),
                            to_floor(m, {room.max.x, y, room.max.z}), to_floor(m, {room.min.x, y, room.max.z})};
    return floor;
}

std::array<glm::dvec2, 2> door_line(const layout::Portal& portal, const math::dmat4& m) {
    const math::PortalRect& r = portal.rect;
    const math::dvec3 half = math::portal_right(r) * (0.5 * r.width);
    return {to_floor(m, r.center - half), to_floor(m, r.center + half)};
}

}  // namespace impossible::design
