// The preview walks a layout with changes as `walk` does (its walk driver,
// session::WalkDriver, with the seen test on the options' eyes, changed as
// the keys change them), and its HUD shows the armed and the made changes.
#include <gtest/gtest.h>

#include "changes/change_layouts.hpp"
#include "preview/hud_text.hpp"
#include "session/walk_driver.hpp"

namespace impossible::preview {
namespace {

math::HeadPose at(double x, double yaw) { return {{x, 1.6, 0.0}, yaw, 0.0, 0.0}; }

TEST(PreviewChanges, TheHudLineNamesTheArmedAndTheMadeChanges) {
    layout::Layout l = changes::testing::door_swap();
    layout::Change back;
    back.id = "back";
    back.when.after = 0;
    back.when.enter = 0;
    back.pairs = {{0, 1}};
    l.changes.push_back(back);
    const session::Session s(l);
    session::WalkDriver driver(s);
    driver.step(at(0.0, -90));
    ASSERT_NE(driver.changes(), nullptr);
    EXPECT_EQ(driver.seen_passes(), 0);  // nothing armed: no seen test
    EXPECT_EQ(changes_line(l, *driver.changes(), 0), "changes armed: none   made: none   not armed: 2");
    driver.step(at(3.0, 90));  // in the study, study_west in view
    EXPECT_EQ(changes_line(l, *driver.changes(), 0), "changes armed: swap   made: none   not armed: 1");
    EXPECT_GT(driver.seen_passes(), 0);  // through study_west into the hall
    EXPECT_EQ(changes_line(l, *driver.changes(), 3),
              "changes armed: swap   made: none   not armed: 1   seen test 3 passes");
    driver.step(at(3.0, -90));  // turned away: made
    EXPECT_EQ(changes_line(l, *driver.changes(), 0), "changes armed: none   made: swap (frame 2)   not armed: 1");
    // The HUD shows it under the room's line.
    HudFacts f;
    f.changes = changes_line(l, *driver.changes(), 0);
    const HudText hud = hud_text(PreviewOptions{}, f, {});
    ASSERT_EQ(hud.lines.size(), 9u);
    EXPECT_EQ(hud.lines[3], f.changes);
    // Without changes, no line.
    EXPECT_EQ(hud_text(PreviewOptions{}, HudFacts{}, {}).lines.size(), 8u);
}

TEST(PreviewChanges, TheEyesOfTheSeenTestFollowTheOptions) {
    // 0.3 m from study_west looking south: its edge lies 31 degrees off the
    // view axis, in view at render's default field of view, out of view at
    // 10 degrees (the preview's options changed between frames).
    const session::Session s(changes::testing::door_swap());
    session::WalkDriver driver(s);
    driver.step(at(0.0, -90));
    EXPECT_TRUE(driver.step(at(2.3, 180)).changes.empty());
    math::View narrow;
    narrow.fov_y_deg = 10.0;
    driver.set_view(narrow);
    EXPECT_EQ(driver.step(at(2.3, 180)).changes, std::vector<int>{0});
    EXPECT_EQ(driver.session().layout().portals.size(), 2u);
}

TEST(PreviewChanges, AReloadGoesOnInTheRoomWithTheSameMapping) {
    // As poll_reload: a new driver resumes the old walker's W and physical
    // pose in its room; the changes start over.
    const session::Session s(changes::testing::door_swap());
    session::WalkDriver first(s);
    first.step(at(0.0, -90));
    first.step(at(3.0, 90));
    session::WalkDriver next(s);
    next.resume(first.walker().room(), first.walker().physical_to_virtual(), first.walker().physical_pose());
    const session::WalkedFrame f = next.step(at(3.0, -90));
    EXPECT_EQ(f.room, 1);
    EXPECT_TRUE(f.teleports.empty());
    EXPECT_EQ(f.changes, std::vector<int>{0});  // armed in the study at once
    // start_in: a walk that starts in the room named.
    session::WalkDriver in_study(s);
    in_study.start_in(1);
    EXPECT_EQ(in_study.step(at(3.0, 90)).room, 1);
}

}  // namespace
}  // namespace impossible::preview
