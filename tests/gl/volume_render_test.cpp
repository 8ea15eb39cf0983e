// Volume portals in the rasteriser (layout-format.md, "Volume portals";
// docs/crossing.md) against the reference tracer: head-on, edge-on, from
// inside the volume, through a door and in a mirror, in every stereo mode and
// both clip modes, multisampled and with render-to-texture portals.
#include <string>

#include "crossing_rig.hpp"

namespace impossible {
namespace {

using testing::CrossingRig;
using testing::expect_agree;
using testing::frame_at;
using testing::stereo_name;

// "lab" has a scanner volume showing "past" (tinted), a mirror on its +x wall
// and a door in its +z wall to "hall", which lies beyond it.
const char* kVolumeLayout = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "lab", "position": [0.3, 1.6, 2.0] },
  "rooms": [
    { "id": "lab", "min": [-2.5, 0, -2.5], "max": [2.5, 3, 2.5], "color": [0.9, 0.91, 0.93],
      "face_colors": { "floor": [0.55, 0.58, 0.62], "-z": [0.80, 0.86, 0.92] },
      "props": [
        { "box": { "min": [-2.2, 0, -2.3], "max": [1.0, 0.9, -1.6] }, "color": [0.95, 0.95, 0.97] },
        { "box": { "min": [-0.25, 0, -0.6], "max": [0.25, 1.0, -0.2] }, "color": [0.85, 0.2, 0.2] }
      ] },
    { "id": "past", "min": [-2.5, 0, -2.5], "max": [2.5, 3, 2.5], "color": [0.72, 0.62, 0.46],
      "face_colors": { "floor": [0.40, 0.28, 0.18] }, "checker": 0.4,
      "props": [
        { "box": { "min": [-1.0, 0, -2.3], "max": [1.4, 1.0, -1.7] }, "color": [0.45, 0.30, 0.18] },
        { "box": { "min": [-0.2, 0, -1.2], "max": [0.4, 0.5, -0.6] }, "color": [0.6, 0.5, 0.3] }
      ] },
    { "id": "hall", "min": [-2.5, 0, 2.5], "max": [2.5, 3, 7.5], "color": [0.7, 0.75, 0.85] }
  ],
  "portals": [
    { "id": "scanner", "room": "lab", "kind": "volume", "target": "past",
      "center": [0.0, 1.15, -1.4], "normal": [0, 0, 1], "up": [0, 1, 0],
      "width": 1.2, "height": 2.5, "depth": 2.6, "tint": [0.75, 0.95, 0.9] },
    { "id": "glass", "room": "lab", "kind": "mirror", "center": [2.5, 1.4, 0.0], "normal": [-1, 0, 0],
      "width": 3.0, "height": 2.0 },
    { "id": "lab_door", "room": "lab", "center": [0, 1.2, 2.5], "normal": [0, 0, -1], "width": 1.2,
      "height": 2.0, "target": "hall_door" },
    { "id": "hall_door", "room": "hall", "center": [0, 1.2, 2.5], "normal": [0, 0, 1], "width": 1.2,
      "height": 2.0, "target": "lab_door" }
  ]
})";

using VolumeView = testing::NamedView;

const VolumeView kVolumeViews[] = {
    {"head-on", "lab", {0.0, 1.6, 2.0}, 0.0, -10.0},
    {"edge-on (the eye in a side plane)", "lab", {0.6, 1.6, 1.5}, 0.0, -5.0},
    {"grazing a side 1 mm off its plane", "lab", {0.601, 1.6, 1.5}, 1.0, -5.0},
    {"from inside the volume", "lab", {0.1, 1.5, -1.0}, 20.0, -20.0},
    {"through the door from the hall", "hall", {0.2, 1.6, 6.5}, 0.0, -5.0},
    {"in the mirror", "lab", {-1.5, 1.6, 1.5}, -75.0, -10.0},
};

