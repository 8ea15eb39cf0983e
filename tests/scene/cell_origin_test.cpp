// Cell origins: each room's vertices are relative to an origin of its own, so
// that float vertices stay fine far from the layout's origin.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.hpp"
#include "scene_test_helpers.hpp"
#include "shading/shading.hpp"

namespace impossible::scene::test {
namespace {

TEST(CellOrigin, RoomsNearTheOriginKeepTheLayoutsCoordinates) {
    const layout::Layout l = one_room_layout();
    const Scene s = build_scene(l);
    ASSERT_EQ(s.origins.size(), 1u);
    EXPECT_EQ(s.origins[0].origin, glm::dvec3(0.0));
    EXPECT_EQ(s.origins[0].checker_offset, glm::vec3(0.0f));
    // Centre (-30, 0, 31): within 32 m on every axis.
    EXPECT_EQ(origin_of_cell(make_room("r", {-40, -3, 21}, {-20, 3, 41})).origin, glm::dvec3(0.0));
    // Centre (-50, 0, 33): the nearest multiples of 64 m.
    EXPECT_EQ(origin_of_cell(make_room("r", {-60, -3, 23}, {-40, 3, 43})).origin, glm::dvec3(-64, 0, 64));
}

// Far from the origin the origin is the room's centre on a 64 m grid, and a
// vertex plus its cell's origin is the layout point to within the float
// spacing of the local coordinate (not of the far-away one).
TEST(CellOrigin, FarRoomsAreExactRelativeToTheirOrigin) {
    layout::Layout l;
    l.source = "<test>";
    const glm::dvec3 lo{1598.3, 0.0, -1302.7}, hi{1602.3, 3.0, -1298.7};
    l.rooms.push_back(make_room("far", lo, hi));
    l.rooms.back().props.push_back(
        layout::BoxProp{{1600.8, 0.0, -1302.2}, {1601.8, 1.0, -1301.2}, {0.5, 0.5, 0.5}, {}, {}});
    impossible::test::add_pair(l, make_portal("a", 0, {1599.3, 1.1, -1300.2}, {0, 0, 1}, 0.9, 2.2),
                               make_portal("b", 0, {1601.3, 1.1, -1299.5}, {0, 0, 1}, 0.9, 2.2));
    const Scene s = build_scene(l);
    const glm::dvec3 origin = s.origins[0].origin;
    EXPECT_EQ(origin, glm::dvec3(1600, 0, -1280));
    // Every coordinate the layout gives on each axis: room, prop, the doors'
    // edges and the back of their 0.25 m boxes.
    const std::vector<double> known[3] = {
        {lo.x, hi.x, 1600.8, 1601.8, 1599.3 - 0.45, 1599.3 + 0.45, 1601.3 - 0.45, 1601.3 + 0.45},
        {lo.y, hi.y, 1.0, 0.0, 2.2},
        {lo.z, hi.z, -1302.2, -1301.2, -1300.2, -1300.2 - 0.25, -1299.5, -1299.5 - 0.25}};
    double worst = 0.0;
    // The room's and the doors' vertices: the hand's mesh comes after them,
    // with an origin of its own.
    auto end = static_cast<std::uint32_t>(s.vertices.size());
    for (const DrawBatch& b : s.object_meshes.back().batches)
        for (std::uint32_t k = b.range.first; k < b.range.first + b.range.count; ++k) end = std::min(end, s.indices[k]);
    for (std::uint32_t vi = 0; vi < end; ++vi) {
        const Vertex& v = s.vertices[vi];
        // Within 25 m of the origin, where floats are 1.9 µm apart.
        EXPECT_LT(glm::length(glm::dvec3(v.position)), 25.0);
        for (int axis = 0; axis < 3; ++axis) {
            const double world = double(v.position[axis]) + origin[axis];
            double nearest = 1e9;
            for (const double k : known[axis]) nearest = std::min(nearest, std::abs(world - k));
            worst = std::max(worst, nearest);
        }
    }
    // Float layout coordinates would be up to 61 µm off here.
    EXPECT_LT(worst, 2e-6);
}

// The shader evaluates the checker at vertex + checker_offset; its parity
// there equals the parity at the layout point.
TEST(CellOrigin, TheCheckerOffsetKeepsThePattern) {
    layout::Room r = make_room("far", {1598.3, 0.0, -1302.7}, {1602.3, 3.0, -1298.7});
    for (const double side : {0.25, 0.3, 0.7, 1.0}) {
        r.checker = side;
        const CellOrigin f = origin_of_cell(r);
        for (int k = 0; k < 50; ++k) {
            const glm::dvec3 local{0.037 * k - 1.3, 0.0, 0.051 * k - 2.1};
            const glm::dvec3 world = f.origin + local;
            const glm::dvec3 shifted = glm::dvec3(f.checker_offset) + local;
            if (std::abs(std::remainder(world.x, side)) < 1e-4 || std::abs(std::remainder(world.z, side)) < 1e-4)
                continue;  // on a square's edge: float rounding may pick either side
            EXPECT_EQ(shading::checker_dark(world, {0, 1, 0}, side), shading::checker_dark(shifted, {0, 1, 0}, side))
                << "side " << side << " point " << k;
        }
    }
}

}  // namespace
}  // namespace impossible::scene::test
