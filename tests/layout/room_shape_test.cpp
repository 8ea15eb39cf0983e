// layout/room_shape.hpp: rooms as lists of faces (box and prism).
#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "common/layouts.hpp"
#include "layout/room_shape.hpp"

namespace impossible::layout {
namespace {

// An L: 4 × 4 with the (+x, -z) quarter cut away, listed clockwise in (x, z).
Room l_room() { return test::prism_room("l", {{0, 0}, {0, -4}, {2, -4}, {2, -2}, {4, -2}, {4, 0}}, 0.0, 3.0); }

TEST(RoomShape, ABoxRoomHasSixFacesWithInwardFramesMatchingItsBox) {
    const Room box = test::make_room("b", {-1, 0, -2}, {3, 2.5, 4});
    EXPECT_FALSE(is_prism(box));
    EXPECT_EQ(face_count(box), 6);
    EXPECT_EQ(face_name(box, 3), "+x");
    const glm::dvec3 centre = (box.min + box.max) / 2.0;
    for (int f = 0; f < 6; ++f) {
        const FaceFrame fr = face_frame(box, f);
        EXPECT_NEAR(glm::dot(glm::cross(fr.s_axis, fr.t_axis), fr.normal), 1.0, 1e-12) << f;
        EXPECT_GT(glm::dot(centre - fr.origin, fr.normal), 0.0) << f;  // the normal points into the room
        EXPECT_GT(math::signed_area(fr.outline), 0.0) << f;
        // Every outline corner lies on the box's surface.
        for (const glm::dvec2& st : fr.outline) {
            const glm::dvec3 p = from_face(fr, st);
            EXPECT_TRUE(room_contains(box, p, 1e-12)) << f;
        }
    }
    EXPECT_NEAR(math::area(face_frame(box, static_cast<int>(Face::NegX)).outline), 6.0 * 2.5, 1e-12);
    EXPECT_NEAR(math::area(face_frame(box, static_cast<int>(Face::Floor)).outline), 4.0 * 6.0, 1e-12);
}

// The walls a segment between two points of the room can cross (what a
// light's shadow ray meets): an L's two reflex walls, in either winding;
// none in a box, a convex polygon or a square with a collinear corner; the
// inner arc of a curved corridor, not its outer arc or its ends.
TEST(RoomShape, OnlyWallsWithCornersBehindThemCanBeCrossed) {
    EXPECT_EQ(crossable_walls(l_room()), (std::vector<int>{2, 3}));
    EXPECT_EQ(crossable_walls(test::prism_room("l", {{4, 0}, {4, -2}, {2, -2}, {2, -4}, {0, -4}, {0, 0}}, 0.0, 3.0)),
              (std::vector<int>{1, 2}));
    EXPECT_TRUE(crossable_walls(test::make_room("b", {-1, 0, -2}, {3, 2.5, 4})).empty());
    EXPECT_TRUE(crossable_walls(test::prism_room("sq", {{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, 0.0, 3.0)).empty());
    std::vector<glm::dvec2> arc;
    const double quarter = 2.0 * std::atan(1.0);
    for (int k = 0; k <= 8; ++k) arc.push_back(3.0 * glm::dvec2(std::cos(quarter * k / 8), std::sin(quarter * k / 8)));
    for (int k = 8; k >= 0; --k) arc.push_back(2.0 * glm::dvec2(std::cos(quarter * k / 8), std::sin(quarter * k / 8)));
    EXPECT_TRUE(
        crossable_walls(test::prism_room("hex", {{2, 0}, {1, 1.7}, {-1, 1.7}, {-2, 0}, {-1, -1.7}}, 0, 3)).empty());
    EXPECT_EQ(crossable_walls(test::prism_room("arc", arc, 0.0, 3.0)),
              (std::vector<int>{9, 10, 11, 12, 13, 14, 15, 16}));
}

TEST(RoomShape, APrismRoomHasAWallPerEdgeFacingInwards) {
    const Room l = l_room();
    EXPECT_TRUE(is_prism(l));
    EXPECT_EQ(wall_count(l), 6);
    EXPECT_EQ(face_count(l), 8);
    EXPECT_EQ(face_name(l, 2), "wall0");
    EXPECT_FALSE(floor_convex(l));
    EXPECT_NEAR(floor_area(l), 12.0, 1e-12);
    // Wall 0 runs from (0, 0) to (0, -4): the room lies at +x.
    const FaceFrame w0 = face_frame(l, 2);
    EXPECT_NEAR(glm::distance(w0.normal, glm::dvec3(1, 0, 0)), 0.0, 1e-12);
    EXPECT_NEAR(math::area(w0.outline), 4.0 * 3.0, 1e-12);
    // Wall 3 runs from (2, -2) to (4, -2): the room lies at +z.
    EXPECT_NEAR(glm::distance(face_frame(l, 5).normal, glm::dvec3(0, 0, 1)), 0.0, 1e-12);
    for (int f = 0; f < face_count(l); ++f) {
        const FaceFrame fr = face_frame(l, f);
        EXPECT_NEAR(glm::dot(glm::cross(fr.s_axis, fr.t_axis), fr.normal), 1.0, 1e-12) << f;
        EXPECT_GT(math::signed_area(fr.outline), 0.0) << f;
        const glm::dvec2 mid = (fr.outline[0] + fr.outline[2]) / 2.0;
        // A point just inside from the face is in the room (faces of an L:
        // the middle of each wall rectangle's diagonal lies on the wall).
        if (f >= 2) {
            EXPECT_TRUE(room_contains(l, from_face(fr, mid) + 1e-6 * fr.normal)) << f;
        }
    }
}

TEST(RoomShape, TheWindingOfTheFileDoesNotChangeTheNormals) {
    Room cw = l_room();
    Room ccw = cw;
    std::reverse(ccw.floor.begin(), ccw.floor.end());
    // Reversed, wall i runs the other way round: wall 0 of ccw is (4, 0)→(4, -2)… compare by edge.
    for (int i = 0; i < 6; ++i) {
        const Wall a = wall(cw, i);
        const Wall b = wall(ccw, 4 - i < 0 ? 4 - i + 6 : 4 - i);
        EXPECT_NEAR(glm::distance(a.a, b.b), 0.0, 1e-12) << i;
        EXPECT_NEAR(glm::distance(a.inward, b.inward), 0.0, 1e-12) << i;
    }
    EXPECT_GT(math::signed_area(floor_outline(cw)), 0.0);
    EXPECT_GT(math::signed_area(floor_outline(ccw)), 0.0);
}

TEST(RoomShape, ContainmentUsesThePolygonNotTheBoundingBox) {
    const Room l = l_room();
    EXPECT_TRUE(room_contains(l, {1, 1.6, -3}));
    EXPECT_TRUE(room_contains(l, {3, 1.6, -1}));
    EXPECT_FALSE(room_contains(l, {3, 1.6, -3}));  // the notch
    EXPECT_TRUE(room_contains(l, {2, 1.6, -3}));   // on an edge
    EXPECT_FALSE(room_contains(l, {1, 3.1, -1}));  // above the ceiling
}

TEST(RoomShape, WallTexturesRunFromTheFirstCornerTowardsTheViewersRight) {
    const Room l = l_room();
    // Wall 0 from (0, 0) to (0, -4), seen from +x looking along -x: the
    // viewer's right is -z, towards corner 1.
    const glm::dvec2 uv = wall_uv(l, 0, {0, 1.0, -1.5}, 0.5);
    EXPECT_NEAR(uv.x, 3.0, 1e-12);
    EXPECT_NEAR(uv.y, -2.0, 1e-12);
}

}  // namespace
}  // namespace impossible::layout
