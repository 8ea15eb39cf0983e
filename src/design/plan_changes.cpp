// Each change's pairs on the plan (layout-format.md, "Changes while
// walking"); see plan_parts.hpp.
#include <cmath>

#include "design/plan_parts.hpp"

namespace impossible::design::plan_parts {

namespace {

// Where a door stands on the physical floor: its floor line's middle.
glm::dvec2 door_spot(const layout::Layout& layout, const Report& r, int portal) {
    const layout::Portal& door = layout.portals[static_cast<std::size_t>(portal)];
    const auto line = door_line(door, r.placement.rooms[static_cast<std::size_t>(door.room)].to_physical);
    return 0.5 * (line[0] + line[1]);
}

}  // namespace

std::string reach_note(const layout::Layout& layout, const Report& r, std::size_t room, const char* unreachable) {
    if (r.placement.rooms[room].reachable) return "";
    const int after = room < r.changes.after_change.size() ? r.changes.after_change[room] : -1;
    if (after >= 0) return " (after " + layout.changes[static_cast<std::size_t>(after)].id + ")";
    return unreachable;
}

void add_changes(Drawing& d, const layout::Layout& layout, const Report& r) {
    // A change's pairs: a dashed line between the two doors of each pair,
    // or a dashed ring where they stand on one spot, with the change's id.
    for (const layout::Change& change : layout.changes) {
        for (const auto& pair : change.pairs) {
            const glm::dvec2 a = door_spot(layout, r, pair[0]), b = door_spot(layout, r, pair[1]);
            const std::string name = change.id + ": " + layout.portals[static_cast<std::size_t>(pair[0])].id + "/" +
                                     layout.portals[static_cast<std::size_t>(pair[1])].id;
            glm::dvec2 label = 0.5 * (a + b);
            if (glm::distance(a, b) < 0.3) {
                d.shapes.push_back(stroke("changes", name, circle(label, 0.3), kChangeColour, 0.035, true, true));
                label.y -= 0.38;
            } else {
                d.shapes.push_back(stroke("changes", name, {a, b}, kChangeColour, 0.035, false, true));
                for (const glm::dvec2& end : {a, b})
                    d.shapes.push_back(fill("changes", name, circle(end, 0.06), kChangeColour));
                label.y -= 0.12;
            }
            PlanShape text = fill("changes", name, {label}, kChangeColour);
            text.kind = PlanShape::Kind::Text;
            text.text = change.id;
            text.size = 0.18;
            d.shapes.push_back(text);
        }
    }
}

}  // namespace impossible::design::plan_parts
