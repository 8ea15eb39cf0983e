// The designer tools on prism rooms (layout-format.md, "Rooms of any
// shape"): validate measures overlap and fit by the floor polygon, plan draws
// it, tour walks round an L's inner corner and along a curved corridor.
#include "design_test_util.hpp"

#include <cmath>

#include "../common/layouts.hpp"
#include "design/plan.hpp"
#include "design/plan_pieces.hpp"
#include "design/report.hpp"
#include "design/room_grid.hpp"
#include "design/tour.hpp"
#include "layout/room_shape.hpp"
#include "walk/walker.hpp"

namespace design_test {
namespace {

// An L of two 2 m wide arms, 6 m long (20 m²): its bounding box's centre
// (3, 3) lies in the notch. A door at the end of the arm along z leads into
// a 2 x 2 m box room "den" beyond it.
const math::Polygon2 kEll = {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}};
const std::string kEllJson = "[[0, 0], [6, 0], [6, 2], [2, 2], [2, 6], [0, 6]]";

std::string ell_layout(const std::string& play_area, const std::string& extra_room = "") {
    return "{ \"format\": \"impossible-layout\", \"version\": 1,\n" +
           (play_area.empty() ? "" : "\"play_area\": " + play_area + ",\n") +
           "\"start\": { \"room\": \"ell\", \"position\": [5.5, 1.6, 1], \"yaw_deg\": 90 },\n"
           "\"rooms\": [ { \"id\": \"ell\", \"floor\": " +
           kEllJson +
           ", \"y\": [0, 3] },\n"
           "  { \"id\": \"den\", \"min\": [0, 0, 6], \"max\": [2, 3, 8] }" +
           extra_room +
           " ],\n"
           "\"portals\": [\n"
           "  { \"id\": \"out\", \"room\": \"ell\", \"center\": [1, 1.05, 6], \"normal\": [0, 0, -1], \"width\": 0.9, "
           "\"height\": 2.1, \"target\": \"in\" },\n"
           "  { \"id\": \"in\", \"room\": \"den\", \"center\": [1, 1.05, 6], \"normal\": [0, 0, 1], \"width\": 0.9, "
           "\"height\": 2.1, \"target\": \"out\" } ] }";
}

layout::Layout load_ell(const std::string& text) {
    const layout::LoadResult r = layout::load_layout_text(text, "ell.json", ".");
    std::string errors;
    for (const auto& e : r.errors) errors += e.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors;
    return r.layout.value_or(layout::Layout{});
}

// The play area: the L and the den beyond it, nothing of the notch.
const std::string kEllArea = "{ \"polygon\": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 8], [0, 8]] }";

TEST(PrismDesign, TourTurnsTheCornerOfAnLShapedRoom) {
    const layout::Layout l = load_ell(ell_layout(kEllArea));
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value()) << tour.error();
    EXPECT_EQ(tour->visited.size(), 2u);
    EXPECT_TRUE(tour->missed.empty());
    EXPECT_GE(tour->closest_edge, 0.1 - 1e-9);  // the planner's edge margin, in a polygon play area
    // The way from the start to the door leaves the L: the tour must turn.
    EXPECT_FALSE(math::segment_inside(kEll, {5.5, 1.0}, {1.0, 5.65}));
    walk::Walker walker(l);
    int in_ell = 0;
    glm::dvec2 previous{5.5, 1.0};
    for (std::size_t i = 0; i < tour->poses.size(); ++i) {
        walker.step(tour->poses[i]);
        const glm::dvec2 p{tour->poses[i].position.x, tour->poses[i].position.z};
        if (walker.room() == 0) {
            ++in_ell;
            EXPECT_TRUE(math::contains(kEll, p)) << "pose " << i;
            EXPECT_TRUE(math::segment_inside(kEll, previous, p)) << "pose " << i;
            // A body radius from every wall, but where it walks through the door.
            if (glm::distance(p, glm::dvec2(1.0, 6.0)) > 0.4) {
                EXPECT_GE(math::distance_to_boundary(kEll, p), 0.25 - 1e-6) << "pose " << i;
            }
        }
        previous = p;
    }
    EXPECT_GT(in_ell, 100);
}

