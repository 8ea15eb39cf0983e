// What a renderer keeps between frames (render::Renderer::kept,
// release_targets, release_shadow_maps; render/kept_buffers.cpp): counted as
// the buffers it made, and once released, made again by the next frame,
// which draws the same pixels (the shadow maps drawn again).
#include <cstdint>
#include <optional>

#include "gl_fixture.hpp"

namespace impossible {
namespace {

struct KeptRig {
    layout::Layout layout = testing::example_layout("lamp_hall.json");
    gl::Context context = gl::create_context(gl::Backend::Egl).value();
    std::optional<render::Renderer> renderer;
    render::FrameDesc frame;

    KeptRig() {
        Result<render::Renderer> made = render::Renderer::create(context.state(), scene::build_scene(layout));
        EXPECT_TRUE(made.has_value()) << made.error();
        if (made) renderer.emplace(std::move(*made));
        frame.head = {{-1.6, 1.2, 1.6}, -70.0, 0.0, 0.0};
        frame.room = layout::find_room(layout, "hall");
        frame.eye_width = 96;
        frame.eye_height = 54;
    }
    render::RenderedFrame draw() {
        Result<render::RenderedFrame> drawn = renderer->render(frame);
        EXPECT_TRUE(drawn.has_value()) << drawn.error();
        return drawn ? std::move(*drawn) : render::RenderedFrame{};
    }
};

TEST(KeptBuffers, CountsTheTargetsAndTheShadowMapsItMade) {
    KeptRig rig;
    ASSERT_TRUE(rig.renderer);
    EXPECT_EQ(rig.renderer->kept().target_samples, 0);  // nothing before the first frame
    EXPECT_EQ(rig.renderer->kept().shadow_map_bytes, 0);
    const render::RenderedFrame first = rig.draw();
    ASSERT_GT(first.stats.shadow_maps_drawn, 0);
    const std::int64_t frame_samples = 2 * 96 * 54;
    EXPECT_EQ(rig.renderer->kept().target_samples, frame_samples);
    // Each map 6 faces of 512² R32F texels, and one DEPTH32F face to draw them.
    const std::int64_t face = 512 * 512 * 4;
    EXPECT_EQ(rig.renderer->kept().shadow_map_bytes, face * (6 * first.stats.shadow_maps_drawn + 1));
    rig.frame.samples = 4;
    rig.draw();
    EXPECT_EQ(rig.renderer->kept().target_samples, frame_samples * (1 + 4));  // and the resolve's target
}

TEST(KeptBuffers, ReleasedBuffersAreMadeAgainWithTheSamePixels) {
    KeptRig rig;
    ASSERT_TRUE(rig.renderer);
    const int maps = rig.draw().stats.shadow_maps_drawn;
    ASSERT_GT(maps, 0);
    for (int samples : {1, 4}) {
        rig.frame.samples = samples;
        const render::RenderedFrame first = rig.draw();
        EXPECT_EQ(first.stats.shadow_maps_drawn, 0);  // kept: not drawn again
        rig.renderer->release_targets();
        rig.renderer->release_shadow_maps();
        EXPECT_EQ(rig.renderer->kept().target_samples, 0);
        EXPECT_EQ(rig.renderer->kept().shadow_map_bytes, 0);
        const render::RenderedFrame again = rig.draw();
        EXPECT_EQ(again.stats.shadow_maps_drawn, maps) << samples;
        EXPECT_EQ(again.image.rgb, first.image.rgb) << samples;
        EXPECT_EQ(again.image.ids, first.image.ids) << samples;
        EXPECT_GT(rig.renderer->kept().shadow_map_bytes, 0);
    }
}

}  // namespace
}  // namespace impossible
