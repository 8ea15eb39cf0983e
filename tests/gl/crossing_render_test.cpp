// Crossing objects, moving props and hands in the rasteriser (layout-format.md,
// "Moving props, hands and crossing objects"; docs/crossing.md), against the
// reference tracer: the id maps agree beyond the one-pixel edge tolerance in
// every stereo mode, both clip modes, at several depths, multisampled and
// with render-to-texture portals.
#include <cstdio>
#include <string>
#include <utility>

#include "crossing_rig.hpp"

namespace impossible {
namespace {

// Two rooms over the same floor joined by coincident doors across z = 0; a
// third room "hall" with a turned door into "a". A crate in "a" stands half
// through the door; a crate in "hall" slides through the turned door and back.
const char* kCrossingLayout = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [-0.9, 1.6, 1.7], "yaw_deg": -20 },
  "rooms": [
    { "id": "a", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.86, 0.82, 0.72],
      "face_colors": { "floor": [0.42, 0.36, 0.30] },
      "props": [
        { "id": "crate", "box": { "min": [-0.5, 0, -0.4], "max": [0.3, 0.8, 0.4] }, "color": [0.62, 0.40, 0.22] },
        { "box": { "min": [1.3, 0, 1.2], "max": [1.9, 0.9, 1.9] }, "color": [0.85, 0.25, 0.20] }
      ] },
    { "id": "b", "min": [-2, 0, -2], "max": [2, 2.6, 2], "color": [0.64, 0.78, 0.62], "checker": 0.5,
      "props": [ { "box": { "min": [-1.8, 0, -1.8], "max": [-1.2, 1.8, -1.4] }, "color": [0.9, 0.9, 0.88] } ] },
    { "id": "hall", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.84, 0.80, 0.72],
      "props": [
        { "id": "slider", "box": { "min": [0.4, 0, -0.3], "max": [1.0, 0.6, 0.3] }, "color": [0.9, 0.55, 0.15],
          "motion": { "path": [[0, 0, 0, 0], [3, 2.6, 0, 0], [6, 0, 0, 0]], "loop": true } }
      ] }
  ],
  "portals": [
    { "id": "a_b", "room": "a", "center": [0, 1.1, 0], "normal": [0, 0, 1], "width": 1.6, "height": 2.2,
      "target": "b_a" },
    { "id": "b_a", "room": "b", "center": [0, 1.1, 0], "normal": [0, 0, -1], "width": 1.6, "height": 2.2,
      "target": "a_b" },
    { "id": "hall_east", "room": "hall", "center": [2, 1.1, 0], "normal": [-1, 0, 0], "width": 1.2,
      "height": 2.2, "target": "a_north" },
    { "id": "a_north", "room": "a", "center": [0, 1.1, -2], "normal": [0, 0, 1], "width": 1.2, "height": 2.2,
      "target": "hall_east" },
    { "id": "a_mirror", "room": "a", "kind": "mirror", "center": [2, 1.3, 0.5], "normal": [-1, 0, 0],
      "width": 2.5, "height": 2.0 }
  ]
})";

using testing::CrossingRig;
using testing::expect_agree;
using testing::frame_at;
using testing::stereo_name;

TEST(CrossingRender, BoxHalfThroughADoorMatchesTheTracerInEveryMode) {
    CrossingRig rig(kCrossingLayout);
    ASSERT_TRUE(rig.renderer);
    for (const int depth : {1, 8, 64}) {
        render::FrameDesc f = frame_at(rig.layout, "a", {-0.9, 1.6, 1.7}, -20.0, -15.0);
        f.max_depth = depth;
        const image::Image traced = rig.trace(f);
        for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique})
            for (const render::StereoMode stereo :
                 {render::StereoMode::ClipShift, render::StereoMode::ViewportIndex, render::StereoMode::TwoPass})
                for (const int samples : {1, 4}) {
                    f.clip = clip;
                    f.stereo = stereo;
                    f.samples = samples;
                    char what[96];
                    std::snprintf(what, sizeof what, "depth %d %s %s samples %d", depth,
                                  clip == render::ClipMode::Oblique ? "oblique" : "clip-distance", stereo_name(stereo),
                                  samples);
                    expect_agree(rig.render(f), traced, what);
                }
        f.clip = render::ClipMode::ClipDistance;
        f.stereo = render::StereoMode::ClipShift;
        f.samples = 1;
        f.portal_texture_scale = 1.0;
        expect_agree(rig.render(f), traced, "depth " + std::to_string(depth) + " portal texture");
    }
}

