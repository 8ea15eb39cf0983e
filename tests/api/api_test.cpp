// The public C++ API (include/impossible/impossible.hpp) against the
// library's own paths: the same layouts, frames and walks as the commands.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "api/api_data.hpp"
#include "common/temp_dir.hpp"
#include "impossible/impossible.hpp"
#include "layout/layout.hpp"
#include "trace/tracer.hpp"
#include "walk/walker.hpp"

namespace impossible::api {
namespace {

namespace fs = std::filesystem;

std::string layout_file(const char* name) { return std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name; }

TEST(ApiVersion, HeaderAndLibraryAgree) {
    EXPECT_STREQ(version(), IMPOSSIBLE_VERSION);
    EXPECT_EQ(IMPOSSIBLE_VERSION_NUMBER,
              IMPOSSIBLE_VERSION_MAJOR * 10000 + IMPOSSIBLE_VERSION_MINOR * 100 + IMPOSSIBLE_VERSION_PATCH);
}

TEST(ApiLayout, LoadsAndReports) {
    const Expected<Layout> l = Layout::load(layout_file("four_rooms.json"));
    ASSERT_TRUE(l) << l.error().message;
    EXPECT_EQ(l->room_ids().size(), 4u);
    EXPECT_FALSE(l->start_room().empty());
    EXPECT_NE(l->report_text().find("rooms"), std::string::npos);
    EXPECT_EQ(l->report_json().front(), '{');
    const Layout builtin = Layout::builtin();
    EXPECT_EQ(builtin.start_room(), "hall");
}

TEST(ApiLayout, BadInputIsAnErrorWithEveryPosition) {
    const test::TempDir dir("api_test");
    const fs::path file = dir / "bad.json";
    std::ofstream(file) << "{\"format\": \"impossible-layout\", \"version\": 1,\n \"bogus\": 1, \"rooms\": []}\n";
    const Expected<Layout> l = Layout::load(file.string());
    ASSERT_FALSE(l);
    EXPECT_NE(l.error().message.find(file.string() + ":2:2: "), std::string::npos) << l.error().message;
    EXPECT_NE(l.error().message.find('\n'), std::string::npos) << "every problem, one a line";
    EXPECT_FALSE(Layout::load((dir / "missing.json").string()));
    EXPECT_FALSE(Layout::parse("{", "text", "."));
}

TEST(ApiView, RangesAndRoomsAreChecked) {
    const Layout l = Layout::builtin();
    View v;
    v.width = 0;
    EXPECT_FALSE(trace(l, v));
    v = View{};
    v.room = "no-such-room";
    const Expected<Frame> none = trace(l, v);
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().message.find("no-such-room"), std::string::npos);
    v = View{};
    v.pose = Pose{100, 1.6, 100, 0, 0, 0};
    EXPECT_NE(trace(l, v).error().message.find("in no room"), std::string::npos);
}

// The API's frame is the library's frame, byte for byte.
TEST(ApiRenderer, RenderAndTraceEqualTheLibrary) {
    const Expected<Layout> l = Layout::load(layout_file("three_kinds.json"));
    ASSERT_TRUE(l) << l.error().message;
    View v;
    v.width = 96;
    v.height = 54;
    Expected<Renderer> renderer = Renderer::headless(*l);
    ASSERT_TRUE(renderer) << renderer.error().message;
    const Expected<Frame> drawn = renderer->render(v);
    ASSERT_TRUE(drawn) << drawn.error().message;
    EXPECT_EQ(drawn->width, 192);
    EXPECT_EQ(drawn->rgb.size(), 192u * 54 * 3);
    EXPECT_GT(drawn->stats.draw_calls, 0);

    const layout::Layout& own = l->data().layout;
    math::View frame;
    frame.head.position = own.start.position;
    frame.head.yaw_deg = own.start.yaw_deg;
    frame.room = own.start.room;
    frame.eye_width = 96;
    frame.eye_height = 54;
    Expected<Renderer> second = Renderer::headless(*l);  // a second renderer in the same process
    ASSERT_TRUE(second);
    const Expected<Frame> again = second->render(v);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->rgb, drawn->rgb);
    EXPECT_EQ(again->ids, drawn->ids);

    trace::TraceDesc desc;
    static_cast<math::View&>(desc) = frame;
    const Result<image::Image> reference = trace::trace_frame(own, desc);
    ASSERT_TRUE(reference);
    const Expected<Frame> traced = trace(*l, v, 1);
    ASSERT_TRUE(traced);
    EXPECT_EQ(traced->rgb, reference->rgb);
    EXPECT_EQ(traced->ids, reference->ids);
}

TEST(ApiWalker, WalksAsTheLibraryDoes) {
    const Layout l = Layout::builtin();
    const Expected<std::vector<Pose>> poses = tour(l);
    ASSERT_TRUE(poses) << poses.error().message;
    ASSERT_GT(poses->size(), 10u);
    const std::vector<WalkStep> steps = walk(l, *poses);
    walk::Walker own(l.data().layout);
    int teleports = 0;
    for (std::size_t k = 0; k < poses->size(); ++k) {
        const Pose& p = (*poses)[k];
        const std::vector<int> passed = own.step(math::HeadPose{{p.x, p.y, p.z}, p.yaw, p.pitch, p.roll});
        ASSERT_EQ(steps[k].teleports.size(), passed.size()) << k;
        teleports += static_cast<int>(passed.size());
        EXPECT_EQ(steps[k].room, l.data().layout.rooms[own.room()].id);
        EXPECT_EQ(steps[k].position[0], own.position().x);
        EXPECT_EQ(steps[k].forward[2], own.forward().z);
    }
    EXPECT_GT(teleports, 0) << "the tour passes a door";
    // The walked frame renders: its virtual pose and room.
    View v;
    v.width = 32;
    v.height = 18;
    v.pose = steps.back().virtual_pose;
    v.room = steps.back().room;
    EXPECT_TRUE(trace(l, v, 1));
}

TEST(ApiDesign, GenerateIsDeterministicAndLoads) {
    GenerateRequest request;
    request.rooms = 3;
    request.seed = 7;
    const Expected<std::string> a = generate(request), b = generate(request);
    ASSERT_TRUE(a) << a.error().message;
    EXPECT_EQ(*a, *b);
    const Expected<Layout> l = Layout::parse(*a, "generated", ".");
    ASSERT_TRUE(l) << l.error().message;
    EXPECT_EQ(l->room_ids().size(), 3u);
    const Expected<std::string> svg = plan_svg(*l);
    ASSERT_TRUE(svg);
    EXPECT_EQ(svg->rfind("<svg", 0) == 0 || svg->rfind("<?xml", 0) == 0, true);
    request.rooms = 0;
    EXPECT_FALSE(generate(request));
}

}  // namespace
}  // namespace impossible::api
