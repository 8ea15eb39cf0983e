// The walker and mirrors and windows (layout-format.md, "Head, eyes and
// walking", last paragraph): only doors teleport; a head crossing a
// mirror's or a window's plane stays where it is, in its room.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/geometric.hpp>

#include "walk/walk_test_layouts.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {
namespace {

using namespace testing;
using glm::dvec3;
using math::HeadPose;

int add_mirror(layout::Layout& l, const std::string& id, int room, const math::PortalRect& rect) {
    layout::Portal p{id, room, rect};
    p.kind = layout::PortalKind::Mirror;
    p.tint = dvec3(0.9, 0.95, 1.0);
    l.portals.push_back(p);
    return static_cast<int>(l.portals.size()) - 1;
}

int add_window_pair(layout::Layout& l, const std::string& id_a, int ra, const math::PortalRect& a,
                    const std::string& id_b, int rb, const math::PortalRect& b) {
    const int ia = add_pair(l, id_a, ra, a, id_b, rb, b);
    for (int k = ia; k <= ia + 1; ++k) {
        l.portals[static_cast<std::size_t>(k)].kind = layout::PortalKind::Window;
        l.portals[static_cast<std::size_t>(k)].reflectance = 0.2;
    }
    return ia;
}

// doorway() (hall and annex, a coincident door at x = 2) with a mirror in
// the hall's -z wall, a window in the hall's -x wall whose partner is in the
// annex's +x wall, and a window pair in the annex's -z and +z walls. The
// door is listed after the mirror and windows, so that the walker has to
// skip them to find it.
layout::Layout mirrors_and_windows() {
    layout::Layout l = empty_layout("mirrors and windows");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int annex = add_room(l, "annex", {2, 0, -2}, {6, 3, 2});
    add_mirror(l, "hall_mirror", hall, make_rect({0, 1.5, -2}, {0, 0, 1}, 2.0, 2.0));
    add_window_pair(l, "hall_window", hall, make_rect({-2, 1.5, 0}, {1, 0, 0}, 1.0, 1.0), "annex_window", annex,
                    make_rect({6, 1.5, 0}, {-1, 0, 0}, 1.0, 1.0));
    add_window_pair(l, "annex_north", annex, make_rect({4, 1.5, -2}, {0, 0, 1}, 1.0, 1.0), "annex_south", annex,
                    make_rect({4, 1.5, 2}, {0, 0, -1}, 1.0, 1.0));
    add_pair(l, "hall_east", hall, make_rect({2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), "annex_west", annex,
             make_rect({2, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    l.start = {hall, {0, 1.6, 1}, 0.0};
    return l;
}

constexpr int kHall = 0;
constexpr int kAnnex = 1;
constexpr int kHallMirror = 0;
constexpr int kHallEast = 5;
constexpr int kAnnexWest = 6;

TEST(WalkerMirrors, TheLayoutIsWhatTheTestsSay) {
    const layout::Layout l = mirrors_and_windows();
    ASSERT_EQ(l.portals.size(), 7u);
    EXPECT_EQ(l.portals[kHallMirror].kind, layout::PortalKind::Mirror);
    EXPECT_EQ(l.portals[kHallMirror].target, -1);
    EXPECT_EQ(l.portals[1].kind, layout::PortalKind::Window);
    EXPECT_EQ(l.portals[1].target, 2);
    EXPECT_EQ(l.portals[kHallEast].kind, layout::PortalKind::Door);
    EXPECT_EQ(l.portals[kHallEast].target, kAnnexWest);
    // The mirror is among its room's portals (the renderers need it there).
    const Walker w(l);
    const std::vector<int>& hall = w.links().room_portals[kHall];
    EXPECT_NE(std::find(hall.begin(), hall.end(), kHallMirror), hall.end());
}

TEST(WalkerMirrors, AHeadCrossingAMirrorStaysInItsRoom) {
    const layout::Layout l = mirrors_and_windows();
    Walker w(l);
    w.step(at({0, 1.5, -1}));
    EXPECT_EQ(w.step(at({0, 1.5, -1.99})), none());
    EXPECT_EQ(w.step(at({0, 1.5, -2.0})), none());  // on the plane
    EXPECT_EQ(w.step(at({0, 1.5, -2.3})), none());  // behind it, through the middle of the rectangle
    EXPECT_EQ(w.room(), kHall);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));
    EXPECT_EQ(w.position(), dvec3(0, 1.5, -2.3));
    EXPECT_EQ(w.forward(), dvec3(0, 0, -1));
    // And back out through the back of the mirror.
    EXPECT_EQ(w.step(at({0, 1.5, 0})), none());
    EXPECT_EQ(w.room(), kHall);
    EXPECT_EQ(w.position(), dvec3(0, 1.5, 0));
}

TEST(WalkerMirrors, AFastStepThroughAMirrorDoesNotTeleport) {
    const layout::Layout l = mirrors_and_windows();
    Walker w(l);
    w.step(at({0, 1.5, 1.9}));
    EXPECT_EQ(w.step(at({0, 1.5, -50.0})), none());  // 52 m in one frame, through the mirror's centre
    EXPECT_EQ(w.room(), kHall);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));
    EXPECT_EQ(w.position(), dvec3(0, 1.5, -50.0));
}

TEST(WalkerMirrors, AHeadCrossingAWindowStaysInItsRoom) {
    const layout::Layout l = mirrors_and_windows();
    Walker w(l);
    w.step(at({-1, 1.5, 0}, 90.0));
    EXPECT_EQ(w.step(at({-2.0, 1.5, 0}, 90.0)), none());
    EXPECT_EQ(w.step(at({-2.2, 1.5, 0}, 90.0)), none());
    EXPECT_EQ(w.room(), kHall);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));
    EXPECT_EQ(w.position(), dvec3(-2.2, 1.5, 0));
    EXPECT_EQ(w.forward(), dvec3(-1, 0, 0));
    // A fast step through the window and far beyond.
    Walker fast(l);
    fast.step(at({1.5, 1.5, 0}));
    EXPECT_EQ(fast.step(at({-40, 1.5, 0})), none());
    EXPECT_EQ(fast.room(), kHall);
    EXPECT_EQ(fast.position(), dvec3(-40, 1.5, 0));
}

