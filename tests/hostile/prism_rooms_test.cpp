// `impossible validate` on prism rooms (layout-format.md, "Rooms of any
// shape"): a good one validates; each bad one is refused with exit 1 and one
// line that names FILE:LINE:COLUMN and the field.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// One room per line (line 5 is rooms[0], line 6 rooms[1]); `top` adds
// top-level fields on line 2.
std::string prism_file(const std::string& room0, const std::string& room1 = "", const std::string& portals = "",
                       const std::string& top = "") {
    return "{ \"format\": \"impossible-layout\", \"version\": 1,\n" + top +
           "\n  \"start\": { \"room\": \"r\", \"position\": [1, 1.6, 1] },\n  \"rooms\": [\n    " + room0 +
           (room1.empty() ? "" : ",\n    " + room1) + "\n  ]" +
           (portals.empty() ? "" : ",\n  \"portals\": [\n    " + portals + "\n  ]") + "\n}\n";
}

const std::string kL = "[[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]]";

// "FILE:LINE:COLUMN: " of the nth `needle` in `text` (columns in bytes:
// the texts here are ASCII).
std::string where(const std::string& file, const std::string& text, const std::string& needle, int nth = 0) {
    std::size_t at = text.find(needle);
    for (int i = 0; i < nth && at != std::string::npos; ++i) at = text.find(needle, at + 1);
    EXPECT_NE(at, std::string::npos) << needle;
    int line = 1, column = 1;
    for (std::size_t i = 0; i < at && at != std::string::npos; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

class HostilePrism : public Hostile {
protected:
    // Writes `text` to p.json, validates it, and expects exit 1 and one line:
    // the position of `needle` and then `message`.
    void expect_refused_at(const std::string& text, const std::string& needle, const std::string& message) {
        spit(dir_ / "p.json", text);
        const Outcome r = run("$BIN validate p.json");
        expect_refused(r, 1, where("p.json", text, needle) + message);
    }
};

TEST_F(HostilePrism, AnLShapedRoomWithATrapdoorValidates) {
    const std::string text = prism_file(
        "{ \"id\": \"r\", \"floor\": " + kL + ", \"y\": [0, 3], \"face_colors\": { \"walls\": [0, 0, 1] } }",
        "{ \"id\": \"s\", \"floor\": [[0, 0], [4, 0], [4, 4], [0, 4]], \"y\": [3, 6] }",
        "{ \"id\": \"up\", \"room\": \"r\", \"center\": [1, 3, 1], \"normal\": [0, -1, 0], \"up\": [0, 0, 1], "
        "\"width\": 1, \"height\": 1, \"target\": \"down\" },\n    "
        "{ \"id\": \"down\", \"room\": \"s\", \"center\": [1, 3, 1], \"normal\": [0, 1, 0], \"up\": [0, 0, "
        "-1], \"width\": 1, \"height\": 1, \"target\": \"up\" }");
    spit(dir_ / "p.json", text);
    const Outcome r = run("$BIN validate p.json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("floor area: 28.00 m2"), std::string::npos) << r.out;
}

TEST_F(HostilePrism, ASelfIntersectingFloorIsRefusedAtItsCorner) {
    const std::string text =
        prism_file("{ \"id\": \"r\", \"floor\": [[0, 0], [4, 4], [4, 0], [0, 4]], \"y\": [0, 3] }");
    expect_refused_at(text, "[4, 0]",
                      "rooms[0].floor[2]: the floor must be a simple polygon: edge 2 crosses edge 0 (the polygon "
                      "intersects itself)");
}

TEST_F(HostilePrism, BothShapesInOneRoomAreRefused) {
    const std::string text =
        prism_file("{ \"id\": \"r\", \"min\": [0, 0, 0], \"max\": [4, 3, 4], \"floor\": " + kL + ", \"y\": [0, 3] }");
    expect_refused_at(text, "\"floor\"",
                      "rooms[0].floor: a room is either a box (\"min\" and \"max\") or a prism over a floor polygon "
                      "(\"floor\" and \"y\"), never both");
}

TEST_F(HostilePrism, ACeilingBelowTheFloorIsRefused) {
    const std::string text = prism_file("{ \"id\": \"r\", \"floor\": " + kL + ", \"y\": [3, 0] }");
    expect_refused_at(text, "[3, 0]", "rooms[0].y: the ceiling y1 must be above the floor y0 (0 <= 3)");
}

TEST_F(HostilePrism, ABoxFaceKeyOnAPrismIsRefused) {
    const std::string text =
        prism_file("{ \"id\": \"r\", \"floor\": " + kL + ", \"y\": [0, 3], \"face_colors\": { \"+x\": [1, 0, 0] } }");
    expect_refused_at(text, "\"+x\"",
                      "rooms[0].face_colors.+x: the face \"+x\" is only for a box room (\"min\" and \"max\"); a room "
                      "with a floor polygon has the faces \"floor\", \"ceiling\", \"walls\", \"wall0\" to \"wall5\"");
}

TEST_F(HostilePrism, AWallPastTheLastIsRefused) {
    const std::string text = prism_file("{ \"id\": \"r\", \"face_colors\": { \"wall9\": [1, 0, 0] }, \"floor\": " + kL +
                                        ", \"y\": [0, 3] }");
    expect_refused_at(text, "\"wall9\"",
                      "rooms[0].face_colors.wall9: there is no wall \"wall9\": the room's floor has 6 corners, so its "
                      "walls are \"wall0\" to \"wall5\"");
}

TEST_F(HostilePrism, WallKeysOnABoxRoomAreRefused) {
    const std::string text = prism_file(
        "{ \"id\": \"r\", \"min\": [0, 0, 0], \"max\": [4, 3, 4], \"face_colors\": { \"walls\": [1, 0, 0] } }");
    expect_refused_at(text, "\"walls\"",
                      "rooms[0].face_colors.walls: the face \"walls\" is only for a room with a floor polygon");
}

TEST_F(HostilePrism, ADoorOverTwoCollinearWallsIsRefused) {
    const std::string text =
        prism_file("{ \"id\": \"r\", \"floor\": [[0, 0], [2, 0], [4, 0], [4, 4], [0, 4]], \"y\": [0, 3] }",
                   "{ \"id\": \"s\", \"min\": [10, 0, 0], \"max\": [14, 3, 4] }",
                   "{ \"id\": \"a\", \"room\": \"r\", \"center\": [2, 1, 0], \"normal\": [0, 0, 1], \"width\": 1, "
                   "\"height\": 2, \"target\": \"b\" },\n    { \"id\": \"b\", \"room\": \"s\", \"center\": [12, 1, 2], "
                   "\"normal\": [0, 0, 1], \"width\": 1, \"height\": 2, \"target\": \"a\" }");
    expect_refused_at(text, "[2, 1, 0]",
                      "portals[0].center: the rectangle lies in the plane of the wall0 face of room \"r\" but is only "
                      "partly inside that face");
}

TEST_F(HostilePrism, ATrapdoorPartlyOverTheFloorIsRefused) {
    const std::string text = prism_file(
        "{ \"id\": \"r\", \"floor\": " + kL + ", \"y\": [0, 3] }",
        "{ \"id\": \"s\", \"min\": [10, 0, 0], \"max\": [14, 3, 4] }",
        "{ \"id\": \"a\", \"room\": \"r\", \"center\": [2.25, 0, 2.25], \"normal\": [0, 1, 0], \"up\": [0, 0, -1], "
        "\"width\": 1, \"height\": 1, \"target\": \"b\" },\n    { \"id\": \"b\", \"room\": \"s\", \"center\": [12, 1, "
        "2], \"normal\": [0, 0, 1], \"width\": 1, \"height\": 1, \"target\": \"a\" }");
    expect_refused_at(text, "[2.25, 0, 2.25]",
                      "portals[0].center: the rectangle lies in the plane of the floor face of room \"r\" but is only "
                      "partly inside that face");
}

TEST_F(HostilePrism, AMirrorBesideAWallOfAPrismIsRefused) {
    const std::string text =
        prism_file("{ \"id\": \"r\", \"floor\": " + kL + ", \"y\": [0, 3] }", "",
                   "{ \"id\": \"m\", \"room\": \"r\", \"kind\": \"mirror\", \"center\": [1, 1.5, 2], "
                   "\"normal\": [0, 0, -1], \"width\": 1, \"height\": 1 }");
    expect_refused_at(text, "[1, 1.5, 2]",
                      "portals[0].center: a mirror must lie in a face of its own room \"r\" (within 0.0001 m of the "
                      "face's plane, inside the face), but this one stands free: it lies in the plane of wall2");
}

TEST_F(HostilePrism, ALightOnTheReflexCornerOfALitLIsRefused) {
    // The corner (2, 2) is on the floor's boundary: not strictly inside.
    const std::string text = prism_file(
        "{ \"id\": \"r\", \"floor\": " + kL + ", \"y\": [0, 3], \"lights\": [ { \"position\": [2, 1, 2] } ] }", "", "",
        "  \"lighting\": \"lights\",");
    expect_refused_at(text, "[2, 1, 2]",
                      "rooms[0].lights[0].position: the light at [2, 1, 2] is not strictly inside its room \"r\"");
}

}  // namespace
}  // namespace impossible::hostile
