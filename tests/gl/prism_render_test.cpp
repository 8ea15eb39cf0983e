// Prism rooms (layout-format.md, "Rooms of any shape") drawn by the
// rasteriser and traced, at 0 id mismatches in both clip modes: an eye 1 mm
// from a slanted wall, an eye in a door box in a slanted wall, a door in a
// concave corner's wall seen past the corner, a trapdoor from above and from
// below, grazing views along a curved corridor, an L-shaped room and a
// turned room. The layouts are written as layout files (so the loader
// decides the holes) from polygons computed here.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

using Floor = std::vector<glm::dvec2>;

constexpr double kPrismPi = 3.14159265358979323846;

std::string prism_num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string prism_vec(glm::dvec3 v) {
    return "[" + prism_num(v.x) + ", " + prism_num(v.y) + ", " + prism_num(v.z) + "]";
}

// A layout file's text, put together from rooms and portals as JSON.
struct PrismText {
    std::vector<std::string> rooms, portals;
    std::string start_room;
    glm::dvec3 start{0.0};

    bool lit = false;

    void prism(const std::string& id, const Floor& floor, double y0, double y1, double checker = 0.0,
               const std::string& extra = "") {
        std::string s = "{\"id\": \"" + id + "\", \"floor\": [";
        for (std::size_t k = 0; k < floor.size(); ++k)
            s += (k ? ", [" : "[") + prism_num(floor[k].x) + ", " + prism_num(floor[k].y) + "]";
        s += "], \"y\": [" + prism_num(y0) + ", " + prism_num(y1) + "], \"color\": [0.7, 0.65, 0.6]";
        s += ", \"face_colors\": {\"floor\": [0.3, 0.35, 0.5], \"ceiling\": [0.9, 0.9, 0.85], \"wall0\": [0.8, 0.3, "
             "0.2]}";
        if (checker > 0.0) s += ", \"checker\": " + prism_num(checker);
        rooms.push_back(s + extra + "}");
    }
    void box(const std::string& id, glm::dvec3 min, glm::dvec3 max, const std::string& extra = "") {
        rooms.push_back("{\"id\": \"" + id + "\", \"min\": " + prism_vec(min) + ", \"max\": " + prism_vec(max) +
                        ", \"color\": [0.4, 0.7, 0.45], \"checker\": 0.5" + extra + "}");
    }
    void door(const std::string& id, const std::string& room, glm::dvec3 centre, glm::dvec3 normal, double width,
              double height, const std::string& target, glm::dvec3 up = {0, 1, 0}) {
        portals.push_back("{\"id\": \"" + id + "\", \"room\": \"" + room + "\", \"center\": " + prism_vec(centre) +
                          ", \"normal\": " + prism_vec(normal) + ", \"up\": " + prism_vec(up) +
                          ", \"width\": " + prism_num(width) + ", \"height\": " + prism_num(height) +
                          ", \"target\": \"" + target + "\"}");
    }
    layout::Layout load() const {
        std::string s = "{\"format\": \"impossible-layout\", \"version\": 1, \"start\": {\"room\": \"" + start_room +
                        "\", \"position\": " + prism_vec(start) + "}, ";
        if (lit) s += "\"lighting\": \"lights\", ";
        s += "\"rooms\": [";
        for (std::size_t k = 0; k < rooms.size(); ++k) s += (k ? ", " : "") + rooms[k];
        s += "], \"portals\": [";
        for (std::size_t k = 0; k < portals.size(); ++k) s += (k ? ", " : "") + portals[k];
        return testing::layout_from_text(s + "]}");
    }
};

