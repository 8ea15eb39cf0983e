// The large grid layout; see large_layout.hpp.
#include "design/large_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <nlohmann/json.hpp>

#include "design/decimetres.hpp"

namespace impossible::design {
namespace {

using nlohmann::ordered_json;

constexpr int kSide = 40;  // dm: every room is kSide x kSide on the floor
constexpr int kHeight = 30;

struct Cell {
    int row = 0, column = 0;
    int x0() const { return kSide * row; }      // dm
    int z1() const { return -kSide * column; }  // dm; the room reaches from z1 - kSide to z1
};

Cell cell_of(int k) {
    const int row = k / kLargeRowLength, j = k % kLargeRowLength;
    return {row, row % 2 == 0 ? j : kLargeRowLength - 1 - j};
}

ordered_json colour(int k, double value) {
    // A hue per room (golden-ratio steps), as HSV with saturation 0.35.
    double h = std::fmod(k * 0.6180339887498949, 1.0) * 6.0;
    const int i = static_cast<int>(h) % 6;
    const double f = h - std::floor(h), s = 0.35, v = value;
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    return {cents(rgb[i][0]), cents(rgb[i][1]), cents(rgb[i][2])};
}

ordered_json box(const Cell& c, std::array<int, 6> local, const ordered_json& color) {
    // local: dm from the room's (-x, floor, -z) corner.
    const int x0 = c.x0(), z0 = c.z1() - kSide;
    return {{"box",
             {{"min", {dm(x0 + local[0]), dm(local[1]), dm(z0 + local[2])}},
              {"max", {dm(x0 + local[3]), dm(local[4]), dm(z0 + local[5])}}}},
            {"color", color}};
}

ordered_json room(int k) {
    const Cell c = cell_of(k);
    ordered_json r;
    r["id"] = "r" + std::to_string(k);
    r["min"] = {dm(c.x0()), 0.0, dm(c.z1() - kSide)};
    r["max"] = {dm(c.x0() + kSide), dm(kHeight), dm(c.z1())};
    r["color"] = colour(k, 0.85);
    r["face_colors"] = {{"floor", colour(k + 3, 0.45)}};
    if (k % 2 == 1) r["checker"] = 0.5;
    // Two corner boxes and a low one in the middle: clear of every door
    // (doors in z walls span 7.5..16.5 or 23.5..32.5 dm along x; doors in x
    // walls span 15.5..24.5 dm along z).
    const int tall = 8 + 2 * (k % 5);
    r["props"] = {box(c, {1, 0, 1, 6, tall, 6}, colour(k + 1, 0.5)),
                  box(c, {34, 0, 34, 39, 12, 39}, colour(k + 2, 0.6)),
                  box(c, {17, 0, 17, 23, 5, 23}, colour(k + 4, 0.7))};
    return r;
}

ordered_json portal(const std::string& id, int room, std::array<double, 3> centre, std::array<int, 3> normal,
                    const std::string& target) {
    return {{"id", id},         {"room", "r" + std::to_string(room)},
            {"center", centre}, {"normal", normal},
            {"width", 0.9},     {"height", 2.1},
            {"target", target}};
}

// The door pair from room k to room k + 1.
std::array<ordered_json, 2> doors(int k) {
    const Cell a = cell_of(k), b = cell_of(k + 1);
    const std::string out = "d" + std::to_string(k) + "_next", in = "d" + std::to_string(k + 1) + "_prev";
    if (a.row != b.row) {  // across the +x wall of a
        const std::array<double, 3> centre{dm(a.x0() + kSide), 1.05, dm(a.z1() - kSide / 2)};
        return {portal(out, k, centre, {-1, 0, 0}, in), portal(in, k + 1, centre, {1, 0, 0}, out)};
    }
    const int x = a.x0() + (k % 2 == 0 ? 12 : 28);
    const bool forward = b.column > a.column;  // b lies towards -z
    const int z = forward ? a.z1() - kSide : a.z1();
    const std::array<double, 3> centre{dm(x), 1.05, dm(z)};
    const int n = forward ? 1 : -1;  // into a
    return {portal(out, k, centre, {0, 0, n}, in), portal(in, k + 1, centre, {0, 0, -n}, out)};
}

}  // namespace

std::string large_layout_text(int rooms) {
    rooms = std::clamp(rooms, 1, kMaxLargeRooms);
    const int rows = (rooms + kLargeRowLength - 1) / kLargeRowLength;
    const int columns = std::min(rooms, kLargeRowLength);
    ordered_json head;
    head["format"] = "impossible-layout";
    head["version"] = 1;
    head["name"] = "Large layout: " + std::to_string(rooms) + " rooms in a chain";
    head["_comment"] = "Written by make_large_layout (src/design/large_layout.hpp); regenerate, do not edit.";
    head["play_area"] = {{"min", {0.0, dm(-kSide * columns)}}, {"max", {dm(kSide * rows), 0.0}}};
    head["start"] = {{"room", "r0"}, {"position", {0.6, 1.6, -0.4}}, {"yaw_deg", 0.0}};
    std::string text = head.dump();
    text.pop_back();  // the closing brace
    text += ",\n\"rooms\": [\n";
    for (int k = 0; k < rooms; ++k) text += room(k).dump() + (k + 1 < rooms ? ",\n" : "\n");
    text += "],\n\"portals\": [\n";
    for (int k = 0; k + 1 < rooms; ++k) {
        const auto pair = doors(k);
        text += pair[0].dump() + ",\n" + pair[1].dump() + (k + 2 < rooms ? ",\n" : "\n");
    }
    text += "]}\n";
    return text;
}

}  // namespace impossible::design
