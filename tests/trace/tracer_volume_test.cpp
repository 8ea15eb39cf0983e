// Volume portals in the tracer (layout-format.md, "Volume portals"): inside
// the box the target room's surfaces show, tinted, with its id; the room's
// own surfaces there, door boxes and mirrors included, are hidden; a ray
// that finds nothing of the target inside goes on beyond. Every expected
// point, id and colour is worked out by hand in the comments.
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
using test::make_mirror;
using test::make_portal;
using test::make_room;
using test::shade_by_hand;

layout::Volume volume_box(int room, dvec3 center, dvec3 size, int target, dvec3 tint) {
    layout::Volume v;
    v.id = "scanner";
    v.room = room;
    v.rect.center = center;
    v.rect.normal = {0, 0, 1};
    v.rect.up = {0, 1, 0};
    v.rect.width = size.x;
    v.rect.height = size.y;
    v.rect.depth = size.z;
    v.target_room = target;
    v.tint = tint;
    return v;
}

// lab (0) and past (1) fill [-3, 3] × [0, 3] × [-3, 3] with different
// colours; past has no portals.
layout::Layout volume_rooms() {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("lab", {-3, 0, -3}, {3, 3, 3}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("past", {-3, 0, -3}, {3, 3, 3}, {0, 0.2, 0.1}));
    l.start.room = 0;
    return l;
}

const dvec3 kScanTint{0.5, 1.0, 0.8};

// The volume against lab's -z wall: x in [-1, 1], y in [0, 3], z in [-3, -2].
layout::Layout wall_volume() {
    layout::Layout l = volume_rooms();
    l.volumes.push_back(volume_box(0, {0, 1.5, -2.5}, {2, 3, 1}, 1, kScanTint));
    return l;
}

