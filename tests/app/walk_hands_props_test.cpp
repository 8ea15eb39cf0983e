// `impossible walk` with hands and moving props (cli.md, "Time, hands and
// lights"): 18-number path lines give "hands":["ROOM","ROOM"], a layout
// with moving props gives "props":{"ID":"ROOM",...} on every line, at time
// k / fps for line k. Layouts built in code.
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cmd_walk.hpp"
#include "walk/walk_test_layouts.hpp"

namespace impossible::app {
namespace {

using walk::testing::add_pair;
using walk::testing::add_room;
using walk::testing::empty_layout;
using walk::testing::make_rect;

struct HandsReplay {
    int status = -1;
    std::string out;
    std::string err;
    std::vector<nlohmann::json> lines;
};

HandsReplay hands_replay(const layout::Layout& l, const std::string& text, double fps = layout::kDefaultPathFps) {
    std::istringstream in(text);
    std::ostringstream out, err;
    HandsReplay r;
    WalkSettings settings;
    settings.fps = fps;
    r.status = run_walk_stream(session::Session(l), in, "walk.txt", out, err, settings);
    r.out = out.str();
    r.err = err.str();
    std::istringstream lines(r.out);
    std::string line;
    while (std::getline(lines, line)) r.lines.push_back(nlohmann::json::parse(line));
    return r;
}

// "hall" (x -2..2) with a door at x = 2 that leads to "annex", a room far
// away (x 10..14): what is past hall's east wall is annex only through the
// door (0.5 m either side of z = 0, 2.2 m high).
layout::Layout far_annex() {
    layout::Layout l = empty_layout("far_annex");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int annex = add_room(l, "annex", {10, 0, -2}, {14, 3, 2});
    add_pair(l, "hall_east", hall, make_rect({2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), "annex_west", annex,
             make_rect({10, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    l.start = {hall, {0, 1.6, 1}, 0.0};
    return l;
}

// far_annex with a box in hall, anchor (0.95, 0.7, 0), sliding 2 m east in
// 1 s: its anchor passes the door at x = 2 at t = 1.05 / 2 = 0.525 s.
layout::Layout sliding_box(bool with_still_box) {
    layout::Layout l = far_annex();
    if (with_still_box) {
        layout::BoxProp still;
        still.min = {-1.5, 0, -1.5};
        still.max = {-1.0, 0.5, -1.0};
        still.id = "still";
        l.rooms[0].props.push_back(still);
    }
    layout::BoxProp box;
    box.min = {0.85, 0.6, -0.1};
    box.max = {1.05, 0.8, 0.1};
    box.id = "crate";
    box.motion.keys = {layout::MotionKey{0.0, {0, 0, 0}}, layout::MotionKey{1.0, {2, 0, 0}}};
    l.rooms[0].props.push_back(box);
    return l;
}

std::string still_head_lines(int count) {
    std::string text;
    for (int k = 0; k < count; ++k) text += "0 1.6 1 0 0 0\n";
    return text;
}

TEST(WalkHands, AHandThroughADoorIsInTheTargetRoomWhileTheHeadIsNot) {
    // The head stands 0.3 m before the door; the right hand reaches 0.3 m
    // through it, the left past the wall beside the door (z 0.75 at x = 2).
    const HandsReplay r = hands_replay(far_annex(),
                                       "1.7 1.6 0 -90 0 0\n"
                                       "1.7 1.6 0 -90 0 0  2.3 1.6 1.5 -90 0 0  2.3 1.2 0 -90 0 0\n");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(r.lines.size(), 2u);
    EXPECT_EQ(r.lines[0].size(), 5u) << r.out;  // a 6-number line: no "hands"
    EXPECT_FALSE(r.lines[0].contains("props"));
    EXPECT_EQ(r.lines[1]["room"], "hall");
    EXPECT_EQ(r.lines[1]["hands"], nlohmann::json::array({"hall", "annex"})) << r.out;
    EXPECT_FALSE(r.lines[1].contains("props"));  // no prop moves
}

TEST(WalkHands, HandsAreWalkedFromTheHeadAfterItsTeleports) {
    // The head has gone through the door (W moves it 8 m east): the hands,
    // given in physical coordinates like the head, are mapped by W first. The
    // left hand reaches back through annex's door into hall.
    const HandsReplay r = hands_replay(far_annex(),
                                       "1.5 1.6 0 -90 0 0\n"
                                       "2.5 1.6 0 -90 0 0  1.8 1.2 0 -90 0 0  2.8 1.2 0.3 -90 0 0\n");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(r.lines.size(), 2u);
    EXPECT_EQ(r.lines[1]["room"], "annex");
    EXPECT_EQ(r.lines[1]["teleports"], nlohmann::json::array({"hall_east"}));
    EXPECT_EQ(r.lines[1]["hands"], nlohmann::json::array({"hall", "annex"})) << r.out;
}

TEST(WalkHands, SixNumberLinesStayAsTheyWereInAMixedFile) {
    const std::string six = "1.7 1.6 0 -90 0 0\n1.8 1.6 0 -90 0 0\n";
    const HandsReplay plain = hands_replay(far_annex(), six);
    const HandsReplay mixed =
        hands_replay(far_annex(), "1.7 1.6 0 -90 0 0\n1.7 1.6 0 -90 0 0 1 1 0 0 0 0 1 1 0 0 0 0\n1.8 1.6 0 -90 0 0\n");
    ASSERT_EQ(plain.status, 0) << plain.err;
    ASSERT_EQ(mixed.status, 0) << mixed.err;
    ASSERT_EQ(mixed.lines.size(), 3u);
    std::istringstream plain_lines(plain.out), mixed_lines(mixed.out);
    std::string a, b;
    std::getline(plain_lines, a);
    std::getline(mixed_lines, b);
    EXPECT_EQ(a, b);
    EXPECT_EQ(mixed.lines[1]["hands"], nlohmann::json::array({"hall", "hall"}));
    EXPECT_FALSE(mixed.lines[2].contains("hands"));
    EXPECT_EQ(mixed.lines[2]["frame"], 2);
    EXPECT_EQ(mixed.lines[2]["position"], plain.lines[1]["position"]);
}

// The room of the sliding box changes at the first line whose time k / fps
// is past 0.525 s: line 48 at 90 fps (47 / 90 = 0.522), line 6 at 10 fps.
TEST(WalkProps, AMovingPropChangesRoomAtTheLineOfItsTime) {
    for (const auto& [fps, first_annex] : {std::pair{90.0, 48}, std::pair{10.0, 6}}) {
        const HandsReplay r = hands_replay(sliding_box(true), still_head_lines(60), fps);
        ASSERT_EQ(r.status, 0) << r.err;
        ASSERT_EQ(r.lines.size(), 60u);
        for (int k = 0; k < 60; ++k) {
            const nlohmann::json& props = r.lines[static_cast<std::size_t>(k)]["props"];
            ASSERT_EQ(props.size(), 1u) << "only the prop with a motion: " << props.dump();
            EXPECT_EQ(props["crate"], k < first_annex ? "hall" : "annex") << "fps " << fps << ", line " << k;
        }
    }
    // The default is 90.
    const HandsReplay r = hands_replay(sliding_box(false), still_head_lines(49));
    ASSERT_EQ(r.lines.size(), 49u);
    EXPECT_EQ(r.lines[47]["props"]["crate"], "hall");
    EXPECT_EQ(r.lines[48]["props"]["crate"], "annex");
}

TEST(WalkProps, PropsFollowTheLayoutOrderAfterTheHands) {
    layout::Layout l = sliding_box(false);
    layout::BoxProp other;
    other.min = {10.5, 0, -1.5};
    other.max = {11, 0.5, -1};
    other.id = "ball";
    other.motion.keys = {layout::MotionKey{0.0, {0, 0, 0}}, layout::MotionKey{2.0, {0, 0, 1}}};
    l.rooms[1].props.push_back(other);
    const HandsReplay r = hands_replay(l, "0 1.6 1 0 0 0 0 1 0 0 0 0 0 1 0 0 0 0\n", 10.0);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out,
              "{\"frame\":0,\"room\":\"hall\",\"teleports\":[],\"position\":[0,1.6,1],\"forward\":[0,0,-1],"
              "\"hands\":[\"hall\",\"hall\"],\"props\":{\"crate\":\"hall\",\"ball\":\"annex\"}}\n");
}

TEST(WalkProps, SevenNumberLinesAreRefusedWithNoOutput) {
    const HandsReplay r = hands_replay(sliding_box(false), "0 1.6 1 0 0 0\n0 1.6 1 0 0 0 1\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err,
              "walk.txt:2: expected 6 or 18 numbers (X Y Z YAW PITCH ROLL of the head, then of the left and the right "
              "hand), found 7 fields\n");
}

}  // namespace
}  // namespace impossible::app
