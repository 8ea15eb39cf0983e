// The public API walks a layout with changes as `walk` does (layout-format.md,
// "Changes while walking"): each step names the changes made at it, the
// walker gives the layout with the pairing in force, and paired_at gives the
// one at frame K of a path, which the renderer and the tracer draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "api/api_data.hpp"
#include "changes/change_layouts.hpp"
#include "common/cli_walk.hpp"
#include "impossible/impossible.hpp"

#include <nlohmann/json.hpp>

namespace impossible::api {
namespace {

// Suma's door swap built in code (tests/changes/change_layouts.hpp): the
// change "swap" is armed in the study and makes hall_east lead into the
// garden; study_west and hall_west are closed.
Layout door_swap() { return Layout::of(std::make_shared<LayoutData>(changes::testing::door_swap())); }

Pose at(double x, double yaw) { return {x, 1.6, 0.0, yaw, 0.0, 0.0}; }

// Into the study through hall_east looking back west at study_west (seen:
// the change waits), then turning east (unseen: it is made at frame 2).
std::vector<PathLine> turn_round() {
    return {{at(0.0, -90), std::nullopt}, {at(3.0, 90), std::nullopt}, {at(3.0, -90), std::nullopt}};
}

View small() {
    View v;
    v.width = 64;
    v.height = 36;
    return v;
}

bool has_id(const Frame& f, std::uint8_t id) { return std::find(f.ids.begin(), f.ids.end(), id) != f.ids.end(); }

TEST(ApiWalkChanges, AStepNamesTheChangesMadeAtItAndTheWalkerGivesThePairedLayout) {
    const Layout layout = door_swap();
    Walker walker(layout);
    EXPECT_EQ(walker.layout().portal_ids().size(), 4u);
    const WalkStep first = walker.step(at(0.0, -90));
    EXPECT_TRUE(first.changes.empty());
    ASSERT_EQ(walker.changes().size(), 1u);
    EXPECT_FALSE(walker.changes()[0].armed);
    const WalkStep second = walker.step(at(3.0, 90));  // in the study, study_west in view
    EXPECT_EQ(second.room, "study");
    EXPECT_EQ(second.teleports, std::vector<std::string>{"hall_east"});
    EXPECT_TRUE(second.changes.empty());
    EXPECT_TRUE(walker.changes()[0].armed);
    EXPECT_EQ(walker.changes()[0].made_frame, -1);
    const WalkStep third = walker.step(at(3.0, -90));
    EXPECT_EQ(third.changes, std::vector<std::string>{"swap"});
    EXPECT_EQ(walker.changes()[0].made_frame, 2);
    const Layout paired = walker.layout();
    EXPECT_EQ(paired.portal_ids(), (std::vector<std::string>{"hall_east", "garden_west"}));
    EXPECT_EQ(paired.room_ids(), layout.room_ids());
    EXPECT_EQ(&paired.data().layout.rooms[0].id, &walker.layout().data().layout.rooms[0].id);  // made once
    // Back west: study_west is closed, no teleport.
    const WalkStep fourth = walker.step(at(1.5, -90));
    EXPECT_TRUE(fourth.teleports.empty());
    EXPECT_EQ(fourth.room, "study");
}

TEST(ApiWalkChanges, TheViewOfTheSeenTestDecidesTheFrame) {
    const Layout layout = door_swap();
    const std::vector<PathLine> lines = turn_round();
    const std::vector<WalkStep> plain = walk(layout, lines, 90.0);
    ASSERT_EQ(plain.size(), 3u);
    EXPECT_TRUE(plain[1].changes.empty());
    EXPECT_EQ(plain[2].changes, std::vector<std::string>{"swap"});
    // A field of view of 10 degrees looking west from x = 3 still sees the
    // door 1 m away; looking east it sees none of the four.
    View narrow;
    narrow.fov_deg = 10;
    const Expected<std::vector<WalkStep>> steps = walk(layout, lines, 90.0, narrow);
    ASSERT_TRUE(steps) << steps.error().message;
    EXPECT_EQ((*steps)[2].changes, std::vector<std::string>{"swap"});
    // Walker::make with the same view.
    Expected<Walker> walker = Walker::make(layout, narrow);
    ASSERT_TRUE(walker) << walker.error().message;
    for (const PathLine& line : lines) walker->step(line.head);
    EXPECT_EQ(walker->layout().portal_ids().size(), 2u);
    // A bad view is an Error, worded as the renderer words it.
    View bad;
    bad.width = 0;
    const Expected<std::vector<WalkStep>> refused = walk(layout, lines, 90.0, bad);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("size 0x720"), std::string::npos) << refused.error().message;
    EXPECT_FALSE(Walker::make(layout, bad));
}

TEST(ApiWalkChanges, PairedAtGivesTheLayoutOfTheFrame) {
    const Layout layout = door_swap();
    const std::vector<PathLine> lines = turn_round();
    const Expected<Layout> before = paired_at(layout, lines, 1, 90.0);
    ASSERT_TRUE(before) << before.error().message;
    EXPECT_EQ(&before->data(), &layout.data());  // no change yet: the layout itself
    const Expected<Layout> after = paired_at(layout, lines, 2, 90.0);
    ASSERT_TRUE(after) << after.error().message;
    EXPECT_EQ(after->portal_ids(), (std::vector<std::string>{"hall_east", "garden_west"}));
    EXPECT_FALSE(paired_at(layout, lines, 3, 90.0));
    EXPECT_FALSE(paired_at(layout, lines, 0, 0.0));
}

TEST(ApiWalkChanges, TheTracerAndTheRendererDrawTheClosedDoorAsItsWall) {
    // From the study looking west at study_west: through it the hall (id 1)
    // before the change; after it, the study's own wall (id 2) only.
    const Layout layout = door_swap();
    const Expected<Layout> after = paired_at(layout, turn_round(), 2, 90.0);
    ASSERT_TRUE(after) << after.error().message;
    View view = small();
    view.pose = at(3.0, 90);
    view.room = "study";
    const Expected<Frame> open = trace(layout, view, 1);
    ASSERT_TRUE(open) << open.error().message;
    EXPECT_TRUE(has_id(*open, 1));
    const Expected<Frame> closed = trace(*after, view, 1);
    ASSERT_TRUE(closed) << closed.error().message;
    EXPECT_FALSE(has_id(*closed, 1));
    EXPECT_TRUE(has_id(*closed, 2));
    Expected<Renderer> renderer = Renderer::headless(*after);
    ASSERT_TRUE(renderer) << renderer.error().message;
    const Expected<Frame> drawn = renderer->render(view);
    ASSERT_TRUE(drawn) << drawn.error().message;
    EXPECT_EQ(drawn->ids, closed->ids);
}

using test::cli_walk;

TEST(ApiWalkChanges, TheExampleWalksMakeTheirChangesAtWalksFrames) {
    for (const char* name : {"door_swap", "rerouted_corridor"}) {
        SCOPED_TRACE(name);
        const std::string base = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name;
        const Expected<Layout> layout = Layout::load(base + ".json");
        ASSERT_TRUE(layout) << layout.error().message;
        const Expected<std::vector<PathLine>> lines = read_path_lines(base + "_walk.txt");
        ASSERT_TRUE(lines) << lines.error().message;
        View view;  // the eyes of walk --size 320x180 --fov 60
        view.width = 320;
        view.height = 180;
        view.fov_deg = 60;
        const Expected<std::vector<WalkStep>> steps = walk(*layout, *lines, 90.0, view);
        ASSERT_TRUE(steps) << steps.error().message;
        const std::vector<nlohmann::json> cli = cli_walk(base + ".json", base + "_walk.txt", "--size 320x180 --fov 60");
        ASSERT_EQ(cli.size(), steps->size());
        int made = 0;
        for (std::size_t k = 0; k < cli.size(); ++k) {
            EXPECT_EQ((*steps)[k].room, cli[k]["room"]) << k;
            const std::vector<std::string> expected = cli[k].contains("changes")
                                                          ? cli[k]["changes"].get<std::vector<std::string>>()
                                                          : std::vector<std::string>{};
            EXPECT_EQ((*steps)[k].changes, expected) << k;
            made += static_cast<int>(expected.size());
        }
        EXPECT_EQ(made, 1);
    }
}

}  // namespace
}  // namespace impossible::api
