// Rays through portals: coincident, rotated and translated pairs, holes in
// walls, and the recursion limit. Expected hit points are computed by hand in
// the comments.
#include <gtest/gtest.h>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::add_pair;
using test::expect_point;
using test::face_color;
using test::kBlue;
using test::kGreen;
using test::kRed;
using test::kTol;
using test::make_portal;
using test::make_room;
using test::shade_by_hand;

// Hall and annex fill the same box; a free-standing door with coincident
// portals (transfer = identity) joins them, as in the default layout.
layout::Layout coincident_pair() {
    layout::Layout l;
    l.rooms.push_back(make_room("hall", {-2, 0, -2}, {2, 3, 2}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("annex", {-2, 0, -2}, {2, 3, 2}, {0, 0.2, 0.1}));
    add_pair(l, make_portal("hall_door", 0, {0, 1.1, 0}, {0, 0, 1}, 1.0, 2.2),
             make_portal("annex_door", 1, {0, 1.1, 0}, {0, 0, -1}, 1.0, 2.2));
    return l;
}

TEST(TracerPortal, CoincidentPairShowsTheOtherRoomAndNothingMoves) {
    const layout::Layout l = coincident_pair();
    const Scene scene = prepare_scene(l).value();
    EXPECT_EQ(scene.portals[0].transfer, dmat4(1.0));

    const TraceHit through = trace_ray(scene, {0, 1.1, 1.5}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(through.id, 2);
    EXPECT_EQ(through.room, 1);
    EXPECT_EQ(through.portals_passed, 1);
    EXPECT_EQ(through.origin, dvec3(0, 1.1, 1.5));  // the virtual eye is the eye
    expect_point(through.point, {0, 1.1, -2});
    const dvec3 annex_wall = shade_by_hand(face_color(l.rooms[1], layout::Face::NegZ), {0, 0, 1}, false);
    EXPECT_NEAR(through.color.y, annex_wall.y, 1e-12);
    EXPECT_NEAR(through.color.z, annex_wall.z, 1e-12);

    // Past the door's edge (it crosses z = 0 at x = 0.64): the hall's own wall.
    const TraceHit beside = trace_ray(scene, {0, 1.1, 1.5}, {1.5, 0, -3.5}, 0, 8);
    EXPECT_EQ(beside.id, 1);
    expect_point(beside.point, {1.5, 1.1, -2});

    // From the annex side the other way round; the hall is clipped to z > 0.
    const TraceHit back = trace_ray(scene, {0, 1.1, -1.5}, {0, 0, 1}, 1, 8);
    EXPECT_EQ(back.id, 1);
    EXPECT_EQ(back.portals_passed, 1);
    expect_point(back.point, {0, 1.1, 2});
}

// Room A at the origin; room B ten metres east. Portal a cuts a hole in A's
// -z wall and faces +Z; portal b cuts a hole in B's -x wall and faces +X.
// Looking into a along -Z comes out of b along +X: a 90° turn.
layout::Layout rotated_pair() {
    layout::Layout l;
    l.rooms.push_back(make_room("a", {-2, 0, -2}, {2, 3, 2}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("b", {10, 0, -2}, {14, 3, 2}, {0, 0.2, 0.1}));
    add_pair(l, make_portal("a_door", 0, {0, 1.5, -2}, {0, 0, 1}), make_portal("b_door", 1, {10, 1.5, 0}, {1, 0, 0}));
    return l;
}

TEST(TracerPortal, HolesAreFoundInTheRightFaces) {
    const Scene scene = prepare_scene(rotated_pair()).value();
    for (int f = 0; f < layout::kFaceCount; ++f) {
        const auto& a_holes = scene.rooms[0].faces[f].holes;
        const auto& b_holes = scene.rooms[1].faces[f].holes;
        EXPECT_EQ(a_holes, (f == int(layout::Face::NegZ) ? std::vector<int>{0} : std::vector<int>{})) << f;
        EXPECT_EQ(b_holes, (f == int(layout::Face::NegX) ? std::vector<int>{1} : std::vector<int>{})) << f;
    }
}

TEST(TracerPortal, RotatedPairTurnsTheRayByNinetyDegrees) {
    const layout::Layout l = rotated_pair();
    const Scene scene = prepare_scene(l).value();
    // Eye (0, 1.5, 0) is 2 m in front of a; the virtual eye is 2 m behind b:
    // (10 - 2, 1.5, 0), looking along +X, and meets B's +x wall at x = 14.
    const TraceHit straight = trace_ray(scene, {0, 1.5, 0}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(straight.id, 2);
    EXPECT_EQ(straight.portals_passed, 1);
    expect_point(straight.origin, {8, 1.5, 0});
    expect_point(straight.dir, {1, 0, 0});
    expect_point(straight.point, {14, 1.5, 0});
    EXPECT_EQ(straight.normal, dvec3(-1, 0, 0));
    const dvec3 b_wall = shade_by_hand(face_color(l.rooms[1], layout::Face::PosX), {-1, 0, 0}, false);
    EXPECT_NEAR(straight.color.x, b_wall.x, 1e-12);

    // Direction (0.2, 0, -1) in a's frame is (0.2, 0, -1) → rotated by 180°
    // about up → (-0.2, 0, 1) in b's frame, whose right is -Z and normal +X:
    // world (1, 0, 0.2). From (8, 1.5, 0) it meets x = 14 at z = 1.2.
    const TraceHit slanted = trace_ray(scene, {0, 1.5, 0}, {0.2, 0, -1}, 0, 8);
    EXPECT_EQ(slanted.id, 2);
    expect_point(slanted.dir, {1, 0, 0.2});
    expect_point(slanted.point, {14, 1.5, 1.2});
}

TEST(TracerPortal, ARayThroughAHoleHitsThePortalAndOneBesideItHitsTheWall) {
    const layout::Layout l = rotated_pair();
    const Scene scene = prepare_scene(l).value();
    // The hole spans x in [-0.5, 0.5] at z = -2; from (0, 1.5, 0) the ray
    // (s, 0, -1) meets the wall at x = 2s.
    const TraceHit edge = trace_ray(scene, {0, 1.5, 0}, {0.25, 0, -1}, 0, 8);  // x = 0.5: the edge is the hole's
    EXPECT_EQ(edge.id, 2);
    EXPECT_EQ(edge.portals_passed, 1);
    const TraceHit beside = trace_ray(scene, {0, 1.5, 0}, {0.25 + 1e-6, 0, -1}, 0, 8);
    EXPECT_EQ(beside.id, 1);
    EXPECT_EQ(beside.portals_passed, 0);
    expect_point(beside.point, {0.5 + 2e-6, 1.5, -2}, 1e-12);
    EXPECT_EQ(beside.normal, dvec3(0, 0, 1));
    // Above the hole's top edge (y = 2.5): the wall again.
    const TraceHit above = trace_ray(scene, {0, 1.5, 0}, {0, 0.5 + 1e-6, -1}, 0, 8);
    EXPECT_EQ(above.id, 1);
    const TraceHit below_top = trace_ray(scene, {0, 1.5, 0}, {0, 0.5 - 1e-6, -1}, 0, 8);
    EXPECT_EQ(below_top.id, 2);
}

TEST(TracerPortal, HoleRuleNeedsThePlaneTheFaceAndTheNormal) {
    const AxisRect neg_z = room_face_rect({-2, 0, -2}, {2, 3, 2}, layout::Face::NegZ);
    math::PortalRect rect = make_portal("p", 0, {0, 1.5, -2}, {0, 0, 1}).rect;
    EXPECT_TRUE(cuts_hole(neg_z, rect));
    rect.center.z = -2 + 0.9e-4;  // within the tolerance of the plane
    EXPECT_TRUE(cuts_hole(neg_z, rect));
    rect.center.z = -2 + 2e-4;  // in front of the wall: free-standing
    EXPECT_FALSE(cuts_hole(neg_z, rect));
    rect = make_portal("p", 0, {5, 1.5, -2}, {0, 0, 1}).rect;  // in the plane, wholly outside the face
    EXPECT_FALSE(cuts_hole(neg_z, rect));
    rect = make_portal("p", 0, {0, 1.5, -2}, {0, 0, -1}).rect;  // facing out of the room
    EXPECT_FALSE(cuts_hole(neg_z, rect));
}

// Two overlapping rooms with a free-standing pair: a at (0, 1.5, -1) facing
// +Z in A, b at (1, 1.5, 0) facing -Z in B. M_AB is the translation (1, 0, 1).
layout::Layout translated_pair() {
    layout::Layout l;
    l.rooms.push_back(make_room("a", {-3, 0, -3}, {3, 3, 3}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("b", {-3, 0, -3}, {3, 3, 3}, {0, 0.2, 0.1}));
    add_pair(l, make_portal("a_door", 0, {0, 1.5, -1}, {0, 0, 1}), make_portal("b_door", 1, {1, 1.5, 0}, {0, 0, -1}));
    return l;
}

TEST(TracerPortal, TranslatedPairMovesTheVirtualEye) {
    const Scene scene = prepare_scene(translated_pair()).value();
    expect_point(dvec3(scene.portals[0].transfer * dvec4(0, 0, 0, 1)), {1, 0, 1});
    expect_point(dmat3(scene.portals[0].transfer) * dvec3(0.3, 0.4, 0.5), {0.3, 0.4, 0.5});
    // Eye (0.2, 1.5, 1) → virtual eye (1.2, 1.5, 2); the ray meets B's -z wall at z = -3.
    const TraceHit hit = trace_ray(scene, {0.2, 1.5, 1}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(hit.id, 2);
    expect_point(hit.origin, {1.2, 1.5, 2});
    expect_point(hit.point, {1.2, 1.5, -3});
}

TEST(TracerPortal, TargetGeometryBehindThePlaneIsClippedAndInFrontIsSeen) {
    layout::Layout l = translated_pair();
    // In B, on the line of sight from the virtual eye (1, 1.5, 2) along -Z:
    // a red box behind b's plane (z in [0.5, 1]) and a blue one in front of it.
    l.rooms[1].props.push_back(layout::BoxProp{{0.8, 1.3, 0.5}, {1.2, 1.7, 1.0}, kRed, {}, {}});
    l.rooms[1].props.push_back(layout::BoxProp{{0.8, 1.3, -1.0}, {1.2, 1.7, -0.5}, kBlue, {}, {}});
    // A box straddling the plane on another line of sight (x = 0.7). It meets
    // b_door's rectangle, so it is a crossing object (layout-format.md,
    // "Moving props, hands and crossing objects"): b shows its part in front
    // of b (z <= 0), and a shows the part behind b as its image, moved by
    // M_ba = (-1, 0, -1): x in [-0.4, -0.25], z in (-1, -0.7].
    l.rooms[1].props.push_back(layout::BoxProp{{0.6, 1.3, -0.3}, {0.75, 1.7, 0.3}, kRed, {}, {}});
    const Scene scene = prepare_scene(l).value();

    const TraceHit hit = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(hit.id, 2);
    expect_point(hit.point, {1, 1.5, -0.5});
    EXPECT_NEAR(hit.color.z, shade_by_hand(kBlue, {0, 0, 1}, false).z, 1e-12);
    EXPECT_EQ(hit.color.x, 0.0);

    // In a, before the door, the image's front face z = -0.7.
    const TraceHit image = trace_ray(scene, {-0.3, 1.5, 1}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(image.id, 1);
    expect_point(image.point, {-0.3, 1.5, -0.7});
    // Its own part in b (z in [-0.3, 0]), seen through the door over the
    // image: from (-0.3, 2.25, 1) along (0, -1, -4) the ray is at y = 1.825
    // at z = -0.7 and 1.75 at the door (z = -1); from the virtual eye
    // (0.7, 2.25, 2) it meets the top y = 1.7 at t = 0.55: (0.7, 1.7, -0.2).
    const TraceHit own = trace_ray(scene, {-0.3, 2.25, 1}, {0, -1, -4}, 0, 8);
    EXPECT_EQ(own.id, 2);
    expect_point(own.point, {0.7, 1.7, -0.2});

    // The same red box seen directly by an eye standing in B is not clipped.
    const TraceHit direct = trace_ray(scene, {1, 1.5, 2}, {0, 0, -1}, 1, 8);
    expect_point(direct.point, {1, 1.5, 1.0});
}

TEST(TracerPortal, AnEyeOneMillimetreInFrontSeesOnlyTheTarget) {
    const layout::Layout l = translated_pair();
    const Scene scene = prepare_scene(l).value();
    const TraceHit hit = trace_ray(scene, {0, 1.5, -0.999}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(hit.id, 2);
    expect_point(hit.origin, {1, 1.5, 0.001}, 1e-12);
    expect_point(hit.point, {1, 1.5, -3});
    // The whole view: the portal fills it (the rasteriser's near plane at
    // 0.01 m would cut the front face here; its inner faces show the same).
    TraceDesc desc;
    desc.head.position = {0, 1.5, -0.999};
    desc.eye_width = 16;
    desc.eye_height = 9;
    const image::Image image = trace_frame(scene, desc).value();
    EXPECT_EQ(test::count_id(image, 2), 32 * 9);
}

TEST(TracerPortal, AnEyeInsideTheBoxSeesTheTargetOnTheInnerFacesAndItsRoomBehind) {
    layout::Layout l = translated_pair();
    // A green box in B just in front of b's plane, between the virtual eye and
    // the mapped back face.
    l.rooms[1].props.push_back(layout::BoxProp{{0.8, 1.3, -0.2}, {1.2, 1.7, -0.15}, kGreen, {}, {}});
    const Scene scene = prepare_scene(l).value();
    const dvec3 eye{0, 1.5, -1.1};    // 0.1 m behind a's plane, in its column,
    const dvec3 head{0, 1.5, -0.95};  // reached from the head through the door
    const auto from_eye = [&](const dvec3& dir) {
        return trace_ray(scene, PixelRay{eye, dir, head}, 0, RayLimits{8}, scene.rest);
    };

    // Along -Z: a's back face at z = -1.25 → virtual eye (1, 1.5, -0.1), which
    // is in front of b: nothing clips, and the green box at z = -0.15 shows.
    const TraceHit ahead = from_eye({0, 0, -1});
    EXPECT_EQ(ahead.id, 2);
    EXPECT_EQ(ahead.portals_passed, 1);
    expect_point(ahead.origin, {1, 1.5, -0.1});
    expect_point(ahead.point, {1, 1.5, -0.15});
    EXPECT_NEAR(ahead.color.y, shade_by_hand(kGreen, {0, 0, 1}, false).y, 1e-12);

    // Through a's side face x = 0.5 at t = 0.5 (z = -1.15): B's +x wall at
    // x = 3, z = -0.1 - 0.2.
    const TraceHit side = from_eye({1, 0, -0.1});
    EXPECT_EQ(side.id, 2);
    expect_point(side.point, {3, 1.5, -0.3});

    // Looking back through the open front: its own room's +z wall.
    const TraceHit back = from_eye({0, 0, 1});
    EXPECT_EQ(back.id, 1);
    EXPECT_EQ(back.portals_passed, 0);
    expect_point(back.point, {0, 1.5, 3});

    // The same eye with the head beside it, behind the plane (it walked round
    // the door): the box is not there, and -Z shows A's -z wall.
    const TraceHit walked_round = trace_ray(scene, eye, {0, 0, -1}, 0, 8);
    EXPECT_EQ(walked_round.id, 1);
    expect_point(walked_round.point, {0, 1.5, -3});

    // A head there: both eyes are in the column but neither was reached
    // through the door, so the whole view is A either way.
    TraceDesc desc;
    desc.head.position = eye;
    desc.eye_width = 16;
    desc.eye_height = 9;
    EXPECT_EQ(test::count_id(trace_frame(scene, desc).value(), 1), 32 * 9);
    desc.head.yaw_deg = 180.0;
    EXPECT_EQ(test::count_id(trace_frame(scene, desc).value(), 1), 32 * 9);
}

TEST(TracerPortal, BesideOrBehindAFreeStandingPortalShowsNothingOfIt) {
    const Scene scene = prepare_scene(translated_pair()).value();
    // Beside, level with the box (z = -1.1), looking across it along -X: the
    // far side face faces the ray but the eye is not in the column.
    const TraceHit across = trace_ray(scene, {2, 1.5, -1.1}, {-1, 0, 0}, 0, 8);
    EXPECT_EQ(across.id, 1);
    expect_point(across.point, {-3, 1.5, -1.1});
    // Behind, beyond the box, looking along +Z through the rectangle from its back.
    const TraceHit behind = trace_ray(scene, {0, 1.5, -2}, {0, 0, 1}, 0, 8);
    EXPECT_EQ(behind.id, 1);
    expect_point(behind.point, {0, 1.5, 3});

    TraceDesc desc;
    desc.eye_width = 16;
    desc.eye_height = 9;
    desc.head.position = {2, 1.5, -1.1};
    desc.head.yaw_deg = 90.0;  // looking along -X
    EXPECT_EQ(test::count_id(trace_frame(scene, desc).value(), 1), 32 * 9);
    desc.head.position = {0, 1.5, -2};
    desc.head.yaw_deg = 180.0;  // looking along +Z
    EXPECT_EQ(test::count_id(trace_frame(scene, desc).value(), 1), 32 * 9);
}

// Two portals of one room facing each other and linked to each other: a hall
// of mirrors. M from the far one (z = -2) to the near one (z = 2) is the
// translation (0, 0, 4).
layout::Layout facing_pair() {
    layout::Layout l;
    l.rooms.push_back(make_room("hall", {-3, 0, -3}, {3, 3, 3}));
    add_pair(l, make_portal("far", 0, {0, 1.5, -2}, {0, 0, 1}), make_portal("near", 0, {0, 1.5, 2}, {0, 0, -1}));
    return l;
}

TEST(TracerPortal, RecursionStopsWithTheFillExactlyAtMaxDepth) {
    const Scene scene = prepare_scene(facing_pair()).value();
    for (int depth : {0, 1, 2, 5, 8}) {
        const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0, 0, -1}, 0, depth);
        EXPECT_EQ(hit.id, shading::kFillId) << depth;
        EXPECT_EQ(hit.portals_passed, depth);
        EXPECT_EQ(hit.color, ::impossible::shading::kPortalFillColor);
        expect_point(hit.origin, {0, 1.5, 4.0 * depth});
        expect_point(hit.point, {0, 1.5, -2});
    }
    // Slanted by 0.1: the first crossing is at x = 0.2 (inside), the next
    // would be at x = 0.6 (outside the 1 m wide portal), so after one pass
    // the ray meets the -z wall at x = 0.7.
    EXPECT_EQ(trace_ray(scene, {0, 1.5, 0}, {0.1, 0, -1}, 0, 0).id, shading::kFillId);
    for (int depth : {1, 2, 8}) {
        const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0.1, 0, -1}, 0, depth);
        EXPECT_EQ(hit.id, 1) << depth;
        EXPECT_EQ(hit.portals_passed, 1);
        expect_point(hit.point, {0.7, 1.5, -3});
    }
}

TEST(TracerPortal, FrameShowsTheFillWhereTheRecursionEnds) {
    const Scene scene = prepare_scene(facing_pair()).value();
    TraceDesc desc;
    desc.head.position = {0, 1.5, 0};
    desc.eye_width = 9;
    desc.eye_height = 9;
    desc.max_depth = 3;
    const image::Image image = trace_frame(scene, desc).value();
    EXPECT_EQ(test::pixel_id(image, 4, 4), 255);
    EXPECT_EQ(test::pixel_rgb(image, 4, 4), test::bytes_of(::impossible::shading::kPortalFillColor));
    EXPECT_EQ(test::pixel_id(image, 0, 0), 1);  // the corner looks past the portals
    EXPECT_EQ(test::count_id(image, 0), 0);
}

}  // namespace
}  // namespace impossible::trace
