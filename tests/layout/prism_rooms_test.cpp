// Prism rooms (layout-format.md, "Rooms of any shape"): `floor` and `y`
// instead of `min`/`max`, the polygon rules, the face keys of `face_colors`
// and `textures`, and the hole rule on walls, floor and ceiling.
#include <cmath>
#include <filesystem>
#include <fstream>

#include "gltf_writer.hpp"
#include "hostile/png_bytes.hpp"
#include "layout/room_shape.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;

// An L: 4 x 4 without its corner [2..4] x [2..4]. Walls: 0 z=0, 1 x=4, 2
// z=2 (x 4..2), 3 x=2 (z 2..4), 4 z=4, 5 x=0.
const std::string kLFloor = "[[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]]";

// A layout whose rooms and portals are the given JSON texts (comma-joined),
// starting in the first room at `start`.
std::string prism_layout(const std::vector<std::string>& rooms, const std::vector<std::string>& portals = {},
                         const std::string& start = "[1, 1.6, 1]", const std::string& extra = "") {
    std::string text = "{\n  \"format\": \"impossible-layout\", \"version\": 1,\n" + extra +
                       "  \"start\": { \"room\": \"r\", \"position\": " + start + " },\n  \"rooms\": [\n";
    for (std::size_t i = 0; i < rooms.size(); ++i) text += "    " + rooms[i] + (i + 1 < rooms.size() ? ",\n" : "\n");
    text += "  ]";
    if (!portals.empty()) {
        text += ",\n  \"portals\": [\n";
        for (std::size_t i = 0; i < portals.size(); ++i) {
            text += "    " + portals[i] + (i + 1 < portals.size() ? ",\n" : "\n");
        }
        text += "  ]";
    }
    return text + "\n}\n";
}

std::string l_room(const std::string& fields = "") {
    return "{ \"id\": \"r\", \"floor\": " + kLFloor + ", \"y\": [0, 3]" + (fields.empty() ? "" : ", " + fields) + " }";
}

// A box room "s" with a free-standing door `id` (targeting `target`) in its
// middle, to pair with a portal under test.
std::string box_s() { return "{ \"id\": \"s\", \"min\": [10, 0, 0], \"max\": [14, 3, 4] }"; }
std::string door_in_s(const std::string& id, const std::string& target, double z = 2.0, double w = 1.0,
                      double h = 2.0) {
    return "{ \"id\": \"" + id + "\", \"room\": \"s\", \"center\": [12, 1.5, " + std::to_string(z) +
           "], \"normal\": [0, 0, 1], \"width\": " + std::to_string(w) + ", \"height\": " + std::to_string(h) +
           ", \"target\": \"" + target + "\" }";
}
std::string door(const std::string& id, const std::string& room, const std::string& center, const std::string& normal,
                 const std::string& target, const std::string& more = "") {
    return "{ \"id\": \"" + id + "\", \"room\": \"" + room + "\", \"center\": " + center + ", \"normal\": " + normal +
           ", \"width\": 1, \"height\": 2" + (more.empty() ? "" : ", " + more) + ", \"target\": \"" + target + "\" }";
}

TEST(LayoutPrismRooms, AnLShapedRoomLoadsWithItsBoundingBoxAndWalls) {
    const Layout l = expect_valid(prism_layout({l_room()}));
    ASSERT_EQ(l.rooms.size(), 1u);
    const Room& r = l.rooms[0];
    ASSERT_EQ(r.floor.size(), 6u);
    EXPECT_EQ(r.floor[3], glm::dvec2(2, 2));  // file order
    EXPECT_EQ(r.min, glm::dvec3(0, 0, 0));
    EXPECT_EQ(r.max, glm::dvec3(4, 3, 4));
    EXPECT_EQ(face_count(r), 8);
    EXPECT_EQ(r.face_color.size(), 8u);
    EXPECT_EQ(r.face_texture.size(), 8u);
    EXPECT_EQ(r.face_color[7], glm::dvec3(0.8));
    EXPECT_FALSE(floor_convex(r));
    EXPECT_DOUBLE_EQ(floor_area(r), 12.0);
    EXPECT_EQ(summarize(l).floor_area, 12.0);
}

