// The walker: rules of layout-format.md, "Head, eyes and walking".
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "math/crossing.hpp"
#include "math/eyes.hpp"
#include "math/rigid.hpp"
#include "walk/walk_test_layouts.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {
namespace {

using namespace testing;
using glm::dvec3;
using math::HeadPose;

TEST(Walker, StartsInTheStartRoomWithIdentity) {
    const layout::Layout l = doorway();
    Walker w(l);
    EXPECT_EQ(w.room(), 0);
    EXPECT_FALSE(w.started());
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));
    EXPECT_EQ(w.position(), dvec3(0, 1.6, 1));
    EXPECT_EQ(w.forward(), dvec3(0, 0, -1));
}

TEST(Walker, FirstPoseIsPlacedWithoutACrossingTest) {
    const layout::Layout l = doorway();
    Walker w(l);
    // The start is at (0, 1.6, 1); the first pose is beyond the doorway.
    EXPECT_EQ(w.step(at({3, 1.6, 0})), none());
    EXPECT_TRUE(w.started());
    EXPECT_EQ(w.room(), 0);
    EXPECT_EQ(w.position(), dvec3(3, 1.6, 0));
}

TEST(Walker, WalksThroughACoincidentDoorway) {
    const layout::Layout l = doorway();
    Walker w(l);
    w.step(at({0, 1.6, 0}, -90.0));
    EXPECT_EQ(w.step(at({1.5, 1.6, 0}, -90.0)), none());
    EXPECT_EQ(w.step(at({2.5, 1.6, 0}, -90.0)), std::vector<int>{0});
    EXPECT_EQ(w.room(), 1);
    EXPECT_EQ(w.physical_to_virtual(), math::dmat4(1.0));  // only the room changed
    EXPECT_EQ(w.position(), dvec3(2.5, 1.6, 0));
    EXPECT_EQ(w.forward(), dvec3(1, 0, 0));
    // And back.
    EXPECT_EQ(w.step(at({1.0, 1.6, 0}, -90.0)), std::vector<int>{1});
    EXPECT_EQ(w.room(), 0);
    // Beside the doorway (z = 1 is outside its 1 m width): no teleport.
    EXPECT_EQ(w.step(at({1.5, 1.6, 1.0})), none());
    EXPECT_EQ(w.step(at({2.5, 1.6, 1.0})), none());
    EXPECT_EQ(w.room(), 0);
}

TEST(Walker, OnThePlaneIsInFront) {
    const layout::Layout l = doorway();
    Walker w(l);
    w.step(at({1.0, 1.6, 0}));
    EXPECT_EQ(w.step(at({2.0, 1.6, 0})), none());  // d = 0: still in front
    EXPECT_EQ(w.room(), 0);
    EXPECT_EQ(w.step(at({2.0, 1.6, 0})), none());
    EXPECT_EQ(w.step(at({std::nextafter(2.0, 3.0), 1.6, 0})), std::vector<int>{0});
    EXPECT_EQ(w.room(), 1);
}

TEST(Walker, ResumedWalkContinuesExactlyAsTheOriginal) {
    // After a teleport through the skewed pair, a new walker resumed with the
    // old one's W and pose walks on exactly as the old one does.
    const layout::Layout l = skewed_pair();
    Walker original(l);
    const math::PortalRect& a = l.portals[0].rect;
    const math::HeadPose before = at(a.center + 0.3 * a.normal), after = at(a.center - 0.3 * a.normal);
    original.step(before);
    ASSERT_EQ(original.step(after), std::vector<int>{0});
    Walker resumed(l, original.room());
    resumed.resume(original.physical_to_virtual(), after);
    EXPECT_EQ(resumed.position(), original.position());
    // Walking on: exactly the same. Walking back: the same teleports; the
    // original restores its remembered W while the resumed walker (no
    // history) multiplies by M_BA, so positions agree to rounding.
    for (const math::HeadPose& next : {at(a.center - 0.6 * a.normal), before, after}) {
        EXPECT_EQ(resumed.step(next), original.step(next));
        EXPECT_EQ(resumed.room(), original.room());
        EXPECT_LT(glm::length(resumed.position() - original.position()), 1e-12);
    }
}

