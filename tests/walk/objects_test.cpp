// walk/objects.hpp: which props are dynamic, moving props walked through a
// turned door, hands placed from the head, and the instances each object
// becomes (layout-format.md, "Moving props, hands and crossing objects").
#include <gtest/gtest.h>

#include <chrono>

#include <glm/geometric.hpp>

#include "links/portal_links.hpp"
#include "walk/objects.hpp"
#include "walk/walk_test_layouts.hpp"

// A namespace of its own: the unity build compiles this file with the
// other walk tests, which name their rooms kHall and kAnnex too.
namespace impossible::walk::objects_test {
namespace {

using glm::dvec3;
using namespace testing;

constexpr double kEps = 1e-12;

dvec3 apply(const math::dmat4& m, const dvec3& p) { return dvec3(m * math::dvec4(p, 1.0)); }
dvec3 turn(const math::dmat4& m, const dvec3& v) { return dvec3(m * math::dvec4(v, 0.0)); }

void expect_near(const dvec3& a, const dvec3& b, double eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

layout::BoxProp box(dvec3 lo, dvec3 hi) {
    layout::BoxProp b;
    b.min = lo;
    b.max = hi;
    return b;
}

constexpr int kHall = 0;
constexpr int kAnnex = 1;

// A 0.4 m box sliding 3 m along +x in 2 s, from x 0.5..0.9.
layout::BoxProp sliding_box(bool loop = false) {
    layout::BoxProp b = box({0.5, 0.0, -0.2}, {0.9, 0.4, 0.2});
    b.id = "crate";
    b.motion.keys = {{0.0, {0, 0, 0}}, {2.0, {3, 0, 0}}};
    if (loop) b.motion.keys.push_back({4.0, {0, 0, 0}});
    b.motion.loop = loop;
    return b;
}

ObjectSet set_of(const layout::Layout& l) { return build_object_set(l, links::link_portals(l)); }

TEST(DynamicProps, OnlyPropsThatMoveOrAreCutByADoor) {
    layout::Layout l = turned_door();
    l.rooms[kHall].props = {box({-1, 0, -1}, {-0.5, 1, -0.5}),       // far from the door
                            box({1.7, 0, -0.2}, {2.3, 0.8, 0.2}),    // half through it
                            box({1.5, 0, -0.2}, {2.0, 0.8, 0.2}),    // touching its plane from the front
                            box({1.5, 0, -0.2}, {1.999, 0.8, 0.2}),  // a millimetre short
                            box({1.7, 0, 0.6}, {2.3, 0.8, 1.0}),     // through the plane beside the rectangle
                            box({2.0, 0, -0.2}, {2.5, 0.8, 0.2}),    // touching it from behind
                            sliding_box()};
    const ObjectSet set = set_of(l);
    // Touching from the front, a prop is cut to itself and its image is
    // empty: it stays static, drawn whole as before.
    EXPECT_EQ(set.dynamic[kHall], (std::vector<bool>{false, true, false, false, false, true, true}));
    ASSERT_EQ(set.props.size(), 3u);
    EXPECT_EQ(set.props[0].index, 1);
    EXPECT_EQ(set.props[1].index, 5);
    EXPECT_EQ(set.props[2].index, 6);
    expect_near(set.props[2].anchor, {0.7, 0.2, 0.0});
}

TEST(DynamicProps, ModelTrianglesMeetOnlyWithinTheRectangle) {
    layout::Layout l = turned_door();
    layout::GltfProp across, beside;
    assets::ModelTriangle t;
    t.position = {dvec3(1.8, 0.5, 0.0), dvec3(2.2, 0.5, 0.0), dvec3(2.0, 1.0, 0.1)};
    across.triangles = {t};
    t.position = {dvec3(1.8, 0.5, 0.7), dvec3(2.2, 0.5, 0.7), dvec3(2.0, 1.0, 0.8)};
    beside.triangles = {t};
    l.rooms[kHall].props = {across, beside};
    EXPECT_EQ(set_of(l).dynamic[kHall], (std::vector<bool>{true, false}));
}

TEST(WalkProp, SlidesThroughATurnedDoorAndArrivesTurned) {
    layout::Layout l = turned_door();
    l.rooms[kHall].props = {sliding_box()};
    const ObjectSet set = set_of(l);
    const PropState before = walk_prop(set, 0, 0.5);
    EXPECT_EQ(before.room, kHall);
    EXPECT_EQ(before.w, math::dmat4(1.0));
    expect_near(before.offset, {0.75, 0, 0});
    const PropState after = walk_prop(set, 0, 2.0);
    EXPECT_EQ(after.room, kAnnex);
    expect_near(after.offset, {3, 0, 0});
    // The centre 1.7 m behind the hall's door is 1.7 m in front of the annex's.
    const math::dmat4 to_cell = after.w;
    expect_near(apply(to_cell, dvec3(0.7, 0.2, 0.0) + after.offset), {12.0, 0.2, -0.3}, 1e-9);
    expect_near(turn(to_cell, {1, 0, 0}), {0, 0, 1}, 1e-12);
    // Held after the last key.
    EXPECT_EQ(walk_prop(set, 0, 50.0).w, after.w);
    // A negative time reads as 0.
    EXPECT_EQ(walk_prop(set, 0, -3.0).offset, dvec3(0.0));
}

TEST(WalkProp, LoopingThroughADoorAndBackRepeatsExactly) {
    layout::Layout l = turned_door();
    l.rooms[kHall].props = {sliding_box(true)};
    const ObjectSet set = set_of(l);
    EXPECT_EQ(walk_prop(set, 0, 1.0).room, kAnnex);
    const PropState back = walk_prop(set, 0, 4.0);
    EXPECT_EQ(back.room, kHall);
    EXPECT_EQ(back.w, math::dmat4(1.0));  // the pair just passed restores W exactly
    // A million periods later, fast: the repeat is found after one period.
    const auto start = std::chrono::steady_clock::now();
    const PropState far_out = walk_prop(set, 0, 4.0e6 + 2.0);
    const PropState far_back = walk_prop(set, 0, 4.0e6 + 0.5);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 0.5);
    EXPECT_EQ(far_out.room, kAnnex);
    EXPECT_EQ(far_out.w, walk_prop(set, 0, 2.0).w);
    EXPECT_EQ(far_back.room, kHall);
}

TEST(PlaceObjects, APropInTheDoorwayIsCutAndImaged) {
    layout::Layout l = turned_door();
    l.rooms[kHall].props = {sliding_box()};
    const ObjectSet set = set_of(l);
    math::View view;
    view.room = kHall;
    view.time = 0.8;  // the box spans x 1.7..2.1, its centre still in the hall
    const std::vector<ObjectInstance> objects = place_objects(set, view);
    ASSERT_EQ(objects.size(), 2u);
    const ObjectInstance& own = objects[0];
    EXPECT_EQ(own.cell, kHall);
    EXPECT_FALSE(own.image);
    ASSERT_EQ(own.cut_count, 1);
    EXPECT_FALSE(own.cuts[0].strict);
    EXPECT_EQ(own.cuts[0].door, 0);
    const ObjectInstance& image = objects[1];
    EXPECT_EQ(image.cell, kAnnex);
    EXPECT_TRUE(image.image);
    ASSERT_EQ(image.cut_count, 1);
    EXPECT_TRUE(image.cuts[0].strict);
    EXPECT_EQ(image.cuts[0].door, 1);
    // The far end (x 2.1, 0.1 m behind the hall's door) shows 0.1 m in front of the annex's.
    const dvec3 far_end = apply(image.to_cell, {0.9, 0.2, 0.0});
    expect_near(far_end, {12.0, 0.2, -1.9}, 1e-9);
    const double d = glm::dot(image.cuts[0].plane, math::dvec4(far_end, 1.0));
    EXPECT_NEAR(d, 0.1, 1e-9);
}

TEST(PlaceObjects, AHandThroughADoorWhileTheHeadIsNot) {
    layout::Layout l = turned_door();
    const ObjectSet set = set_of(l);
    math::View view;
    view.room = kHall;
    view.head.position = {1.5, 1.6, 0.0};
    const math::HeadPose left{{1.0, 1.2, 0.0}, -90.0, 0.0, 0.0};
    const math::HeadPose right{{2.3, 1.2, 0.0}, -90.0, 0.0, 0.0};  // 0.3 m through, facing +x
    view.hands = std::array<math::HeadPose, 2>{left, right};
    const std::vector<ObjectInstance> objects = place_objects(set, view);
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[0].kind, ObjectKind::Hand);
    EXPECT_EQ(objects[0].cell, kHall);
    EXPECT_EQ(objects[0].cut_count, 0);
    EXPECT_EQ(objects[1].index, 1);
    EXPECT_EQ(objects[1].cell, kAnnex);
    expect_near(apply(objects[1].to_cell, dvec3(0.0)), {12.0, 1.2, -1.7}, 1e-9);
    // The hand's forward (-z of its frame) points along the annex's +z.
    expect_near(turn(objects[1].to_cell, {0, 0, -1}), {0, 0, 1}, 1e-12);
    const HandState placed = place_hand(set, kHall, view.head.position, right);
    EXPECT_EQ(placed.teleports, std::vector<int>{0});

