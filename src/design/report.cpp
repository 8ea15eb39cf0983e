// The designer's report: findings about a valid layout; see report.hpp.
#include "design/report.hpp"

#include <algorithm>
#include <cstdio>

#include "base/user_text.hpp"
#include "design/room_grid.hpp"
#include "lights/light_bound.hpp"
#include "lights/light_images.hpp"

namespace impossible::design {
namespace {

std::string fixed(double v, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

std::string ids(const layout::Layout& layout, const std::vector<int>& rooms) {
    if (rooms.empty()) return " none";
    std::string out;
    for (const int r : rooms) out += " " + layout.rooms[r].id;
    return out;
}

// Where the search for overlaps stopped early, if it did.
const char* const kSearchStopped = "the search stopped at its limit of pairs tested";

void count_lights(const layout::Layout& layout, Report& r) {
    if (layout.lighting != layout::Lighting::Lights) return;
    const links::PortalLinks& links = r.placement.links;  // linked once, by place_rooms
    // The paths frames are lit by: within the bound of both renderers.
    const lights::LightBound bound = lights::light_bound(layout, links);
    r.light_paths_depth = std::min(layout.light_depth, bound.depth);
    r.light_cut = lights::light_cut(bound, layout.light_depth);
    r.lit_lights = bound.lit_lights;
    r.lights = bound.lights;
    const std::vector<lights::RoomLights> images =
        lights::light_images(lights::with_lit_lights(layout, bound), links, r.light_paths_depth);
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        r.room_lights.push_back(static_cast<int>(layout.rooms[i].lights.size()));
        r.room_light_paths.push_back(i < images.size() ? static_cast<int>(images[i].images.size()) : 0);
    }
}

// "lighting: ..." and a line per room, for lit layouts only (the report of
// a "fixed" layout stays as it was).
std::string lights_text(const layout::Layout& layout, const Report& r) {
    if (layout.lighting != layout::Lighting::Lights) return "";
    std::string out = "lighting: lights, light depth " + std::to_string(layout.light_depth) + "\n";
    if (r.light_cut == lights::LightCut::Paths) {
        out += "  light paths: more than " + std::to_string(kMaxReportedLightPaths) +
               " in all rooms together; frames are lit at light depth " + std::to_string(r.light_paths_depth) +
               ", the deepest within that\n";
    } else if (r.light_cut == lights::LightCut::Rects && r.lit_lights < r.lights) {
        out += "  path rectangles: more than " + std::to_string(lights::kMaxLightRects) +
               " in all rooms together, even at light depth 0; frames are lit at light depth 0 by " +
               std::to_string(r.lit_lights) + " of the " + std::to_string(r.lights) + " lights\n";
    } else if (r.light_cut == lights::LightCut::Rects) {
        out += "  path rectangles: more than " + std::to_string(lights::kMaxLightRects) +
               " in all rooms together; frames are lit at light depth " + std::to_string(r.light_paths_depth) +
               ", the deepest within that\n";
    }
    for (std::size_t i = 0; i < r.room_lights.size(); ++i) {
        out += "  " + layout.rooms[i].id + ": " +
               count_of(static_cast<std::size_t>(r.room_lights[i]), "light", "lights") + ", " +
               count_of(static_cast<std::size_t>(r.room_light_paths[i]), "light path", "light paths") + "\n";
    }
    return out;
}

void find_outside(const layout::Layout& layout, Report& r) {
    if (!layout.play_area) return;
    const math::Polygon2 area = layout::outline(*layout.play_area);
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        const double room_area = math::area(r.floors[i]);
        // A convex floor (every box room's) is clipped as before; any other by the library.
        const double inside =
            is_convex(r.floors[i]) ? math::intersection_area(area, r.floors[i]) : intersection_area(area, r.floors[i]);
        const double outside = room_area - inside;
        if (outside > 1e-9 * (1.0 + room_area)) r.rooms_outside.push_back({static_cast<int>(i), outside});
    }
    for (std::size_t p = 0; p < layout.portals.size(); ++p) {
        const layout::Portal& portal = layout.portals[p];
        if (portal.kind != layout::PortalKind::Door) continue;  // not walked through
        const auto line = door_line(portal, r.placement.rooms[portal.room].to_physical);
        if (!math::segment_inside(area, line[0], line[1], 1e-9)) r.doors_outside.push_back(static_cast<int>(p));
    }
}

void find_blocked(const layout::Layout& layout, Report& r) {
    const GridOptions grid;
    r.blocked = blocked_doors(layout, room_obstacles(layout, r.placement.links, grid.head_height), grid.body_radius);
    r.behind_blocked.assign(r.blocked.size(), {});
    if (r.blocked.empty()) return;
    for (const int room : r.placement.order)
        if (const BlockedDoor* b = blocked_on_way(layout, r.placement, r.blocked, room))
            r.behind_blocked[static_cast<std::size_t>(b - r.blocked.data())].push_back(room);
}

// "door "east" is blocked by rooms[0].props[2] (table)".
std::string blocked_text(const layout::Layout& layout, const BlockedDoor& b) {
    return "door \"" + layout.portals[static_cast<std::size_t>(b.portal)].id + "\" is blocked by " +
           obstacle_name(layout, b.by);
}

void write_findings(const layout::Layout& layout, Report& r) {
    for (const int room : r.unreachable)
        r.findings.push_back("no door leads from the start to room \"" + layout.rooms[room].id + "\"");
    for (const Overlap& o : r.overlaps) {
        if (!o.noticeable) continue;
        r.findings.push_back("rooms \"" + layout.rooms[o.a].id + "\" and \"" + layout.rooms[o.b].id + "\" overlap by " +
                             fixed(o.percent, 1) + " % of the smaller floor (more than " + fixed(o.limit, 0) +
                             " % is likely to be noticed)");
    }
    if (overlaps_truncated(r))
        r.findings.push_back((r.overlaps_exact ? "" : "at least ") + std::to_string(r.overlap_pairs) +
                             " pairs of rooms overlap" +
                             (r.overlaps_exact ? "" : std::string(" (") + kSearchStopped + ")") +
                             "; the report lists the first " + std::to_string(r.overlaps.size()));
    for (const RoomFinding& f : r.rooms_outside)
        r.findings.push_back("room \"" + layout.rooms[f.room].id + "\" reaches " + fixed(f.outside_area, 2) +
                             " m2 outside the play area");
    for (const int p : r.doors_outside)
        r.findings.push_back("door \"" + layout.portals[p].id + "\" is not inside the play area");
    for (std::size_t i = 0; i < r.blocked.size(); ++i) {
        std::string line = blocked_text(layout, r.blocked[i]) + ": nobody walks through it";
        if (!r.behind_blocked[i].empty())
            line += ", so no tour reaches room" + std::string(r.behind_blocked[i].size() > 1 ? "s" : "");
        for (std::size_t k = 0; k < r.behind_blocked[i].size(); ++k)
            line += (k ? ", \"" : " \"") + layout.rooms[static_cast<std::size_t>(r.behind_blocked[i][k])].id + "\"";
        r.findings.push_back(line);
    }
    for (std::size_t i = 0; i < r.placement.rooms.size(); ++i)
        if (r.placement.rooms[i].inconsistent)
            r.findings.push_back("room \"" + layout.rooms[i].id +
                                 "\" is reached at different places on the floor by different doors"
                                 " (the first way is reported)");
}

// "5 of 5", and with rooms reachable only after a change "5 of 5 (2 only
// after a change: red_corridor after reroute, library after reroute)".
std::string reachable_text(const layout::Layout& layout, const Report& r) {
    std::string later;
    std::size_t count = r.placement.order.size(), after = 0;
    for (std::size_t i = 0; i < r.changes.after_change.size(); ++i) {
        const int c = r.changes.after_change[i];
        if (c < 0) continue;
        ++after;
        later +=
            (after > 1 ? ", " : "") + layout.rooms[i].id + " after " + layout.changes[static_cast<std::size_t>(c)].id;
    }
    count += after;
    std::string out = std::to_string(count) + " of " + std::to_string(layout.rooms.size());
    if (after > 0) out += " (" + std::to_string(after) + " only after a change: " + later + ")";
    return out;
}

// "changes: N" and a line per change: its condition, pairs and what it
// makes reachable (only for layouts with changes).
std::string changes_text(const layout::Layout& layout, const Report& r) {
    if (layout.changes.empty()) return "";
    std::string out = "changes: " + std::to_string(layout.changes.size()) + "\n";
    for (std::size_t c = 0; c < layout.changes.size(); ++c) {
        const layout::Change& change = layout.changes[c];
        const ChangeReach& reach = r.changes.changes[c];
        out += "  " + change.id + " (when " + condition_text(layout, change) + "): pairs";
        for (const auto& pair : change.pairs)
            out += " " + layout.portals[static_cast<std::size_t>(pair[0])].id + "/" +
                   layout.portals[static_cast<std::size_t>(pair[1])].id;
        out += "; makes reachable:" + ids(layout, reach.makes_reachable);
        if (!reach.can_happen) out += "; can never happen";
        out += "\n";
    }
    return out;
}

}  // namespace