double prism_signed_area(const Floor& f) {
    double a = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const glm::dvec2 p = f[i], q = f[(i + 1) % f.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

// Wall i's inward normal [x, 0, z] and the point `along` of the way from
// corner i to corner i + 1 at height y.
glm::dvec3 wall_normal(const Floor& f, std::size_t i) {
    const glm::dvec2 d = glm::normalize(f[(i + 1) % f.size()] - f[i]);
    const double sign = prism_signed_area(f) > 0.0 ? 1.0 : -1.0;
    return {-sign * d.y, 0.0, sign * d.x};
}
glm::dvec3 wall_point(const Floor& f, std::size_t i, double along, double y) {
    const glm::dvec2 p = f[i] + along * (f[(i + 1) % f.size()] - f[i]);
    return {p.x, y, p.y};
}

// The yaw that looks along `dir` (yaw 0 looks along -z, positive turns left).
double yaw_along(glm::dvec3 dir) { return std::atan2(-dir.x, -dir.z) * 180.0 / kPrismPi; }

// The head's right (ipd direction) for a yaw.
glm::dvec3 prism_right(double yaw) {
    const double y = yaw * kPrismPi / 180.0;
    return {std::cos(y), 0.0, -std::sin(y)};
}

// A frame whose left eye (ipd 0.064) stands at `eye`.
render::FrameDesc prism_frame(const layout::Layout& l, const char* room, glm::dvec3 eye, double yaw, double pitch = 0.0,
                              double fov = 90.0) {
    render::FrameDesc f;
    f.head.position = eye + 0.5 * f.ipd * prism_right(yaw);
    f.head.yaw_deg = yaw;
    f.head.pitch_deg = pitch;
    f.room = layout::find_room(l, room);
    f.fov_y_deg = fov;
    f.eye_width = 192;
    f.eye_height = 128;
    return f;
}

// Renders and traces `f` in both clip modes; the id mismatches, summed.
// With `through`, the traced view must show another room (a door seen).
int prism_mismatches(const layout::Layout& l, render::FrameDesc f, const char* what, bool through = true) {
    int sum = 0;
    for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
        f.clip = clip;
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        EXPECT_FALSE(image::incomparable(raster, traced));
        const image::Comparison c = image::compare_pictures(raster, traced);
        const char* mode = clip == render::ClipMode::Oblique ? " (oblique)" : " (clip plane)";
        std::printf("  %-44s%-13s %s\n", what, mode, image::summary_line(c).c_str());
        EXPECT_EQ(c.id_mismatches, 0) << what << mode;
        // The same surfaces, shaded alike, away from silhouette edges.
        EXPECT_GE(c.interior_psnr_db, 40.0) << what << mode;
        const auto own = static_cast<std::uint8_t>(f.room + 1);
        const bool other =
            std::any_of(traced.ids.begin(), traced.ids.end(), [&](std::uint8_t id) { return id != own; });
        if (through) {
            EXPECT_TRUE(other) << what << ": no door in sight";
        }
        sum += static_cast<int>(c.id_mismatches);
    }
    return sum;
}

// A rectangle 5 × 4 turned 30 degrees, with a door in its slanted wall 0
// into a box room.
const Floor kTurned = [] {
    Floor f;
    const double c = std::cos(kPrismPi / 6), s = std::sin(kPrismPi / 6);
    for (const glm::dvec2 p : {glm::dvec2(-2.5, -2), glm::dvec2(2.5, -2), glm::dvec2(2.5, 2), glm::dvec2(-2.5, 2)})
        f.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
    return f;
}();

layout::Layout turned_layout() {
    PrismText t;
    t.prism("turned", kTurned, 0.0, 3.0, 0.4);
    t.box("box", {-2, 0, -2}, {2, 3, 2});
    t.door("slanted", "turned", wall_point(kTurned, 0, 0.5, 1.1), wall_normal(kTurned, 0), 1.0, 2.2, "back");
    t.door("back", "box", {0, 1.1, -2}, {0, 0, 1}, 1.0, 2.2, "slanted");
    t.start_room = "turned";
    t.start = {0, 1.6, 0};
    return t.load();
}

TEST(PrismRender, EyeAMillimetreFromASlantedWall) {
    const layout::Layout l = turned_layout();
    const glm::dvec3 n = wall_normal(kTurned, 0);
    const glm::dvec3 along = glm::normalize(wall_point(kTurned, 0, 1, 0) - wall_point(kTurned, 0, 0, 0));
    // Facing the wall, the left eye 1 mm from it and 0.5 mm inside the
    // door's edge (the door spans along = 0.5 ± 0.1 of the 5 m wall).
    const glm::dvec3 edge = wall_point(kTurned, 0, 0.4, 1.2) + 0.0005 * along;
    int sum = prism_mismatches(l, prism_frame(l, "turned", edge + 0.001 * n, yaw_along(-n)), "1 mm, facing the wall");
    // Looking along the wall, 60 and 80 degrees from its normal, towards the
    // door 20 cm ahead, the left eye 1 mm from the wall: the way along the
    // wall that keeps the right eye in the room.
    for (const double deg : {60.0, 80.0}) {
        const double a = deg * kPrismPi / 180.0;
        glm::dvec3 s = along;
        if (glm::dot(prism_right(yaw_along(-std::cos(a) * n + std::sin(a) * s)), n) < 0.0) s = -s;
        const double yaw = yaw_along(-std::cos(a) * n + std::sin(a) * s);
        const glm::dvec3 eye = wall_point(kTurned, 0, 0.5, 1.5) - 0.7 * s + 0.001 * n;
        char what[64];
        std::snprintf(what, sizeof what, "1 mm, %.0f deg from the normal", deg);
        sum += prism_mismatches(l, prism_frame(l, "turned", eye, yaw, deg > 70.0 ? -10.0 : 0.0), what);
    }
    EXPECT_EQ(sum, 0);
}

TEST(PrismRender, OneEyeInADoorBoxInASlantedWall) {
    const layout::Layout l = turned_layout();
    const glm::dvec3 n = wall_normal(kTurned, 0);
    const glm::dvec3 centre = wall_point(kTurned, 0, 0.5, 1.5);
    // Head 2 mm in front of the door, looking along the wall: one eye
    // stands 30 mm behind the plane, in the box.
    int sum = 0;
    for (const double turn : {90.0, -90.0}) {
        render::FrameDesc f = prism_frame(l, "turned", centre, yaw_along(-n) + turn);
        f.head.position = centre + 0.002 * n;
        sum +=
            prism_mismatches(l, f, turn > 0 ? "one eye in the box, looking left" : "one eye in the box, looking right");
    }
    // Looking back at the turned room from 20 cm behind the plane and 35 cm
    // from the door's middle: a head there did not come through the door, so
    // its eyes have no inner faces (layout-format.md, "The portal box") and
    // see only the turned room, in both programs.
    const glm::dvec3 along = glm::normalize(wall_point(kTurned, 0, 1, 0) - wall_point(kTurned, 0, 0, 0));
    render::FrameDesc back = prism_frame(l, "turned", centre, yaw_along(n));
    back.head.position = centre - 0.2 * n + 0.35 * along;
    sum += prism_mismatches(l, back, "behind the plane, not through the door", false);
    EXPECT_EQ(sum, 0);
}

// An L: 6 × 6 less its 3 × 3 corner at +x +z; a door in wall 4 (z = 6,
// x from 3 to 0, facing -z), beside the reflex corner (3, 3).
const Floor kPrismL = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};

