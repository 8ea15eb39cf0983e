// The hole rule: a portal in the plane of one of its room's faces is wholly
// inside it (a hole), wholly outside it (free-standing), or an error; holes
// in one face must not overlap.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

// Rooms r and s share the box [-2,0,-2]..[2,3,2]. Each portal given here
// belongs to r and is paired with a free-standing portal in the middle of s.
struct TestPortal {
    std::string id;
    std::string center;
    std::string normal;
    std::string up = "[0, 1, 0]";
    double width = 1.0;
    double height = 2.2;
};

std::string layout_with(const std::vector<TestPortal>& portals) {
    std::string text =
        "{\n"
        "  \"format\": \"impossible-layout\", \"version\": 1,\n"
        "  \"start\": { \"room\": \"r\", \"position\": [0, 1.6, 0] },\n"
        "  \"rooms\": [\n"
        "    { \"id\": \"r\", \"min\": [-2, 0, -2], \"max\": [2, 3, 2] },\n"
        "    { \"id\": \"s\", \"min\": [-2, 0, -2], \"max\": [2, 3, 2] }\n"
        "  ],\n"
        "  \"portals\": [\n";
    for (std::size_t i = 0; i < portals.size(); ++i) {
        const TestPortal& p = portals[i];
        const std::string size = "\"width\": " + std::to_string(p.width) + ", \"height\": " + std::to_string(p.height);
        text += "    { \"id\": \"" + p.id + "\", \"room\": \"r\", \"center\": " + p.center +
                ", \"normal\": " + p.normal + ", \"up\": " + p.up + ", " + size + ", \"target\": \"" + p.id +
                "_back\" },\n";
        text += "    { \"id\": \"" + p.id + "_back\", \"room\": \"s\", \"center\": [0, 1.5, " +
                std::to_string(-0.5 * double(i)) + "], \"normal\": [0, 0, 1], " + size + ", \"target\": \"" + p.id +
                "\" }";
        text += i + 1 < portals.size() ? ",\n" : "\n";
    }
    text += "  ]\n}\n";
    return text;
}

int hole_of(const std::vector<TestPortal>& portals, std::size_t index = 0) {
    const Layout layout = expect_valid(layout_with(portals));
    return layout.portals.size() > 2 * index ? layout.portals[2 * index].hole_face : -99;
}

TEST(LayoutHoles, ADoorwayInsideAWallIsAHole) {
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 0]", "[-1, 0, 0]"}}), int(Face::PosX));
    EXPECT_EQ(hole_of({{"a", "[-2, 1.1, 0]", "[1, 0, 0]"}}), int(Face::NegX));
    EXPECT_EQ(hole_of({{"a", "[0, 1.1, -2]", "[0, 0, 1]"}}), int(Face::NegZ));
    EXPECT_EQ(hole_of({{"a", "[0, 1.1, 2]", "[0, 0, -1]"}}), int(Face::PosZ));
    EXPECT_EQ(hole_of({{"a", "[0, 0, 0]", "[0, 1, 0]", "[0, 0, -1]", 1, 1}}), int(Face::Floor));
    EXPECT_EQ(hole_of({{"a", "[0, 3, 0]", "[0, -1, 0]", "[0, 0, 1]", 1, 1}}), int(Face::Ceiling));
    // The whole face, edges included, is still inside.
    EXPECT_EQ(hole_of({{"a", "[2, 1.5, 0]", "[-1, 0, 0]", "[0, 1, 0]", 4, 3}}), int(Face::PosX));
}

TEST(LayoutHoles, TheCornersMayBeOffThePlaneByUpTo1e4) {
    EXPECT_EQ(hole_of({{"a", "[1.99995, 1.1, 0]", "[-1, 0, 0]"}}), int(Face::PosX));
    EXPECT_EQ(hole_of({{"a", "[1.9998, 1.1, 0]", "[-1, 0, 0]"}}), -1);  // free-standing
}

TEST(LayoutHoles, ARectangleWhollyOutsideTheFaceStandsFree) {
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 3]", "[-1, 0, 0]"}}), -1);
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 2.5]", "[-1, 0, 0]"}}), -1);  // touching the face's edge
}

TEST(LayoutHoles, APortalFacingOutOfTheRoomIsNoHole) {
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 0]", "[1, 0, 0]"}}), -1);
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 1.8]", "[1, 0, 0]"}}), -1);  // even partly over the face
}

TEST(LayoutHoles, ARectanglePartlyInsideTheFaceIsAnError) {
    const std::string text = layout_with({{"a", "[2, 1.1, 1.8]", "[-1, 0, 0]"}});
    expect_one_error(text, "[2, 1.1, 1.8]",
                     "portals[0].center: the rectangle lies in the plane of the +x face of room \"r\" "
                     "but is only partly inside that face");
    const std::string low = layout_with({{"a", "[0, 1, 2]", "[0, 0, -1]", "[0, 1, 0]", 1, 2.2}});
    expect_one_error(low, "[0, 1, 2]", "portals[0].center: the rectangle lies in the plane of the +z face");
}

TEST(LayoutHoles, RotatedRectanglesAreTestedByTheirCorners) {
    // A diamond (45°) in the +x wall: inside, then over the edge.
    EXPECT_EQ(hole_of({{"a", "[2, 1.5, 0]", "[-1, 0, 0]", "[0, 1, 1]", 1, 1}}), int(Face::PosX));
    const std::string text = layout_with({{"a", "[2, 1.5, 1.6]", "[-1, 0, 0]", "[0, 1, 1]", 1, 1}});
    expect_one_error(text, "[2, 1.5, 1.6]", "portals[0].center: the rectangle lies in the plane");
    // Beyond the face's corner its bounding box overlaps the face, but the
    // diamond itself stays outside.
    EXPECT_EQ(hole_of({{"a", "[2, 3.5, 2.5]", "[-1, 0, 0]", "[0, 1, 1]", 1, 1}}), -1);
}

TEST(LayoutHoles, HolesInOneFaceMustNotOverlap) {
    const std::string text = layout_with({{"a", "[2, 1.1, 0]", "[-1, 0, 0]"}, {"b", "[2, 1.1, 0.5]", "[-1, 0, 0]"}});
    expect_one_error(text, "[2, 1.1, 0.5]",
                     "portals[2].center: its hole in the +x face of room \"r\" overlaps the hole of "
                     "portal \"a\" (portals[0])");
    // Side by side, sharing an edge, is fine; so are holes in different faces.
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 0]", "[-1, 0, 0]"}, {"b", "[2, 1.1, 1]", "[-1, 0, 0]"}}, 1), int(Face::PosX));
    EXPECT_EQ(hole_of({{"a", "[2, 1.1, 0]", "[-1, 0, 0]"}, {"b", "[-2, 1.1, 0]", "[1, 0, 0]"}}, 1), int(Face::NegX));
}

TEST(LayoutHoles, EachOverlappingPortalIsReportedOnce) {
    const std::string text = layout_with({{"a", "[2, 1.1, 0]", "[-1, 0, 0]"},
                                          {"b", "[2, 1.1, 0.2]", "[-1, 0, 0]"},
                                          {"c", "[2, 1.1, 0.4]", "[-1, 0, 0]"}});
    const LoadResult r = load(text);
    ASSERT_EQ(r.errors.size(), 2u) << all_messages(r.errors);
    EXPECT_TRUE(has_error(r, position_of(text, "[2, 1.1, 0.2]"), "portals[2].center: its hole"));
    EXPECT_TRUE(has_error(r, position_of(text, "[2, 1.1, 0.4]"), "portals[4].center: its hole"));
}

}  // namespace
}  // namespace layout_test