TEST(LayoutPrismRooms, ATurnedRectangleAndEitherWindingLoad) {
    // 3 x 2 turned by 30 degrees about [1, 1], clockwise in file order.
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    std::string floor = "[";
    const double pts[4][2] = {{0, 0}, {0, 2}, {3, 2}, {3, 0}};
    for (int i = 0; i < 4; ++i) {
        const double x = pts[i][0] - 1, z = pts[i][1] - 1;
        floor += (i ? ", [" : "[") + std::to_string(1 + c * x - s * z) + ", " + std::to_string(1 + s * x + c * z) + "]";
    }
    floor += "]";
    const Layout l = expect_valid(prism_layout({"{ \"id\": \"r\", \"floor\": " + floor + ", \"y\": [-1, 2.5] }"}));
    const Room& r = l.rooms[0];
    EXPECT_EQ(r.floor.size(), 4u);
    EXPECT_NEAR(floor_area(r), 6.0, 1e-5);
    EXPECT_TRUE(floor_convex(r));
    EXPECT_EQ(r.min.y, -1.0);
    EXPECT_EQ(r.max.y, 2.5);
    EXPECT_NEAR(r.min.x, 1 + c * -1 - s * 1, 1e-6);
}

// A quarter ring, radii 2 and 4, as 11 steps on each arc: 24 corners.
std::string curved_corridor() {
    std::string floor = "[";
    for (int i = 0; i <= 11; ++i) {
        const double a = M_PI / 2 * i / 11;
        floor += (i ? ", [" : "[") + std::to_string(4 * std::cos(a)) + ", " + std::to_string(4 * std::sin(a)) + "]";
    }
    for (int i = 11; i >= 0; --i) {
        const double a = M_PI / 2 * i / 11;
        floor += ", [" + std::to_string(2 * std::cos(a)) + ", " + std::to_string(2 * std::sin(a)) + "]";
    }
    return floor + "]";
}

TEST(LayoutPrismRooms, ACurvedCorridorOf24Walls) {
    const std::string room = "{ \"id\": \"r\", \"floor\": " + curved_corridor() +
                             ", \"y\": [0, 2.5], \"face_colors\": { \"walls\": [0, 0, 1], \"wall23\": [1, 0, 0] } }";
    const Layout l = expect_valid(prism_layout({room}, {}, "[2.1, 1.6, 2.1]"));
    const Room& r = l.rooms[0];
    EXPECT_EQ(wall_count(r), 24);
    EXPECT_EQ(r.face_color.size(), 26u);
    EXPECT_EQ(r.face_color[2], glm::dvec3(0, 0, 1));
    EXPECT_EQ(r.face_color[25], glm::dvec3(1, 0, 0));
    EXPECT_EQ(r.face_color[0], glm::dvec3(0.8));
    EXPECT_TRUE(l.rooms.size() == 1 && load(prism_layout({room}, {}, "[2.1, 1.6, 2.1]")).warnings.empty());
}

TEST(LayoutPrismRooms, ATrapdoorJoinsARoomAboveToARoomBelow) {
    const std::string above = "{ \"id\": \"r\", \"floor\": [[0, 0], [4, 0], [4, 4], [0, 4]], \"y\": [3, 6] }";
    const std::string below = "{ \"id\": \"s\", \"floor\": " + kLFloor + ", \"y\": [0, 3] }";
    const Layout l =
        expect_valid(prism_layout({above, below},
                                  {door("down", "r", "[1, 3, 1]", "[0, 1, 0]", "up", "\"up\": [0, 0, -1]"),
                                   door("up", "s", "[1, 3, 1]", "[0, -1, 0]", "down", "\"up\": [0, 0, 1]")},
                                  "[1, 4.6, 1]"));
    ASSERT_EQ(l.portals.size(), 2u);
    EXPECT_EQ(l.portals[0].hole_face, int(Face::Floor));
    EXPECT_EQ(l.portals[1].hole_face, int(Face::Ceiling));
}

TEST(LayoutPrismRooms, ADoorInAWallCutsAHoleInThatWall) {
    // Wall 3 runs along x = 2 from z = 2 to z = 4, facing -x... into the room: -x.
    const Layout l = expect_valid(
        prism_layout({l_room(), box_s()}, {door("a", "r", "[2, 1, 3]", "[-1, 0, 0]", "b"), door_in_s("b", "a"),
                                           door("c", "r", "[3, 1, 0]", "[0, 0, 1]", "d"), door_in_s("d", "c", 3.0),
                                           door("e", "r", "[3, 1, 2]", "[0, 0, -1]", "f"), door_in_s("f", "e", 1.0)}));
    ASSERT_EQ(l.portals.size(), 6u);
    EXPECT_EQ(l.portals[0].hole_face, 2 + 3);
    EXPECT_EQ(l.portals[2].hole_face, 2 + 0);
    EXPECT_EQ(l.portals[4].hole_face, 2 + 2);
    EXPECT_EQ(l.portals[1].hole_face, -1);
}

