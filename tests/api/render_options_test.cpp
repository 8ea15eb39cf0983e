// Every rasteriser option of `render` reaches a library user through
// api::RenderOptions: each stereo, clip, depth and technique mode (and
// samples, the budget, shadows, occlusion test, culling) drawn through the
// API equals the command's PNGs byte for byte; a bad option is an error
// naming the field.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "common/png.hpp"
#include "common/temp_dir.hpp"
#include "impossible/impossible.hpp"

namespace impossible::api {
namespace {

std::string source_file(const std::string& relative) { return std::string(IMPOSSIBLE_SOURCE_DIR) + "/" + relative; }

struct ModeCase {
    const char* layout;  // under layouts/
    const char* flags;   // the command's
    View view;
    RenderOptions options;
};

View small_view(int max_depth = 8, int samples = 1) {
    View v;
    v.width = 96;
    v.height = 54;
    v.max_depth = max_depth;
    v.samples = samples;
    return v;
}

std::vector<ModeCase> mode_cases() {
    std::vector<ModeCase> cases;
    auto add = [&](const char* layout, const char* flags, View view, auto set) {
        RenderOptions o;
        set(o);
        cases.push_back({layout, flags, view, o});
    };
    add("four_rooms.json", "", small_view(), [](RenderOptions&) {});
    add("four_rooms.json", "--stereo viewport-index", small_view(),
        [](RenderOptions& o) { o.stereo = Stereo::ViewportIndex; });
    add("four_rooms.json", "--stereo two-pass", small_view(), [](RenderOptions& o) { o.stereo = Stereo::TwoPass; });
    add("mirror_hall.json", "--clip oblique", small_view(), [](RenderOptions& o) { o.clip = Clip::Oblique; });
    add("four_rooms.json", "--depth standard", small_view(), [](RenderOptions& o) { o.depth = Depth::Standard; });
    add("four_rooms.json", "--technique hybrid --texture-from-level 1 --portal-texture 0.5", small_view(),
        [](RenderOptions& o) {
            o.technique = Technique::Hybrid;
            o.texture_from_level = 1;
            o.texture_scale = 0.5;
        });
    add("four_rooms.json", "--technique hybrid", small_view(),
        [](RenderOptions& o) { o.technique = Technique::Hybrid; });
    add("four_rooms.json", "--technique z-clear --max-depth 1", small_view(1),
        [](RenderOptions& o) { o.technique = Technique::ZClear; });
    add("four_rooms.json", "--no-cull --occlusion-test", small_view(), [](RenderOptions& o) {
        o.cull = false;
        o.occlusion_test = true;
    });
    add("four_rooms.json", "--samples 4", small_view(8, 4), [](RenderOptions&) {});
    add("lamp_hall.json", "--shadow-size 64", small_view(), [](RenderOptions& o) { o.shadow_size = 64; });
    add("lamp_hall.json", "--no-shadows", small_view(), [](RenderOptions& o) { o.shadows = false; });
    View budget = small_view();
    budget.max_portal_passes = 3;
    add("four_rooms.json", "--max-portal-passes 3", budget, [](RenderOptions&) {});
    return cases;
}

TEST(ApiRenderOptions, EveryModeEqualsTheCommand) {
    const test::TempDir dir("api_render_options");
    for (const ModeCase& c : mode_cases()) {
        const std::string layout_path = source_file(std::string("layouts/") + c.layout);
        const Expected<Layout> l = Layout::load(layout_path);
        ASSERT_TRUE(l) << l.error().message;
        Expected<Renderer> renderer = Renderer::headless(*l);
        ASSERT_TRUE(renderer) << renderer.error().message;
        const std::string colour = (dir / "c.png").string(), ids = (dir / "i.png").string();
        const std::string line = std::string(IMPOSSIBLE_BINARY) + " render '" + layout_path + "' --size 96x54 " +
                                 c.flags + " --out '" + colour + "' --ids '" + ids + "' 2>/dev/null";
        ASSERT_EQ(std::system(line.c_str()), 0) << line;
        const Expected<Frame> frame = renderer->render(c.view, c.options);
        ASSERT_TRUE(frame) << c.flags << ": " << frame.error().message;
        EXPECT_TRUE(frame->rgb == testing::read_png_ok(colour).data) << c.flags;
        EXPECT_TRUE(frame->ids == testing::read_png_ok(ids).data) << c.flags;
    }
}

TEST(ApiRenderOptions, ErrorsNameTheField) {
    const Layout l = Layout::builtin();
    Expected<Renderer> renderer = Renderer::headless(l);
    ASSERT_TRUE(renderer) << renderer.error().message;
    RenderOptions zclear;
    zclear.technique = Technique::ZClear;
    EXPECT_EQ(renderer->render(small_view(), zclear).error().message,
              "technique z-clear draws one level of doors: max_depth 8 (give max_depth 1)");
    zclear.cull = false;
    EXPECT_EQ(renderer->render(small_view(1), zclear).error().message,
              "technique z-clear needs each door's rectangle: not with cull = false");
    RenderOptions bad;
    bad.shadow_size = 5000;
    EXPECT_EQ(renderer->render(small_view(), bad).error().message, "shadow_size 5000 is not in 0..4096");
    bad = {};
    bad.texture_scale = 0;
    EXPECT_EQ(renderer->render(small_view(), bad).error().message, "texture_scale 0 is not in (0, 4]");
    bad = {};
    bad.texture_from_level = 251;
    EXPECT_EQ(renderer->render(small_view(), bad).error().message, "texture_from_level 251 is not in 0..250");
    View big = small_view(8, 4);
    big.width = 8192;
    big.height = 4096;
    EXPECT_EQ(renderer->render(big).error().message,
              "size 8192x4096 with samples 4 makes 268435456 samples a frame, more than the renderer's bound of "
              "134217728 (2 x 8192 x 8192; docs/bounded-work.md)");
    bad = {};
    bad.stereo = Stereo::TwoPass;
    bad.technique = Technique::Hybrid;
    EXPECT_EQ(renderer->render(small_view(), bad).error().message, "render-to-texture portals need stereo clip-shift");
}

}  // namespace
}  // namespace impossible::api
