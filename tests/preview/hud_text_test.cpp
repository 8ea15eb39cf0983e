// The HUD's words without a window.
#include <gtest/gtest.h>

#include "preview/hud_text.hpp"

namespace impossible::preview {
namespace {

TEST(PreviewHudText, ReportsTheFrameAndTheSettings) {
    PreviewOptions o;
    o.frame.ipd = 0.07;
    o.frame.clip = render::ClipMode::Oblique;
    HudFacts f;
    f.title = "impossible preview - t";
    f.median_ms = 16.66;
    f.timed_frames = 60;
    f.eye_width = 320;
    f.eye_height = 240;
    f.room = "hall";
    f.portal_passes_drawn = 3;
    f.portal_passes_culled = 1;
    f.max_level_reached = 2;
    f.physical = {{1.0, 1.6, -0.5}, 12.4, -3.0, 0.0};
    f.time = 2.46;
    const HudText hud = hud_text(o, f, {});
    ASSERT_EQ(hud.lines.size(), 8u);
    EXPECT_EQ(hud.lines[0], "impossible preview - t   view: parallel");
    EXPECT_EQ(hud.lines[1], "frame 16.7 ms (median of 60)   eye 320x240   time 2.5 s");
    EXPECT_EQ(hud.lines[2], "room hall   portal passes 3 drawn, 1 culled");
    EXPECT_EQ(hud.lines[3], "recursion depth 8 (reached 2)   IPD 70 mm");
    EXPECT_EQ(hud.lines[4], "clip oblique   culling on   exposure 0.0 EV");
    EXPECT_EQ(hud.lines[5], "physical head 1.00 1.60 -0.50  yaw 12  pitch -3");
    EXPECT_EQ(hud.lines[6], "click to look around, Esc quits");
    EXPECT_NE(hud.lines[7].find("G , . hand"), std::string::npos);
    // G's hand: how far it is held out.
    o.hand = true;
    EXPECT_EQ(hud_text(o, f, {}).lines[5], "physical head 1.00 1.60 -0.50  yaw 12  pitch -3   hand 0.40 m");
    // Each eye's pose: how far apart the eyes are.
    o.frame.eye_offsets = std::array<math::EyeOffset, 2>{math::EyeOffset{{-0.03, 0.0, -0.01}, math::dmat3(1.0)},
                                                         math::EyeOffset{{0.03, 0.0, 0.0}, math::dmat3(1.0)}};
    EXPECT_EQ(hud_text(o, f, {}).lines[3], "recursion depth 8 (reached 2)   eye poses 61 mm apart");
    EXPECT_TRUE(hud.errors.empty());
    o.hud = false;
    EXPECT_TRUE(hud_text(o, f, {}).lines.empty());
}

TEST(PreviewHudText, LitLayoutsShowTheirLightsAndShadows) {
    PreviewOptions o;
    HudFacts f;
    f.room = "hall";
    const std::size_t unlit = hud_text(o, f, {}).lines.size();
    f.lit = true;
    f.room_lights = 2;
    f.light_images = 7;
    f.light_depth = 1;
    const HudText hud = hud_text(o, f, {});
    ASSERT_EQ(hud.lines.size(), unlit + 1);
    EXPECT_EQ(hud.lines[3], "lights 2 in this room   light images 7   light depth 1   shadows on");
    EXPECT_NE(hud.lines.back().find("L shadows"), std::string::npos);
    o.frame.shadows = false;
    EXPECT_EQ(hud_text(o, f, {}).lines[3], "lights 2 in this room   light images 7   light depth 1   shadows off");
}

TEST(PreviewHudText, ListsTheFirstReloadErrors) {
    EXPECT_TRUE(reload_error_lines({}).empty());
    const std::vector<std::string> two = reload_error_lines({"a", "b"});
    ASSERT_EQ(two.size(), 3u);
    EXPECT_EQ(two[0], "layout reload failed; still showing the last good layout:");
    EXPECT_EQ(two[2], "b");
    const std::vector<std::string> many = reload_error_lines(std::vector<std::string>(11, "e"));
    ASSERT_EQ(many.size(), 1 + kMaxReloadErrors + 1);
    EXPECT_EQ(many.back(), "... and 3 more");
    PreviewOptions o;
    o.hud = false;
    EXPECT_EQ(hud_text(o, HudFacts{}, {"x"}).errors.size(), 2u);  // errors show without the HUD
}

}  // namespace
}  // namespace impossible::preview

namespace impossible::preview {
namespace {

// A small window keeps most of its view: --size 160x90 makes a 320x90
// window, where the whole HUD (8 lines of 12 pixels and more) covered all of
// it; the default 640x480 an eye keeps every line whole.
TEST(PreviewHudText, SmallWindowsGetAShorterHud) {
    PreviewOptions o;
    HudFacts f;
    f.title = "impossible preview - t";
    f.room = "hall";
    const HudText full = hud_text(o, f, {});
    EXPECT_EQ(hud_scale(90), 1.0f);
    EXPECT_EQ(hud_scale(480), 1.5f);
    const HudText small = fit_hud(full, 320, 90, hud_scale(90));
    ASSERT_EQ(small.lines.size(), 2u);  // 2 rows of 12 px in 40 % of 90 px
    EXPECT_EQ(small.lines[0], full.lines[0]);
    for (const std::string& line : small.lines) EXPECT_LE(line.size() * 6 + 6, 320u) << line;
    EXPECT_EQ(fit_hud(full, 160, 90, 1.0f).lines[0], "impossible preview - t...");
    // The errors of a failed reload come first.
    const HudText failed = fit_hud(hud_text(o, f, {"a.json:1:1: bad"}), 320, 90, 1.0f);
    ASSERT_EQ(failed.errors.size(), 2u);
    EXPECT_TRUE(failed.lines.empty());
    // The default window: nothing cut.
    const HudText big = fit_hud(full, 1280, 480, hud_scale(480));
    EXPECT_EQ(big.lines, full.lines);
    o.hud = false;
    EXPECT_TRUE(fit_hud(hud_text(o, f, {}), 320, 90, 1.0f).lines.empty());
}

}  // namespace
}  // namespace impossible::preview
