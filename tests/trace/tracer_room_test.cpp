// One closed room without portals: faces, checker, prop boxes, glTF triangles.
#include <gtest/gtest.h>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::bytes_of;
using test::face_color;
using test::kTol;
using test::make_room;
using test::one_room;
using test::shade_by_hand;

TEST(TracerRoom, EveryPixelOfAClosedRoomShowsIt) {
    const layout::Layout l = one_room();
    TraceDesc desc;
    desc.head.position = {0.3, 1.5, -0.2};
    desc.head.yaw_deg = 35.0;
    desc.head.pitch_deg = -20.0;
    desc.eye_width = 24;
    desc.eye_height = 16;
    const image::Image image = trace_frame(l, desc).value();
    ASSERT_EQ(image.width, 48);
    ASSERT_EQ(image.height, 16);
    ASSERT_EQ(image.rgb.size(), 48u * 16u * 3u);
    EXPECT_EQ(test::count_id(image, 1), 48 * 16);
}

TEST(TracerRoom, CentrePixelsHaveTheWallsShadeComputedByHand) {
    const layout::Layout l = one_room();
    TraceDesc desc;
    desc.head.position = {0.0, 1.5, 0.0};
    desc.eye_width = 9;  // odd: the centre pixel looks straight ahead, along -Z
    desc.eye_height = 9;
    const image::Image image = trace_frame(l, desc).value();
    // The -z wall, normal +Z, no checker; both eyes see the same colour.
    const auto expected = bytes_of(shade_by_hand(face_color(l.rooms[0], layout::Face::NegZ), {0, 0, 1}, false));
    EXPECT_EQ(test::pixel_rgb(image, 4, 4), expected);
    EXPECT_EQ(test::pixel_rgb(image, 9 + 4, 4), expected);
    // Row 0 is the top: the ceiling (normal -Y, no light from above); the last row the floor.
    const auto ceiling = bytes_of(shade_by_hand(face_color(l.rooms[0], layout::Face::Ceiling), {0, -1, 0}, false));
    const auto floor = bytes_of(shade_by_hand(face_color(l.rooms[0], layout::Face::Floor), {0, 1, 0}, false));
    EXPECT_EQ(test::pixel_rgb(image, 4, 0), ceiling);
    EXPECT_EQ(test::pixel_rgb(image, 4, 8), floor);
    EXPECT_NE(ceiling, floor);

    // The rays themselves: the left eye at head - ipd/2 · right.
    const PixelRay left = pixel_ray(desc, 0, 4, 4), right = pixel_ray(desc, 1, 4, 4);
    EXPECT_NEAR(left.origin.x, -0.032, kTol);
    EXPECT_NEAR(right.origin.x, 0.032, kTol);
    EXPECT_NEAR(left.dir.z, -1.0, kTol);
    const TraceHit hit = trace_ray(prepare_scene(l).value(), left.origin, left.dir, 0, 8);
    EXPECT_EQ(hit.id, 1);
    EXPECT_EQ(hit.portals_passed, 0);
    EXPECT_NEAR(hit.point.x, -0.032, kTol);
    EXPECT_NEAR(hit.point.y, 1.5, kTol);
    EXPECT_NEAR(hit.point.z, -2.0, kTol);
    EXPECT_EQ(hit.normal, dvec3(0, 0, 1));
}

TEST(TracerRoom, CheckerDarkensAlternateSquaresOfTheFaces) {
    layout::Layout l = one_room();
    l.rooms[0].checker = 0.5;
    const Scene scene = prepare_scene(l).value();
    const dvec3 floor = face_color(l.rooms[0], layout::Face::Floor);
    struct Case {
        double x, z;
        bool dark;
    };
    // Squares (floor(x / 0.5), floor(z / 0.5)): (1, 0) odd, (0, 0) even, (-1, 0) odd.
    for (const Case c : {Case{0.3, 0.2, false}, Case{0.8, 0.2, true}, Case{-0.2, 0.2, true}, Case{-0.7, 0.2, false}}) {
        const TraceHit hit = trace_ray(scene, {c.x, 1.5, c.z}, {0, -1, 0}, 0, 8);
        EXPECT_EQ(hit.id, 1);
        EXPECT_NEAR(hit.point.y, 0.0, kTol);
        const dvec3 expected = shade_by_hand(floor, {0, 1, 0}, c.dark);
        EXPECT_NEAR(hit.color.x, expected.x, 1e-12) << c.x;
        EXPECT_NEAR(hit.color.z, expected.z, 1e-12) << c.x;
    }
}

