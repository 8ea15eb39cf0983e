// The bound on a frame's light work (lights/light_bound.hpp,
// docs/bounded-work.md "Path rectangles"): past kMaxLightRects path
// rectangles the light depth is lowered, and past them at depth 0 lights
// are dropped in file order; layouts within the bound are lit exactly as
// before.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "layout/layout.hpp"
#include "layout/room_shape.hpp"
#include "lights/light_bound.hpp"
#include "lights/light_images.hpp"
#include "lights/lights_test_layouts.hpp"

namespace impossible::lights {
namespace {

using namespace testing;
using glm::dvec3;

std::size_t total_rects(const std::vector<RoomLights>& rooms) {
    std::size_t n = 0;
    for (const RoomLights& room : rooms)
        for (const LightImage& image : room.images) n += path_rect_count(image);
    return n;
}

TEST(LightBound, AStarRoomIsLitByTheLightsWhoseWallsFit) {
    // 1,000 walls, all crossable; each lamp lies behind 478 of them, and
    // within the margin of 4 more planes: 4,820 path rectangles at light
    // depth 0 (10,000 before the cull).
    const layout::Layout l = star_room(1000, 10);
    const links::PortalLinks links = links::link_portals(l);
    EXPECT_EQ(layout::crossable_walls(l.rooms[0]).size(), 1000u);
    const LightWork work = light_work(l, links, 0);
    ASSERT_EQ(work.own_rects.size(), 1u);
    for (const std::size_t rects : work.own_rects[0]) EXPECT_EQ(rects, 482u);
    EXPECT_EQ(work.rects[0], 4820u);
    const LightBound bound = light_bound(l, links);
    EXPECT_EQ(bound.depth, 0);
    EXPECT_EQ(bound.lights, 10u);
    EXPECT_EQ(bound.lit_lights, 2u);
    EXPECT_EQ(bound.lit[0], (std::vector<bool>{true, true, false, false, false, false, false, false, false, false}));
    EXPECT_EQ(light_cut(bound, 0), LightCut::Rects);
    const layout::Layout lit = with_lit_lights(l, bound);
    ASSERT_EQ(lit.rooms[0].lights.size(), 2u);
    EXPECT_EQ(lit.rooms[0].lights[1].position, l.rooms[0].lights[1].position);
    const auto rooms = light_images(lit, links, bound.depth);
    EXPECT_EQ(rooms[0].images.size(), 2u);
    EXPECT_EQ(total_rects(rooms), 964u);
    EXPECT_LE(total_rects(rooms), kMaxLightRects);
}

TEST(LightBound, LightsAreKeptInFileOrderWhileTheirRectanglesFit) {
    // Three star lamps (482 rectangles each) and, after them, a box room's
    // two lamps (none): the third star lamp does not fit, the box's do.
    layout::Layout l = star_room(1000, 3);
    const int box = add_room(l, "box", {20, 0, -2}, {24, 3, 2});
    add_light(l, box, {22, 1.5, 0});
    add_light(l, box, {22, 2.5, 1});
    const LightBound bound = light_bound(l, links::link_portals(l));
    EXPECT_EQ(bound.depth, 0);
    EXPECT_EQ(bound.lit[0], (std::vector<bool>{true, true, false}));
    EXPECT_EQ(bound.lit[1], (std::vector<bool>{true, true}));
    EXPECT_EQ(bound.lit_lights, 4u);
    EXPECT_EQ(lit_lights(l, bound, 1).size(), 2u);
    EXPECT_EQ(lit_lights(l, bound, 0).size(), 2u);
}

TEST(LightBound, TheRectanglesLowerTheLightDepth) {
    // A star of 100 corners with mirrors in its floor and ceiling, facing:
    // every bounce adds a leg with the walls its image lies behind, while
    // the paths stay few (a mirror keeps the light's strength).
    layout::Layout l = star_room(100, 2);
    add_portal(l, "floor_mirror", 0, make_rect({0, 0, 0}, {0, 1, 0}, 5, 5, {0, 0, 1}), layout::PortalKind::Mirror, 0);
    add_portal(l, "ceiling_mirror", 0, make_rect({0, 3, 0}, {0, -1, 0}, 5, 5, {0, 0, 1}), layout::PortalKind::Mirror,
               1);
    const links::PortalLinks links = links::link_portals(l);
    const LightBound bound = light_bound(l, links);
    EXPECT_EQ(bound.paths_depth, layout::kMaxLightDepth);
    ASSERT_LT(bound.depth, bound.paths_depth);
    EXPECT_EQ(bound.lit_lights, bound.lights);
    EXPECT_EQ(light_cut(bound, bound.depth), LightCut::None);
    EXPECT_EQ(light_cut(bound, bound.depth + 1), LightCut::Rects);
    EXPECT_LE(total_rects(light_images(l, links, bound.depth)), kMaxLightRects);
    EXPECT_GT(total_rects(light_images(l, links, bound.depth + 1)), kMaxLightRects);
}

TEST(LightBound, LayoutsWithinTheBoundAreLitAsWritten) {
    const layout::Layout l = l_flat();
    const links::PortalLinks links = links::link_portals(l);
    const LightBound bound = light_bound(l, links);
    EXPECT_EQ(bound.depth, bound.paths_depth);
    EXPECT_EQ(bound.lit_lights, 4u);
    EXPECT_EQ(light_cut(bound, l.light_depth), LightCut::None);
    // Every lit layout the project ships is within it.
    int lit = 0;
    for (const auto& entry : std::filesystem::directory_iterator(IMPOSSIBLE_SOURCE_DIR "/layouts")) {
        if (entry.path().extension() != ".json") continue;
        const layout::LoadResult loaded = layout::load_layout_file(entry.path().string());
        ASSERT_TRUE(loaded.layout) << entry.path();
        const layout::Layout& shipped = *loaded.layout;
        if (shipped.lighting != layout::Lighting::Lights) continue;
        ++lit;
        const LightBound b = light_bound(shipped, links::link_portals(shipped));
        EXPECT_EQ(light_cut(b, shipped.light_depth), LightCut::None) << entry.path();
        EXPECT_NE(light_cut(b, layout::kMaxLightDepth), LightCut::Rects) << entry.path();
    }
    EXPECT_GE(lit, 5);
}

}  // namespace
}  // namespace impossible::lights