TEST(WalkerMirrors, TwoWindowsOfOneRoomAreNotWalkedThroughEither) {
    const layout::Layout l = mirrors_and_windows();
    Walker w(l, kAnnex);
    w.step(at({4, 1.5, 0}));
    // Out through the south window, then in one step through both.
    EXPECT_EQ(w.step(at({4, 1.5, 2.5})), none());
    EXPECT_EQ(w.step(at({4, 1.5, -2.5})), none());
    EXPECT_EQ(w.room(), kAnnex);
    EXPECT_EQ(w.position(), dvec3(4, 1.5, -2.5));
}

TEST(WalkerMirrors, DoorsStillTeleportBesideMirrorsAndWindows) {
    const layout::Layout l = mirrors_and_windows();
    Walker w(l);
    w.step(at({0, 1.6, 0}, -90.0));
    EXPECT_EQ(w.step(at({2.5, 1.6, 0}, -90.0)), std::vector<int>{kHallEast});
    EXPECT_EQ(w.room(), kAnnex);
    EXPECT_EQ(w.position(), dvec3(2.5, 1.6, 0));
    // In the annex, through its window (toward +x) and back: still the annex.
    EXPECT_EQ(w.step(at({6.5, 1.6, 0}, -90.0)), none());
    EXPECT_EQ(w.room(), kAnnex);
    EXPECT_EQ(w.step(at({1.0, 1.6, 0}, 90.0)), std::vector<int>{kAnnexWest});
    EXPECT_EQ(w.room(), kHall);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));
}

// A mirror and a door on one segment, the mirror crossed first: it does not
// take the crossing, the door behind it still teleports.
TEST(WalkerMirrors, AMirrorBeforeADoorDoesNotTakeTheCrossing) {
    layout::Layout l = empty_layout("mirror in front of a door");
    const int r0 = add_room(l, "r0", {-2, 0, 0}, {2, 3, 2});
    const int r1 = add_room(l, "r1", {8, 0, -2}, {12, 3, 2});
    add_mirror(l, "m", r0, make_rect({0, 1, 0}, {0, 0, 1}, 1.0, 2.0));  // r0's -z wall
    add_pair(l, "a", r0, make_rect({0, 1, -0.5}, {0, 0, 1}), "b", r1, make_rect({10, 1, -0.5}, {0, 0, -1}));
    l.start = {r0, {0, 1.6, 1}, 0.0};
    Walker w(l);
    w.step(at({0, 1, 1}));
    EXPECT_EQ(w.step(at({0, 1, -1})), std::vector<int>{1});
    EXPECT_EQ(w.room(), r1);
}

}  // namespace
}  // namespace impossible::walk