TEST(Walker, RotatedPairMapsPositionAndForward) {
    // A in r0 at the origin facing +Z; B in r1 at (5, 0, 0) facing +X:
    // M maps (x, y, z) to (5 - z, y, x).
    layout::Layout l = empty_layout("rotated");
    const int r0 = add_room(l, "r0", {-2, -1, -2}, {2, 3, 2});
    const int r1 = add_room(l, "r1", {5, -1, -2}, {9, 3, 2});
    add_pair(l, "a", r0, make_rect({0, 0, 0}, {0, 0, 1}), "b", r1, make_rect({5, 0, 0}, {1, 0, 0}));
    l.start = {r0, {0, 0, 1}, 0.0};
    Walker w(l);
    w.step(at({0.2, 0.5, 0.5}));
    EXPECT_EQ(w.step(at({0.2, 0.5, -0.5})), std::vector<int>{0});
    EXPECT_EQ(w.room(), r1);
    EXPECT_EQ(w.position(), dvec3(5.5, 0.5, 0.2));
    EXPECT_EQ(w.forward(), dvec3(1, 0, 0));  // walking into A along -Z, out of B along +X
    const auto eyes = w.eyes(0.064);
    // Physical right (+X) maps to virtual +Z, so the left eye is on the -Z side.
    EXPECT_NEAR(eyes[0].position.z, 0.2 - 0.032, 1e-15);
    EXPECT_NEAR(eyes[1].position.z, 0.2 + 0.032, 1e-15);
    EXPECT_EQ(eyes[0].position.x, 5.5);
    // Turning physically: yaw 90 looks along physical -X, virtual -Z.
    w.step(at({0.2, 0.5, -0.5}, 90.0));
    EXPECT_EQ(w.forward(), dvec3(0, 0, -1));
}

TEST(Walker, OffsetEyePastADoorPlaneTheHeadHasNotCrossed) {
    // The head 2 cm in front of the turned door's plane (x = 2), facing it
    // (+x); the left eye 5 cm ahead of the head centre and canted 5°
    // outwards stands 3 cm past the plane. The head, not the eye, walks:
    // no teleport, and the eye, reached from the head through the door,
    // has the box's inner faces (math::has_inner_faces with Eye::head).
    const layout::Layout l = turned_door();
    Walker w(l);
    const std::array<math::EyeOffset, 2> offsets = {math::eye_offset(HeadPose{{-0.032, 0.0, -0.05}, 5.0, 0.0, 0.0}),
                                                    math::eye_offset(HeadPose{{0.032, 0.0, 0.0}, -5.0, 0.0, 0.0})};
    w.step(at({1.5, 1.6, 0}, -90.0));
    EXPECT_EQ(w.step(at({1.98, 1.6, 0}, -90.0)), none());
    EXPECT_EQ(w.room(), 0);
    const math::PortalRect& door = l.portals[0].rect;
    std::array<math::Eye, 2> eyes = w.eyes(offsets);
    EXPECT_NEAR(eyes[0].position.x, 2.03, 1e-12);
    EXPECT_NEAR(eyes[0].position.z, -0.032, 1e-12);
    EXPECT_EQ(eyes[0].head, w.position());
    EXPECT_LT(math::signed_distance(door, eyes[0].position), 0.0);
    EXPECT_GT(math::signed_distance(door, eyes[0].head), 0.0);
    EXPECT_TRUE(math::has_inner_faces(door, eyes[0].position, eyes[0].head));
    // Canted: the left eye looks 5° left of the head, towards -z.
    EXPECT_NEAR(math::forward_of(eyes[0].rotation).z, -std::sin(math::radians(5.0)), 1e-15);
    EXPECT_NEAR(math::forward_of(eyes[1].rotation).z, std::sin(math::radians(5.0)), 1e-15);
    // With the IPD rule the same head's eyes stay in front of the plane.
    for (const math::Eye& eye : w.eyes(0.064)) EXPECT_GT(math::signed_distance(door, eye.position), 0.0);
    // Once the head crosses, the eyes are mapped into the annex with it: the
    // door turns the hall's +x into the annex's +z.
    EXPECT_EQ(w.step(at({2.1, 1.6, 0}, -90.0)), std::vector<int>{0});
    eyes = w.eyes(offsets);
    EXPECT_EQ(eyes[0].head, w.position());
    EXPECT_NEAR(math::forward_of(eyes[0].rotation).x, std::sin(math::radians(5.0)), 1e-12);
    EXPECT_NEAR(glm::distance(eyes[0].position, eyes[0].head), glm::length(offsets[0].position), 1e-12);
}