TEST(CrossingRender, BothHalvesOfTheCrateShowWithTheirRoomsIds) {
    CrossingRig rig(kCrossingLayout);
    ASSERT_TRUE(rig.renderer);
    // Looking down at the crate from above the door line: its near half is
    // drawn in "a" (id 1), the half behind the door's plane in "b" (id 2).
    render::FrameDesc f = frame_at(rig.layout, "a", {-0.1, 2.4, 1.0}, 0.0, -60.0);
    const image::Image img = rig.render(f);
    const image::Image traced = rig.trace(f);
    expect_agree(img, traced, "crate from above");
    int in_a = 0, in_b = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width / 2; ++x) {
            const std::uint8_t* p = testing::pixel(img, x, y);
            const bool crate = p[0] > p[1] + 20 && p[1] > p[2] + 20;  // brown
            if (!crate) continue;
            in_a += testing::id_at(img, x, y) == 1;
            in_b += testing::id_at(img, x, y) == 2;
        }
    EXPECT_GT(in_a, 50);
    EXPECT_GT(in_b, 50);
}

TEST(CrossingRender, MovingPropMatchesTheTracerAtSeveralTimes) {
    CrossingRig rig(kCrossingLayout);
    ASSERT_TRUE(rig.renderer);
    // Times going back too: the renderer walks the props on from its last
    // frame, or again from the start.
    for (const double t : {0.0, 1.5, 2.2, 2.6, 3.0, 4.5, 8.2, 2.3, 14.1}) {
        render::FrameDesc f = frame_at(rig.layout, "hall", {-1.2, 1.6, 1.5}, -60.0, -10.0);
        f.time = t;
        const image::Image traced = rig.trace(f);
        for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
            f.clip = clip;
            expect_agree(rig.render(f), traced, "slider at t = " + std::to_string(t));
        }
    }
}

TEST(CrossingRender, HandsThroughADoorMatchTheTracer) {
    CrossingRig rig(kCrossingLayout);
    ASSERT_TRUE(rig.renderer);
    // The head 0.4 m in front of the door, the hands reaching through it.
    render::FrameDesc f = frame_at(rig.layout, "a", {0.0, 1.5, 0.45}, 0.0, -20.0);
    const image::Image bare = rig.render(f);
    f.hands = std::array<math::HeadPose, 2>{math::HeadPose{{-0.15, 1.3, -0.05}, 10.0, -10.0, 0.0},
                                            math::HeadPose{{0.15, 1.3, 0.1}, -10.0, 0.0, 20.0}};
    const image::Image traced = rig.trace(f);
    for (const render::StereoMode stereo :
         {render::StereoMode::ClipShift, render::StereoMode::ViewportIndex, render::StereoMode::TwoPass}) {
        f.stereo = stereo;
        const image::Image img = rig.render(f);
        expect_agree(img, traced, std::string("hands ") + stereo_name(stereo));
        EXPECT_GT(testing::count_colour_differences(img, bare), 200);  // the hands are seen
    }
}

TEST(CrossingRender, CrossingObjectsAndHandsInAMirror) {
    CrossingRig rig(kCrossingLayout);
    ASSERT_TRUE(rig.renderer);
    // The crate half through the door, and a hand reaching through it, seen
    // in the mirror on a's +x wall (the reflected levels wind the other way).
    render::FrameDesc f = frame_at(rig.layout, "a", {-1.2, 1.6, 0.9}, -70.0, -15.0);
    f.hands = std::array<math::HeadPose, 2>{math::HeadPose{{-0.6, 1.2, 0.05}, 0.0, 0.0, 0.0},
                                            math::HeadPose{{-0.3, 1.4, 0.4}, 30.0, 0.0, 0.0}};
    const image::Image traced = rig.trace(f);
    for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique})
        for (const render::StereoMode stereo : {render::StereoMode::ClipShift, render::StereoMode::TwoPass}) {
            f.clip = clip;
            f.stereo = stereo;
            expect_agree(
                rig.render(f), traced,
                std::string("mirror ") + stereo_name(stereo) + (clip == render::ClipMode::Oblique ? " oblique" : ""));
        }
}