TEST(LayoutPrismRooms, HolesInTheWallsOfACounterClockwiseFloorToo) {
    // The L written the other way round: wall i now runs from corner i of
    // the reversed list.
    const std::string room =
        "{ \"id\": \"r\", \"floor\": [[0, 4], [2, 4], [2, 2], [4, 2], [4, 0], [0, 0]], "
        "\"y\": [0, 3] }";
    const Layout l = expect_valid(
        prism_layout({room, box_s()}, {door("a", "r", "[2, 1, 3]", "[-1, 0, 0]", "b"), door_in_s("b", "a")}));
    EXPECT_EQ(l.portals[0].hole_face, 2 + 1);
}

TEST(LayoutPrismRooms, OutsideAWallInItsPlaneStandsFreeAndFacingOutIsNoHole) {
    // In the plane of wall 2 (z = 2, x 2..4) but at x = 1: inside the room, no hole.
    const Layout l = expect_valid(
        prism_layout({l_room(), box_s()}, {door("a", "r", "[1, 1, 2]", "[0, 0, -1]", "b"), door_in_s("b", "a"),
                                           door("c", "r", "[2, 1, 3]", "[1, 0, 0]", "d"), door_in_s("d", "c", 3.0)}));
    EXPECT_EQ(l.portals[0].hole_face, -1);
    EXPECT_EQ(l.portals[2].hole_face, -1);
}

TEST(LayoutPrismRooms, ADoorSpanningTwoCollinearWallsIsAnError) {
    // Walls 0 and 1 both lie on z = 0.
    const std::string room = "{ \"id\": \"r\", \"floor\": [[0, 0], [2, 0], [4, 0], [4, 4], [0, 4]], \"y\": [0, 3] }";
    const std::string text =
        prism_layout({room, box_s()}, {door("a", "r", "[2, 1, 0]", "[0, 0, 1]", "b"), door_in_s("b", "a")});
    expect_one_error(text, "[2, 1, 0]",
                     "portals[0].center: the rectangle lies in the plane of the wall0 face of room \"r\" but is only "
                     "partly inside that face");
    // Wholly inside the second of the two walls: a hole in it.
    const Layout l = expect_valid(
        prism_layout({room, box_s()}, {door("a", "r", "[3, 1, 0]", "[0, 0, 1]", "b"), door_in_s("b", "a")}));
    EXPECT_EQ(l.portals[0].hole_face, 2 + 1);
}

TEST(LayoutPrismRooms, ATrapdoorPartlyOverTheNotchIsAnError) {
    const std::string text =
        prism_layout({l_room(), box_s()},
                     {door("a", "r", "[2.25, 0, 2.25]", "[0, 1, 0]", "b", "\"up\": [0, 0, -1]"), door_in_s("b", "a")});
    expect_one_error(text, "[2.25, 0, 2.25]",
                     "portals[0].center: the rectangle lies in the plane of the floor face of room \"r\" but is only "
                     "partly inside that face");
    // Wholly inside the notch it stands free; inside the floor, a hole.
    const Layout free = expect_valid(
        prism_layout({l_room(), box_s()},
                     {door("a", "r", "[3, 0, 3]", "[0, 1, 0]", "b", "\"up\": [0, 0, -1]"), door_in_s("b", "a")}));
    EXPECT_EQ(free.portals[0].hole_face, -1);
    // A sliver of 1e-4 m outside is inside.
    const Layout in = expect_valid(
        prism_layout({l_room(), box_s()},
                     {door("a", "r", "[1.50005, 0, 3]", "[0, 1, 0]", "b", "\"up\": [0, 0, -1]"), door_in_s("b", "a")}));
    EXPECT_EQ(in.portals[0].hole_face, int(Face::Floor));
}