// A half ring of 32 walls a side round (0, 0), radii 2 and 3.5, as the
// generator's and diff_fuzz's curved corridors are.
math::Polygon2 half_ring() {
    math::Polygon2 out;
    for (int i = 0; i <= 16; ++i) out.push_back(3.5 * glm::dvec2(std::cos(M_PI * i / 16), std::sin(M_PI * i / 16)));
    for (int i = 16; i >= 0; --i) out.push_back(2.0 * glm::dvec2(std::cos(M_PI * i / 16), std::sin(M_PI * i / 16)));
    return out;
}

TEST(PrismDesign, AWayAlongACurvedCorridorStaysInIt) {
    layout::Layout l;
    l.rooms.push_back(test::prism_room("arc", half_ring(), 0.0, 3.0));
    const design::RoomGrid grid(l, 0, math::dmat4(1.0), {}, design::GridOptions{});
    // From one end of the corridor to the other: the straight way crosses the hole.
    const glm::dvec2 from{2.75, 0.3}, to{-2.75, 0.3};
    EXPECT_TRUE(grid.free(from));
    EXPECT_TRUE(grid.free(to));
    EXPECT_FALSE(grid.free({0.0, 1.0}));   // the ring's hole (inside the bounding box)
    EXPECT_FALSE(grid.free({3.45, 0.5}));  // within the body radius of the outer wall
    const auto path = grid.find_path(from, to);
    ASSERT_TRUE(path.has_value());
    EXPECT_GT(path->size(), 3u);
    const math::Polygon2 ring = half_ring();
    for (std::size_t i = 1; i < path->size(); ++i) {
        EXPECT_TRUE(math::segment_inside(ring, (*path)[i - 1], (*path)[i])) << "leg " << i;
        for (int s = 0; s <= 20; ++s) {
            const glm::dvec2 p = (*path)[i - 1] + ((*path)[i] - (*path)[i - 1]) * (s / 20.0);
            EXPECT_GE(math::distance_to_boundary(ring, p), 0.25 - 0.06) << "leg " << i;  // a cell's slack
        }
    }
}

TEST(PrismDesign, TheGridsFreeCellsAreThoseAtLeastABodyRadiusInside) {
    // Every cell centre against every wall, for an L, the half ring and a
    // star of 41 corners turned off the axes.
    math::Polygon2 star;
    for (int i = 0; i < 41; ++i) {
        const double a = 2.0 * M_PI * i / 41 + 0.3, r = i % 2 ? 1.2 : 3.0;
        star.push_back({1.0 + r * std::cos(a), -2.0 + r * std::sin(a)});
    }
    for (const math::Polygon2& floor : {kEll, half_ring(), star}) {
        layout::Layout l;
        l.rooms.push_back(test::prism_room("p", floor, 0.0, 3.0));
        const design::GridOptions options;
        const design::RoomGrid grid(l, 0, math::dmat4(1.0), {}, options);
        const glm::dvec2 lo{l.rooms[0].min.x, l.rooms[0].min.z}, hi{l.rooms[0].max.x, l.rooms[0].max.z};
        int free = 0;
        for (double z = lo.y + 0.025; z < hi.y; z += 0.05)
            for (double x = lo.x + 0.025; x < hi.x; x += 0.05) {
                const glm::dvec2 c{x, z};
                const bool expected = math::contains(floor, c, 0.0) && math::distance_to_boundary(floor, c) >= 0.25;
                ASSERT_EQ(grid.free(c), expected) << x << ", " << z;
                free += expected;
            }
        EXPECT_GT(free, 100);
    }
}

TEST(PrismDesign, ValidateMeasuresTheLNotItsBox) {
    // A 2 x 2 m box over the L's inner corner: a quarter of it in the notch.
    const layout::Layout l =
        load_ell(ell_layout(kEllArea, ",\n  { \"id\": \"box\", \"min\": [1, 0, 1], \"max\": [3, 3, 3] }"));
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.floors.size(), 3u);
    EXPECT_EQ(r.floors[0].size(), 6u);  // the polygon, not its box
    EXPECT_NEAR(math::area(r.floors[0]), 20.0, 1e-12);
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].area, 3.0, 1e-9);  // 4 m² by the bounding box
    EXPECT_NEAR(r.overlaps[0].percent, 75.0, 1e-9);
    // Fit by the polygon: the L fits the L-shaped play area; the box's notch quarter does not.
    ASSERT_EQ(r.rooms_outside.size(), 1u);
    EXPECT_EQ(r.rooms_outside[0].room, 2);
    EXPECT_NEAR(r.rooms_outside[0].outside_area, 1.0, 1e-9);
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("ell / box: 3.00 m2, 75.0 %"), std::string::npos) << text;
    EXPECT_NE(text.find("rooms outside the play area as walked: box\n"), std::string::npos) << text;
}

