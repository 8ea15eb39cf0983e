// The headless renderers of one thread (api/headless_share.hpp): one context,
// and the shadow maps they keep together within render::kMaxShadowMapBytes,
// the least recently drawn renderer's released first; a released renderer
// draws its next frame with the same pixels. lamp_hall's two maps at
// 1024² texels take 52 MiB a renderer, so the fifth renderer's frame
// releases the first's maps. Renderers that share a context's programs
// draw what each draws alone.
#include <cstdint>
#include <memory>
#include <vector>

#include "api/headless_share.hpp"
#include "gl_fixture.hpp"
#include "render/lights/shadow_maps.hpp"

namespace impossible {
namespace {

struct ShareRig {
    layout::Layout layout = testing::example_layout("lamp_hall.json");
    std::shared_ptr<api::HeadlessShare> share = api::HeadlessShare::of_this_thread(gl::Backend::Egl).value();
    std::vector<std::unique_ptr<render::Renderer>> renderers;
    render::FrameDesc frame;

    explicit ShareRig(int n) {
        frame.head = {{-1.6, 1.2, 1.6}, -70.0, 0.0, 0.0};
        frame.room = layout::find_room(layout, "hall");
        frame.eye_width = 64;
        frame.eye_height = 36;
        frame.shadow_map_size = 1024;
        EXPECT_TRUE(gl::make_current(share->context()).has_value());
        for (int i = 0; i < n; ++i) {
            Result<render::Renderer> made =
                render::Renderer::create(share->context().state(), scene::build_scene(layout));
            EXPECT_TRUE(made.has_value()) << made.error();
            renderers.push_back(std::make_unique<render::Renderer>(std::move(*made)));
            share->join(*renderers.back());
        }
    }
    ~ShareRig() {
        for (const auto& r : renderers) share->leave(*r);
    }
    // A frame of renderer i, as api::Renderer draws one.
    render::RenderedFrame draw(int i) {
        render::Renderer& r = *renderers[static_cast<std::size_t>(i)];
        share->before_frame(r, 2LL * frame.eye_width * frame.eye_height);
        Result<render::RenderedFrame> drawn = r.render(frame);
        share->after_frame(r);
        EXPECT_TRUE(drawn.has_value()) << drawn.error();
        return drawn ? std::move(*drawn) : render::RenderedFrame{};
    }
    std::int64_t maps_kept() const {
        std::int64_t sum = 0;
        for (const auto& r : renderers) sum += r->kept().shadow_map_bytes;
        return sum;
    }
};

TEST(HeadlessShare, TheRenderersOfAThreadKeepTheirShadowMapsWithinTheBound) {
    ShareRig rig(8);
    ASSERT_EQ(rig.renderers.size(), 8u);
    const render::RenderedFrame first = rig.draw(0);
    const std::int64_t one = rig.renderers[0]->kept().shadow_map_bytes;
    ASSERT_GT(one, 40 << 20);
    const auto bound = static_cast<std::int64_t>(render::kMaxShadowMapBytes);
    const int fit = static_cast<int>(bound / one);  // 4 of 52 MB each
    for (int i = 1; i < 8; ++i) {
        rig.draw(i);
        EXPECT_LE(rig.maps_kept(), bound) << i;
    }
    // The last `fit` drawn keep theirs; the ones before were released, the
    // least recently drawn first.
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(rig.renderers[static_cast<std::size_t>(i)]->kept().shadow_map_bytes, i >= 8 - fit ? one : 0) << i;
    const render::RenderedFrame again = rig.draw(0);
    EXPECT_EQ(again.stats.shadow_maps_drawn, first.stats.shadow_maps_drawn);  // drawn again
    EXPECT_EQ(again.image.rgb, first.image.rgb);
    EXPECT_EQ(again.image.ids, first.image.ids);
    EXPECT_EQ(rig.renderers[0]->kept().shadow_map_bytes, one);
    EXPECT_EQ(rig.renderers[static_cast<std::size_t>(8 - fit)]->kept().shadow_map_bytes, 0);  // now the oldest
    EXPECT_LE(rig.maps_kept(), bound);
}

// Renderers of one context draw with its programs (render::SharedPrograms).
// Two layouts that need different variants (lights and shadow lookups; a
// volume), drawn in turn in every stereo mode, give the bytes each gives
// alone in a fresh context: nothing one sets in a program is left for the
// other.
TEST(HeadlessShare, RenderersThatShareProgramsDrawWhatEachDrawsAlone) {
    const layout::Layout lamp = testing::example_layout("lamp_hall.json");
    const layout::Layout lab = testing::example_layout("scanner_lab.json");
    render::FrameDesc lamp_frame;
    lamp_frame.head = {{-1.6, 1.2, 1.6}, -70.0, 0.0, 0.0};
    lamp_frame.room = layout::find_room(lamp, "hall");
    lamp_frame.eye_width = 96;
    lamp_frame.eye_height = 54;
    render::FrameDesc lab_frame = lamp_frame;
    lab_frame.head = {{0.3, 1.6, 2.0}, 10.0, 0.0, 0.0};
    lab_frame.room = layout::find_room(lab, "lab");
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    Result<render::Renderer> a = render::Renderer::create(context->state(), scene::build_scene(lamp));
    ASSERT_TRUE(a.has_value()) << a.error();
    Result<render::Renderer> b = render::Renderer::create(context->state(), scene::build_scene(lab), a->programs());
    ASSERT_TRUE(b.has_value()) << b.error();
    EXPECT_EQ(a->programs().get(), b->programs().get());
    for (const render::StereoMode mode :
         {render::StereoMode::ClipShift, render::StereoMode::ViewportIndex, render::StereoMode::TwoPass}) {
        lamp_frame.stereo = lab_frame.stereo = mode;
        const image::Image lamp_alone = testing::render_once(gl::Backend::Egl, lamp, lamp_frame);
        const image::Image lab_alone = testing::render_once(gl::Backend::Egl, lab, lab_frame);
        ASSERT_TRUE(gl::make_current(*context).has_value());
        context->state().invalidate();  // render_once's contexts were current
        for (int turn = 0; turn < 2; ++turn) {
            Result<render::RenderedFrame> lamp_drawn = a->render(lamp_frame);
            ASSERT_TRUE(lamp_drawn.has_value()) << lamp_drawn.error();
            Result<render::RenderedFrame> lab_drawn = b->render(lab_frame);
            ASSERT_TRUE(lab_drawn.has_value()) << lab_drawn.error();
            EXPECT_EQ(lamp_drawn->image.rgb, lamp_alone.rgb) << static_cast<int>(mode) << " " << turn;
            EXPECT_EQ(lamp_drawn->image.ids, lamp_alone.ids) << static_cast<int>(mode) << " " << turn;
            EXPECT_EQ(lab_drawn->image.rgb, lab_alone.rgb) << static_cast<int>(mode) << " " << turn;
            EXPECT_EQ(lab_drawn->image.ids, lab_alone.ids) << static_cast<int>(mode) << " " << turn;
        }
    }
}

}  // namespace
}  // namespace impossible