TEST(LayoutPrismRooms, OverlappingHolesInOneWallAreAnError) {
    const std::string text =
        prism_layout({l_room(), box_s()}, {door("a", "r", "[1, 1, 4]", "[0, 0, -1]", "b"), door_in_s("b", "a"),
                                           door("c", "r", "[1.5, 1, 4]", "[0, 0, -1]", "d"), door_in_s("d", "c", 3.0)});
    expect_one_error(text, "[1.5, 1, 4]",
                     "portals[2].center: its hole in the wall4 face of room \"r\" overlaps the hole of portal \"a\"");
    const std::string up = "\"up\": [0, 0, -1]";
    const std::string floor = prism_layout(
        {l_room(), box_s()}, {door("a", "r", "[1, 0, 1]", "[0, 1, 0]", "b", up), door_in_s("b", "a"),
                              door("c", "r", "[1, 0, 1.5]", "[0, 1, 0]", "d", up), door_in_s("d", "c", 3.0)});
    expect_one_error(floor, "[1, 0, 1.5]",
                     "portals[2].center: its hole in the floor face of room \"r\" overlaps the hole of portal \"a\"");
    // Side by side, touching: fine.
    const Layout l = expect_valid(prism_layout(
        {l_room(), box_s()}, {door("a", "r", "[1, 0, 1]", "[0, 1, 0]", "b", up), door_in_s("b", "a"),
                              door("c", "r", "[1, 0, 3]", "[0, 1, 0]", "d", up), door_in_s("d", "c", 3.0)}));
    EXPECT_EQ(l.portals[2].hole_face, int(Face::Floor));
}

TEST(LayoutPrismRooms, MirrorsMustLieInAFaceOfAPrismRoom) {
    const Layout l = expect_valid(
        prism_layout({l_room()}, {"{ \"id\": \"m\", \"room\": \"r\", \"kind\": \"mirror\", \"center\": [3, 1.5, 2], "
                                  "\"normal\": [0, 0, -1], \"width\": 1, \"height\": 1 }"}));
    EXPECT_EQ(l.portals[0].hole_face, 2 + 2);
    const std::string text =
        prism_layout({l_room()}, {"{ \"id\": \"m\", \"room\": \"r\", \"kind\": \"mirror\", \"center\": [3, 1.5, 2.5], "
                                  "\"normal\": [0, 0, -1], \"width\": 1, \"height\": 1 }"});
    expect_one_error(text, "[3, 1.5, 2.5]",
                     "portals[0].center: a mirror must lie in a face of its own room \"r\" (within 0.0001 m of the "
                     "face's plane, inside the face), but this one stands free: a corner is 0.5 m from wall2 (from "
                     "[4, 2] to [2, 2]), the face its normal looks away from; move it into that face");
    const std::string beside =
        prism_layout({l_room()}, {"{ \"id\": \"m\", \"room\": \"r\", \"kind\": \"mirror\", \"center\": [1, 1.5, 2], "
                                  "\"normal\": [0, 0, -1], \"width\": 1, \"height\": 1 }"});
    expect_one_error(beside, "[1, 1.5, 2]",
                     "portals[0].center: a mirror must lie in a face of its own room \"r\" (within 0.0001 m of the "
                     "face's plane, inside the face), but this one stands free: it lies in the plane of wall2 (from "
                     "[4, 2] to [2, 2]) but outside that face; move it inside the face");
    const std::string out =
        prism_layout({l_room()}, {"{ \"id\": \"m\", \"room\": \"r\", \"kind\": \"mirror\", \"center\": [3, 1.5, 2], "
                                  "\"normal\": [0, 0, 1], \"width\": 1, \"height\": 1 }"});
    expect_one_error(out, "[3, 1.5, 2]",
                     "portals[0].center: a mirror must lie in a face of its own room \"r\" (within 0.0001 m of the "
                     "face's plane, inside the face), but this one stands free: it lies in the plane of wall2 (from "
                     "[4, 2] to [2, 2]) but its normal points out of the room; turn the normal around");
}

TEST(LayoutPrismRooms, BothFormsOrNeitherAreErrors) {
    expect_one_error(prism_layout({"{ \"id\": \"r\", \"min\": [0, 0, 0], \"max\": [4, 3, 4], \"floor\": " + kLFloor +
                                   ", \"y\": [0, 3] }"}),
                     "\"floor\"",
                     "rooms[0].floor: a room is either a box (\"min\" and \"max\") or a prism over a floor polygon "
                     "(\"floor\" and \"y\"), never both");
    expect_one_error(prism_layout({"{ \"id\": \"r\", \"max\": [4, 3, 4], \"y\": [0, 3] }"}), "\"y\"",
                     "rooms[0].y: a room is either a box");
    expect_one_error(prism_layout({"{ \"id\": \"r\", \"floor\": " + kLFloor + " }"}), "{ \"id\": \"r\"",
                     "rooms[0]: missing required field \"y\" (a room with \"floor\" needs it)");
    expect_one_error(prism_layout({"{ \"id\": \"r\", \"y\": [0, 3] }"}), "{ \"id\": \"r\"",
                     "rooms[0]: missing required field \"floor\" (a room with \"y\" needs it)");
    const LoadResult r = load(prism_layout({"{ \"id\": \"r\" }"}));
    ASSERT_EQ(r.errors.size(), 2u) << all_messages(r.errors);
    EXPECT_EQ(r.errors[0].message, "rooms[0]: missing required field \"min\"");
}