TEST(TracerRoom, PropBoxesFaceOutwardsAndAreNotChequered) {
    layout::Layout l = one_room();
    l.rooms[0].checker = 0.5;
    const dvec3 red{0.9, 0.2, 0.2};
    l.rooms[0].props.push_back(layout::BoxProp{{-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}, red, {}, {}});
    const Scene scene = prepare_scene(l).value();

    const TraceHit top = trace_ray(scene, {0.3, 2.0, 0.2}, {0, -1, 0}, 0, 8);
    EXPECT_EQ(top.id, 1);
    EXPECT_NEAR(top.point.y, 1.0, kTol);
    EXPECT_EQ(top.normal, dvec3(0, 1, 0));
    EXPECT_NEAR(top.color.x, shade_by_hand(red, {0, 1, 0}, false).x, 1e-12);

    // The -x side: normal -X faces away from the light, ambient only.
    const TraceHit side = trace_ray(scene, {-1.5, 0.5, 0.1}, {1, 0, 0}, 0, 8);
    EXPECT_NEAR(side.point.x, -0.5, kTol);
    EXPECT_EQ(side.normal, dvec3(-1, 0, 0));
    EXPECT_NEAR(side.color.x, 0.9 * shading::kAmbient, 1e-12);

    // From inside the box its faces are back faces: the ray reaches the +x wall.
    const TraceHit inside = trace_ray(scene, {0.0, 0.5, 0.1}, {1, 0, 0}, 0, 8);
    EXPECT_NEAR(inside.point.x, 2.0, kTol);
    EXPECT_EQ(inside.normal, dvec3(-1, 0, 0));
    EXPECT_EQ(inside.id, 1);
}

TEST(TracerRoom, GltfTrianglesArePlacedAndSeenFromTheirCounterClockwiseSide) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    model.position = {0.0, 0.0, -1.0};
    model.yaw_deg = 90.0;  // model +Z turns to +X
    model.scale = 2.0;
    const dvec3 green{0.2, 0.8, 0.3};
    // Counter-clockwise seen from the model's +Z.
    model.triangles.push_back({{dvec3(-0.5, 0, 0), dvec3(0.5, 0, 0), dvec3(0, 1, 0)},
                               {dvec3(0, 0, 1), dvec3(0, 0, 1), dvec3(0, 0, 1)},
                               green});
    l.rooms[0].props.push_back(model);
    const Scene scene = prepare_scene(l).value();
    ASSERT_EQ(scene.rooms[0].triangles.size(), 1u);

    // Placed: vertices (0,0,0), (0,0,-2), (0,2,-1), facing +X.
    const TraceHit front = trace_ray(scene, {1.5, 0.5, -1.0}, {-1, 0, 0}, 0, 8);
    EXPECT_EQ(front.id, 1);
    EXPECT_NEAR(front.point.x, 0.0, 1e-9);
    EXPECT_NEAR(front.normal.x, 1.0, 1e-9);
    EXPECT_NEAR(front.color.y, shade_by_hand(green, {1, 0, 0}, false).y, 1e-9);

    // From behind the triangle is culled: the ray reaches the +x wall.
    const TraceHit back = trace_ray(scene, {-1.5, 0.5, -1.0}, {1, 0, 0}, 0, 8);
    EXPECT_NEAR(back.point.x, 2.0, kTol);

    // Outside the triangle (above its apex): the -x wall.
    const TraceHit miss = trace_ray(scene, {1.5, 2.5, -1.0}, {-1, 0, 0}, 0, 8);
    EXPECT_NEAR(miss.point.x, -2.0, kTol);
}

TEST(TracerRoom, TriangleNormalsAreInterpolatedBarycentrically) {
    layout::Layout l = one_room();
    layout::GltfProp model;  // identity placement
    const dvec3 n0{0, 0, 1};
    const dvec3 n1 = glm::normalize(dvec3(1, 0, 1));
    const dvec3 n2 = glm::normalize(dvec3(0, 1, 1));
    model.triangles.push_back({{dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0)}, {n0, n1, n2}, dvec3(0.5)});
    l.rooms[0].props.push_back(model);
    const TraceHit hit = trace_ray(prepare_scene(l).value(), {0.25, 0.25, 1.0}, {0, 0, -1}, 0, 8);
    // Weights: 0.5 for vertex 0, 0.25 each for vertices 1 and 2.
    const dvec3 expected = glm::normalize(0.5 * n0 + 0.25 * n1 + 0.25 * n2);
    EXPECT_NEAR(hit.point.z, 0.0, kTol);
    EXPECT_NEAR(hit.normal.x, expected.x, 1e-12);
    EXPECT_NEAR(hit.normal.y, expected.y, 1e-12);
    EXPECT_NEAR(hit.normal.z, expected.z, 1e-12);
}

TEST(TracerRoom, AnEyeOutsideEveryRoomSeesNothing) {
    // Looking away from the room's box: no front face anywhere.
    const TraceHit hit = trace_ray(prepare_scene(one_room()).value(), {0, 1.5, 5}, {0, 0, 1}, 0, 8);
    EXPECT_EQ(hit.id, kIdNothing);
    EXPECT_EQ(hit.room, -1);
    EXPECT_EQ(hit.color, ::impossible::shading::kBackgroundColor);
}

TEST(TracerRoom, BadFrameDescriptionsAreErrors) {
    const layout::Layout l = one_room();
    TraceDesc desc;
    desc.eye_width = 4;
    desc.eye_height = 4;
    desc.room = 1;
    EXPECT_EQ(trace_frame(l, desc).error(), "trace: room index 1 is out of range");
    desc.room = 0;
    desc.eye_height = 0;
    EXPECT_EQ(trace_frame(l, desc).error(), "trace: bad eye image size");
    desc.eye_height = 4;
    desc.max_depth = -1;
    EXPECT_EQ(trace_frame(l, desc).error(), "trace: max_depth is negative");
    desc.max_depth = 0;
    EXPECT_TRUE(trace_frame(l, desc));
}

}  // namespace
}  // namespace impossible::trace