TEST(Walker, FastStepThroughASmallPortal) {
    layout::Layout l = empty_layout("small");
    const int r0 = add_room(l, "r0", {-2, 0, -2}, {2, 3, 2});
    const int r1 = add_room(l, "r1", {-2, 0, -2}, {2, 3, 2});
    add_pair(l, "a", r0, make_rect({0, 1.5, 0}, {0, 0, 1}, 0.5, 0.5), "b", r1,
             make_rect({0, 1.5, 0}, {0, 0, -1}, 0.5, 0.5));
    l.start = {r0, {0, 1.5, 1}, 0.0};
    {
        Walker w(l);
        w.step(at({0, 1.5, 1.0}));
        EXPECT_EQ(w.step(at({0, 1.5, -1.0})), std::vector<int>{0});  // 2 m in one frame
        EXPECT_EQ(w.room(), r1);
    }
    {
        Walker w(l);
        w.step(at({0.3, 1.5, 1.0}));  // beside the 0.5 m rectangle
        EXPECT_EQ(w.step(at({0.3, 1.5, -1.0})), none());
        EXPECT_EQ(w.room(), r0);
    }
    {
        Walker w(l);
        w.step(at({0.25, 1.75, 1.0}));  // exactly on a corner: edges included
        EXPECT_EQ(w.step(at({0.25, 1.75, -1.0})), std::vector<int>{0});
    }
}

// A chain: r0 --a/b--> r1 --c/d--> r2, each pair a translation by +10 in x.
layout::Layout chain() {
    layout::Layout l = empty_layout("chain");
    const int r0 = add_room(l, "r0", {-2, 0, -2}, {2, 3, 2});
    const int r1 = add_room(l, "r1", {8, 0, -2}, {12, 3, 2});
    const int r2 = add_room(l, "r2", {18, 0, -2}, {22, 3, 2});
    add_pair(l, "a", r0, make_rect({0, 1, 0}, {0, 0, 1}), "b", r1, make_rect({10, 1, 0}, {0, 0, -1}));
    add_pair(l, "c", r1, make_rect({10, 1, -0.5}, {0, 0, 1}), "d", r2, make_rect({20, 1, -0.5}, {0, 0, -1}));
    l.start = {r0, {0, 1.6, 1}, 0.0};
    return l;
}

TEST(Walker, OneStepPassesTwoPortalsInARow) {
    const layout::Layout l = chain();
    Walker w(l);
    w.step(at({0, 1, 1}));
    // Crosses a at z = 0, comes out of b in r1, and the rest of the segment
    // crosses c at z = -0.5 in r1.
    EXPECT_EQ(w.step(at({0, 1, -1})), (std::vector<int>{0, 2}));
    EXPECT_EQ(w.room(), 2);
    EXPECT_EQ(w.position(), dvec3(20, 1, -1));
    math::dmat4 expected(1.0);
    expected[3] = math::dvec4(20, 0, 0, 1);
    EXPECT_EQ(w.physical_to_virtual(), expected);
    // Stepping back passes d then b.
    EXPECT_EQ(w.step(at({0, 1, 1})), (std::vector<int>{3, 1}));
    EXPECT_EQ(w.room(), 0);
    EXPECT_EQ(w.position(), dvec3(0, 1, 1));
    // A shorter step stops in r1.
    EXPECT_EQ(w.step(at({0, 1, -0.25})), std::vector<int>{0});
    EXPECT_EQ(w.room(), 1);
}

// r0 holds two parallel portals on the path, p at z = -0.5 listed first and
// q at z = 0; they lead to r1 and r2.
layout::Layout two_on_a_line(double z_p, double z_q) {
    layout::Layout l = empty_layout("two");
    const int r0 = add_room(l, "r0", {-2, 0, -2}, {2, 3, 2});
    const int r1 = add_room(l, "r1", {8, 0, -2}, {12, 3, 2});
    const int r2 = add_room(l, "r2", {18, 0, -2}, {22, 3, 2});
    add_pair(l, "p", r0, make_rect({0, 1, z_p}, {0, 0, 1}), "p_out", r1, make_rect({10, 1, z_p}, {0, 0, -1}));
    add_pair(l, "q", r0, make_rect({0, 1, z_q}, {0, 0, 1}), "q_out", r2, make_rect({20, 1, z_q}, {0, 0, -1}));
    l.start = {r0, {0, 1.6, 1}, 0.0};
    return l;
}

TEST(Walker, NearestCrossingWins) {
    const layout::Layout l = two_on_a_line(-0.5, 0.0);
    Walker w(l);
    w.step(at({0, 1, 1}));
    EXPECT_EQ(w.step(at({0, 1, -1})), std::vector<int>{2});  // q (t = 0.5) before p (t = 0.75)
    EXPECT_EQ(w.room(), 2);
    EXPECT_EQ(w.position(), dvec3(20, 1, -1));
}