layout::Layout l_layout() {
    PrismText t;
    t.prism("l", kPrismL, 0.0, 2.8);
    t.box("box", {-2, 0, -2}, {2, 3, 2});
    t.door("corner", "l", {1.0, 1.1, 6.0}, {0, 0, -1}, 1.0, 2.2, "back");
    t.door("back", "box", {0, 1.1, -2}, {0, 0, 1}, 1.0, 2.2, "corner");
    // A hatch in the floor flush with the wall x = 0, into the box's ceiling.
    t.door("hatch", "l", {0.5, 0.0, 1.5}, {0, 1, 0}, 1.0, 1.2, "lid", {0, 0, 1});
    t.door("lid", "box", {0.0, 3.0, 0.0}, {0, -1, 0}, 1.0, 1.2, "hatch", {0, 0, 1});
    t.start_room = "l";
    t.start = {1.5, 1.6, 1.5};
    return t.load();
}

TEST(PrismRender, DoorInAConcaveCornersWallSeenPastTheCorner) {
    const layout::Layout l = l_layout();
    // From the L's other arm the reflex corner's edge (3, y, 3) cuts the
    // door: only its part at x < 0.75 is in sight from (4.5, 1.0).
    const glm::dvec3 eye(4.5, 1.6, 1.0);
    int sum = prism_mismatches(l, prism_frame(l, "l", eye, yaw_along(glm::dvec3(1.0, 1.1, 6.0) - eye)),
                               "L: door past the reflex corner");
    // From (4.5, 0.5) the corner's edge lines up with x = 1.2 of the door.
    sum += prism_mismatches(l, prism_frame(l, "l", {4.5, 1.4, 0.5}, yaw_along({-3.5, 0, 5.5}), 5.0),
                            "L: the corner's edge across the door");
    // The whole L from its far corner, and the door straight on.
    sum +=
        prism_mismatches(l, prism_frame(l, "l", {5.8, 2.0, 0.2}, yaw_along({-1, 0, 1}), -15.0), "L: overview", false);
    sum += prism_mismatches(l, prism_frame(l, "l", {1.0, 1.6, 3.0}, 180.0), "L: the door straight on");
    EXPECT_EQ(sum, 0);
}

