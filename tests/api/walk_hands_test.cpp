// The public API's walk with hands: each step of a path line with hands
// holds the hands' virtual poses (W · physical, as `render --path --frame`
// draws them) and rooms (as `impossible walk` prints them), so frame k of a
// walk can be drawn with its hands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/api_data.hpp"
#include "common/cli_walk.hpp"
#include "impossible/impossible.hpp"
#include "layout/path_file.hpp"
#include "walk/replay.hpp"

namespace impossible::api {
namespace {

std::string source_file(const char* name) { return std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name; }

using test::cli_walk;

TEST(ApiWalkHands, StepsHoldTheHandsVirtualPosesAndRooms) {
    const Expected<Layout> l = Layout::load(source_file("hands_door.json"));
    ASSERT_TRUE(l) << l.error().message;
    const std::string path = source_file("hands_walk.txt");
    const Expected<std::vector<PathLine>> lines = read_path_lines(path);
    ASSERT_TRUE(lines) << lines.error().message;
    const Expected<std::vector<Pose>> heads = read_path(path);
    ASSERT_TRUE(heads);
    ASSERT_EQ(lines->size(), heads->size());
    const std::vector<WalkStep> steps = walk(*l, *lines);
    const std::vector<nlohmann::json> cli = cli_walk(source_file("hands_door.json"), path);
    ASSERT_EQ(cli.size(), steps.size());
    const layout::PathFrames frames = layout::read_path_frames_file(path);
    ASSERT_TRUE(frames);
    std::vector<std::string> hand_rooms;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const WalkStep& s = steps[k];
        EXPECT_EQ((*lines)[k].head.z, (*heads)[k].z);
        EXPECT_EQ(s.room, cli[k]["room"]) << k;
        ASSERT_EQ(s.hands.has_value(), cli[k].contains("hands")) << k;
        if (!s.hands) continue;
        EXPECT_EQ((*s.hands)[0].room, cli[k]["hands"][0]) << k;
        EXPECT_EQ((*s.hands)[1].room, cli[k]["hands"][1]) << k;
        hand_rooms.push_back((*s.hands)[0].room);
        if (k % 17 != 0) continue;
        // Frame k drawn from the step (its head, room, hands and time) is
        // the frame `render --path --frame k` draws, bit for bit.
        View v;
        v.pose = s.virtual_pose;
        v.room = s.room;
        v.time = static_cast<double>(k) / 90.0;
        v.hands = std::array<Pose, 2>{(*s.hands)[0].virtual_pose, (*s.hands)[1].virtual_pose};
        const Result<math::View> mine = resolve_view(l->data().layout, v);
        ASSERT_TRUE(mine) << mine.error();
        math::View replayed;
        walk::set_replayed_view(replayed, l->data().layout, *frames, k, 90.0);
        EXPECT_EQ(mine->room, replayed.room) << k;
        EXPECT_EQ(mine->time, replayed.time) << k;
        EXPECT_EQ(mine->head.position, replayed.head.position) << k;
        ASSERT_TRUE(mine->hands && replayed.hands);
        for (std::size_t h = 0; h < 2; ++h) {
            EXPECT_EQ((*mine->hands)[h].position, (*replayed.hands)[h].position) << k;
            EXPECT_EQ((*mine->hands)[h].yaw_deg, (*replayed.hands)[h].yaw_deg) << k;
            EXPECT_EQ((*mine->hands)[h].pitch_deg, (*replayed.hands)[h].pitch_deg) << k;
            EXPECT_EQ((*mine->hands)[h].roll_deg, (*replayed.hands)[h].roll_deg) << k;
        }
    }
    // The walk reaches through the door: the hands are in both rooms.
    std::sort(hand_rooms.begin(), hand_rooms.end());
    hand_rooms.erase(std::unique(hand_rooms.begin(), hand_rooms.end()), hand_rooms.end());
    EXPECT_EQ(hand_rooms.size(), 2u);
}

TEST(ApiWalkHands, AStepWithoutHandsHasNone) {
    const Layout l = Layout::builtin();
    Walker walker(l);
    EXPECT_FALSE(walker.step(l.start()).hands);
    const Pose start = l.start();
    const Pose left{start.x - 0.2, start.y - 0.4, start.z, 0, 0, 0},
        right{start.x + 0.2, start.y - 0.4, start.z, 0, 0, 0};
    const WalkStep with = walker.step(start, {left, right});
    ASSERT_TRUE(with.hands);
    // Not moved: W is the identity, the virtual hands are the physical ones,
    // beside the head in its room.
    EXPECT_EQ((*with.hands)[0].room, with.room);
    EXPECT_EQ((*with.hands)[1].room, with.room);
    EXPECT_EQ((*with.hands)[1].virtual_pose.x, right.x);
    EXPECT_EQ((*with.hands)[1].virtual_pose.y, right.y);
    EXPECT_FALSE(walker.step(l.start()).hands);
}

}  // namespace
}  // namespace impossible::api
