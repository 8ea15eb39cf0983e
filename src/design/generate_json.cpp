// The generator's packing written as layout JSON: ids, colours, props, doors.
// A room that is an axis-aligned rectangle is a box room (min/max); any other
// (turned, L-shaped, a corridor) a prism room (floor polygon and y).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/decimetres.hpp"
#include "design/generate.hpp"
#include "design/pack_search.hpp"

namespace impossible::design {
namespace {

using nlohmann::ordered_json;

const char* const kNames[] = {"hall",    "library", "studio",  "garden",     "kitchen", "gallery",
                              "attic",   "cellar",  "chapel",  "workshop",   "pantry",  "parlour",
                              "nursery", "study",   "armoury", "observatory"};
constexpr int kNameCount = sizeof kNames / sizeof kNames[0];

std::string room_id(int i) {
    return i < kNameCount ? kNames[i] : std::string(kNames[i % kNameCount]) + "_" + std::to_string(i / kNameCount + 1);
}

// HSV to RGB, rounded to hundredths.
ordered_json hsv(double h, double s, double v) {
    h = (h - std::floor(h)) * 6.0;
    const int k = static_cast<int>(h) % 6;
    const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    return {cents(rgb[k][0]), cents(rgb[k][1]), cents(rgb[k][2])};
}

ordered_json vec(double a, double b, double c) { return {a, b, c}; }
double micro(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }

// Where a prop of floor size `s` (x, z) fits in the corner `k` of the room:
// the first spot along the corner's bisector with the whole box 2 cm inside.
std::optional<glm::dvec2> corner_spot(const math::Polygon2& room, std::size_t k, glm::dvec2 s) {
    const std::size_t n = room.size();
    const glm::dvec2 p = room[k], a = glm::normalize(room[(k + n - 1) % n] - p),
                     b = glm::normalize(room[(k + 1) % n] - p);
    if (a.x * b.y - a.y * b.x > -1e-9) return std::nullopt;  // a reflex or straight corner
    const glm::dvec2 bisector = glm::normalize(a + b);
    for (double r = 0.3; r <= 1.6; r += 0.05) {
        const glm::dvec2 lo = glm::dvec2(cents(p.x + bisector.x * r - s.x / 2), cents(p.y + bisector.y * r - s.y / 2));
        const glm::dvec2 hi = lo + s;
        bool fits = true;
        for (const glm::dvec2 c : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)})
            fits = fits && math::contains(room, c, 0.0) && math::distance_to_boundary(room, c) >= 0.02;
        for (const glm::dvec2& q : room) fits = fits && !(q.x > lo.x && q.x < hi.x && q.y > lo.y && q.y < hi.y);
        if (fits) return lo;
    }
    return std::nullopt;
}

// Corner props: one shape per room (by index), in corners at least 1 m from its doors.
ordered_json props(int index, const math::Polygon2& room, const std::vector<std::array<glm::dvec2, 2>>& doors,
                   double hue, std::uint64_t bits) {
    static const double kShape[4][3] = {{0.4, 2.4, 0.4}, {0.6, 0.6, 0.6}, {0.5, 1.2, 0.5}, {0.6, 0.9, 0.3}};
    const double* s = kShape[index % 4];
    ordered_json out = ordered_json::array();
    int placed = 0;
    const std::size_t corners = room.size();
    for (std::size_t c = 0; c < corners && placed < 1 + static_cast<int>(bits & 1); ++c) {
        const std::optional<glm::dvec2> lo = corner_spot(room, (c + (bits >> 1)) % corners, {s[0], s[2]});
        if (!lo) continue;
        bool clear = true;
        for (const auto& d : doors)
            for (const glm::dvec2 p : {d[0], (d[0] + d[1]) / 2.0, d[1]}) {
                const double dx = std::max({lo->x - p.x, 0.0, p.x - (lo->x + s[0])});
                const double dz = std::max({lo->y - p.y, 0.0, p.y - (lo->y + s[2])});
                if (std::hypot(dx, dz) < 1.0) clear = false;
            }
        if (!clear) continue;
        ordered_json prop;
        prop["box"] = {{"min", vec(lo->x, 0, lo->y)}, {"max", vec(cents(lo->x + s[0]), s[1], cents(lo->y + s[2]))}};
        prop["color"] = hsv(hue + 0.5 + 0.08 * placed, 0.65, 0.75);
        out.push_back(prop);
        ++placed;
    }
    return out;
}

ordered_json portal(const std::string& id, const std::string& room, glm::dvec2 c, glm::dvec2 n,
                    const std::string& target) {
    ordered_json p;
    p["id"] = id;
    p["room"] = room;
    p["center"] = vec(c.x, 1.05, c.y);
    p["normal"] = vec(micro(n.x), 0, micro(n.y));
    p["width"] = kPackDoorWidth;
    p["height"] = 2.1;
    p["target"] = target;
    return p;
}

