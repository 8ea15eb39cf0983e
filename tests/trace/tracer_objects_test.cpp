// Crossing objects in the tracer (layout-format.md, "Moving props, hands and
// crossing objects"): a prop through a door shows its part in front of the
// door in its own room and its image behind the partner door in the other; a
// moving prop walks and teleports with time; a hand is placed from the head
// and cut by a door like a prop. Every expected point, id and colour is worked
// out by hand in the comments.
#include <gtest/gtest.h>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::add_pair;
using test::expect_point;
using test::kBlue;
using test::kGreen;
using test::kRed;
using test::make_portal;
using test::make_room;
using test::shade_by_hand;

// Rooms a (0) and b (1), each [-3, 3] × [0, 3] × [-3, 3]. Door a_door in a at
// (0, 1.5, -1), normal +z (x in [-0.5, 0.5], y in [0.5, 2.5]); b_door in b at
// (1, 1.5, 0), normal -z. M_ab moves by (1, 0, 1) and turns nothing.
layout::Layout objects_pair() {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("a", {-3, 0, -3}, {3, 3, 3}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("b", {-3, 0, -3}, {3, 3, 3}, {0, 0.2, 0.1}));
    add_pair(l, make_portal("a_door", 0, {0, 1.5, -1}, {0, 0, 1}), make_portal("b_door", 1, {1, 1.5, 0}, {0, 0, -1}));
    l.start.room = 0;
    l.start.position = {0, 1.5, 1};
    return l;
}

// The frame's objects of a view at `time` with the head at (0, 1.5, 1) in a.
FrameObjects objects_at(const Scene& scene, double time,
                        std::optional<std::array<math::HeadPose, 2>> hands = std::nullopt) {
    math::View view;
    view.room = 0;
    view.head.position = {0, 1.5, 1};
    view.time = time;
    view.hands = hands;
    return place_frame_objects(scene, view);
}

void expect_color(const dvec3& got, const dvec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

const RayLimits kObjectLimits{8};

// A red box x in [-0.2, 0.2], y in [1.3, 1.7], z in [-1.3, -0.7] stands half
// through a_door (z = -1). In a only z >= -1 shows; in b its image, moved by
// (1, 0, 1) to x in [0.8, 1.2], z in [-0.3, 0.3], shows only in front of
// b_door (z < 0): z in [-0.3, 0).
TEST(TracerObjects, ABoxHalfThroughADoorShowsBothPartsFromTheFront) {
    layout::Layout l = objects_pair();
    l.rooms[0].props.push_back(layout::BoxProp{{-0.2, 1.3, -1.3}, {0.2, 1.7, -0.7}, kRed, {}, {}});
    const Scene scene = prepare_scene(l).value();
    EXPECT_TRUE(scene.rooms[0].boxes.empty());  // dynamic: no part of the room's static surfaces
    ASSERT_EQ(scene.props.size(), 1u);

    // Straight at it: the own part's front face at z = -0.7, room a's id.
    const TraceHit own = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kObjectLimits);
    EXPECT_EQ(own.id, 1);
    expect_point(own.point, {0, 1.5, -0.7});
    expect_color(own.color, shade_by_hand(kRed, {0, 0, 1}, false));

    // Over its top through the door: from (0, 2.25, 1) along (0, -1, -4) the
    // ray is at y = 1.825 at z = -0.7 and y = 1.75 at z = -1 (above the own
    // part), passes the door, and from the virtual eye (1, 2.25, 2) meets the
    // image's top y = 1.7 at t = 0.55: (1, 1.7, -0.2), in front of b_door.
    const TraceHit image = trace_ray(scene, {0, 2.25, 1}, {0, -1, -4}, 0, kObjectLimits);
    EXPECT_EQ(image.id, 2);
    EXPECT_EQ(image.portals_passed, 1);
    expect_point(image.point, {1, 1.7, -0.2});
    expect_point(image.normal, {0, 1, 0});
    expect_color(image.color, shade_by_hand(kRed, {0, 1, 0}, false));

    // The part behind a_door is not in a: along -z at y = 1.5 beside the own
    // part's front (x = 0.3 misses it) the ray goes through the door to b's wall.
    const TraceHit beside = trace_ray(scene, {0.3, 1.5, 1}, {0, 0, -1}, 0, kObjectLimits);
    EXPECT_EQ(beside.id, 2);
    expect_point(beside.point, {1.3, 1.5, -3});
}