TEST(LayoutPrismRooms, TheFloorFollowsThePlayAreaPolygonRules) {
    const auto with_floor = [](const std::string& floor) {
        return prism_layout({"{ \"id\": \"r\", \"floor\": " + floor + ", \"y\": [0, 3] }"});
    };
    expect_one_error(with_floor("[[0, 0], [4, 4], [4, 0], [0, 4]]"), "[4, 0]",
                     "rooms[0].floor[2]: the floor must be a simple polygon: edge 2 crosses edge 0");
    expect_one_error(with_floor("[[0, 0], [4, 0], [4, 4], [4, 0], [0, 4]]"), "[4, 0], [0, 4]",
                     "rooms[0].floor[3]: the floor must be a simple polygon: corner 3 repeats corner 1");
    expect_one_error(with_floor("[[0, 0], [4, 0]]"), "[[0, 0], [4, 0]]",
                     "rooms[0].floor: the floor must be a simple polygon: a polygon needs at least 3 corners (got 2)");
    expect_one_error(with_floor("[[0, 0], [1, 0], [2, 0]]"), "[2, 0]",
                     "rooms[0].floor[2]: the floor must be a simple polygon: edges 0 and 2 overlap");
    // Folding back on itself: [4, 0] → [2, 0] runs back along the first edge.
    expect_one_error(with_floor("[[0, 0], [4, 0], [2, 0], [2, 4]]"), "[4, 0]",
                     "rooms[0].floor[1]: the floor must be a simple polygon: edges 0 and 1 overlap");
    // Two corners that touch an edge of the polygon.
    expect_one_error(with_floor("[[0, 0], [4, 0], [4, 4], [2, 0], [0, 4]]"), "[4, 4]",
                     "rooms[0].floor[2]: the floor must be a simple polygon: edge 2 crosses edge 0");
    expect_one_error(with_floor("[[0, 0], [4, 0, 1], [0, 4]]"), "[4, 0, 1]",
                     "rooms[0].floor[1]: must be an array of 2 numbers [x, z] (got an array of 3)");
    expect_one_error(with_floor("[[0, 0], [4, 1e6], [0, 4]]"), "1e6", "rooms[0].floor[1][1]: 1000000 is out of range");
    expect_one_error(with_floor("{}"), "{}", "rooms[0].floor: must be an array");
    expect_one_error(with_floor("[[0, 0], [4, 0], [4, 0.0000001], [0, 4]]"), "[4, 0.0000001]",
                     "rooms[0].floor[2]: wall 1 is too short (corners 1 and 2 are 1e-07 m apart; the minimum is "
                     "1e-06 m)");
    std::string many = "[";
    for (int i = 0; i < 1001; ++i) {
        const double a = 2 * M_PI * i / 1001;
        many += (i ? ", [" : "[") + std::to_string(10 * std::cos(a)) + ", " + std::to_string(10 * std::sin(a)) + "]";
    }
    expect_one_error(with_floor(many + "]"), many, "rooms[0].floor: has 1001 entries; at most 1000 are allowed");
}

TEST(LayoutPrismRooms, YIsTwoNumbersUpwardsAndNotTooThin) {
    const auto with_y = [](const std::string& y) {
        return prism_layout({"{ \"id\": \"r\", \"floor\": " + kLFloor + ", \"y\": " + y + " }"}, {}, "[1, 0.5, 1]");
    };
    expect_one_error(with_y("[3, 3]"), "[3, 3]", "rooms[0].y: the ceiling y1 must be above the floor y0 (3 <= 3)");
    expect_one_error(with_y("[3, 0]"), "[3, 0]", "rooms[0].y: the ceiling y1 must be above the floor y0 (0 <= 3)");
    expect_one_error(with_y("[0, 0.0000001]"), "[0, 0.0000001]",
                     "rooms[0].y: the room is too thin (y: 1e-07 m; the minimum is 1e-06 m)");
    expect_one_error(with_y("[0, 1, 2]"), "[0, 1, 2]",
                     "rooms[0].y: must be an array of 2 numbers [y0, y1] (got an array of 3)");
    expect_one_error(with_y("3"), "3 }", "rooms[0].y: must be an array of 2 numbers [y0, y1] (got a number)");
    expect_one_error(with_y("[0, \"3\"]"), "\"3\"", "rooms[0].y[1]: must be a number (got a string)");
}