TEST(VolumeRender, TheDiscardingVariantDrawsOnlyWhereTheVolumeMayBeSeen) {
    // Issue 39: outside the volume's screen bounds the lab is drawn by the
    // plain variant (early depth test), the discarding one only inside, and
    // the target room in pieces (scene/volume_pieces.hpp): the pixels it
    // covers are a part of the image, the whole image without the split, and
    // the two frames are the same picture (the parts are scissor rectangles
    // of the same draws), the tracer's.
    CrossingRig rig(kVolumeLayout);
    ASSERT_TRUE(rig.renderer);
    for (const VolumeView& v : kVolumeViews) {
        render::FrameDesc f = frame_at(rig.layout, v.room, v.position, v.yaw, v.pitch);
        render::FrameStats split, whole;
        const image::Image a = rig.render(f, &split);
        f.split_volume_draws = false;
        const image::Image b = rig.render(f, &whole);
        EXPECT_EQ(testing::count_colour_differences(a, b), 0) << v.what;
        EXPECT_EQ(testing::count_id_differences(a, b), 0) << v.what;
        EXPECT_LE(split.volume_variant_pixels, whole.volume_variant_pixels) << v.what;
        const image::Image traced = rig.trace(f);
        expect_agree(a, traced, std::string(v.what) + ", split");
        expect_agree(b, traced, std::string(v.what) + ", one variant");
    }
    // Head-on: the scanner covers a part of the image; without the split
    // the lab's draws cover all of it with the discarding variant.
    render::FrameDesc f = frame_at(rig.layout, "lab", {0.0, 1.6, 2.0}, 0.0, -10.0);
    render::FrameStats split, whole;
    rig.render(f, &split);
    f.split_volume_draws = false;
    rig.render(f, &whole);
    const long image = 2L * f.eye_width * f.eye_height;
    EXPECT_GE(whole.volume_variant_pixels, image);
    EXPECT_GT(split.volume_variant_pixels, 0);
    EXPECT_LT(split.volume_variant_pixels, image / 2) << split.volume_variant_pixels << " of " << image;
    // The target room in pieces, each within where it meets the volume
    // (scene/volume_pieces.hpp): fewer fragments shaded, and discarded, for
    // the same picture.
    {
        GLuint query = 0;
        glGenQueries(1, &query);
        const auto invocations = [&](bool pieces) {
            f.split_volume_draws = true;
            f.volume_pieces = pieces;
            glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS, query);
            const image::Image out = rig.render(f);
            glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS);
            GLuint64 n = 0;
            glGetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
            return std::pair{out, n};
        };
        const auto [in_pieces, fewer] = invocations(true);
        const auto [whole_target, more] = invocations(false);
        glDeleteQueries(1, &query);
        EXPECT_EQ(testing::count_colour_differences(in_pieces, whole_target), 0);
        EXPECT_EQ(testing::count_id_differences(in_pieces, whole_target), 0);
        EXPECT_LT(fewer + static_cast<GLuint64>(image / 20), more) << fewer << " and " << more << " invocations";
    }
    // The same picture in the other stereo modes and multisampled.
    for (const render::StereoMode stereo : {render::StereoMode::TwoPass, render::StereoMode::ViewportIndex})
        for (const int samples : {1, 4}) {
            f.stereo = stereo;
            f.samples = samples;
            f.split_volume_draws = true;
            const image::Image a = rig.render(f);
            f.split_volume_draws = false;
            const image::Image b = rig.render(f);
            EXPECT_EQ(testing::count_colour_differences(a, b), 0) << stereo_name(stereo) << " x" << samples;
            EXPECT_EQ(testing::count_id_differences(a, b), 0) << stereo_name(stereo) << " x" << samples;
        }
    f.stereo = render::StereoMode::ClipShift;
    f.samples = 1;
    // Turned away from the scanner: none at all.
    f = frame_at(rig.layout, "lab", {0.0, 1.6, 0.0}, 180.0, -10.0);
    f.split_volume_draws = true;
    rig.render(f, &split);
    EXPECT_EQ(split.volume_variant_pixels, 0);
}

TEST(VolumeRender, MatchesTheTracerInEveryView) {
    CrossingRig rig(kVolumeLayout);
    ASSERT_TRUE(rig.renderer);
    for (const VolumeView& v : kVolumeViews)
        for (const int depth : {1, 8, 64}) {
            render::FrameDesc f = frame_at(rig.layout, v.room, v.position, v.yaw, v.pitch);
            f.max_depth = depth;
            const image::Image traced = rig.trace(f);
            for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
                f.clip = clip;
                expect_agree(rig.render(f), traced,
                             std::string(v.what) + ", depth " + std::to_string(depth) +
                                 (clip == render::ClipMode::Oblique ? " oblique" : ""));
            }
        }
}

TEST(VolumeRender, EveryStereoModeSamplesAndPortalTextures) {
    CrossingRig rig(kVolumeLayout);
    ASSERT_TRUE(rig.renderer);
    for (const VolumeView& v : {kVolumeViews[0], kVolumeViews[3], kVolumeViews[4]}) {
        render::FrameDesc f = frame_at(rig.layout, v.room, v.position, v.yaw, v.pitch);
        const image::Image traced = rig.trace(f);
        for (const render::StereoMode stereo :
             {render::StereoMode::ClipShift, render::StereoMode::ViewportIndex, render::StereoMode::TwoPass})
            for (const int samples : {1, 4}) {
                f.stereo = stereo;
                f.samples = samples;
                expect_agree(rig.render(f), traced,
                             std::string(v.what) + " " + stereo_name(stereo) + " x" + std::to_string(samples));
            }
        f.stereo = render::StereoMode::ClipShift;
        f.samples = 1;
        f.portal_texture_scale = 1.0;
        expect_agree(rig.render(f), traced, std::string(v.what) + " portal texture");
    }
}

