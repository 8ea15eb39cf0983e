// Per-object culling (render/objects/object_culling.hpp): props outside every eye's
// frustum, narrowed through portals, are not drawn, and the image is the one
// drawn without culling, pixel for pixel.
#include <cmath>
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "scene/cell_objects.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

TEST(ObjectCulling, SameImageWithFarFewerTrianglesThroughSixDoors) {
    const layout::Layout l = testing::crowded_vr_study(150);
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    Result<render::Renderer> renderer = render::Renderer::create(context->state(), scene::build_scene(l));
    ASSERT_TRUE(renderer.has_value()) << renderer.error();
    long culled_total = 0, full_total = 0, culled_draws = 0, separate_draws = 0;
    for (int k = 0; k < 6; ++k) {
        render::FrameDesc f;
        f.room = l.start.room;
        f.head.position = l.start.position + glm::dvec3(0.2 * (k % 3) - 0.2, 0.0, 0.15 * (k % 2));
        f.head.yaw_deg = 60.0 * k;
        f.head.pitch_deg = -10.0 + 5.0 * (k % 4);
        f.eye_width = 160;
        f.eye_height = 90;
        f.max_depth = 4;
        // The boxes' indices as stored (their faces culled on the CPU are
        // BoxFaces.*'s; they take a draw of their own per level).
        f.cull_box_faces = false;
        Result<render::RenderedFrame> culled = renderer->render(f);
        f.multi_draw = false;
        Result<render::RenderedFrame> separate = renderer->render(f);
        f.multi_draw = true;
        f.cull_objects = false;
        Result<render::RenderedFrame> full = renderer->render(f);
        ASSERT_TRUE(culled && separate && full);
        EXPECT_EQ(testing::count_colour_differences(culled->image, full->image), 0) << "pose " << k;
        EXPECT_EQ(testing::count_id_differences(culled->image, full->image), 0) << "pose " << k;
        EXPECT_EQ(testing::count_colour_differences(culled->image, separate->image), 0) << "pose " << k;
        EXPECT_EQ(testing::count_id_differences(culled->image, separate->image), 0) << "pose " << k;
        EXPECT_LT(culled->stats.triangles, full->stats.triangles) << "pose " << k;
        EXPECT_EQ(culled->stats.triangles, separate->stats.triangles) << "pose " << k;
        // The runs of visible props between culled ones take one multi-draw
        // per cell drawn: no more calls than drawing every prop.
        EXPECT_LE(culled->stats.draw_calls, full->stats.draw_calls) << "pose " << k;
        culled_total += culled->stats.triangles;
        full_total += full->stats.triangles;
        culled_draws += culled->stats.draw_calls;
        separate_draws += separate->stats.draw_calls;
    }
    // Seven rooms of 1,800 prop triangles each: a view sees a fraction of the
    // head's room and slivers of the others.
    EXPECT_LT(culled_total * 3, full_total);
    EXPECT_LT(2 * culled_draws, separate_draws);
}

TEST(ObjectCulling, ATreeOverManyObjectsKeepsEveryObjectOnceAndBoundsItsChildren) {
    const scene::Scene s = scene::build_scene(testing::crowded_vr_study(1000));
    for (const scene::CellObjects& cell : s.objects) {
        ASSERT_GE(cell.objects.size(), 1000u);
        std::vector<int> seen(cell.objects.size(), 0);
        for (const scene::CullNode& node : cell.nodes) {
            if (node.count == 0) continue;
            EXPECT_LE(node.count, scene::kCullLeafSize);
            for (int i = node.first; i < node.first + node.count; ++i) {
                const scene::CellObject& o =
                    cell.objects[static_cast<std::size_t>(cell.order[static_cast<std::size_t>(i)])];
                seen[static_cast<std::size_t>(cell.order[static_cast<std::size_t>(i)])] += 1;
                for (int a = 0; a < 3; ++a) {
                    EXPECT_LE(node.lo[a], o.lo[a]);
                    EXPECT_GE(node.hi[a], o.hi[a]);
                }
            }
        }
        for (const int n : seen) EXPECT_EQ(n, 1);
        // Objects are stored in leaf order: index ranges follow one another.
        for (std::size_t o = 1; o < cell.objects.size(); ++o) {
            const scene::DrawBatch& prev = cell.batches[cell.objects[o - 1].first_batch];
            EXPECT_EQ(prev.range.first + prev.range.count, cell.batches[cell.objects[o].first_batch].range.first);
        }
    }
}