Report make_report(const layout::Layout& layout) {
    Report r;
    r.summary = layout::summarize(layout);
    r.placement = place_rooms(layout);
    r.changes = changes_reach(layout);
    // A volume's target room is seen inside the volume, never walked into
    // (layout-format.md, "Volume portals"): not unreachable, and its
    // overlap with the room it shows in is the point, not a finding.
    std::vector<bool> seen_only(layout.rooms.size(), false);
    for (const layout::Volume& v : layout.volumes)
        if (!r.placement.rooms[static_cast<std::size_t>(v.target_room)].reachable)
            seen_only[static_cast<std::size_t>(v.target_room)] = true;
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        r.floors.push_back(physical_floor(layout.rooms[i], r.placement.rooms[i].to_physical));
        if (!r.placement.rooms[i].reachable && !r.changes.reachable[i] && !seen_only[i])
            r.unreachable.push_back(static_cast<int>(i));
    }
    Overlaps overlaps = room_overlaps(r.floors);
    r.overlaps = std::move(overlaps.listed);
    for (Overlap& o : r.overlaps)
        if (seen_only[static_cast<std::size_t>(o.a)] || seen_only[static_cast<std::size_t>(o.b)]) o.noticeable = false;
    r.overlap_pairs = overlaps.pairs;
    r.overlaps_exact = overlaps.exact;
    find_outside(layout, r);
    find_blocked(layout, r);
    write_findings(layout, r);
    count_lights(layout, r);
    return r;
}

