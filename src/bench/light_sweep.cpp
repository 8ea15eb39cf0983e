#include "bench/light_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::bench {

bool inside_floor(const layout::Room& room, const glm::dvec3& p, double margin) {
    if (!layout::room_contains(room, p)) return false;
    return !layout::is_prism(room) || math::distance_to_boundary(layout::floor_outline(room), {p.x, p.z}) > margin;
}

layout::Layout with_lights(const layout::Layout& layout, int n) {
    layout::Layout out = layout;
    if (n < 0) {
        out.lighting = layout::Lighting::Fixed;
        for (layout::Room& room : out.rooms) room.lights.clear();
        return out;
    }
    out.lighting = layout::Lighting::Lights;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(n, 1)))));
    for (layout::Room& room : out.rooms) {
        room.lights.clear();
        // In a prism, the grid's points outside its floor are left out.
        const glm::dvec3 lo = room.min + 0.15 * (room.max - room.min);
        const glm::dvec3 extent = 0.7 * (room.max - room.min);
        for (int i = 0; i < n; ++i) {
            layout::Light light;
            light.position = {lo.x + (i % side + 0.5) * extent.x / side, room.min.y + 0.8 * (room.max.y - room.min.y),
                              lo.z + (i / side + 0.5) * extent.z / side};
            if (layout::is_prism(room) && !inside_floor(room, light.position)) continue;
            room.lights.push_back(light);
        }
        for (layout::Light& light : room.lights) light.intensity = 4.0 / static_cast<double>(room.lights.size());
    }
    return out;
}

}  // namespace impossible::bench
