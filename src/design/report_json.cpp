// The designer's report as one JSON document (`validate --json`).
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "design/report.hpp"

namespace impossible::design {
namespace {

using nlohmann::ordered_json;

// Rounded to a micrometre (or a thousandth of a percent), so that the
// document reads well and does not change with the last bits of rounding.
double rounded(double v) {
    const double r = std::round(v * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r;
}

ordered_json points(const math::Polygon2& poly) {
    ordered_json out = ordered_json::array();
    for (const glm::dvec2& p : poly) out.push_back({rounded(p.x), rounded(p.y)});
    return out;
}

std::optional<ordered_json> hands_json(const layout::HandShape& hands) {
    ordered_json j;
    if (hands.model) {
        j["shape"] = "gltf";
        j["gltf"] = hands.model->path;
        j["scale"] = hands.model->scale;
        return j;
    }
    const layout::HandShape standard;
    if (hands.box == standard.box && hands.color == standard.color) return std::nullopt;
    j["shape"] = "box";
    j["box"] = {rounded(hands.box.x), rounded(hands.box.y), rounded(hands.box.z)};
    j["color"] = {rounded(hands.color.r), rounded(hands.color.g), rounded(hands.color.b)};
    return j;
}

ordered_json summary_json(const layout::Layout& layout, const Report& r) {
    const layout::Summary& s = r.summary;
    ordered_json j;
    j["rooms"] = s.rooms;
    j["portals"] = s.portals;
    j["pairs"] = s.pairs;
    j["door_pairs"] = s.door_pairs;
    j["window_pairs"] = s.window_pairs;
    j["mirrors"] = s.mirrors;
    // Only with volumes, moving props or hands other than the default box,
    // so that the documents of other layouts stay as they were.
    if (s.volumes > 0) j["volumes"] = s.volumes;
    if (s.moving_props > 0) j["moving_props"] = s.moving_props;
    if (const auto hands = hands_json(layout.hands)) j["hands"] = *hands;
    j["floor_area"] = rounded(s.floor_area);
    if (layout.play_area) {
        ordered_json area;
        area["shape"] = layout.play_area->polygon.empty() ? "rectangle" : "polygon";
        area["corners"] = points(layout::outline(*layout.play_area));
        area["area"] = rounded(*s.play_area_area);
        j["play_area"] = area;
        j["expansion_ratio"] = rounded(*s.expansion_ratio);
    } else {
        j["play_area"] = nullptr;
        j["expansion_ratio"] = nullptr;
    }
    ordered_json outside = ordered_json::array();
    for (const std::string& id : s.rooms_outside_play_area) outside.push_back(id);
    j["rooms_outside_play_area"] = outside;  // in the rooms' own coordinates, as the summary says
    return j;
}

ordered_json rooms_json(const layout::Layout& layout, const Report& r) {
    std::vector<double> outside(layout.rooms.size(), 0.0);
    for (const RoomFinding& f : r.rooms_outside) outside[f.room] = f.outside_area;
    ordered_json rooms = ordered_json::array();
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        const RoomPlacement& p = r.placement.rooms[i];
        ordered_json room;
        room["id"] = layout.rooms[i].id;
        const int after = i < r.changes.after_change.size() ? r.changes.after_change[i] : -1;
        room["reachable"] = p.reachable || after >= 0;
        // Only for a room reachable only after a change: other documents stay as they were.
        if (after >= 0) room["reachable_after_change"] = layout.changes[static_cast<std::size_t>(after)].id;
        room["doors_from_start"] = p.reachable ? ordered_json(p.doors) : ordered_json(nullptr);
        room["entered_through"] = p.via >= 0 ? ordered_json(layout.portals[p.via].id) : ordered_json(nullptr);
        room["floor_area"] = rounded(math::area(r.floors[i]));
        room["physical_floor"] = points(r.floors[i]);
        room["area_outside_play_area"] = rounded(outside[i]);
        room["placed_consistently"] = !p.inconsistent;
        rooms.push_back(room);
    }
    return rooms;
}

// "lighting": the light depth, where frames are lit otherwise and why
// (the light paths' or the path rectangles' bound), and each room's lights
// and light paths.
ordered_json lighting_json(const layout::Layout& layout, const Report& r) {
    ordered_json lighting;
    lighting["light_depth"] = layout.light_depth;
    if (r.light_cut == lights::LightCut::Paths) {  // only then
        lighting["light_paths_truncated"] = true;
        lighting["light_paths_depth"] = r.light_paths_depth;
    }
    if (r.light_cut == lights::LightCut::Rects) {  // only then
        lighting["light_rects_truncated"] = true;
        lighting["light_paths_depth"] = r.light_paths_depth;
        if (r.lit_lights < r.lights) lighting["lit_lights"] = r.lit_lights;
    }
    ordered_json rooms = ordered_json::array();
    for (std::size_t i = 0; i < r.room_lights.size(); ++i) {
        ordered_json room;
        room["id"] = layout.rooms[i].id;
        room["lights"] = r.room_lights[i];
        room["light_paths"] = r.room_light_paths[i];
        rooms.push_back(room);
    }
    lighting["rooms"] = rooms;
    return lighting;
}

// Each door a prop blocks: the door, the prop (its room, index and id, and
// whether it is a moving prop where its motion leaves it) and the rooms
// behind it.
ordered_json blocked_json(const layout::Layout& layout, const Report& r) {
    ordered_json list = ordered_json::array();
    for (std::size_t i = 0; i < r.blocked.size(); ++i) {
        const BlockedDoor& b = r.blocked[i];
        ordered_json e;
        e["door"] = layout.portals[static_cast<std::size_t>(b.portal)].id;
        ordered_json prop;
        prop["room"] = layout.rooms[static_cast<std::size_t>(b.by.listed_room)].id;
        prop["index"] = b.by.prop;
        const std::string& id =
            layout::prop_id(layout.rooms[static_cast<std::size_t>(b.by.listed_room)].props[b.by.prop]);
        prop["id"] = id.empty() ? ordered_json(nullptr) : ordered_json(id);
        prop["resting"] = b.by.resting;
        prop["name"] = obstacle_name(layout, b.by);
        e["blocked_by"] = prop;
        ordered_json behind = ordered_json::array();
        for (const int room : r.behind_blocked[i]) behind.push_back(layout.rooms[static_cast<std::size_t>(room)].id);
        e["rooms_behind"] = behind;
        list.push_back(e);
    }
    return list;
}

// Each change: its id, condition, pairs, affected doors, whether it can
// happen and the rooms it makes reachable (design/report_changes.hpp).
ordered_json changes_json(const layout::Layout& layout, const Report& r) {
    ordered_json list = ordered_json::array();
    auto portal_id = [&layout](int p) { return layout.portals[static_cast<std::size_t>(p)].id; };
    for (std::size_t c = 0; c < layout.changes.size(); ++c) {
        const layout::Change& change = layout.changes[c];
        const ChangeReach& reach = r.changes.changes[c];
        ordered_json e;
        e["id"] = change.id;
        ordered_json when;
        if (change.when.enter >= 0) when["enter"] = layout.rooms[static_cast<std::size_t>(change.when.enter)].id;
        if (change.when.after >= 0) when["after"] = layout.changes[static_cast<std::size_t>(change.when.after)].id;
        if (change.when.time) when["time"] = *change.when.time;
        e["when"] = when;
        ordered_json pairs = ordered_json::array();
        for (const auto& pair : change.pairs) pairs.push_back({portal_id(pair[0]), portal_id(pair[1])});
        e["pairs"] = pairs;
        ordered_json affected = ordered_json::array();
        for (const int d : reach.affected) affected.push_back(portal_id(d));
        e["affected_doors"] = affected;
        e["can_happen"] = reach.can_happen;
        ordered_json rooms = ordered_json::array();
        for (const int room : reach.makes_reachable) rooms.push_back(layout.rooms[static_cast<std::size_t>(room)].id);
        e["makes_reachable"] = rooms;
        list.push_back(e);
    }
    return list;
}

}  // namespace

ordered_json report_json(const layout::Layout& layout, const Report& r,
                         const std::vector<layout::Diagnostic>& warnings) {
    ordered_json j;
    j["file"] = layout.source;
    j["name"] = layout.name;
    j["valid"] = true;
    j["summary"] = summary_json(layout, r);
    j["start_room"] = layout.rooms[layout.start.room].id;
    j["rooms"] = rooms_json(layout, r);
    ordered_json overlaps = ordered_json::array();
    for (const Overlap& o : r.overlaps) {
        ordered_json e;
        e["rooms"] = {layout.rooms[o.a].id, layout.rooms[o.b].id};
        e["area"] = rounded(o.area);
        e["percent"] = rounded(o.percent);
        e["limit_percent"] = o.limit;
        e["noticeable"] = o.noticeable;
        overlaps.push_back(e);
    }
    j["overlaps"] = overlaps;
    if (overlaps_truncated(r)) {  // only then, so that the documents of other layouts stay as they were
        j["overlaps_truncated"] = true;
        j["overlap_pairs"] = r.overlap_pairs;
        j["overlap_pairs_exact"] = r.overlaps_exact;
    }
    ordered_json unreachable = ordered_json::array();
    for (const int room : r.unreachable) unreachable.push_back(layout.rooms[room].id);
    j["unreachable_rooms"] = unreachable;
    ordered_json rooms_outside = ordered_json::array();
    for (const RoomFinding& f : r.rooms_outside) rooms_outside.push_back(layout.rooms[f.room].id);
    j["rooms_outside_play_area"] = rooms_outside;
    ordered_json doors_outside = ordered_json::array();
    for (const int p : r.doors_outside) doors_outside.push_back(layout.portals[p].id);
    j["doors_outside_play_area"] = doors_outside;
    j["blocked_doors"] = blocked_json(layout, r);
    if (!layout.changes.empty()) j["changes"] = changes_json(layout, r);  // only then
    // Only then: fixed layouts' documents stay as they were.
    if (layout.lighting == layout::Lighting::Lights) j["lighting"] = lighting_json(layout, r);
    ordered_json lines = ordered_json::array();
    for (const layout::Diagnostic& d : warnings) lines.push_back(d.str());
    for (const std::string& f : r.findings) lines.push_back(layout.source + ": " + f);
    j["warnings"] = lines;
    return j;
}

ordered_json errors_json(const std::string& file, const std::vector<layout::Diagnostic>& errors) {
    ordered_json j;
    j["file"] = file;
    j["valid"] = false;
    ordered_json list = ordered_json::array();
    for (const layout::Diagnostic& d : errors) {
        ordered_json e;
        e["file"] = d.file;
        e["line"] = d.line;
        e["column"] = d.column;
        e["message"] = d.message;
        list.push_back(e);
    }
    j["errors"] = list;
    return j;
}

}  // namespace impossible::design