// From b, in front of b_door, the image is a solid box: its face z = -0.3
// (facing -z) is seen from (1, 1.5, -2) along +z. Its cut at z = 0 is open:
// looking from inside the door's side it is not a surface.
TEST(TracerObjects, TheImageIsSeenFromTheOtherRoom) {
    layout::Layout l = objects_pair();
    l.rooms[0].props.push_back(layout::BoxProp{{-0.2, 1.3, -1.3}, {0.2, 1.7, -0.7}, kRed, {}, {}});
    const Scene scene = prepare_scene(l).value();

    const TraceHit hit = trace_ray(scene, {1, 1.5, -2}, {0, 0, 1}, 1, kObjectLimits);
    EXPECT_EQ(hit.id, 2);
    EXPECT_EQ(hit.portals_passed, 0);
    expect_point(hit.point, {1, 1.5, -0.3});
    expect_color(hit.color, shade_by_hand(kRed, {0, 0, -1}, false));

    // Behind b_door, from (1, 1.5, 2) along -z: the image's part behind b's
    // plane (z in [0, 0.3]) is not there, and its cut at z = 0 is open, so
    // the ray passes through (b_door's own box faces away) to b's wall.
    const TraceHit behind = trace_ray(scene, {1, 1.5, 2}, {0, 0, -1}, 1, kObjectLimits);
    EXPECT_EQ(behind.id, 2);
    expect_point(behind.point, {1, 1.5, -3});

    // From b through b_door into a: over the image (y = 2.1 at z = -0.3), the
    // door at y = 2.25; in a from the virtual eye (0, 1.25, -3) along (0, 1, 2)
    // the own part (y > 2.2 there) is missed, and a's ceiling y = 3 is met at
    // t = 1.75: (0, 3, 0.5).
    const TraceHit through = trace_ray(scene, {1, 1.25, -2}, {0, 1, 2}, 1, kObjectLimits);
    EXPECT_EQ(through.id, 1);
    expect_point(through.point, {0, 3, 0.5});

    // A ray from a's side that enters the own part through its cut (z = -1)
    // sees no surface there: from (0, 1.5, -2) along +z (behind a_door, which
    // is seen only from its front), the box's faces are back faces; a's +z
    // wall shows.
    const TraceHit cut = trace_ray(scene, {0, 1.5, -2}, {0, 0, 1}, 0, kObjectLimits);
    EXPECT_EQ(cut.id, 1);
    expect_point(cut.point, {0, 1.5, 3});
}

// "This holds also when B lies in the object's own room": both doors in room
// 0; a_door at (0, 1.5, -1) normal +z, b_door at (2, 1.5, 1) normal -z, so
// M_ab moves by (2, 0, 2). The image of the box lies at x in [1.8, 2.2],
// z in [0.7, 1.3], kept for z < 1.
TEST(TracerObjects, AnImageInTheObjectsOwnRoom) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("a", {-3, 0, -3}, {3, 3, 3}));
    add_pair(l, make_portal("a_door", 0, {0, 1.5, -1}, {0, 0, 1}), make_portal("b_door", 0, {2, 1.5, 1}, {0, 0, -1}));
    l.rooms[0].props.push_back(layout::BoxProp{{-0.2, 1.3, -1.3}, {0.2, 1.7, -0.7}, kGreen, {}, {}});
    const Scene scene = prepare_scene(l).value();

    const TraceHit image = trace_ray(scene, {2, 1.5, -2}, {0, 0, 1}, 0, kObjectLimits);
    EXPECT_EQ(image.id, 1);
    expect_point(image.point, {2, 1.5, 0.7});
    expect_color(image.color, shade_by_hand(kGreen, {0, 0, -1}, false));
    const TraceHit own = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kObjectLimits);
    expect_point(own.point, {0, 1.5, -0.7});
}

// A blue box x in [-0.2, 0.2], y in [1.3, 1.7], z in [-0.3, 0.3] (centre
// (0, 1.5, 0)) slides to offset (0, 0, -2) over 2 s, through a_door.
layout::Layout moving_box_layout() {
    layout::Layout l = objects_pair();
    layout::BoxProp box{{-0.2, 1.3, -0.3}, {0.2, 1.7, 0.3}, kBlue, "slider", {}};
    box.motion.keys = {{0.0, {0, 0, 0}}, {2.0, {0, 0, -2}}};
    l.rooms[0].props.push_back(box);
    return l;
}

