// The preview's logic without a window: where the eyes go in the window, the
// head's movement and the virtual pose, live reload, the path file, the HUD's
// median and the boundary grid's fade.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include <glm/gtc/matrix_transform.hpp>

#include "common/temp_dir.hpp"
#include "layout/path_file.hpp"
#include "preview/grid.hpp"
#include "preview/head.hpp"
#include "preview/hud.hpp"
#include "preview/minimap.hpp"
#include "preview/present.hpp"
#include "preview/reload.hpp"

namespace impossible::preview {
namespace {

namespace fs = std::filesystem;

TEST(PreviewWindowLayout, KeepsTheEyeAspectAndCentres) {
    // A window as wide as two eyes: the eyes fill it exactly.
    WindowLayout l = window_layout(640, 240, 320.0 / 240.0, PreviewView::Parallel);
    EXPECT_EQ(l.eye_rects[0].x, 0);
    EXPECT_EQ(l.eye_rects[1].x, 320);
    EXPECT_EQ(l.eye_rects[0].width, 320);
    EXPECT_EQ(l.eye_rects[0].height, 240);
    // Taller: bars above and below; wider: bars left and right. Aspect kept.
    l = window_layout(640, 600, 4.0 / 3.0, PreviewView::Parallel);
    EXPECT_EQ(l.eye_rects[0].width, 320);
    EXPECT_EQ(l.eye_rects[0].height, 240);
    EXPECT_EQ(l.eye_rects[0].y, 180);
    l = window_layout(1000, 240, 4.0 / 3.0, PreviewView::Parallel);
    EXPECT_EQ(l.eye_rects[0].width, 320);
    EXPECT_EQ(l.eye_rects[0].x, 180);
    EXPECT_EQ(l.eye_rects[1].x, 500);
    // Cross swaps the places; anaglyph puts both eyes in one.
    const WindowLayout c = window_layout(1000, 240, 4.0 / 3.0, PreviewView::Cross);
    EXPECT_EQ(c.eye_rects[0].x, 500);
    EXPECT_EQ(c.eye_rects[1].x, 180);
    const WindowLayout a = window_layout(1000, 600, 4.0 / 3.0, PreviewView::Anaglyph);
    EXPECT_EQ(a.eye_rects[0].width, 800);
    EXPECT_EQ(a.eye_rects[0].height, 600);
    EXPECT_EQ(a.eye_rects[0].x, a.eye_rects[1].x);
}

TEST(PreviewHead, MovesAlongTheYawAndStaysInThePlayArea) {
    const layout::PlayArea area{{-2.0, -2.0}, {2.0, 2.0}};
    math::HeadPose head{{0.0, 1.6, 0.0}, 90.0, 0.0, 0.0};  // looking along -X
    MoveInput in;
    in.dt = 0.5;
    in.forward = 1;
    head = move_head(head, in, area);
    EXPECT_NEAR(head.position.x, -kWalkSpeed * 0.5, 1e-12);
    EXPECT_NEAR(head.position.z, 0.0, 1e-12);
    for (int i = 0; i < 20; ++i) head = move_head(head, in, area);
    EXPECT_DOUBLE_EQ(head.position.x, -2.0);  // stopped at the edge
    // Mouse right turns right (yaw decreases); mouse down looks down; pitch is clamped.
    MoveInput look;
    look.mouse_dx = 100.0;
    look.mouse_dy = 10000.0;
    const math::HeadPose turned = move_head(head, look, area);
    EXPECT_NEAR(turned.yaw_deg, 90.0 - 100.0 * kMouseDegPerPixel, 1e-9);
    EXPECT_DOUBLE_EQ(turned.pitch_deg, -kMaxPitch);
    // Without a play area nothing stops the head.
    math::HeadPose free{{0.0, 1.6, 0.0}, 0.0, 0.0, 0.0};
    for (int i = 0; i < 20; ++i) free = move_head(free, in, std::nullopt);
    EXPECT_LT(free.position.z, -10.0);
}

TEST(PreviewGrid, FadesInWithinHalfAMetre) {
    EXPECT_EQ(grid_alpha(0.6), 0.0f);
    EXPECT_EQ(grid_alpha(kGridDistance), 0.0f);
    EXPECT_NEAR(grid_alpha(0.25), 0.5f, 1e-6);
    EXPECT_EQ(grid_alpha(0.0), 1.0f);
    EXPECT_EQ(grid_alpha(-0.3), 1.0f);
    const layout::PlayArea area{{-2.0, -2.0}, {2.0, 2.0}};
    math::Eye eye;
    OverlayBatch batch;
    EXPECT_EQ(add_boundary_grid(batch, area, {0.0, 1.6, 0.0}, eye, math::dmat4(1.0)), 0);
    EXPECT_TRUE(batch.empty());
    EXPECT_EQ(add_boundary_grid(batch, area, {1.8, 1.6, -1.9}, eye, math::dmat4(1.0)), 2);  // +x and -z
    EXPECT_FALSE(batch.lines.empty());
}

TEST(PreviewHud, MedianOfFrameTimes) {
    EXPECT_EQ(median_ms({}), 0.0);
    EXPECT_EQ(median_ms({5.0, 1.0, 100.0}), 5.0);
    EXPECT_EQ(median_ms({4.0, 1.0, 2.0, 100.0}), 3.0);
}

TEST(PreviewMinimap, BoundsHoldThePlayAreaTheRoomAndTheHead) {
    layout::Layout l;
    // Set in place: GCC 12 under -fsanitize=address warns (wrongly) that the
    // moved-in polygon vector may be uninitialised.
    l.play_area.emplace();
    l.play_area->min = {-2.0, -2.0};
    l.play_area->max = {2.0, 2.0};
    layout::Room room;
    room.min = {0.0, 0.0, 0.0};
    room.max = {6.0, 3.0, 1.0};
    l.rooms.push_back(room);
    MinimapInput in;
    in.layout = &l;
    in.physical_head.position = {1.0, 1.6, 1.0};
    const MapBounds b = minimap_bounds(in);
    EXPECT_LT(b.min.x, -2.0);
    EXPECT_GT(b.max.x, 6.0);
    EXPECT_LT(b.min.y, -2.0);
    EXPECT_GT(b.max.y, 2.0);
    // Moved by W: the room's footprint is shown where it lies on the physical floor.
    in.physical_to_virtual = glm::translate(math::dmat4(1.0), math::dvec3(10.0, 0.0, 0.0));
    const MapBounds moved = minimap_bounds(in);
    EXPECT_LT(moved.min.x, -10.0 + 1e-9);
    EXPECT_LT(moved.max.x, 6.0);
}

const char* kLayout = R"({ "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [0, 1.6, 0] },
  "rooms": [ { "id": "a", "min": [-1, 0, -1], "max": [1, 3, 1] } ] })";

