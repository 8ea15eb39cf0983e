// The numbers `impossible validate` prints about a valid layout.
#include <cstdio>

#include "layout/layout.hpp"

namespace impossible::layout {

Summary summarize(const Layout& layout) {
    Summary s;
    s.rooms = static_cast<int>(layout.rooms.size());
    s.portals = static_cast<int>(layout.portals.size());
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        // Count each linked pair once, at its first portal.
        const int target = layout.portals[i].target;
        if (target > static_cast<int>(i)) ++s.pairs;
    }
    for (const Room& room : layout.rooms) {
        s.floor_area += (room.max.x - room.min.x) * (room.max.z - room.min.z);
    }
    if (layout.play_area) {
        const PlayArea& area = *layout.play_area;
        s.play_area_area = (area.max.x - area.min.x) * (area.max.y - area.min.y);
        s.expansion_ratio = s.floor_area / *s.play_area_area;
        const double eps = 1e-9;
        for (const Room& room : layout.rooms) {
            // PlayArea's glm::dvec2 holds [x, z] as (x, y).
            const bool inside = room.min.x >= area.min.x - eps && room.max.x <= area.max.x + eps &&
                                room.min.z >= area.min.y - eps && room.max.z <= area.max.y + eps;
            if (!inside) s.rooms_outside_play_area.push_back(room.id);
        }
    }
    return s;
}

std::string summary_text(const Layout& layout, const Summary& summary) {
    char line[256];
    std::string out;
    if (!layout.name.empty()) out += "name: " + layout.name + "\n";
    out += "rooms: " + std::to_string(summary.rooms) + "\n";
    out += "portals: " + std::to_string(summary.portals) + "\n";
    out += "pairs: " + std::to_string(summary.pairs) + "\n";
    if (!summary.play_area_area) {
        out += "play area: none\n";
        std::snprintf(line, sizeof line, "floor area: %.2f m2\n", summary.floor_area);
        out += line;
        out += "expansion ratio: n/a (no play area)\n";
        return out;
    }
    std::snprintf(line, sizeof line, "play area: %.2f m2\n", *summary.play_area_area);
    out += line;
    out += "rooms outside the play area:";
    if (summary.rooms_outside_play_area.empty()) out += " none";
    for (const std::string& id : summary.rooms_outside_play_area) out += " " + id;
    out += "\n";
    std::snprintf(line, sizeof line, "floor area: %.2f m2\n", summary.floor_area);
    out += line;
    std::snprintf(line, sizeof line, "expansion ratio: %.3f\n", *summary.expansion_ratio);
    out += line;
    return out;
}

}  // namespace impossible::layout