// Where the walk starts in room 0: of a few points on its body, the one
// farthest from its walls, doors and props.
glm::dvec2 start_point(const RoomGeom& room, const std::vector<std::array<glm::dvec2, 2>>& doors,
                       const ordered_json& props) {
    const math::Polygon2& body = room.pieces[room.pieces.size() / 2];
    glm::dvec2 centre(0.0);
    for (const glm::dvec2& p : body) centre += p / static_cast<double>(body.size());
    glm::dvec2 best = centre;
    double clearance = -1.0;
    for (const glm::dvec2& corner : body)
        for (const double f : {0.0, 0.25, 0.5}) {
            const glm::dvec2 p(cents(centre.x + (corner.x - centre.x) * f),
                               cents(centre.y + (corner.y - centre.y) * f));
            double c = math::contains(room.outline, p, 0.0) ? math::distance_to_boundary(room.outline, p) : -1.0;
            for (const auto& d : doors) c = std::min(c, math::distance_to_segment(p, d[0], d[1]));
            for (const ordered_json& prop : props) {
                const ordered_json &lo = prop["box"]["min"], &hi = prop["box"]["max"];
                const double dx = std::max({lo[0].get<double>() - p.x, 0.0, p.x - hi[0].get<double>()});
                const double dz = std::max({lo[2].get<double>() - p.y, 0.0, p.y - hi[2].get<double>()});
                c = std::min(c, std::hypot(dx, dz));
            }
            if (c > clearance + 1e-9) clearance = c, best = p;
        }
    return best;
}

// The start's yaw: of the eight compass points, the one that looks furthest
// across room 0 (yaw 0 looks along -z, a positive yaw turns left).
double start_yaw(const RoomGeom& room, glm::dvec2 start) {
    double best = 0.0, reach = -1.0;
    for (int k = 0; k < 8; ++k) {
        const double yaw = 45.0 * k, a = yaw * 3.14159265358979323846 / 180.0;
        const glm::dvec2 d(-std::sin(a), -std::cos(a));
        for (const Interval& v : line_inside(room.outline, start, d))
            if (v.lo <= 1e-9 && v.hi > reach + 1e-9) reach = v.hi, best = yaw;
    }
    return best;
}

ordered_json room_json(int i, const RoomGeom& g, int height, const std::vector<std::array<glm::dvec2, 2>>& doors,
                       std::uint64_t prop_seed) {
    const double hue = 0.13 + 0.618034 * static_cast<double>(i);
    ordered_json room;
    room["id"] = room_id(i);
    if (g.box) {
        room["min"] = vec(g.lo.x, 0, g.lo.y);
        room["max"] = vec(g.hi.x, dm(height), g.hi.y);
    } else {
        ordered_json floor = ordered_json::array();
        for (const glm::dvec2& p : g.outline) floor.push_back({p.x, p.y});
        room["floor"] = floor;
        room["y"] = {0.0, dm(height)};
    }
    room["color"] = hsv(hue, 0.35, 0.88);
    room["face_colors"] = {{"floor", hsv(hue, 0.5, 0.45)}};
    if (i % 2 == 1) room["checker"] = 0.5;
    const std::uint64_t bits = (prop_seed >> (2 * (i % 30))) ^ static_cast<std::uint64_t>(i);
    room["props"] = props(i, g.outline, doors, hue, bits);
    return room;
}

}  // namespace

std::string layout_text(const GenerateOptions& o, const Packing& pk, const std::vector<int>& heights,
                        std::uint64_t prop_seed) {
    ordered_json j;
    j["format"] = "impossible-layout";
    j["version"] = 1;
    j["name"] = std::to_string(pk.rooms.size()) + " generated rooms (seed " + std::to_string(o.seed) + ")";
    char ratio[64];
    std::snprintf(ratio, sizeof ratio, "%.3f", pk.floor_area / math::area(o.play_area));
    j["_generated"] = std::string("impossible generate; rooms packed onto the play area and joined by coincident ") +
                      "doors, each inside it; expansion ratio " + ratio;
    if (o.rectangle) {
        j["play_area"] = {{"min", {o.play_area[0].x, o.play_area[0].y}}, {"max", {o.play_area[2].x, o.play_area[2].y}}};
    } else {
        ordered_json poly = ordered_json::array();
        for (const glm::dvec2& p : o.play_area) poly.push_back({p.x, p.y});
        j["play_area"] = {{"polygon", poly}};
    }
    std::vector<std::vector<std::array<glm::dvec2, 2>>> lines(pk.rooms.size());
    ordered_json portals = ordered_json::array();
    for (const PackedDoor& d : pk.doors) {
        const glm::dvec2 along(d.normal.y, -d.normal.x), half = along * (kPackDoorWidth / 2);
        const std::string ida = room_id(d.from), idb = room_id(d.to);
        portals.push_back(portal(ida + "_to_" + idb, ida, d.centre, d.normal, idb + "_from_" + ida));
        portals.push_back(portal(idb + "_from_" + ida, idb, d.centre, -d.normal, ida + "_to_" + idb));
        lines[d.from].push_back({d.centre - half, d.centre + half});
        lines[d.to].push_back({d.centre - half, d.centre + half});
    }
    ordered_json list = ordered_json::array();
    for (std::size_t i = 0; i < pk.rooms.size(); ++i)
        list.push_back(room_json(static_cast<int>(i), pk.rooms[i], heights[i], lines[i], prop_seed));
    const glm::dvec2 start = start_point(pk.rooms[0], lines[0], list[0]["props"]);
    j["start"] = {
        {"room", room_id(0)}, {"position", vec(start.x, 1.6, start.y)}, {"yaw_deg", start_yaw(pk.rooms[0], start)}};
    j["rooms"] = list;
    j["portals"] = portals;
    return j.dump(2) + "\n";
}

}  // namespace impossible::design