TEST(PrismRender, TrapdoorFlushWithAWall) {
    const layout::Layout l = l_layout();
    // Down at the hatch along the wall it touches, from 1 cm and from 1 m
    // off the wall, and up at it from the room below.
    int sum =
        prism_mismatches(l, prism_frame(l, "l", {0.01, 1.2, 0.3}, 180.0, -55.0), "hatch along its wall, 1 cm off");
    sum += prism_mismatches(l, prism_frame(l, "l", {1.2, 1.8, 0.6}, 150.0, -60.0), "hatch from above");
    sum += prism_mismatches(l, prism_frame(l, "box", {0.8, 1.4, 1.2}, 30.0, 55.0), "hatch from below");
    EXPECT_EQ(sum, 0);
}

TEST(PrismRender, TurnedRoom) {
    const layout::Layout l = turned_layout();
    int sum = prism_mismatches(l, prism_frame(l, "turned", {-1.0, 1.7, 0.8}, yaw_along(-wall_normal(kTurned, 0))),
                               "turned: door ahead");
    sum += prism_mismatches(l, prism_frame(l, "turned", {0.5, 2.5, -0.5}, 30.0, -40.0, 100.0), "turned: from high");
    EXPECT_EQ(sum, 0);
}

// A pentagon over a turned trapezoid: the upper room's floor has a trapdoor
// turned 20 degrees, leading to the lower room's ceiling.
layout::Layout trapdoor_layout() {
    const Floor upper = {{-3, -2}, {2.5, -2.5}, {3.5, 1}, {0, 3}, {-3.2, 1.2}};
    const Floor lower = {{-2.8, -2.2}, {2.4, -2.4}, {2.6, 2.6}, {-2.5, 2.2}};
    PrismText t;
    t.prism("upper", upper, 0.0, 3.0);
    t.prism("lower", lower, -3.0, 0.0, 0.5);
    const double a = 20.0 * kPrismPi / 180.0;
    const glm::dvec3 up(std::sin(a), 0.0, std::cos(a));
    t.door("down", "upper", {0.3, 0.0, 0.2}, {0, 1, 0}, 1.0, 1.4, "up", up);
    t.door("up", "lower", {0.3, 0.0, 0.2}, {0, -1, 0}, 1.0, 1.4, "down", up);
    t.start_room = "upper";
    t.start = {1.5, 1.6, 1.5};
    return t.load();
}

TEST(PrismRender, TrapdoorFromAboveAndBelow) {
    const layout::Layout l = trapdoor_layout();
    int sum = prism_mismatches(l, prism_frame(l, "upper", {1.6, 1.7, 1.4}, 45.0, -60.0), "trapdoor from above");
    sum += prism_mismatches(l, prism_frame(l, "upper", {0.4, 0.4, 0.3}, 10.0, -89.0), "trapdoor, just above it");
    sum += prism_mismatches(l, prism_frame(l, "lower", {1.4, -1.6, 1.5}, 45.0, 60.0), "trapdoor from below");
    sum += prism_mismatches(l, prism_frame(l, "lower", {-1.8, -2.5, -1.0}, -120.0, 25.0), "trapdoor, from low and far");
    EXPECT_EQ(sum, 0);
}