// A door behind a partition: hidden from the start, it comes into view as the
// head walks past the partition's end and turns towards it. Every frame is
// rendered (occluder culling on, the default) and traced: the ids agree on
// every frame, so the door is drawn in the first frame it shows; and the
// pass is skipped while the partition hides it.
TEST(ObjectCulling, AWalkRoundAPartitionShowsTheDoorInTheFrameItAppears) {
    const layout::Layout l = testing::layout_from_text(R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "a", "position": [0, 1.6, 2] },
      "rooms": [
        { "id": "a", "min": [-3, 0, -4], "max": [3, 3, 4], "color": [0.7, 0.7, 0.6],
          "props": [ { "box": { "min": [-1.5, 0, -2.2], "max": [1.5, 2.8, -2.0] }, "color": [0.5, 0.4, 0.3] } ] },
        { "id": "b", "min": [10, 0, -4], "max": [16, 3, 4], "color": [0.3, 0.5, 0.8] } ],
      "portals": [
        { "id": "a_n", "room": "a", "center": [0, 1.1, -4], "normal": [0, 0, 1], "up": [0, 1, 0],
          "width": 1.2, "height": 2.2, "target": "b_s" },
        { "id": "b_s", "room": "b", "center": [13, 1.1, 4], "normal": [0, 0, -1], "up": [0, 1, 0],
          "width": 1.2, "height": 2.2, "target": "a_n" } ] })");
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    Result<render::Renderer> renderer = render::Renderer::create(context->state(), scene::build_scene(l));
    ASSERT_TRUE(renderer.has_value()) << renderer.error();
    int hidden_frames = 0, shown_frames = 0;
    for (int k = 0; k <= 24; ++k) {
        // Sideways to x = 2.6, forward to z = -3, then turning left to 80°.
        render::FrameDesc f;
        f.room = 0;
        const double s = k / 8.0;
        f.head.position = k <= 8    ? glm::dvec3(2.6 * s, 1.6, 2.0)
                          : k <= 16 ? glm::dvec3(2.6, 1.6, 2.0 - 5.0 * (s - 1.0))
                                    : glm::dvec3(2.6, 1.6, -3.0);
        f.head.yaw_deg = k <= 16 ? 0.0 : 10.0 * (k - 16);
        f.eye_width = 160;
        f.eye_height = 90;
        Result<render::RenderedFrame> drawn = renderer->render(f);
        ASSERT_TRUE(drawn.has_value()) << drawn.error();
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        const image::Comparison cmp = image::compare_pictures(drawn->image, traced);
        EXPECT_EQ(cmp.id_mismatch_percent, 0.0) << "frame " << k << ": " << image::summary_line(cmp);
        int room_b = 0;
        for (const std::uint8_t id : traced.ids) room_b += id == 2;
        if (room_b == 0 && drawn->stats.portal_passes_drawn == 0) ++hidden_frames;
        if (room_b > 0) {
            ++shown_frames;
            EXPECT_EQ(drawn->stats.portal_passes_drawn, 1) << "frame " << k;
        }
        // Without occluder culling, the same image.
        f.cull_objects = false;
        Result<render::RenderedFrame> plain = renderer->render(f);
        ASSERT_TRUE(plain.has_value());
        EXPECT_EQ(testing::count_colour_differences(drawn->image, plain->image), 0) << "frame " << k;
        EXPECT_EQ(testing::count_id_differences(drawn->image, plain->image), 0) << "frame " << k;
    }
    std::printf("  door hidden and skipped in %d frames, shown in %d\n", hidden_frames, shown_frames);
    EXPECT_GE(hidden_frames, 5);
    EXPECT_GE(shown_frames, 3);
}

TEST(ObjectCulling, AWallAcrossTheCorridorSkipsTheWholeRecursionBehindIt) {
    const layout::Layout l =
        testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/corridor_wall.json");
    render::FrameDesc f;
    f.room = l.start.room;
    f.head.position = l.start.position;
    f.eye_width = 160;
    f.eye_height = 90;
    f.max_depth = 16;
    render::FrameStats on, off;
    const image::Image a = testing::render_once(gl::Backend::Egl, l, f, &on);
    f.cull_objects = false;
    const image::Image b = testing::render_once(gl::Backend::Egl, l, f, &off);
    EXPECT_EQ(testing::count_colour_differences(a, b), 0);
    EXPECT_EQ(testing::count_id_differences(a, b), 0);
    EXPECT_EQ(on.portal_passes_drawn, 0);
    EXPECT_GE(off.portal_passes_drawn, 5);  // 7 at 160 x 90: deeper doors cover no pixel centre
}

}  // namespace
}  // namespace impossible
