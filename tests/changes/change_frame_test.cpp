// The example walks with changes (layouts/door_swap.json,
// layouts/rerouted_corridor.json): the rooms they pass, the frame each change
// is made at, and, at that frame, the tracer at 1280x720: the picture with
// the pairing the frame started with and the one with the change made are
// the same bytes (colour and ids), because none of the doors the change
// affects shows in any pixel (layout-format.md, "Changes while walking").
#include <gtest/gtest.h>

#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "session/walk_driver.hpp"
#include "trace/tracer.hpp"

namespace impossible::changes {
namespace {

struct Example {
    const char* layout;
    const char* walk;
    std::vector<std::string> rooms;  // in the order the walk enters them
    std::size_t shown;               // a later frame that looks at the changed doors
};

class ExampleWalks : public ::testing::TestWithParam<Example> {};

image::Image traced(const session::Session& session, const math::View& view) {
    trace::TraceDesc desc;
    static_cast<math::View&>(desc) = view;
    const Result<image::Image> image = trace::trace_frame(session.layout(), desc);
    EXPECT_TRUE(image) << (image ? "" : image.error());
    return image ? *image : image::Image{};
}

TEST_P(ExampleWalks, MakeTheirChangeWhereNoPixelShowsItsDoors) {
    const Example& e = GetParam();
    const std::string dir = IMPOSSIBLE_SOURCE_DIR "/layouts/";
    layout::LoadResult loaded = layout::load_layout_file(dir + e.layout);
    ASSERT_TRUE(loaded.layout) << loaded.errors.front().str();
    const session::Session session(std::move(*loaded.layout));
    const layout::PathFrames frames = layout::read_path_frames_file(dir + e.walk);
    ASSERT_TRUE(frames) << frames.error();

    math::View view;  // render's defaults: 1280x720 an eye, 90°, depth 8
    session::WalkDriver driver(session, view);
    std::vector<std::string> rooms;
    std::vector<std::size_t> change_frames;
    for (std::size_t k = 0; k < frames->size(); ++k) {
        const session::WalkedFrame f = driver.step((*frames)[k].head, std::nullopt, k / 90.0);
        const std::string& room = session.layout().rooms[static_cast<std::size_t>(f.room)].id;
        if (rooms.empty() || rooms.back() != room) rooms.push_back(room);
        if (!f.changes.empty()) change_frames.push_back(k);
    }
    EXPECT_EQ(rooms, e.rooms);
    ASSERT_EQ(change_frames.size(), 1u);
    ASSERT_NE(driver.changes(), nullptr);
    EXPECT_EQ(driver.changes()->status()[0].made_frame, static_cast<int>(change_frames[0]));

    // Frame K's picture with the change made, and with the pairing before
    // it (the loaded one: each example has one change).
    math::View at = view;
    const session::Session paired = session::replay_to(session, at, *frames, change_frames[0], 90.0);
    ASSERT_NE(paired.layout().portals.size(), session.layout().portals.size());  // a door was closed
    const image::Image after = traced(paired, at);
    const image::Image before = traced(session, at);
    EXPECT_EQ(after.rgb, before.rgb);
    EXPECT_EQ(after.ids, before.ids);
    // Later the head has turned round to the doors: there the two
    // pairings differ on screen (else the test above would prove nothing).
    math::View late = view;
    late.eye_width = 320;
    late.eye_height = 180;
    const session::Session turned = session::replay_to(session, late, *frames, e.shown, 90.0);
    EXPECT_NE(traced(turned, late).ids, traced(session, late).ids);
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, ExampleWalks,
    ::testing::Values(Example{"door_swap.json", "door_swap_walk.txt", {"hall", "study", "garden"}, 100},
                      Example{"rerouted_corridor.json",
                              "rerouted_corridor_walk.txt",
                              {"lobby", "blue_corridor", "gallery", "red_corridor", "library"},
                              219}),
    [](const auto& info) { return std::string(info.index == 0 ? "DoorSwap" : "ReroutedCorridor"); });

}  // namespace
}  // namespace impossible::changes