    // Pushed only 5 cm through, the 16 cm hand meets the door: its own
    // part in the annex, its image back in the hall.
    view.hands = std::array<math::HeadPose, 2>{left, math::HeadPose{{2.05, 1.2, 0.0}, -90.0, 0.0, 0.0}};
    const std::vector<ObjectInstance> meeting = place_objects(set, view);
    ASSERT_EQ(meeting.size(), 3u);
    EXPECT_EQ(meeting[1].cell, kAnnex);
    EXPECT_EQ(meeting[1].cut_count, 1);
    EXPECT_EQ(meeting[2].cell, kHall);
    EXPECT_TRUE(meeting[2].image);
}

TEST(PlaceObjects, AFastStepThroughTwoDoorsInOneSegment) {
    // Coincident doorways hall | annex | store along x: one key step of 6 m
    // passes both, as one fast head step would.
    layout::Layout l = doorway();
    const int store = add_room(l, "store", {6, 0, -2}, {10, 3, 2});
    add_pair(l, "annex_east", 1, make_rect({6, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), "store_west", store,
             make_rect({6, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    layout::BoxProp b = box({0.5, 0.0, -0.2}, {0.9, 0.4, 0.2});
    b.id = "dart";
    b.motion.keys = {{0.0, {0, 0, 0}}, {0.01, {7, 0, 0}}};
    l.rooms[0].props = {b};
    const ObjectSet set = set_of(l);
    EXPECT_EQ(walk_prop(set, 0, 0.01).room, store);
    EXPECT_EQ(walk_prop(set, 0, 0.005).room, 1);  // at 3.5 m: x 4.2, in the annex
}

}  // namespace
}  // namespace impossible::walk::objects_test