// A quarter ring (radii 4 and 6, 24 walls on each side) whose two end walls
// hold doors into a box room.
Floor corridor_floor() {
    Floor f;
    const int n = 24;
    for (int k = 0; k <= n; ++k)
        f.push_back({6.0 * std::cos(0.5 * kPrismPi * k / n), 6.0 * std::sin(0.5 * kPrismPi * k / n)});
    for (int k = n; k >= 0; --k)
        f.push_back({4.0 * std::cos(0.5 * kPrismPi * k / n), 4.0 * std::sin(0.5 * kPrismPi * k / n)});
    return f;
}

layout::Layout corridor_layout() {
    const Floor f = corridor_floor();
    PrismText t;
    t.prism("arc", f, 0.0, 2.5, 0.5);
    // Wall 24 joins (0, 6) to (0, 4) (facing +x, into the ring); the last
    // wall joins (4, 0) to (6, 0).
    t.box("box", {-2, 0, -2}, {2, 3, 2});
    t.door("end_a", "arc", wall_point(f, 24, 0.5, 1.1), wall_normal(f, 24), 1.2, 2.2, "box_a");
    t.door("end_b", "arc", wall_point(f, f.size() - 1, 0.5, 1.1), wall_normal(f, f.size() - 1), 1.2, 2.2, "box_b");
    t.door("box_a", "box", {0, 1.1, -2}, {0, 0, 1}, 1.2, 2.2, "end_a");
    t.door("box_b", "box", {0, 1.1, 2}, {0, 0, -1}, 1.2, 2.2, "end_b");
    t.start_room = "arc";
    t.start = {3.5, 1.6, 3.5};
    return t.load();
}

TEST(PrismRender, GrazingViewsAlongACurvedCorridor) {
    const layout::Layout l = corridor_layout();
    int sum = 0;
    // 2 mm from the outer wall, looking along its tangent towards the end
    // wall at 90 degrees (its door), and 2 mm from the inner wall towards
    // the end at 0 degrees: the walls ahead are grazed, then the door; at
    // 45 degrees along the inner wall, the curve hides both ends.
    const struct {
        double deg;
        bool outer;
        bool door;
    } poses[] = {
        {80.0, true, true}, {75.0, true, true}, {15.0, false, true}, {22.5, false, true}, {45.0, false, false}};
    for (const auto& p : poses) {
        const double a = p.deg * kPrismPi / 180.0;
        const glm::dvec3 radial(std::cos(a), 0.0, std::sin(a));
        const glm::dvec3 tangent(-std::sin(a), 0.0, std::cos(a));  // towards 90 degrees
        // The walls are chords: the outer one 6 cos(pi / 96) from the centre
        // at its middle, the inner one 4 at its ends.
        const double r = p.outer ? 6.0 * std::cos(kPrismPi / 96.0) - 0.002 : 4.002;
        char what[64];
        std::snprintf(what, sizeof what, "corridor: %s wall at %.1f deg", p.outer ? "outer" : "inner", p.deg);
        sum += prism_mismatches(
            l, prism_frame(l, "arc", r * radial + glm::dvec3(0, 1.4, 0), yaw_along(p.outer ? tangent : -tangent), 2.0),
            what, p.door);
    }
    EXPECT_EQ(sum, 0);
}

