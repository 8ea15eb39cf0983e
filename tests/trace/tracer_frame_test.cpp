// Whole frames of real layout files: determinism across thread counts, the
// default layout, and agreement with the loader's hole rule.
#include <gtest/gtest.h>

#include <set>

#include "layout/layout.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::load_default;

TraceDesc start_view(const layout::Layout& l) {
    TraceDesc desc;
    desc.head.position = l.start.position;
    desc.head.yaw_deg = l.start.yaw_deg;
    desc.room = l.start.room;
    desc.eye_width = 40;
    desc.eye_height = 24;
    return desc;
}

TEST(TracerFrame, ThreadCountDoesNotChangeTheImage) {
    const layout::Layout l = load_default();
    const Scene scene = prepare_scene(l).value();
    TraceDesc desc = start_view(l);
    desc.head.pitch_deg = -10.0;
    desc.head.roll_deg = 5.0;
    desc.threads = 1;
    const image::Image one = trace_frame(scene, desc).value();
    for (int threads : {2, 3, 7}) {
        desc.threads = threads;
        const image::Image many = trace_frame(scene, desc).value();
        EXPECT_EQ(many.rgb, one.rgb) << threads;
        EXPECT_EQ(many.ids, one.ids) << threads;
    }
}

TEST(TracerFrame, DefaultLayoutShowsTheHallAndTheAnnexThroughTheDoor) {
    const layout::Layout l = load_default();
    const image::Image image = trace_frame(l, start_view(l)).value();
    const std::set<std::uint8_t> ids(image.ids.begin(), image.ids.end());
    EXPECT_EQ(ids, (std::set<std::uint8_t>{1, 2}));
    // The door (x in [-0.5, 0.5], y in [0, 2.2] at z = 0) is ahead and a bit
    // to the right of the start (0.3, 1.6, 1.6) looking along -Z turned 8°
    // left; the centre of each eye's view looks through it.
    EXPECT_EQ(test::pixel_id(image, 20, 12), 2);
    EXPECT_EQ(test::pixel_id(image, 40 + 20, 12), 2);
}

TEST(TracerFrame, HoleRuleAgreesWithTheLoader) {
    const std::string text = R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "a", "position": [0, 1.6, 0] },
      "rooms": [
        { "id": "a", "min": [-2, 0, -2], "max": [2, 3, 2] },
        { "id": "b", "min": [10, 0, -2], "max": [14, 3, 2] }
      ],
      "portals": [
        { "id": "a_wall", "room": "a", "center": [0, 1.5, -2], "normal": [0, 0, 1],
          "width": 1, "height": 2, "target": "b_wall" },
        { "id": "b_wall", "room": "b", "center": [10.00005, 1.5, 0.5], "normal": [1, 0, 0],
          "width": 1, "height": 2, "target": "a_wall" },
        { "id": "a_free", "room": "a", "center": [1, 1.2, 0], "normal": [-1, 0, 0],
          "width": 0.8, "height": 2, "target": "b_free" },
        { "id": "b_free", "room": "b", "center": [12, 1.2, 1.5], "normal": [0, 0, -1],
          "width": 0.8, "height": 2, "target": "a_free" }
      ]
    })";
    const layout::LoadResult loaded = layout::load_layout_text(text, "<test>", ".");
    ASSERT_TRUE(loaded.errors.empty()) << loaded.errors.front().str();
    const layout::Layout& l = *loaded.layout;
    const Scene scene = prepare_scene(l).value();
    for (size_t p = 0; p < l.portals.size(); ++p) {
        int traced_face = -1;
        const SceneRoom& room = scene.rooms[l.portals[p].room];
        for (int f = 0; f < layout::kFaceCount; ++f)
            for (int h : room.faces[f].holes)
                if (h == static_cast<int>(p)) traced_face = f;
        EXPECT_EQ(traced_face, l.portals[p].hole_face) << l.portals[p].id;
    }
    EXPECT_EQ(l.portals[0].hole_face, static_cast<int>(layout::Face::NegZ));
    EXPECT_EQ(l.portals[1].hole_face, static_cast<int>(layout::Face::NegX));
    EXPECT_EQ(l.portals[2].hole_face, -1);
}

}  // namespace
}  // namespace impossible::trace