TEST(VolumeRender, TheTargetRoomShowsInsideTheVolumeWithItsId) {
    CrossingRig rig(kVolumeLayout);
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = frame_at(rig.layout, "lab", kVolumeViews[0].position, 0.0, -10.0);
    const image::Image img = rig.render(f);
    // The centre of each eye looks into the volume: the past (id 2), tinted.
    const int y = img.height / 2;
    EXPECT_EQ(testing::id_at(img, img.width / 4, y), 2);
    EXPECT_EQ(testing::id_at(img, 3 * img.width / 4, y), 2);
    // The edges of the image see the lab (id 1).
    EXPECT_EQ(testing::id_at(img, 1, y), 1);
    EXPECT_EQ(testing::id_at(img, img.width - 2, y), 1);
}

// A large box inside a volume is hidden there, so it must not hide the door
// behind it (the occluder test of render/objects/object_culling.hpp skips portals
// hidden by a room's large boxes).
TEST(VolumeRender, APropInsideAVolumeHidesNoDoor) {
    CrossingRig rig(R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "lab", "position": [0, 1.5, 1.5] },
      "rooms": [
        { "id": "lab", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.8, 0.8, 0.85],
          "props": [ { "box": { "min": [-1, 0, -1.2], "max": [1, 2, -0.8] }, "color": [0.9, 0.2, 0.2] } ] },
        { "id": "empty", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.5, 0.6, 0.4] },
        { "id": "beyond", "min": [-2, 0, -6], "max": [2, 3, -2], "color": [0.3, 0.4, 0.8] }
      ],
      "portals": [
        { "id": "x", "room": "lab", "kind": "volume", "target": "empty", "center": [0, 1, -1],
          "normal": [0, 0, 1], "width": 2.4, "height": 2.4, "depth": 1.0 },
        { "id": "d", "room": "lab", "center": [0, 1.1, -2], "normal": [0, 0, 1], "width": 1.0, "height": 2.0,
          "target": "e" },
        { "id": "e", "room": "beyond", "center": [0, 1.1, -2], "normal": [0, 0, -1], "width": 1.0,
          "height": 2.0, "target": "d" }
      ]
    })");
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = frame_at(rig.layout, "lab", {0.0, 1.5, 1.5}, 0.0, -5.0);
    const image::Image img = rig.render(f);
    expect_agree(img, rig.trace(f), "a box inside a volume before a door");
    // The door is seen through the volume: the centre of each eye shows "beyond".
    EXPECT_EQ(testing::id_at(img, img.width / 4, img.height / 2), 3);
    EXPECT_EQ(testing::id_at(img, 3 * img.width / 4, img.height / 2), 3);
}

// However many volumes a room has (they are read from a buffer, not uniform
// arrays): 300 small boxes in a grid before the viewer.
TEST(VolumeRender, ManyVolumesInOneRoom) {
    std::string volumes;
    for (int i = 0; i < 300; ++i) {
        const double x = -1.5 + 0.2 * (i % 15), y = 0.3 + 0.2 * (i / 15 % 10), z = -1.0 - 0.5 * (i / 150);
        volumes += ",{ \"id\": \"v" + std::to_string(i) + "\", \"room\": \"lab\", \"kind\": \"volume\", " +
                   "\"target\": \"past\", \"center\": [" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                   std::to_string(z) + "], \"normal\": [0, 0, 1], \"width\": 0.12, \"height\": 0.12, " +
                   "\"depth\": 0.12, \"tint\": [0.9, 0.8, 1.0] }";
    }
    const std::string text = R"({ "format": "impossible-layout", "version": 1,
      "start": { "room": "lab", "position": [0, 1.3, 1.5] },
      "rooms": [
        { "id": "lab", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.8, 0.8, 0.85],
          "props": [ { "box": { "min": [-1.8, 0, -1.3], "max": [1.8, 2.4, -1.2] }, "color": [0.9, 0.2, 0.2] } ] },
        { "id": "past", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.5, 0.6, 0.4], "checker": 0.05,
          "props": [ { "box": { "min": [-1.8, 0, -1.0], "max": [1.8, 2.4, -0.99] }, "color": [0.2, 0.3, 0.9] } ] }
      ],
      "portals": [ { "id": "m", "room": "lab", "kind": "mirror", "center": [0, 1.5, 2], "normal": [0, 0, -1],
                     "width": 1, "height": 1 })" +
                             volumes + "] }";
    CrossingRig rig(text.c_str());
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = frame_at(rig.layout, "lab", {0.0, 1.3, 1.5}, 0.0, 0.0);
    const image::Image img = rig.render(f);
    expect_agree(img, rig.trace(f), "300 volumes");
    int past = 0;
    for (const std::uint8_t id : img.ids) past += id == 2;
    EXPECT_GT(past, 1000);
}

}  // namespace
}  // namespace impossible
