// The generator's draft written as layout JSON: ids, colours, props, doors.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/decimetres.hpp"

#include "design/generate.hpp"

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

struct DoorPlace {
    glm::dvec2 centre;  // metres
    bool along_z;       // the door's width runs along z
};

// Corner props: one shape per room (by index), in corners at least 1 m from its doors.
ordered_json props(int index, const std::array<int, 5>& r, const std::vector<DoorPlace>& doors, double hue,
                   std::uint64_t bits) {
    static const double kShape[4][3] = {{0.4, 2.4, 0.4}, {0.6, 0.6, 0.6}, {0.5, 1.2, 0.5}, {0.6, 0.9, 0.3}};
    const double* s = kShape[index % 4];
    ordered_json out = ordered_json::array();
    int placed = 0;
    for (int c = 0; c < 4 && placed < 1 + static_cast<int>(bits & 1); ++c) {
        const int corner = static_cast<int>((c + (bits >> 1)) % 4);
        const bool hi_x = corner & 1, hi_z = corner & 2;
        const double x0 = hi_x ? dm(r[2]) - s[0] : dm(r[0]), z0 = hi_z ? dm(r[3]) - s[2] : dm(r[1]);
        bool clear = true;
        for (const DoorPlace& d : doors) {
            const glm::dvec2 half = d.along_z ? glm::dvec2(0, 0.45) : glm::dvec2(0.45, 0);
            for (const glm::dvec2 p : {d.centre - half, d.centre, d.centre + half}) {
                const double dx = std::max({x0 - p.x, 0.0, p.x - (x0 + s[0])});
                const double dz = std::max({z0 - p.y, 0.0, p.y - (z0 + s[2])});
                if (std::hypot(dx, dz) < 1.0) clear = false;
            }
        }
        if (!clear) continue;
        ordered_json prop;
        prop["box"] = {{"min", vec(cents(x0), 0, cents(z0))}, {"max", vec(cents(x0 + s[0]), s[1], cents(z0 + s[2]))}};
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
    p["normal"] = vec(n.x, 0, n.y);
    p["width"] = dm(kDoorWidth);
    p["height"] = 2.1;
    p["target"] = target;
    return p;
}

}  // namespace

std::string layout_text(const GenerateOptions& o, const std::vector<std::array<int, 5>>& rooms,
                        const std::vector<std::array<int, 4>>& doors, std::uint64_t prop_seed) {
    ordered_json j;
    j["format"] = "impossible-layout";
    j["version"] = 1;
    j["name"] = std::to_string(rooms.size()) + " generated rooms (seed " + std::to_string(o.seed) + ")";
    j["_generated"] = "impossible generate; rooms joined by coincident doors, each inside the play area";
    if (o.rectangle) {
        j["play_area"] = {{"min", {o.play_area[0].x, o.play_area[0].y}}, {"max", {o.play_area[2].x, o.play_area[2].y}}};
    } else {
        ordered_json poly = ordered_json::array();
        for (const glm::dvec2& p : o.play_area) poly.push_back({p.x, p.y});
        j["play_area"] = {{"polygon", poly}};
    }
    const auto& r0 = rooms[0];
    j["start"] = {
        {"room", room_id(0)}, {"position", vec(dm(r0[0] + r0[2]) / 2, 1.6, dm(r0[1] + r0[3]) / 2)}, {"yaw_deg", 0.0}};
    std::vector<std::vector<DoorPlace>> places(rooms.size());
    ordered_json portals = ordered_json::array();
    for (const auto& d : doors) {
        const auto& a = rooms[d[0]];
        const int side = d[2];
        const int wall = side == 0 ? a[0] : side == 1 ? a[2] : side == 2 ? a[1] : a[3];
        const bool along_z = side < 2;
        const glm::dvec2 c = along_z ? glm::dvec2(dm(wall), dm(d[3])) : glm::dvec2(dm(d[3]), dm(wall));
        const double out = side % 2 == 1 ? 1.0 : -1.0;  // A's outward direction along the wall's axis
        const glm::dvec2 n_a = along_z ? glm::dvec2(-out, 0) : glm::dvec2(0, -out);
        const std::string ida = room_id(d[0]), idb = room_id(d[1]);
        portals.push_back(portal(ida + "_to_" + idb, ida, c, n_a, idb + "_from_" + ida));
        portals.push_back(portal(idb + "_from_" + ida, idb, c, -n_a, ida + "_to_" + idb));
        places[d[0]].push_back({c, along_z});
        places[d[1]].push_back({c, along_z});
    }
    ordered_json list = ordered_json::array();
    for (std::size_t i = 0; i < rooms.size(); ++i) {
        const auto& r = rooms[i];
        const double hue = 0.13 + 0.618034 * static_cast<double>(i);
        ordered_json room;
        room["id"] = room_id(static_cast<int>(i));
        room["min"] = vec(dm(r[0]), 0, dm(r[1]));
        room["max"] = vec(dm(r[2]), dm(r[4]), dm(r[3]));
        room["color"] = hsv(hue, 0.35, 0.88);
        room["face_colors"] = {{"floor", hsv(hue, 0.5, 0.45)}};
        if (i % 2 == 1) room["checker"] = 0.5;
        const std::uint64_t bits = (prop_seed >> (2 * (i % 30))) ^ i;
        room["props"] = props(static_cast<int>(i), r, places[i], hue, bits);
        list.push_back(room);
    }
    j["rooms"] = list;
    j["portals"] = portals;
    return j.dump(2) + "\n";
}

}  // namespace impossible::design