TEST(LayoutPrismRooms, FaceColorKeysNameTheWalls) {
    // face_colors before floor in the object: the shape is read first.
    const Layout l = expect_valid(
        prism_layout({"{ \"id\": \"r\", \"face_colors\": { \"wall1\": [1, 0, 0], \"walls\": [0, 1, 0], \"floor\": "
                      "[0, 0, 1], \"ceiling\": [1, 1, 0] }, \"color\": [0.5, 0.5, 0.5], \"floor\": " +
                      kLFloor + ", \"y\": [0, 3] }"}));
    const Room& r = l.rooms[0];
    ASSERT_EQ(r.face_color.size(), 8u);
    EXPECT_EQ(r.face_color[0], glm::dvec3(0, 0, 1));
    EXPECT_EQ(r.face_color[1], glm::dvec3(1, 1, 0));
    EXPECT_EQ(r.face_color[2 + 1], glm::dvec3(1, 0, 0));  // wallN wins over walls
    for (int w : {0, 2, 3, 4, 5}) EXPECT_EQ(r.face_color[2 + w], glm::dvec3(0, 1, 0)) << w;
    // Without "walls", the other walls keep `color`.
    const Layout k =
        expect_valid(prism_layout({l_room("\"color\": [0.5, 0.5, 0.5], \"face_colors\": { "
                                          "\"wall5\": [1, 0, 0] }")}));
    EXPECT_EQ(k.rooms[0].face_color[7], glm::dvec3(1, 0, 0));
    EXPECT_EQ(k.rooms[0].face_color[6], glm::dvec3(0.5));
}

TEST(LayoutPrismRooms, BoxKeysOnAPrismAndWallKeysOnABoxAreErrors) {
    expect_one_error(prism_layout({l_room("\"face_colors\": { \"-x\": [1, 0, 0] }")}), "\"-x\"",
                     "rooms[0].face_colors.-x: the face \"-x\" is only for a box room (\"min\" and \"max\"); a room "
                     "with a floor polygon has the faces \"floor\", \"ceiling\", \"walls\", \"wall0\" to \"wall5\"");
    expect_one_error(prism_layout({l_room("\"face_colors\": { \"wall6\": [1, 0, 0] }")}), "\"wall6\"",
                     "rooms[0].face_colors.wall6: there is no wall \"wall6\": the room's floor has 6 corners, so its "
                     "walls are \"wall0\" to \"wall5\"");
    expect_one_error(prism_layout({l_room("\"face_colors\": { \"wall01\": [1, 0, 0] }")}), "\"wall01\"",
                     "rooms[0].face_colors.wall01: unknown face \"wall01\"; a room with a floor polygon has the faces");
    const std::string box = "{ \"id\": \"r\", \"min\": [0, 0, 0], \"max\": [4, 3, 4], \"face_colors\": { ";
    expect_one_error(prism_layout({box + "\"walls\": [1, 0, 0] } }"}), "\"walls\"",
                     "rooms[0].face_colors.walls: the face \"walls\" is only for a room with a floor polygon "
                     "(\"floor\" and \"y\"); a box room's faces are \"floor\", \"ceiling\", \"-x\", \"+x\", \"-z\", "
                     "\"+z\"");
    expect_one_error(prism_layout({box + "\"wall0\": [1, 0, 0] } }"}), "\"wall0\"",
                     "rooms[0].face_colors.wall0: the face \"wall0\" is only for a room with a floor polygon");
    // A box room's unknown key keeps its message.
    expect_one_error(prism_layout({box + "\"side\": [1, 0, 0] } }"}), "\"side\"",
                     "rooms[0].face_colors.side: unknown face \"side\" (faces are \"floor\", \"ceiling\", \"-x\", "
                     "\"+x\", \"-z\", \"+z\")");
}