TEST(Walker, ExactTieGoesToThePortalListedFirst) {
    {
        const layout::Layout l = two_on_a_line(0.0, 0.0);
        Walker w(l);
        w.step(at({0.1, 1, 1}));
        EXPECT_EQ(w.step(at({0.1, 1, -1})), std::vector<int>{0});  // p, listed first
        EXPECT_EQ(w.room(), 1);
    }
    {
        // The same with the pairs listed the other way round.
        layout::Layout l = empty_layout("two, swapped");
        const int r0 = add_room(l, "r0", {-2, 0, -2}, {2, 3, 2});
        const int r1 = add_room(l, "r1", {8, 0, -2}, {12, 3, 2});
        const int r2 = add_room(l, "r2", {18, 0, -2}, {22, 3, 2});
        add_pair(l, "q", r0, make_rect({0, 1, 0}, {0, 0, 1}), "q_out", r2, make_rect({20, 1, 0}, {0, 0, -1}));
        add_pair(l, "p", r0, make_rect({0, 1, 0}, {0, 0, 1}), "p_out", r1, make_rect({10, 1, 0}, {0, 0, -1}));
        l.start = {r0, {0, 1.6, 1}, 0.0};
        Walker w(l);
        w.step(at({0.1, 1, 1}));
        EXPECT_EQ(w.step(at({0.1, 1, -1})), std::vector<int>{0});  // q now
        EXPECT_EQ(w.room(), r2);
    }
}

TEST(Walker, CrossingsPerFrameAreBounded) {
    // A degenerate layout: in r0, a (+Z) and d (-Z) coincide; in r1, b (-Z)
    // and c (+Z). a → b is the identity and so is c → d, and the rest of the
    // segment always starts on the shared plane: a, c, a, c, ... forever.
    layout::Layout l = empty_layout("loop");
    const int r0 = add_room(l, "r0", {-2, 0, -2}, {2, 3, 2});
    const int r1 = add_room(l, "r1", {-2, 0, -2}, {2, 3, 2});
    add_pair(l, "a", r0, make_rect({0, 1, 0}, {0, 0, 1}), "b", r1, make_rect({0, 1, 0}, {0, 0, -1}));
    add_pair(l, "c", r1, make_rect({0, 1, 0}, {0, 0, 1}), "d", r0, make_rect({0, 1, 0}, {0, 0, -1}));
    l.start = {r0, {0, 1.6, 1}, 0.0};
    Walker w(l);
    w.step(at({0, 1, 1}));
    const std::vector<int> passed = w.step(at({0, 1, -1}));
    ASSERT_EQ(passed.size(), static_cast<std::size_t>(kMaxCrossingsPerFrame));
    for (std::size_t k = 0; k < passed.size(); ++k) EXPECT_EQ(passed[k], k % 2 == 0 ? 0 : 2);
    EXPECT_EQ(w.room(), r0);
    EXPECT_EQ(w.position(), dvec3(0, 1, -1));
}

TEST(PortalLinks, TransferMatricesComputedOncePerPortal) {
    const layout::Layout l = chain();
    const links::PortalLinks links = links::link_portals(l);
    ASSERT_EQ(links.transfer.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const auto& p = l.portals[i];
        EXPECT_EQ(links.transfer[i], math::transfer_matrix(p.rect, l.portals[p.target].rect));
    }
    ASSERT_EQ(links.room_portals.size(), 3u);
    EXPECT_EQ(links.room_portals[0], std::vector<int>{0});
    EXPECT_EQ(links.room_portals[1], (std::vector<int>{1, 2}));
    EXPECT_EQ(links.room_portals[2], std::vector<int>{3});
}

TEST(PortalLinks, BrokenIndicesAreLeftOut) {
    layout::Layout l = chain();
    l.portals[0].target = 17;
    l.portals[3].room = -1;
    const links::PortalLinks links = links::link_portals(l);
    EXPECT_EQ(links.room_portals[0], std::vector<int>{});
    EXPECT_EQ(links.room_portals[2], std::vector<int>{});
    Walker w(l);
    w.step(at({0, 1, 1}));
    EXPECT_EQ(w.step(at({0, 1, -1})), none());  // nothing to pass, no crash
}

}  // namespace
}  // namespace impossible::walk