std::string report_text(const layout::Layout& layout, const Report& r) {
    std::string out;
    out += "start room: " + layout.rooms[layout.start.room].id + "\n";
    out += "reachable rooms: " + reachable_text(layout, r) + "\n";
    out += "unreachable rooms:" + ids(layout, r.unreachable) + "\n";
    if (!r.blocked.empty()) {  // only then, so that other layouts' reports stay as they were
        std::vector<int> behind;
        for (std::size_t i = 0; i < r.blocked.size(); ++i) {
            out += "  " + blocked_text(layout, r.blocked[i]) + "\n";
            behind.insert(behind.end(), r.behind_blocked[i].begin(), r.behind_blocked[i].end());
        }
        out += "rooms behind blocked doors:" + ids(layout, behind) + "\n";
    }
    out += "overlaps (% of the smaller floor; unnoticed up to " + fixed(kSmallRoomLimit, 0) + " % for rooms up to " +
           fixed(kSmallRoomArea, 0) + " m2, " + fixed(kLargeRoomLimit, 0) + " % for larger, Suma et al. 2012):";
    if (r.overlaps.empty() && !overlaps_truncated(r)) out += " none";
    out += "\n";
    for (const Overlap& o : r.overlaps) {
        out += "  " + layout.rooms[o.a].id + " / " + layout.rooms[o.b].id + ": " + fixed(o.area, 2) + " m2, " +
               fixed(o.percent, 1) + " % (limit " + fixed(o.limit, 0) + " %)" + (o.noticeable ? " noticeable" : " ok") +
               "\n";
    }
    if (overlaps_truncated(r)) {
        const std::size_t more = r.overlap_pairs - r.overlaps.size();
        const std::string listed = "the report lists the first " + std::to_string(r.overlaps.size());
        if (r.overlaps_exact) {
            out += "  ... and " + std::to_string(more) + " more pairs (" + listed + ")\n";
        } else {
            out += "  ... and " + (more ? "at least " + std::to_string(more) + " more pairs" : "possibly more pairs") +
                   " (" + kSearchStopped + "; " + listed + ")\n";
        }
    }
    if (layout.play_area) {
        std::vector<int> rooms;
        for (const RoomFinding& f : r.rooms_outside) rooms.push_back(f.room);
        out += "rooms outside the play area as walked:" + ids(layout, rooms) + "\n";
        out += "doors outside the play area:";
        if (r.doors_outside.empty()) out += " none";
        for (const int p : r.doors_outside) out += " " + layout.portals[p].id;
        out += "\n";
    }
    out += changes_text(layout, r);
    out += lights_text(layout, r);
    out += "findings: " + std::to_string(r.findings.size()) + "\n";
    return out;
}

}  // namespace impossible::design