TEST(LayoutPrismRooms, TheStartOutsideThePrismIsAWarning) {
    const LoadResult r = load(prism_layout({l_room()}, {}, "[3, 1.6, 3]"));  // in the notch
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].message, "start.position: the head starts outside its room \"r\"");
    EXPECT_TRUE(load(prism_layout({l_room()}, {}, "[2, 1.6, 4]")).warnings.empty());  // on a wall is inside
}

TEST(LayoutPrismRooms, LightsMustBeStrictlyInsideTheConvexPrism) {
    const std::string lit = "  \"lighting\": \"lights\",\n";
    const std::string tri = "{ \"id\": \"r\", \"floor\": [[0, 0], [4, 0], [0, 4]], \"y\": [0, 3], \"lights\": [ ";
    const Layout l = expect_valid(prism_layout({tri + "{ \"position\": [1, 2, 1] } ] }"}, {}, "[1, 1.6, 1]", lit));
    EXPECT_EQ(l.rooms[0].lights.size(), 1u);
    // Beyond the slanted wall, inside the bounding box.
    expect_one_error(prism_layout({tri + "{ \"position\": [3, 2, 3] } ] }"}, {}, "[1, 1.6, 1]", lit), "[3, 2, 3]",
                     "rooms[0].lights[0].position: the light at [3, 2, 3] is not strictly inside its room \"r\"");
    expect_one_error(prism_layout({tri + "{ \"position\": [2, 2, 2] } ] }"}, {}, "[1, 1.6, 1]", lit), "[2, 2, 2]",
                     "rooms[0].lights[0].position: the light at [2, 2, 2] is not strictly inside its room \"r\"");
}

TEST(LayoutPrismRooms, AGltfPropsLightOutsideThePrismIsDropped) {
    // A model whose point light sits 0.5 m above its origin.
    GltfWriter w;
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
    w.node({{"translation", {0, 0.5, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    w.doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    w.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({{{"type", "point"}}})}}}};
    const std::string path = temp_path("prism_lamp.gltf");
    w.write(path);
    const std::string lit = "  \"lighting\": \"lights\",\n";
    const auto room = [&](const std::string& at) {
        return "{ \"id\": \"r\", \"floor\": [[0, 0], [4, 0], [0, 4]], \"y\": [0, 3], \"props\": [ { \"gltf\": \"" +
               path + "\", \"position\": " + at + " } ] }";
    };
    const Layout l = expect_valid(prism_layout({room("[1, 0, 1]")}, {}, "[1, 1.6, 1]", lit));
    ASSERT_EQ(l.rooms[0].lights.size(), 1u);
    EXPECT_EQ(l.rooms[0].lights[0].position, glm::dvec3(1, 0.5, 1));
    // Beyond the slanted wall, inside the bounding box: dropped, with a warning.
    const LoadResult beyond = load(prism_layout({room("[2.5, 0, 2.5]")}, {}, "[1, 1.6, 1]", lit));
    ASSERT_TRUE(beyond.errors.empty()) << all_messages(beyond.errors);
    EXPECT_TRUE(beyond.layout->rooms[0].lights.empty());
    ASSERT_EQ(beyond.warnings.size(), 1u) << all_messages(beyond.warnings);
    EXPECT_EQ(beyond.warnings[0].message, "rooms[0].props[0]: the model \"" + path +
                                              "\"'s light 0 (node 1) stands at [2.5, 0.5, 2.5], not strictly inside "
                                              "the room \"r\": it is dropped");
}

TEST(LayoutPrismRooms, ANonConvexRoomTakesLightsInsideItsFloor) {
    const std::string lit = "  \"lighting\": \"lights\",\n";
    const Layout l = expect_valid(prism_layout(
        {l_room("\"lights\": [ { \"position\": [3, 2, 1] }, { \"position\": [1, 2, 3] } ]")}, {}, "[1, 1.6, 1]", lit));
    ASSERT_EQ(l.rooms[0].lights.size(), 2u);
    EXPECT_EQ(l.rooms[0].lights[1].position, glm::dvec3(1, 2, 3));
    // In the notch: inside the bounding box, outside the L.
    const std::string notch = "\"lights\": [ { \"position\": [3, 2, 3] } ]";
    expect_one_error(prism_layout({l_room(notch)}, {}, "[1, 1.6, 1]", lit), "[3, 2, 3]",
                     "rooms[0].lights[0].position: the light at [3, 2, 3] is not strictly inside its room \"r\"");
}