TEST(PreviewReload, ReloadsGoodEditsAndReportsBadOnes) {
    const test::TempDir dir("preview-reload");
    const fs::path file = dir / "l.json";
    std::ofstream(file) << kLayout;
    LayoutWatcher w = watch_layout(file.string());
    EXPECT_EQ(poll_layout(w).kind, ReloadPoll::Unchanged);

    std::string text = kLayout;
    text.replace(text.find("[1, 3, 1]"), 9, "[2, 3, 1]");
    std::ofstream(file) << text;
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(1));
    ReloadPoll r = poll_layout(w);
    ASSERT_EQ(r.kind, ReloadPoll::Reloaded);
    EXPECT_EQ(r.layout->rooms[0].max.x, 2.0);
    EXPECT_EQ(poll_layout(w).kind, ReloadPoll::Unchanged);

    std::ofstream(file) << R"({ "format": "impossible-layout", "version": 2 })";
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
    r = poll_layout(w);
    ASSERT_EQ(r.kind, ReloadPoll::Failed);
    EXPECT_FALSE(r.errors.empty());
    EXPECT_NE(r.errors[0].find("l.json"), std::string::npos) << r.errors[0];

    fs::remove(file);
    EXPECT_EQ(poll_layout(w).kind, ReloadPoll::Failed);  // reported once
    EXPECT_EQ(poll_layout(w).kind, ReloadPoll::Unchanged);
    std::ofstream(file) << kLayout;
    EXPECT_EQ(poll_layout(w).kind, ReloadPoll::Reloaded);  // back
}

}  // namespace
}  // namespace impossible::preview