TEST(PrismDesign, ATurnedLIsPlacedAsAPolygon) {
    // Started in the den, whose door faces +x: the L beyond it lies turned
    // by a quarter turn on the physical floor, still six corners and 20 m².
    std::string text = ell_layout("");
    const std::string den = "\"min\": [0, 0, 6], \"max\": [2, 3, 8]";
    text.replace(text.find(den), den.size(), "\"min\": [10, 0, 0], \"max\": [12, 3, 2]");
    const std::string in = "\"center\": [1, 1.05, 6], \"normal\": [0, 0, 1]";
    text.replace(text.find(in), in.size(), "\"center\": [10, 1.05, 1], \"normal\": [1, 0, 0]");
    const std::string start = "\"room\": \"ell\", \"position\": [5.5, 1.6, 1]";
    text.replace(text.find(start), start.size(), "\"room\": \"den\", \"position\": [11, 1.6, 1]");
    const layout::Layout l = load_ell(text);
    const design::Report r = design::make_report(l);
    ASSERT_TRUE(r.placement.rooms[0].reachable);
    ASSERT_EQ(r.floors[0].size(), 6u);
    EXPECT_NEAR(math::area(r.floors[0]), 20.0, 1e-9);
    EXPECT_GT(math::signed_area(r.floors[0]), 0.0);
    // The L's door (1, 6) lands on the den's (10, 1), and its far corner (6, 0)
    // 6 m from it along x, beyond the den: the L is turned, not moved.
    const glm::dvec2 door = design::to_floor(r.placement.rooms[0].to_physical, {1, 0, 6});
    EXPECT_NEAR(glm::distance(door, glm::dvec2(10, 1)), 0.0, 1e-9);
    const glm::dvec2 far = design::to_floor(r.placement.rooms[0].to_physical, {6, 0, 0});
    EXPECT_NEAR(std::abs(far.x - 10.0), 6.0, 1e-9);
    EXPECT_NEAR(std::abs(far.y - 1.0), 5.0, 1e-9);
}

TEST(PrismDesign, PlanDrawsThePolygon) {
    const layout::Layout l = load_ell(ell_layout(""));
    const design::Report r = design::make_report(l);
    const design::Drawing d = design::plan_drawing(l, r, {});
    int fills = 0;
    for (const design::PlanShape& s : d.shapes)
        if (s.group == "rooms" && s.name == "ell") {
            ++fills;
            EXPECT_EQ(s.points, layout::floor_outline(l.rooms[0]));
        }
    EXPECT_EQ(fills, 2);  // the fill and its outline
    const double k = 20.0;
    const std::string svg = design::plan_svg(d, k);
    // The inner corner (2, 2) in pixels, as a corner of the room's polygon.
    char corner[64];
    std::snprintf(corner, sizeof corner, " %.2f,%.2f ", (2 - d.min.x) * k, (2 - d.min.y) * k + 28.0);
    const std::size_t at = svg.find(corner);
    ASSERT_NE(at, std::string::npos) << corner << "\n" << svg;
    EXPECT_NE(svg.rfind("<polygon points=", at), std::string::npos);
    // The raster: the notch is left as bare floor, as far from any room as
    // a spot beyond them; the arm is coloured.
    const image::Pixels png = design::plan_raster(d, k);
    auto pixel = [&](glm::dvec2 p) {
        const int x = static_cast<int>((p.x - d.min.x) * k), y = static_cast<int>((p.y - d.min.y) * k + 28.0);
        const std::size_t i = (static_cast<std::size_t>(y) * png.width + x) * 3;
        return glm::ivec3(png.data[i], png.data[i + 1], png.data[i + 2]);
    };
    EXPECT_EQ(pixel({4.5, 4.5}), pixel({4.5, 7.5}));
    EXPECT_NE(pixel({4.5, 1.5}), pixel({4.5, 7.5}));
}

}  // namespace
}  // namespace design_test