TEST(LayoutPrismRooms, AVolumeInTheNotchIsWhollyOutsideTheRoom) {
    const std::string target = "{ \"id\": \"t\", \"min\": [10, 0, 0], \"max\": [14, 3, 4] }";
    const auto volume = [](const std::string& center) {
        return "{ \"id\": \"v\", \"room\": \"r\", \"kind\": \"volume\", \"center\": " + center +
               ", \"normal\": [0, 0, 1], \"width\": 1, \"height\": 1, \"depth\": 1, \"target\": \"t\" }";
    };
    const LoadResult out = load(prism_layout({l_room(), target}, {volume("[3, 1.5, 3]")}));
    ASSERT_TRUE(out.errors.empty()) << all_messages(out.errors);
    ASSERT_EQ(out.warnings.size(), 1u);
    EXPECT_EQ(out.warnings[0].message,
              "portals[0].center: the volume lies wholly outside its room \"r\", so nothing in the room is seen "
              "through it");
    // Partly inside the L (reaching over its inner corner): no warning.
    EXPECT_TRUE(load(prism_layout({l_room(), target}, {volume("[2.2, 1.5, 2.2]")})).warnings.empty());
    // Above the room: outside.
    EXPECT_EQ(load(prism_layout({l_room(), target}, {volume("[1, 4, 1]")})).warnings.size(), 1u);
}

TEST(LayoutPrismRooms, ThePlayAreaHoldsARoomByItsPolygon) {
    // A play area shaped like the L holds the L room but not its bounding box.
    const std::string play = "  \"play_area\": { \"polygon\": " + kLFloor + " },\n";
    const Layout l = expect_valid(prism_layout({l_room()}, {}, "[1, 1.6, 1]", play));
    EXPECT_TRUE(summarize(l).rooms_outside_play_area.empty());
    EXPECT_DOUBLE_EQ(*summarize(l).expansion_ratio, 1.0);
    const std::string small =
        "  \"play_area\": { \"polygon\": [[0, 0], [4, 0], [4, 2], [2, 2], [2, 3.5], [0, 3.5]] },\n";
    const Layout k = expect_valid(prism_layout({l_room()}, {}, "[1, 1.6, 1]", small));
    EXPECT_EQ(summarize(k).rooms_outside_play_area, std::vector<std::string>{"r"});
}

// A w x h RGBA PNG of one colour.
std::string prism_png(std::uint32_t w, std::uint32_t h, unsigned char r) {
    std::string rows;
    for (std::uint32_t y = 0; y < h; ++y) {
        rows += '\0';
        for (std::uint32_t x = 0; x < w; ++x) rows += std::string{char(r), 0, 0, char(255)};
    }
    return impossible::hostile::png_file(w, h, 8, 6, rows);
}

TEST(LayoutPrismRooms, TexturesOwnKeyThenWallsThenAll) {
    const fs::path dir = temp_path("prism_textures");
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "a.png", std::ios::binary) << prism_png(1, 1, 10);
    std::ofstream(dir / "w.png", std::ios::binary) << prism_png(2, 1, 20);
    std::ofstream(dir / "o.png", std::ios::binary) << prism_png(3, 1, 30);
    const std::string text =
        prism_layout({l_room("\"textures\": { \"all\": \"a.png\", \"walls\": \"w.png\", \"wall4\": \"o.png\" }")});
    const LoadResult r = load_layout_text(text, "t.json", dir.string());
    ASSERT_TRUE(r.layout) << all_messages(r.errors);
    const Room& room = r.layout->rooms[0];
    ASSERT_EQ(room.face_texture.size(), 8u);
    EXPECT_EQ(room.face_texture[0]->width, 1);  // floor: all
    EXPECT_EQ(room.face_texture[1]->width, 1);  // ceiling: all
    for (int w : {0, 1, 2, 3, 5}) EXPECT_EQ(room.face_texture[2 + w]->width, 2) << w;
    EXPECT_EQ(room.face_texture[2 + 4]->width, 3);
    EXPECT_EQ(summarize(*r.layout).textured_faces, 8);
    const LoadResult bad =
        load_layout_text(prism_layout({l_room("\"textures\": { \"+z\": \"a.png\" }")}), "t.json", dir.string());
    ASSERT_EQ(bad.errors.size(), 1u);
    EXPECT_EQ(bad.errors[0].message,
              "rooms[0].textures.+z: the face \"+z\" is only for a box room (\"min\" and \"max\"); a room with a "
              "floor polygon has the faces \"floor\", \"ceiling\", \"walls\", \"wall0\" to \"wall5\" and \"all\"");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace layout_test