void expect_rgb(const dvec3& got, const dvec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

const RayLimits kVolumeLimits{8};

TEST(TracerVolume, HeadOnItShowsTheTargetsWallTinted) {
    const layout::Layout l = wall_volume();
    const Scene scene = prepare_scene(l).value();
    // Lab's wall at (0, 1.5, -3) lies inside: past's wall there shows, past's id,
    // its colour times the tint. The volume's own face z = -2 is no surface.
    const TraceHit hit = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(hit.id, 2);
    EXPECT_EQ(hit.room, 1);
    expect_point(hit.point, {0, 1.5, -3});
    expect_rgb(hit.color, shade_by_hand(face_color(l.rooms[1], layout::Face::NegZ), {0, 0, 1}, false) * kScanTint);
    // Beside it (the wall at x = 2): lab's own wall.
    const TraceHit beside = trace_ray(scene, {0, 1.5, 1}, {2, 0, -4}, 0, kVolumeLimits);
    EXPECT_EQ(beside.id, 1);
    expect_point(beside.point, {2, 1.5, -3});
    expect_rgb(beside.color, shade_by_hand(face_color(l.rooms[0], layout::Face::NegZ), {0, 0, 1}, false));
    // The floor: at (0, 0, -1.5) outside, lab's; at (0, 0, -2.25) inside, past's.
    const TraceHit floor_out = trace_ray(scene, {0, 1.5, 1}, {0, -1.5, -2.5}, 0, kVolumeLimits);
    EXPECT_EQ(floor_out.id, 1);
    expect_point(floor_out.point, {0, 0, -1.5});
    const TraceHit floor_in = trace_ray(scene, {0, 1.5, 1}, {0, -1.5, -3.25}, 0, kVolumeLimits);
    EXPECT_EQ(floor_in.id, 2);
    expect_point(floor_in.point, {0, 0, -2.25});
    expect_rgb(floor_in.color,
               shade_by_hand(face_color(l.rooms[1], layout::Face::Floor), {0, 1, 0}, false) * kScanTint);
}

TEST(TracerVolume, EdgeOnAndGrazingRays) {
    const Scene scene = prepare_scene(wall_volume()).value();
    // Down the side face x = 1: the wall point (1, 1.5, -3) is on the closed
    // box, so past's.
    const TraceHit edge = trace_ray(scene, {1, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(edge.id, 2);
    expect_point(edge.point, {1, 1.5, -3});
    // A micrometre outside it: lab's.
    EXPECT_EQ(trace_ray(scene, {1 + 1e-6, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits).id, 1);
    // Along the front face z = -2, and along z = -2.5 through the middle:
    // past has no surface inside on these lines, so the ray goes on to lab's
    // +x wall at x = 3, outside the volume.
    for (const double z : {-2.0, -2.5}) {
        const TraceHit along = trace_ray(scene, {-2.5, 1.5, z}, {1, 0, 0}, 0, kVolumeLimits);
        EXPECT_EQ(along.id, 1) << z;
        expect_point(along.point, {3, 1.5, z});
    }
    // From outside at a slant that enters by the top edge (y = 3, z = -2)
    // and meets the wall inside: (0.5, 1.5, 1) along (0, 1, -2) meets the
    // ceiling y = 3 at z = -2, on the closed box: past's ceiling.
    const TraceHit grazing = trace_ray(scene, {0.5, 1.5, 1}, {0, 1, -2}, 0, kVolumeLimits);
    EXPECT_EQ(grazing.id, 2);
    expect_point(grazing.point, {0.5, 3, -2});
}

// A floating volume x in [-0.5, 0.5], y in [1, 2], z in [-0.5, 0.5]. Past
// has a green box inside it and a blue one outside; lab a red box whose
// front (z = -0.3) lies inside it.
TEST(TracerVolume, OnlyTheTargetsSurfacesInsideShowAndTheRayGoesOn) {
    layout::Layout l = volume_rooms();
    const dvec3 tint{0.8, 0.9, 1.0};
    l.volumes.push_back(volume_box(0, {0, 1.5, 0}, {1, 1, 1}, 1, tint));
    l.rooms[1].props.push_back(layout::BoxProp{{-0.2, 1.3, -0.2}, {0.2, 1.7, 0.2}, kGreen, {}, {}});
    l.rooms[1].props.push_back(layout::BoxProp{{1.0, 1.3, -0.2}, {1.4, 1.7, 0.2}, kBlue, {}, {}});
    l.rooms[0].props.push_back(layout::BoxProp{{0.3, 1.3, -0.8}, {0.45, 1.7, -0.3}, kRed, {}, {}});
    const Scene scene = prepare_scene(l).value();

    const TraceHit green = trace_ray(scene, {0, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(green.id, 2);
    expect_point(green.point, {0, 1.5, 0.2});
    expect_rgb(green.color, shade_by_hand(kGreen, {0, 0, 1}, false) * tint);
    // Lab's red box is met where it is inside (hidden); its other faces face
    // away; past has nothing there: lab's wall beyond.
    const TraceHit red = trace_ray(scene, {0.35, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(red.id, 1);
    expect_point(red.point, {0.35, 1.5, -3});
    // Past's blue box is outside the volume: not seen.
    const TraceHit blue = trace_ray(scene, {1.2, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(blue.id, 1);
    expect_point(blue.point, {1.2, 1.5, -3});
    // An eye inside the volume: ahead the green box; behind, past has nothing
    // inside, so lab's +z wall.
    EXPECT_EQ(trace_ray(scene, {0, 1.5, 0.4}, {0, 0, -1}, 0, kVolumeLimits).id, 2);
    const TraceHit back = trace_ray(scene, {0, 1.5, 0.3}, {0, 0, 1}, 0, kVolumeLimits);
    EXPECT_EQ(back.id, 1);
    expect_point(back.point, {0, 1.5, 3});
}

// A door (lab to annex) standing inside the volume, and a mirror in lab's
// wall inside it, are hidden: the rays find past's wall instead.
TEST(TracerVolume, DoorsAndMirrorsInsideAreHidden) {
    layout::Layout l = wall_volume();
    l.rooms.push_back(make_room("annex", {-3, 0, -3}, {3, 3, 3}, {0, 0.9, 0.9}));
    add_pair(l, make_portal("lab_door", 0, {0, 1.5, -2.5}, {0, 0, 1}),
             make_portal("annex_door", 2, {0, 1.5, 0}, {0, 0, -1}));
    l.portals.push_back(make_mirror("glass", 0, {0.75, 1.5, -3}, {0, 0, 1}, 0.4, 1.0));
    const Scene scene = prepare_scene(l).value();
    const TraceHit door = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(door.id, 2);
    EXPECT_EQ(door.portals_passed, 0);
    expect_point(door.point, {0, 1.5, -3});
    const TraceHit mirror = trace_ray(scene, {0.75, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(mirror.id, 2);
    EXPECT_EQ(mirror.portals_passed, 0);
    expect_point(mirror.point, {0.75, 1.5, -3});

    // Without the volume the door leads to annex, and the mirror reflects.
    l.volumes.clear();
    const Scene open = prepare_scene(l).value();
    EXPECT_EQ(trace_ray(open, {0, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits).id, 3);
    EXPECT_EQ(trace_ray(open, {0.75, 1.5, 1}, {0, 0, -1}, 0, kVolumeLimits).portals_passed, 1);
}

// hall (0), lab (1) and past (2) coincide; a free-standing door pair at
// z = 0 joins hall (normal +z) and lab (normal -z), so M is the identity and
// a ray from hall continues in lab clipped to z < 0. Lab's volume: x in
// [-1, 1], y in [0, 3], z in [-3, 1].
TEST(TracerVolume, SeenThroughADoorTheClipPlaneCutsTheTarget) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("hall", {-3, 0, -3}, {3, 3, 3}, {0, 0.9, 0.9}));
    l.rooms.push_back(make_room("lab", {-3, 0, -3}, {3, 3, 3}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("past", {-3, 0, -3}, {3, 3, 3}, {0, 0.2, 0.1}));
    add_pair(l, make_portal("hall_door", 0, {0, 1.5, 0}, {0, 0, 1}),
             make_portal("lab_door", 1, {0, 1.5, 0}, {0, 0, -1}));
    l.volumes.push_back(volume_box(1, {0, 1.5, -1}, {2, 3, 4}, 2, kScanTint));
    // Past: a green box wholly behind the door's plane and a red one across it.
    l.rooms[2].props.push_back(layout::BoxProp{{-0.2, 1.3, -0.6}, {0.2, 1.7, -0.3}, kGreen, {}, {}});
    l.rooms[2].props.push_back(layout::BoxProp{{0.25, 1.3, -0.3}, {0.45, 1.7, 0.3}, kRed, {}, {}});
    const Scene scene = prepare_scene(l).value();

    const TraceHit green = trace_ray(scene, {0, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(green.id, 3);
    EXPECT_EQ(green.portals_passed, 1);
    expect_point(green.point, {0, 1.5, -0.3});
    expect_rgb(green.color, shade_by_hand(kGreen, {0, 0, 1}, false) * kScanTint);
    // The red box's front z = 0.3 lies before lab_door's plane: clipped, the
    // box opened up; past's wall shows through it.
    const TraceHit cut = trace_ray(scene, {0.35, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits);
    EXPECT_EQ(cut.id, 3);
    expect_point(cut.point, {0.35, 1.5, -3});
    expect_rgb(cut.color, shade_by_hand(face_color(l.rooms[2], layout::Face::NegZ), {0, 0, 1}, false) * kScanTint);
    // Seen from inside lab, nothing clips it.
    const TraceHit direct = trace_ray(scene, {0.35, 1.5, 2}, {0, 0, -1}, 1, kVolumeLimits);
    EXPECT_EQ(direct.id, 3);
    expect_point(direct.point, {0.35, 1.5, 0.3});
}

// A mirror in lab's +z wall (x in [-0.5, 0.5], y in [0.5, 2.5]) shows the
// volume at lab's -z wall: from (0, 1.5, 0) along +z, reflected at z = 3 to
// the virtual eye (0, 1.5, 6) along -z, past's wall at (0, 1.5, -3), times
// the mirror's tint and the volume's.
TEST(TracerVolume, SeenInAMirror) {
    layout::Layout l = wall_volume();
    const dvec3 glass{0.9, 0.8, 0.7};
    l.portals.push_back(make_mirror("mirror", 0, {0, 1.5, 3}, {0, 0, -1}, 1.0, 2.0, glass));
    const Scene scene = prepare_scene(l).value();
    const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0, 0, 1}, 0, kVolumeLimits);
    EXPECT_EQ(hit.id, 2);
    EXPECT_EQ(hit.portals_passed, 1);
    expect_point(hit.point, {0, 1.5, -3});
    expect_rgb(hit.color,
               glass * (shade_by_hand(face_color(l.rooms[1], layout::Face::NegZ), {0, 0, 1}, false) * kScanTint));
}

// The target's props may move: past's blue box x in [1.5, 1.9], y in
// [1.3, 1.7], z in [-0.2, 0.2] slides by (-1.7, 0, 0) over 2 s into the
// floating volume x in [-0.5, 0.5], y in [1, 2], z in [-0.5, 0.5].
TEST(TracerVolume, TheTargetsMovingPropShowsOnlyInside) {
    layout::Layout l = volume_rooms();
    const dvec3 tint{0.8, 0.9, 1.0};
    l.volumes.push_back(volume_box(0, {0, 1.5, 0}, {1, 1, 1}, 1, tint));
    layout::BoxProp box{{1.5, 1.3, -0.2}, {1.9, 1.7, 0.2}, kBlue, "drifter", {}};
    box.motion.keys = {{0.0, {0, 0, 0}}, {2.0, {-1.7, 0, 0}}};
    l.rooms[1].props.push_back(box);
    const Scene scene = prepare_scene(l).value();
    auto at = [&](double time) {
        math::View view;
        view.time = time;
        return place_frame_objects(scene, view);
    };
    // t = 0: outside the volume, so not seen; inside it past has nothing.
    const TraceHit outside = trace_ray(scene, {1.7, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits, at(0.0));
    EXPECT_EQ(outside.id, 1);
    expect_point(outside.point, {1.7, 1.5, -3});
    EXPECT_EQ(trace_ray(scene, {0, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits, at(0.0)).id, 1);
    // t = 2: at x in [-0.2, 0.2], inside: its front z = 0.2, past's id, tinted.
    const TraceHit inside = trace_ray(scene, {0, 1.5, 2}, {0, 0, -1}, 0, kVolumeLimits, at(2.0));
    EXPECT_EQ(inside.id, 2);
    expect_point(inside.point, {0, 1.5, 0.2});
    expect_rgb(inside.color, shade_by_hand(kBlue, {0, 0, 1}, false) * tint);
}

TEST(TracerVolume, AVolumeWhoseTargetHasPortalsIsRefused) {
    layout::Layout l = wall_volume();
    l.portals.push_back(make_mirror("mirror", 1, {0, 1.5, 3}, {0, 0, -1}));
    const Result<Scene> scene = prepare_scene(l);
    ASSERT_FALSE(scene);
    EXPECT_NE(scene.error().find("scanner"), std::string::npos);
}

}  // namespace
}  // namespace impossible::trace