TEST(TracerObjects, AMovingPropWalksThroughADoor) {
    const Scene scene = prepare_scene(moving_box_layout()).value();
    const dvec3 eye{0, 1.5, 1}, ahead{0, 0, -1};
    const dvec3 front = shade_by_hand(kBlue, {0, 0, 1}, false);

    // t = 0: where it is listed, in a: its front z = 0.3.
    const TraceHit at0 = trace_ray(scene, eye, ahead, 0, kObjectLimits, objects_at(scene, 0.0));
    EXPECT_EQ(at0.id, 1);
    expect_point(at0.point, {0, 1.5, 0.3});
    expect_color(at0.color, front);
    // t = 0.9: offset -0.9, z in [-1.2, -0.6], its centre still in a: the own
    // part's front at z = -0.6.
    const TraceHit at09 = trace_ray(scene, eye, ahead, 0, kObjectLimits, objects_at(scene, 0.9));
    EXPECT_EQ(at09.id, 1);
    expect_point(at09.point, {0, 1.5, -0.6});
    // t = 1.5: its centre passed a_door at t = 1; in b, moved by M_ab:
    // z in [-0.8, -0.2] at x in [0.8, 1.2]. Through the door from the virtual
    // eye (1, 1.5, 2): its front at (1, 1.5, -0.2), b's id.
    const TraceHit at15 = trace_ray(scene, eye, ahead, 0, kObjectLimits, objects_at(scene, 1.5));
    EXPECT_EQ(at15.id, 2);
    expect_point(at15.point, {1, 1.5, -0.2});
    expect_color(at15.color, front);
    // t = 5: held at the last key, offset -2: front at (1, 1.5, -0.7) in b.
    const TraceHit at5 = trace_ray(scene, eye, ahead, 0, kObjectLimits, objects_at(scene, 5.0));
    EXPECT_EQ(at5.id, 2);
    expect_point(at5.point, {1, 1.5, -0.7});
    // Without a frame's objects, a ray sees the objects at time 0.
    expect_point(trace_ray(scene, eye, ahead, 0, kObjectLimits).point, {0, 1.5, 0.3});
}

// The frame's time reaches every pixel: the centre pixel (9 × 9, ipd 0, so
// the ray is exactly -z) shows the box in a at t = 0 and in b at t = 1.5.
TEST(TracerObjects, TraceFrameTakesTheViewsTime) {
    const Scene scene = prepare_scene(moving_box_layout()).value();
    TraceDesc desc;
    desc.head.position = {0, 1.5, 1};
    desc.ipd = 0.0;
    desc.eye_width = 9;
    desc.eye_height = 9;
    desc.threads = 1;
    const auto front = test::bytes_of(shade_by_hand(kBlue, {0, 0, 1}, false));
    const image::Image at0 = trace_frame(scene, desc).value();
    EXPECT_EQ(test::pixel_id(at0, 4, 4), 1);
    EXPECT_EQ(test::pixel_rgb(at0, 4, 4), front);
    desc.time = 1.5;
    const image::Image at15 = trace_frame(scene, desc).value();
    EXPECT_EQ(test::pixel_id(at15, 4, 4), 2);
    EXPECT_EQ(test::pixel_rgb(at15, 4, 4), front);
}

// The default hand, a box 0.08 × 0.04 × 0.16 m of colour (0.85, 0.70, 0.60),
// posed at (0, 1.5, -0.98) looking along -z: x in [-0.04, 0.04], y in
// [1.48, 1.52], z in [-1.06, -0.90], its centre in front of a_door, so in a.
TEST(TracerObjects, AHandThroughADoorIsCutAndImaged) {
    const Scene scene = prepare_scene(objects_pair()).value();
    const dvec3 skin{0.85, 0.70, 0.60};
    math::HeadPose hand;
    hand.position = {0, 1.5, -0.98};
    math::HeadPose away;  // the other hand, out of every ray below
    away.position = {-2, 1.0, 1};
    const FrameObjects objects = objects_at(scene, 0.0, std::array<math::HeadPose, 2>{away, hand});

    // Its own part's front, the face z = -0.90.
    const TraceHit own = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kObjectLimits, objects);
    EXPECT_EQ(own.id, 1);
    expect_point(own.point, {0, 1.5, -0.9});
    expect_color(own.color, shade_by_hand(skin, {0, 0, 1}, false));

    // Over it through the door: from (0, 2.03, 1) along (0, -1, -4), y = 1.555
    // at z = -0.9 and 1.53 at z = -1; from the virtual eye (1, 2.03, 2) the
    // image's top y = 1.52 at t = 0.51: (1, 1.52, -0.04), in b.
    const TraceHit image = trace_ray(scene, {0, 2.03, 1}, {0, -1, -4}, 0, kObjectLimits, objects);
    EXPECT_EQ(image.id, 2);
    expect_point(image.point, {1, 1.52, -0.04}, 1e-12);
    expect_color(image.color, shade_by_hand(skin, {0, 1, 0}, false));

    // No hands in the view: none drawn, the ray reaches b's wall.
    const TraceHit none = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kObjectLimits, objects_at(scene, 0.0));
    EXPECT_EQ(none.id, 2);
    expect_point(none.point, {1, 1.5, -3});

    // Pushed through (centre z = -1.5): in b, moved by M_ab to x in [0.96,
    // 1.04], z in [-0.58, -0.42]; seen through the door at (1, 1.5, -0.42).
    hand.position = {0, 1.5, -1.5};
    const FrameObjects through = objects_at(scene, 0.0, std::array<math::HeadPose, 2>{away, hand});
    const TraceHit far = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kObjectLimits, through);
    EXPECT_EQ(far.id, 2);
    expect_point(far.point, {1, 1.5, -0.42}, 1e-12);
}

}  // namespace
}  // namespace impossible::trace