// 200 crates in a row along x in room "r", moving (or still, at time 0 where
// the moving ones start).
std::string crates_layout(bool moving) {
    std::string props;
    for (int i = 0; i < 200; ++i) {
        const double x = -1.9 + 0.019 * i;
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      R"(%s{ "id": "c%d", "box": { "min": [%.3f, 0, 1.5], "max": [%.3f, 0.2, 1.7] },
                      "color": [0.9, 0.5, 0.1]%s })",
                      i ? "," : "", i, x, x + 0.01,
                      moving ? R"(, "motion": { "path": [[0, 0, 0, 0], [10, 0, 0, -3]] })" : "");
        props += buf;
    }
    return R"({ "format": "impossible-layout", "version": 1,
      "start": { "room": "r", "position": [0, 1.6, 0] },
      "rooms": [ { "id": "r", "min": [-2, 0, -2], "max": [2, 3, 2], "props": [)" +
           props + "] } ] }";
}

TEST(CrossingRender, ManyMovingPropsAreCulledPerInstance) {
    // The 200 moving crates seen from one end looking away from most:
    // culling draws fewer of them than there are (all in one multi-draw
    // either way: fewer instances' triangles), and the picture is the one
    // drawn without culling.
    const std::string text = crates_layout(true);
    CrossingRig rig(text.c_str());
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = frame_at(rig.layout, "r", {0.0, 1.0, 0.9}, 0.0, -20.0);
    f.time = 1.0;
    render::FrameStats culled, all;
    const image::Image a = rig.render(f, &culled);
    f.cull_objects = false;
    const image::Image b = rig.render(f, &all);
    EXPECT_EQ(testing::count_colour_differences(a, b), 0);
    EXPECT_EQ(testing::count_id_differences(a, b), 0);
    EXPECT_LT(culled.triangles + 150 * 12 * 2, all.triangles) << culled.triangles << " vs " << all.triangles;
    EXPECT_LE(culled.draw_calls, all.draw_calls);
    expect_agree(a, rig.trace(f), "200 moving crates");
}

TEST(CrossingRender, MovingPropsAreOneDrawPerLevelAsStillPropsAre) {
    // Issue 39: the 200 crates, all in view, moving: their meshes' index
    // ranges follow one another, and each vertex finds its instance's record
    // by its mesh, so they draw as one run of the index buffer: at most one
    // draw more than the same crates still (in the cell's mesh), whatever
    // their number; without multi-draw (as the web build draws them), the
    // same picture.
    const std::string moving_text = crates_layout(true), still_text = crates_layout(false);
    render::FrameStats m, st, separate;
    render::FrameDesc f;
    {
        CrossingRig still(still_text.c_str());  // its own context, gone before the next
        ASSERT_TRUE(still.renderer);
        f = frame_at(still.layout, "r", {0.0, 1.6, -1.0}, 180.0, -25.0);
        f.time = 0.5;
        still.render(f, &st);
    }
    CrossingRig moving(moving_text.c_str());
    ASSERT_TRUE(moving.renderer);
    const image::Image a = moving.render(f, &m);
    EXPECT_LE(m.draw_calls, st.draw_calls + 1) << m.draw_calls << " vs " << st.draw_calls;
    // Most crates are seen, each by the faces an eye may see, as the still
    // crates' (box faces culled on the CPU for both).
    EXPECT_GT(m.triangles, 150 * 2 * 2);
    EXPECT_LE(m.triangles, st.triangles + st.triangles / 10) << m.triangles << " vs " << st.triangles;
    f.multi_draw = false;
    const image::Image b = moving.render(f, &separate);
    EXPECT_GE(separate.draw_calls, m.draw_calls);
    EXPECT_EQ(testing::count_colour_differences(a, b), 0);
    EXPECT_EQ(testing::count_id_differences(a, b), 0);
    f.multi_draw = true;
    expect_agree(a, moving.trace(f), "200 moving crates, one multi-draw");
    for (const render::StereoMode stereo : {render::StereoMode::TwoPass, render::StereoMode::ViewportIndex}) {
        f.stereo = stereo;
        expect_agree(moving.render(f), moving.trace(f), std::string("200 moving crates, ") + stereo_name(stereo));
    }
}

TEST(CrossingRender, AnObjectAndItsImageInOneRoom) {
    // The endless corridor's doors lead into each other: a crate half
    // through the north door shows its image at the south door, in the same
    // room: one mesh twice in a cell, drawn as two layers of records.
    layout::Layout l = testing::example_layout("corridor.json");
    layout::BoxProp crate;
    crate.min = {-0.2, 0.0, -4.3};
    crate.max = {0.2, 0.6, -3.7};
    crate.color = {0.2, 0.8, 0.3};
    l.rooms[0].props.push_back(crate);
    CrossingRig rig(std::move(l));
    ASSERT_TRUE(rig.renderer);
    for (const auto& [position, yaw] : {std::pair{math::dvec3{0.25, 1.6, 2.0}, 4.0}, {{0.1, 1.4, -2.5}, 180.0}}) {
        render::FrameDesc f = frame_at(rig.layout, "corridor", position, yaw, -15.0);
        const image::Image a = rig.render(f);
        f.multi_draw = false;
        const image::Image b = rig.render(f);
        EXPECT_EQ(testing::count_colour_differences(a, b), 0);
        expect_agree(a, rig.trace(f), "a crate and its image in one room");
    }
}

}  // namespace
}  // namespace impossible
