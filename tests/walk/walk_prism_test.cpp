// The walker in prism rooms (layout-format.md, "Rooms of any shape" and
// "Head, eyes and walking"): an L-shaped room whose point in the notch is
// outside it, a walk round its concave corner that stays in it, and a walk
// through a door in the wall beside that corner and back; the object set's
// copy of the rooms keeps their shape.
#include <gtest/gtest.h>

#include "common/layouts.hpp"
#include "layout/room_shape.hpp"
#include "links/portal_links.hpp"
#include "walk/objects.hpp"
#include "walk/walk_test_layouts.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {
namespace {

using glm::dvec3;
using testing::at;
using testing::none;

// Room 0: the L [0, 4]² without [2, 4] × [2, 4] (y 0..3), with a door 1 m
// wide in its wall x = 2 beside the concave corner (2, 2); room 1: a box
// [10, 14] × [0, 3] × [1, 5] whose +x face holds the partner.
layout::Layout walk_l_room() {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(impossible::test::prism_room("ell", {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, 0.0, 3.0));
    l.rooms.push_back(impossible::test::make_room("box", {10, 0, 1}, {14, 3, 5}));
    impossible::test::add_pair(l, impossible::test::make_portal("a", 0, {2, 1.1, 3}, {-1, 0, 0}, 1.0, 2.2),
                               impossible::test::make_portal("b", 1, {14, 1.1, 3}, {-1, 0, 0}, 1.0, 2.2));
    l.start.room = 0;
    l.start.position = {1, 1.6, 1};
    return l;
}

TEST(WalkPrism, TheNotchOfAnLIsOutsideIt) {
    const layout::Layout l = walk_l_room();
    const layout::Room& ell = l.rooms[0];
    EXPECT_TRUE(layout::room_contains(ell, {1, 1.6, 1}));
    EXPECT_TRUE(layout::room_contains(ell, {1, 1.6, 3.5}));
    EXPECT_TRUE(layout::room_contains(ell, {2, 1.6, 3}));   // on a wall: edges count
    EXPECT_FALSE(layout::room_contains(ell, {3, 1.6, 3}));  // in the notch, inside the bounding box
    EXPECT_FALSE(layout::room_contains(ell, {1, 3.1, 1}));  // above the ceiling
}

TEST(WalkPrism, RoundTheCornerOfAnLAndThroughTheDoorBesideIt) {
    const layout::Layout l = walk_l_room();
    Walker w(l);
    w.step(at({1, 1.6, 1}));
    // Round the concave corner into the L's north arm: no door, same room.
    EXPECT_EQ(w.step(at({1.5, 1.6, 2.5})), none());
    EXPECT_EQ(w.step(at({1.5, 1.6, 3.0}, -90.0)), none());
    EXPECT_EQ(w.room(), 0);
    // East through the door in the wall x = 2: into the box, turned round
    // (both doors face -x), 0.5 m past its partner at x = 14.
    EXPECT_EQ(w.step(at({2.5, 1.6, 3.0}, -90.0)), std::vector<int>{0});
    EXPECT_EQ(w.room(), 1);
    EXPECT_NEAR(w.position().x, 13.5, 1e-12);
    EXPECT_NEAR(w.position().z, 3.0, 1e-12);
    EXPECT_TRUE(layout::room_contains(l.rooms[1], w.position()));
    // And back west.
    EXPECT_EQ(w.step(at({1.5, 1.6, 3.0}, 90.0)), std::vector<int>{1});
    EXPECT_EQ(w.room(), 0);
    EXPECT_TRUE(layout::room_contains(l.rooms[0], w.position()));
    // Through the wall beside the door (z = 2.2 is outside its 1 m width)
    // into the notch: walls do not teleport; the head is then in no room.
    EXPECT_EQ(w.step(at({1.5, 1.6, 2.2})), none());
    EXPECT_EQ(w.step(at({2.5, 1.6, 2.2})), none());
    EXPECT_EQ(w.room(), 0);
    EXPECT_FALSE(layout::room_contains(l.rooms[0], w.position()));
}

TEST(WalkPrism, TheObjectSetsRoomsKeepTheirShape) {
    const layout::Layout l = walk_l_room();
    const ObjectSet set = build_object_set(l, links::link_portals(l));
    ASSERT_EQ(set.walk_layout->rooms.size(), 2u);
    const layout::Room& ell = set.walk_layout->rooms[0];
    EXPECT_EQ(ell.floor, l.rooms[0].floor);
    EXPECT_EQ(layout::face_count(ell), 8);
    EXPECT_EQ(ell.face_color.size(), 8u);
    EXPECT_FALSE(layout::room_contains(ell, {3, 1.6, 3}));
}

}  // namespace
}  // namespace impossible::walk
