// The view options of render, trace and bench through their table: each
// option reaches its field, the first bad value in table order is reported,
// and bench's table lacks the image files.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "cli/view_options.hpp"
#include "math/eyes.hpp"

namespace impossible::cli {
namespace {

ViewOptions parse(const Args& args, const ViewTables& table = view_options()) {
    return parse_view_options(parse_args(args, 1, table), table);
}

std::string input_error(const Args& args) {
    try {
        parse(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

TEST(ViewOptions, EachOptionReachesItsField) {
    const ViewOptions o = parse({"lay.json",
                                 "--pose",
                                 "1,2,3,90,-5,0",
                                 "--room",
                                 "hall",
                                 "--ipd",
                                 "0.07",
                                 "--fov",
                                 "60",
                                 "--size",
                                 "320x180",
                                 "--max-depth",
                                 "3",
                                 "--max-portal-passes",
                                 "99",
                                 "--out",
                                 "a.png",
                                 "--ids",
                                 "b.png",
                                 "--backend",
                                 "osmesa",
                                 "--stereo",
                                 "two-pass",
                                 "--clip",
                                 "oblique",
                                 "--depth",
                                 "standard",
                                 "--no-cull",
                                 "--portal-texture",
                                 "0.5",
                                 "--occlusion-test",
                                 "--samples",
                                 "4",
                                 "--stats"});
    EXPECT_EQ(o.layout_path, "lay.json");
    ASSERT_TRUE(o.pose);
    EXPECT_EQ(o.pose->position.z, 3.0);
    EXPECT_EQ(o.pose->yaw_deg, 90.0);
    EXPECT_EQ(o.pose->pitch_deg, -5.0);
    EXPECT_EQ(o.room, "hall");
    EXPECT_DOUBLE_EQ(o.frame.ipd, 0.07);
    EXPECT_DOUBLE_EQ(o.frame.fov_y_deg, 60.0);
    EXPECT_EQ(o.frame.eye_width, 320);
    EXPECT_EQ(o.frame.eye_height, 180);
    EXPECT_EQ(o.frame.max_depth, 3);
    EXPECT_EQ(o.frame.max_portal_passes, 99);
    EXPECT_EQ(o.out, "a.png");
    EXPECT_EQ(o.ids, "b.png");
    EXPECT_EQ(o.backend, gl::Backend::OSMesa);
    EXPECT_EQ(o.frame.stereo, render::StereoMode::TwoPass);
    EXPECT_EQ(o.frame.clip, render::ClipMode::Oblique);
    EXPECT_EQ(o.frame.depth, render::DepthMode::Standard);
    EXPECT_FALSE(o.frame.cull_portals);
    EXPECT_DOUBLE_EQ(o.frame.portal_texture_scale, 0.5);
    EXPECT_TRUE(o.frame.occlusion_test);
    EXPECT_EQ(o.frame.samples, 4);
    EXPECT_TRUE(o.stats);
}

TEST(ViewOptions, DefaultsWithoutOptions) {
    const ViewOptions o = parse({});
    const render::FrameDesc defaults;
    EXPECT_FALSE(o.layout_path || o.pose || o.room || o.ids || o.backend);
    EXPECT_EQ(o.out, "stereo.png");
    EXPECT_TRUE(o.frame.cull_portals);
    EXPECT_FALSE(o.frame.occlusion_test);
    EXPECT_EQ(o.frame.eye_width, defaults.eye_width);
    EXPECT_FALSE(o.stats);
}

TEST(ViewOptions, BadValuesNameTheirOption) {
    EXPECT_EQ(input_error({"--fov", "200"}), "--fov: 200 is not in 1..179 degrees (at least 1, less than 179)");
    EXPECT_EQ(input_error({"--pose", "1e8,0,0,0,0,0"}), "--pose: 1e8,0,0,0,0,0 has a value beyond 1e7");
    EXPECT_EQ(input_error({"--backend", "vulkan"}), "--backend: 'vulkan' is not egl or osmesa");
    EXPECT_EQ(input_error({"--depth", "w"}), "--depth: 'w' is not reversed-z or standard");
    EXPECT_EQ(input_error({"--portal-texture", "5"}), "--portal-texture: 5 is not in (0, 4]");
    // The first in table order, whatever the order on the command line.
    EXPECT_EQ(input_error({"--samples", "3", "--ipd", "-1"}), "--ipd: -1 is not in 0..10 m");
}

TEST(ViewOptions, EyePosesReachTheirField) {
    const ViewOptions o = parse({"--eye-poses", "-0.03,0.01,-0.02,5,0,0,0.035,0,0,-5,2,1"});
    ASSERT_TRUE(o.frame.eye_offsets);
    const std::array<math::EyeOffset, 2>& eyes = *o.frame.eye_offsets;
    EXPECT_EQ(eyes[0].position, math::dvec3(-0.03, 0.01, -0.02));
    EXPECT_EQ(eyes[1].position, math::dvec3(0.035, 0.0, 0.0));
    // The angles as --pose reads them (math::head_rotation's convention),
    // through the quaternion every front end uses.
    EXPECT_EQ(eyes[0], math::eye_offset(math::HeadPose{{-0.03, 0.01, -0.02}, 5.0, 0.0, 0.0}));
    EXPECT_EQ(eyes[1].rotation, math::eye_offset(math::HeadPose{{}, -5.0, 2.0, 1.0}).rotation);
    EXPECT_NEAR(math::forward_of(eyes[0].rotation).x, -std::sin(math::radians(5.0)), 1e-15);
    EXPECT_FALSE(parse({}).frame.eye_offsets);
}

TEST(ViewOptions, EyePosesExcludeIpd) {
    const Args both = {"--ipd", "0.07", "--eye-poses", "0,0,0,0,0,0,0,0,0,0,0,0"};
    EXPECT_THROW(parse(both), UsageError);
    EXPECT_EQ(input_error({"--eye-poses", "0,0,0,0,0,0,0,0,0,0,-90,0"}),
              "--eye-poses: right eye: pitch -90 is not within ±89.5 degrees");
    EXPECT_EQ(input_error({"--eye-poses", "0,0,1.5,0,0,0,0,0,0,0,0,0"}),
              "--eye-poses: left eye: the position is 1.5 m from the head centre, more than 1 m");
}

TEST(ViewOptions, TheHelpHasEveryOptionAtColumn29) {
    const std::string help = view_help(view_options());
    const auto listed = [&](const auto& o) {
        const std::string left = option_label(o.name, o.value_name, o.label);
        // A long LEFT has its help on the next line.
        EXPECT_TRUE(help.find("  " + left + " ") != std::string::npos ||
                    help.find("  " + left + "\n") != std::string::npos)
            << left;
    };
    for (const Option<ViewOptions>& o : view_options().own) listed(o);
    for (const Option<FrameOptions>& o : view_options().frame) listed(o);
    EXPECT_NE(help.find("\n  --room ID                  the room the head is in;"), std::string::npos);
    EXPECT_TRUE(
        help.ends_with("\n  --no-cull                  draw every portal and prop without per-eye culling and"
                       " scissor\n"));
}

// Every row of the frame's settings is declared once: render, trace, bench
// and preview take the same rows, and no name is in two tables.
TEST(ViewOptions, TheFramesRowsAreOneTablePerSettingsStruct) {
    std::set<std::string> names;
    for (OptionTable<FrameOptions> t : {view_rows(), technique_rows(), diagnostic_rows()})
        for (const Option<FrameOptions>& o : t) EXPECT_TRUE(names.insert(o.name).second) << o.name;
    for (const Option<ViewOptions>& o : view_options().own) EXPECT_TRUE(names.insert(o.name).second) << o.name;
    EXPECT_EQ(view_options().frame.size(), view_rows().size() + technique_rows().size() + diagnostic_rows().size());
    EXPECT_TRUE(names.count("--samples") && names.count("--stereo") && names.count("--max-depth"));
}

}  // namespace
}  // namespace impossible::cli