// tools/diff_fuzz.py --kinds prism --seed 25 --case 1233: a square turned
// 45 degrees with a narrow door in one wall. The ceiling's tessellation
// joined the door's cuts on the ceiling's edge into slivers beside one long
// triangle; llvmpipe snapped them to face away and left one pixel of
// nothing at the ceiling's edge (polygon_tess.cpp now splits them away).
TEST(PrismRender, NoCrackAlongATurnedCeilingsEdge) {
    const layout::Layout l = testing::layout_from_text(R"({"format": "impossible-layout", "version": 1,
      "start": {"room": "a", "position": [1.686970091327769, 0.5745413438895985, -1.5657898334048572]},
      "rooms": [{"id": "a", "floor": [[-4.494495, -0.332043], [0.332043, 4.494495], [4.494495, 0.332043],
                                      [-0.332043, -4.494495]], "y": [0.0, 2.929118], "color": [0.937, 0.215, 0.557]},
                {"id": "b", "floor": [[1.901118, 1.295718], [1.691929, 1.105973], [-3.721253, 2.181083],
                                      [-3.560575, 3.145092], [-2.763749, 3.957295], [2.209234, 3.172428],
                                      [2.22469, 3.14427]], "y": [0.0, 2.997525], "color": [0.389, 0.432, 0.575]}],
      "portals": [{"id": "a_door", "room": "a", "center": [-3.578876, 1.838552, -1.247662],
                   "normal": [0.707106781, 0.0, 0.707106781], "width": 0.095926, "height": 1.744976,
                   "target": "b_door", "depth": 0.089785},
                  {"id": "b_door", "room": "b", "center": [-0.868117, 1.135383, 1.614423],
                   "normal": [0.194804665, 0.0, 0.980842058], "width": 0.095926, "height": 1.744976,
                   "target": "a_door", "depth": 0.312973}]})");
    render::FrameDesc f;
    f.head.position = {1.686970091327769, 0.57454134388959854, -1.5657898334048572};
    f.head.yaw_deg = 93.457232701174945;
    f.head.pitch_deg = 13.474200583483386;
    f.room = 0;
    f.fov_y_deg = 94.191;
    f.eye_width = 96;
    f.eye_height = 64;
    f.max_depth = 2;
    EXPECT_EQ(prism_mismatches(l, f, "fuzz 25/1233: the ceiling's edge", false), 0);
}

// Under "lighting": "lights": a convex hexagon, turned, lit by a point
// light and a spot, with a box prop (its shadow), and a door in a slanted
// wall into a lit box room; faces lit by their exact normals.
TEST(PrismRender, LitConvexPrismRoom) {
    Floor hex;
    for (int k = 0; k < 6; ++k)
        hex.push_back({3.0 * std::cos(kPrismPi / 3 * k + 0.3), 3.0 * std::sin(kPrismPi / 3 * k + 0.3)});
    PrismText t;
    t.lit = true;
    t.prism("hex", hex, 0.0, 3.0, 0.5,
            ", \"ambient\": [0.15, 0.15, 0.15], \"lights\": [{\"position\": [0.5, 2.6, -0.4], \"intensity\": 5}, "
            "{\"position\": [-1.2, 2.2, 1.0], \"intensity\": 12, \"spot\": {\"direction\": [0.36, -0.8, -0.48]}}], "
            "\"props\": [{\"box\": {\"min\": [0.2, 0, -0.6], \"max\": [0.9, 0.8, 0.1]}, \"color\": [0.2, 0.3, 0.8]}]");
    t.box("box", {-2, 0, -2}, {2, 3, 2}, ", \"lights\": [{\"position\": [0.5, 2.5, 0.5], \"intensity\": 6}]");
    t.door("slanted", "hex", wall_point(hex, 1, 0.5, 1.1), wall_normal(hex, 1), 1.0, 2.2, "back");
    t.door("back", "box", {0, 1.1, -2}, {0, 0, 1}, 1.0, 2.2, "slanted");
    t.start_room = "hex";
    t.start = {0, 1.6, 0};
    const layout::Layout l = t.load();
    ASSERT_EQ(l.lighting, layout::Lighting::Lights);
    int sum = prism_mismatches(l, prism_frame(l, "hex", {0.3, 1.6, -1.5}, yaw_along(-wall_normal(hex, 1)), -15.0),
                               "lit hexagon: the slanted door");
    sum += prism_mismatches(l, prism_frame(l, "hex", {-1.5, 2.0, -0.8}, yaw_along({1, 0, 0.3}), -35.0, 100.0),
                            "lit hexagon: walls, floor and the box's shadow", false);
    EXPECT_EQ(sum, 0);
}

}  // namespace
}  // namespace impossible
