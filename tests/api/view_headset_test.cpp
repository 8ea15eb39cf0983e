// Headsets through the public API (docs/api.md, "Headsets"): a profile read
// by load_hmd_profile is the one `--hmd` reads, View::eye_optics reaches the
// library's view, and a frame through it is the library's (and the CLI's:
// tests/python/test_headset.py compares with the command).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "api/api_data.hpp"
#include "common/png.hpp"
#include "common/temp_dir.hpp"
#include "impossible/impossible.hpp"
#include "layout/hmd_profile.hpp"
#include "math/hidden_area.hpp"
#include "trace/tracer.hpp"

namespace impossible::api {
namespace {

std::string headset_source_file(const std::string& name) { return std::string(IMPOSSIBLE_SOURCE_DIR) + "/" + name; }

// The view `render --hmd FILE --size W,H` draws from the layout's start.
math::View headset_cli_view(const layout::Layout& l, const layout::HmdProfile& profile, int width, int height) {
    math::View v;
    v.head.position = l.start.position;
    v.head.yaw_deg = l.start.yaw_deg;
    v.room = l.start.room;
    v.eye_optics = profile.eyes;
    v.ipd = profile.ipd;
    v.eye_width = width;
    v.eye_height = height;
    return v;
}

TEST(ApiHeadset, ProfileIsTheLibrarysAndReachesTheView) {
    const std::string file = headset_source_file("profiles/htc-vive.json");
    const Expected<HmdProfile> profile = load_hmd_profile(file);
    ASSERT_TRUE(profile) << profile.error().message;
    const Result<layout::HmdProfile> own = layout::read_hmd_profile_file(file);
    ASSERT_TRUE(own) << own.error();
    EXPECT_EQ(profile->name, own->name);
    EXPECT_EQ(profile->eye_width, 1852);
    EXPECT_EQ(profile->eye_height, 2056);
    EXPECT_EQ(profile->ipd, 0.0724);
    EXPECT_EQ(profile->eyes[0].fov.left, -54.41);
    EXPECT_GE(profile->eyes[1].visible_area.size(), 3u);

    View view;
    use_hmd_profile(view, *profile);
    EXPECT_EQ(view.width, 1852);
    EXPECT_EQ(view.ipd, 0.0724);
    const Layout layout = Layout::builtin();
    const Result<math::View> v = resolve_view(layout.data().layout, view);
    ASSERT_TRUE(v) << v.error();
    ASSERT_TRUE(v->eye_optics);
    EXPECT_EQ((*v->eye_optics)[0], own->eyes[0]);
    EXPECT_EQ((*v->eye_optics)[1], own->eyes[1]);
}

// The API's frames through a profile are the library's, and the hidden
// pixels are black with id 0 in both the rasterised and the traced frame.
TEST(ApiHeadset, RenderAndTraceThroughAProfile) {
    const Expected<Layout> l = Layout::load(headset_source_file("layouts/four_rooms.json"));
    ASSERT_TRUE(l) << l.error().message;
    const std::string file = headset_source_file("profiles/htc-vive.json");
    const Expected<HmdProfile> profile = load_hmd_profile(file);
    ASSERT_TRUE(profile) << profile.error().message;
    View view;
    use_hmd_profile(view, *profile);
    view.width = 93;  // as `--hmd FILE --size 93,103`
    view.height = 103;

    const layout::Layout& own = l->data().layout;
    trace::TraceDesc desc;
    static_cast<math::View&>(desc) = headset_cli_view(own, *layout::read_hmd_profile_file(file), 93, 103);
    const Result<image::Image> reference = trace::trace_frame(own, desc);
    ASSERT_TRUE(reference) << reference.error();
    const Expected<Frame> traced = trace(*l, view, 1);
    ASSERT_TRUE(traced) << traced.error().message;
    EXPECT_EQ(traced->rgb, reference->rgb);
    EXPECT_EQ(traced->ids, reference->ids);

    Expected<Renderer> renderer = Renderer::headless(*l);
    ASSERT_TRUE(renderer) << renderer.error().message;
    const Expected<Frame> drawn = renderer->render(view);
    ASSERT_TRUE(drawn) << drawn.error().message;
    EXPECT_EQ(drawn->ids, traced->ids);  // docs/headsets.md: four_rooms through the Vive, pixel for pixel
    int hidden = 0;
    for (int e = 0; e < 2; ++e) {
        const std::vector<std::uint8_t> mask = math::hidden_pixels(desc.eye_optics->at(e).visible_area, 93, 103);
        for (int j = 0; j < 103; ++j)
            for (int i = 0; i < 93; ++i) {
                if (!mask[static_cast<std::size_t>(j * 93 + i)]) continue;
                ++hidden;
                const std::size_t at = static_cast<std::size_t>(j * 186 + e * 93 + i);
                ASSERT_EQ(drawn->ids[at], 0) << "eye " << e << " pixel " << i << "," << j;
                ASSERT_EQ(drawn->rgb[3 * at] + drawn->rgb[3 * at + 1] + drawn->rgb[3 * at + 2], 0);
            }
    }
    EXPECT_GT(hidden, 2 * 93 * 103 / 10);  // about 19 % of each eye

    View plain = view;
    plain.eye_optics.reset();
    const Expected<Frame> symmetric = renderer->render(plain);
    ASSERT_TRUE(symmetric);
    EXPECT_NE(symmetric->ids, drawn->ids);
}

TEST(ApiHeadset, BadProfileNamesFileLineAndColumn) {
    const test::TempDir dir("api_headset");
    const std::string file = (dir / "bad.json").string();
    std::ofstream(file) << "{\"name\": \"x\", \"source\": \"y\",\n"
                           " \"left\": {\"fov\": {\"left\": -95, \"right\": 40, \"up\": 40, \"down\": -40},\n"
                           "          \"resolution\": [100, 100]},\n"
                           " \"right\": {\"fov\": {\"left\": -40, \"right\": 40, \"up\": 40, \"down\": -40},\n"
                           "          \"resolution\": [100, 100]}}\n";
    const Expected<HmdProfile> bad = load_hmd_profile(file);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message.rfind(file + ":2:", 0), 0u) << bad.error().message;
    EXPECT_NE(bad.error().message.find("left.fov.left"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("89.5"), std::string::npos) << bad.error().message;
    const Expected<HmdProfile> missing = load_hmd_profile((dir / "missing.json").string());
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("missing.json"), std::string::npos);
}

TEST(ApiHeadset, OpticsAreCheckedAsAProfilesAre) {
    const Layout layout = Layout::builtin();
    View view;
    view.width = 16;
    view.height = 16;
    view.eye_optics = std::array<EyeOptics, 2>{};
    ASSERT_TRUE(trace(layout, view)) << "the default angles, ±45 degrees";
    auto problem = [&](const View& v) { return trace(layout, v).error().message; };
    View v = view;
    (*v.eye_optics)[1].fov.left = 50;
    EXPECT_EQ(problem(v), "right eye: fov: right (45) must be at least 1 degree right of left (50)");
    v = view;
    (*v.eye_optics)[0].fov.up = 90;
    EXPECT_EQ(problem(v), "left eye: fov: 90 is not an angle within ±89.5 degrees");
    v = view;
    (*v.eye_optics)[0].visible_area = {{0, 0}, {1, 1}};
    EXPECT_EQ(problem(v), "left eye: visible_area has 2 corners, not 3..4096");
    v = view;
    (*v.eye_optics)[1].visible_area = {{0, 0}, {1, 0}, {1, 1.5}};
    EXPECT_EQ(problem(v), "right eye: visible_area[2] is not within 0..1");
    v = view;
    (*v.eye_optics)[0].visible_area = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    EXPECT_NE(problem(v).find("left eye: visible_area["), std::string::npos) << problem(v);
    EXPECT_NE(problem(v).find("must be a simple polygon"), std::string::npos) << problem(v);
}

// The API's frames through a profile are the command's, `--hmd FILE --size
// W×H`, byte for byte (colour and ids).
TEST(ApiHeadset, RenderAndTraceEqualTheCommands) {
    const std::string layout_path = headset_source_file("layouts/four_rooms.json");
    const std::string file = headset_source_file("profiles/quest-2.json");
    const Expected<Layout> l = Layout::load(layout_path);
    ASSERT_TRUE(l) << l.error().message;
    const Expected<HmdProfile> profile = load_hmd_profile(file);
    ASSERT_TRUE(profile) << profile.error().message;
    View view;
    use_hmd_profile(view, *profile);
    view.width = 80;
    view.height = 84;
    Expected<Renderer> renderer = Renderer::headless(*l);
    ASSERT_TRUE(renderer) << renderer.error().message;
    const test::TempDir dir("api_headset_cli");
    for (const std::string command : {"render", "trace"}) {
        const std::string colour = (dir / (command + ".png")).string(), ids = (dir / (command + "-ids.png")).string();
        const std::string line = std::string(IMPOSSIBLE_BINARY) + " " + command + " '" + layout_path + "' --hmd '" +
                                 file + "' --size 80x84 --out '" + colour + "' --ids '" + ids + "'";
        ASSERT_EQ(std::system(line.c_str()), 0) << line;
        const Expected<Frame> frame = command == "render" ? renderer->render(view) : trace(*l, view);
        ASSERT_TRUE(frame) << frame.error().message;
        const image::Pixels expected_colour = testing::read_png_ok(colour), expected_ids = testing::read_png_ok(ids);
        ASSERT_EQ(expected_colour.channels, 3);
        ASSERT_EQ(expected_ids.channels, 1);
        EXPECT_EQ(frame->width, 160);
        EXPECT_TRUE(frame->rgb == expected_colour.data) << command;
        EXPECT_TRUE(frame->ids == expected_ids.data) << command;
    }
}

// docs/api.md's example (Headsets), as it is there.
TEST(ApiHeadset, TheDocsExample) {
    namespace api = impossible::api;
    const auto fail = [](const std::string& message) {
        ADD_FAILURE() << message;
        return 1;
    };
    const auto example = [&]() -> int {
        api::View view;
        api::FovAngles left{-50, 40, 45, -35};
        view.eye_optics = std::array<api::EyeOptics, 2>{
            api::EyeOptics{left, {}}, api::EyeOptics{{-left.right, -left.left, left.up, left.down}, {}}};

        api::View vive;
        api::Expected<api::HmdProfile> profile = api::load_hmd_profile(headset_source_file("profiles/htc-vive.json"));
        if (!profile) return fail(profile.error().message);  // FILE:LINE:COLUMN: field: message
        api::use_hmd_profile(vive, *profile);                // its eye size (1852 × 2056) and IPD too
        vive.width = 926;                                    // as --size replaces the profile's
        vive.height = 1028;

        const Layout layout = Layout::builtin();
        const Result<math::View> a = resolve_view(layout.data().layout, view);
        const Result<math::View> b = resolve_view(layout.data().layout, vive);
        EXPECT_TRUE(a && b);
        EXPECT_EQ((*a->eye_optics)[1].fov, math::mirrored((*a->eye_optics)[0].fov));
        EXPECT_EQ(b->eye_width, 926);
        EXPECT_EQ(b->ipd, 0.0724);
        return 0;
    };
    EXPECT_EQ(example(), 0);
}

}  // namespace
}  // namespace impossible::api
