// The preview's keys without a window: actions change the options in order,
// Esc releases the cursor before it quits, held keys become head movement.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "preview/hud_text.hpp"
#include "preview/keys.hpp"

namespace impossible::preview {
namespace {

TEST(PreviewKeys, TogglesAndStepsTheOptions) {
    PreviewOptions o;
    const KeyEffects e = apply_actions({Action::ToggleHud, Action::ToggleMinimap, Action::NextView, Action::DepthUp,
                                        Action::DepthUp, Action::IpdDown, Action::NextClip, Action::ToggleCulling},
                                       false, o);
    EXPECT_FALSE(e.quit || e.release_cursor || e.screenshot || e.reset);
    EXPECT_FALSE(o.hud);
    EXPECT_FALSE(o.minimap);
    EXPECT_EQ(o.view, PreviewView::Cross);
    EXPECT_EQ(o.frame.max_depth, 10);
    EXPECT_DOUBLE_EQ(o.frame.ipd, 0.064 - kIpdStep);
    EXPECT_EQ(o.frame.clip, render::ClipMode::Oblique);
    EXPECT_FALSE(o.frame.cull_portals);
    // Eye size and the other frame settings are untouched.
    EXPECT_EQ(o.frame.eye_width, 640);
    EXPECT_EQ(o.frame.eye_height, 480);
}

TEST(PreviewKeys, StepsStopAtTheirLimits) {
    PreviewOptions o;
    o.frame.max_depth = 0;
    o.frame.ipd = 0.001;
    apply_actions({Action::DepthDown, Action::IpdDown}, false, o);
    EXPECT_EQ(o.frame.max_depth, 0);
    EXPECT_EQ(o.frame.ipd, 0.0);
    o.frame.max_depth = kMaxPreviewDepth;
    o.frame.ipd = kMaxIpd;
    apply_actions({Action::DepthUp, Action::IpdUp}, false, o);
    EXPECT_EQ(o.frame.max_depth, kMaxPreviewDepth);
    EXPECT_EQ(o.frame.ipd, kMaxIpd);
}

TEST(PreviewKeys, IpdKeysLeaveEyePoses) {
    PreviewOptions o;
    const std::array<math::EyeOffset, 2> eyes = {math::EyeOffset{{-0.03, 0.0, 0.0}, math::dmat3(1.0)},
                                                 math::EyeOffset{{0.03, 0.0, 0.0}, math::dmat3(1.0)}};
    o.frame.eye_offsets = eyes;
    apply_actions({Action::IpdDown, Action::IpdUp, Action::IpdUp}, false, o);
    EXPECT_EQ(o.frame.ipd, 0.064);
    EXPECT_EQ(o.frame.eye_offsets, eyes);
}

TEST(PreviewKeys, EscapeReleasesTheCursorThenQuits) {
    PreviewOptions o;
    KeyEffects e = apply_actions({Action::Escape}, true, o);
    EXPECT_TRUE(e.release_cursor);
    EXPECT_FALSE(e.quit);
    e = apply_actions({Action::Escape}, false, o);
    EXPECT_FALSE(e.release_cursor);
    EXPECT_TRUE(e.quit);
    e = apply_actions({Action::Escape, Action::Screenshot, Action::Escape, Action::Reset}, true, o);
    EXPECT_TRUE(e.release_cursor && e.quit && e.screenshot && e.reset);
}

TEST(PreviewKeys, GHoldsAHandOutAndCommaAndPeriodMoveIt) {
    PreviewOptions o;
    EXPECT_FALSE(o.hand);
    EXPECT_EQ(o.hand_distance, kHandDistance);
    apply_actions({Action::ToggleHand, Action::HandFurther, Action::HandFurther, Action::HandCloser}, false, o);
    EXPECT_TRUE(o.hand);
    EXPECT_DOUBLE_EQ(o.hand_distance, kHandDistance + kHandStep);
    for (int i = 0; i < 40; ++i) apply_actions({Action::HandFurther}, false, o);
    EXPECT_EQ(o.hand_distance, kMaxHandDistance);
    for (int i = 0; i < 40; ++i) apply_actions({Action::HandCloser}, false, o);
    EXPECT_EQ(o.hand_distance, kMinHandDistance);
    apply_actions({Action::ToggleHand}, false, o);
    EXPECT_FALSE(o.hand);
}

TEST(PreviewKeys, LTogglesTheShadows) {
    PreviewOptions o;
    EXPECT_TRUE(o.frame.shadows);
    apply_actions({Action::ToggleShadows}, false, o);
    EXPECT_FALSE(o.frame.shadows);
    apply_actions({Action::ToggleShadows}, false, o);
    EXPECT_TRUE(o.frame.shadows);
}

TEST(PreviewKeys, NineAndZeroStepTheExposureFromTheLayoutsWithinItsRange) {
    PreviewOptions o;
    EXPECT_FALSE(o.frame.exposure.has_value());
    apply_actions({Action::ExposureUp}, false, o, 1.0);  // from the layout's 1 EV
    EXPECT_EQ(o.frame.exposure, 1.5);
    apply_actions({Action::ExposureDown, Action::ExposureDown, Action::ExposureDown}, false, o, 1.0);
    EXPECT_EQ(o.frame.exposure, 0.0);
    o.frame.exposure = 19.8;
    apply_actions({Action::ExposureUp}, false, o);
    EXPECT_EQ(o.frame.exposure, 20.0);
    HudFacts f;
    f.exposure = -1.5;
    EXPECT_NE(hud_text(o, f, {}).lines[4].find("exposure -1.5 EV"), std::string::npos);
    f.exposure = 2.0;
    EXPECT_NE(hud_text(o, f, {}).lines[4].find("exposure +2.0 EV"), std::string::npos);
    EXPECT_NE(hud_text(o, f, {}).lines.back().find("9 0 exposure"), std::string::npos);
}

TEST(PreviewKeys, TheHeldRightHandIsInFrontOfTheHeadTurnedAsIt) {
    const math::HeadPose head{{1.0, 1.6, 2.0}, 90.0, -20.0, 0.0};  // looking along -x, down
    const std::array<math::HeadPose, 2> hands = held_hands(head, 0.5);
    const math::HeadPose& right = hands[1];
    EXPECT_EQ(right.yaw_deg, 90.0);
    EXPECT_EQ(right.pitch_deg, -20.0);
    const math::dvec3 offset = right.position - head.position;
    const math::dmat3 r = math::head_rotation(head);
    EXPECT_NEAR(glm::dot(offset, math::forward_of(r)), 0.5, 1e-12);  // 0.5 m ahead
    EXPECT_NEAR(glm::dot(offset, r[0]), kHandOffset, 1e-12);         // to the right
    EXPECT_NEAR(glm::dot(offset, r[1]), -kHandOffset, 1e-12);        // below
    EXPECT_LT(right.position.x, head.position.x);                    // along -x
    // The left hand hangs at the side, below the head.
    EXPECT_NEAR(hands[0].position.y, head.position.y - 0.7, 1e-12);
    EXPECT_EQ(hands[0].yaw_deg, 90.0);
    EXPECT_EQ(hands[0].pitch_deg, 0.0);
}

TEST(PreviewKeys, MoveInputTakesTheMouseOnlyWhenCaptured) {
    HeldKeys held;
    held.forward = 1;
    held.right = -1;
    held.up = 1;
    held.fast = true;
    MoveInput m = move_input(held, 0.5, false, 3.0, 4.0);
    EXPECT_EQ(m.dt, 0.1);  // capped
    EXPECT_EQ(m.forward, 1);
    EXPECT_EQ(m.right, -1);
    EXPECT_EQ(m.up, 1);
    EXPECT_TRUE(m.fast);
    EXPECT_EQ(m.mouse_dx, 0.0);
    m = move_input(held, 0.02, true, 3.0, 4.0);
    EXPECT_EQ(m.dt, 0.02);
    EXPECT_EQ(m.mouse_dx, 3.0);
    EXPECT_EQ(m.mouse_dy, 4.0);
}

}  // namespace
}  // namespace impossible::preview
