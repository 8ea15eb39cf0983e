// Issue 23's goals for `generate`, on a few seeds each (tools/generate_goals.py
// measures 50): 6 rooms on 4 x 4 m at an expansion ratio of at least 2.4, 10
// rooms on 6 x 6 m at 3.0, 8 rooms on an L-shaped floor; every room inside
// the play area, at least 1.5 m wide, reachable and toured; the shapes'
// geometry (the crossing strips share 2.56 m²).
#include <cmath>
#include <limits>

#include "design/generate.hpp"
#include "design/pack_shape.hpp"
#include "design/report.hpp"
#include "design/tour.hpp"
#include "design_test_util.hpp"
#include "layout/room_shape.hpp"

namespace design_test {
namespace {

// How far across the room it is from the middle of each wall (0.3 m or
// longer) straight in: the narrowest is the room's width.
double goals_room_width(const math::Polygon2& poly) {
    double width = std::numeric_limits<double>::infinity();
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = poly[i], b = poly[(i + 1) % n];
        if (glm::distance(a, b) < 0.3) continue;
        const glm::dvec2 d = glm::normalize(b - a), in(-d.y, d.x), p = (a + b) / 2.0;
        for (std::size_t k = 0; k < n; ++k) {
            const glm::dvec2 c = poly[k], e = poly[(k + 1) % n] - c;
            const double den = in.x * e.y - in.y * e.x;
            if (std::abs(den) < 1e-15) continue;
            const glm::dvec2 w = c - p;
            const double t = (w.x * e.y - w.y * e.x) / den, u = (w.x * in.y - w.y * in.x) / den;
            if (t > 1e-9 && u >= -1e-12 && u <= 1 + 1e-12) width = std::min(width, t);
        }
    }
    return width;
}

// Generates, loads and checks one layout; its expansion ratio.
double goals_check(const design::GenerateOptions& o) {
    SCOPED_TRACE("seed " + std::to_string(o.seed) + ", " + std::to_string(o.rooms) + " rooms");
    const auto g = design::generate(o);
    EXPECT_TRUE(g.has_value()) << (g ? "" : g.error());
    if (!g) return 0.0;
    const layout::LoadResult r = layout::load_layout_text(g->text, "generated.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors;
    EXPECT_TRUE(r.warnings.empty());
    if (!r.layout) return 0.0;
    const layout::Layout& l = *r.layout;
    EXPECT_EQ(static_cast<int>(l.rooms.size()), o.rooms);
    for (const layout::Room& room : l.rooms) EXPECT_GE(goals_room_width(layout::floor_outline(room)), 1.5) << room.id;
    const design::Report report = design::make_report(l);
    EXPECT_TRUE(report.unreachable.empty());
    EXPECT_TRUE(report.rooms_outside.empty());
    EXPECT_TRUE(report.doors_outside.empty());
    for (const design::Overlap& ov : report.overlaps) EXPECT_FALSE(ov.noticeable) << ov.a << " " << ov.b;
    EXPECT_NEAR(report.summary.expansion_ratio.value_or(0.0), g->expansion_ratio, 1e-9);
    const auto tour = design::plan_tour(l);
    EXPECT_TRUE(tour.has_value());
    if (tour) {
        EXPECT_EQ(static_cast<int>(tour->visited.size()), o.rooms);
    }
    return g->expansion_ratio;
}

design::GenerateOptions goals_square(double side, int rooms, std::uint64_t seed) {
    design::GenerateOptions o;
    o.play_area = math::rectangle({-side / 2, -side / 2}, {side / 2, side / 2});
    o.rectangle = true;
    o.rooms = rooms;
    o.seed = seed;
    return o;
}

TEST(GenerateGoals, SixRoomsOnFourByFourAtARatioOfAtLeast2Point4) {
    for (std::uint64_t seed : {1u, 2u, 3u}) EXPECT_GE(goals_check(goals_square(4, 6, seed)), 2.4);
}

TEST(GenerateGoals, TenRoomsOnSixBySixAtARatioOfAtLeast3) {
    for (std::uint64_t seed : {1u, 2u}) EXPECT_GE(goals_check(goals_square(6, 10, seed)), 3.0);
}

TEST(GenerateGoals, EightRoomsOnAnLShapedFloor) {
    design::GenerateOptions o;
    o.play_area = {{-3, -3}, {3, -3}, {3, 0}, {0, 0}, {0, 3}, {-3, 3}};
    o.rooms = 8;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        o.seed = seed;
        EXPECT_GT(goals_check(o), 2.0);
    }
}

TEST(GenerateGoals, ASlantedFloorGetsTurnedRooms) {
    design::GenerateOptions o;  // a hexagon: no edge along x or z but two
    for (int k = 0; k < 6; ++k) o.play_area.push_back({3 * std::cos(k * M_PI / 3), 3 * std::sin(k * M_PI / 3)});
    o.rooms = 8;
    o.seed = 3;
    EXPECT_GT(goals_check(o), 2.0);
    const auto g = design::generate(o);
    ASSERT_TRUE(g.has_value());
    int turned = 0;
    const layout::LoadResult loaded = layout::load_layout_text(g->text, "g.json", ".");
    ASSERT_TRUE(loaded.layout.has_value());
    for (const layout::Room& room : loaded.layout->rooms) {
        const math::Polygon2 f = layout::floor_outline(room);
        turned += layout::is_prism(room) && f.size() == 4 && std::abs(f[0].x - f[1].x) > 1e-3 &&
                  std::abs(f[0].y - f[1].y) > 1e-3;
    }
    EXPECT_GT(turned, 0);
}

TEST(GenerateGoals, RoomsThatOnlyTouchUnderAZeroOverlapLimit) {
    design::GenerateOptions o = goals_square(4, 4, 1);
    o.max_overlap = 0.0;
    EXPECT_GT(goals_check(o), 0.99);  // four rooms of 2 x 2 m, doors in the walls they share
}

TEST(GenerateGoals, TheSameSeedWritesTheSameBytesWithPrismRooms) {
    const auto a = design::generate(goals_square(6, 10, 5)), b = design::generate(goals_square(6, 10, 5));
    ASSERT_TRUE(a.has_value() && b.has_value());
    EXPECT_EQ(a->text, b->text);
    EXPECT_NE(a->text.find("\"floor\""), std::string::npos);  // some room is a prism
    EXPECT_NE(design::generate(goals_square(6, 10, 6))->text, a->text);
}

TEST(GenerateGoals, TwoCrossingStripsShare2Point56SquareMetres) {
    design::Shape along_x, along_z;
    along_x.u0 = -2, along_x.u1 = 2, along_x.v0 = -0.8, along_x.v1 = 0.8;
    along_z.u0 = -0.8, along_z.u1 = 0.8, along_z.v0 = -2, along_z.v1 = 2;
    const design::RoomGeom x = design::room_geom(along_x), z = design::room_geom(along_z);
    EXPECT_TRUE(x.box);
    EXPECT_NEAR(design::shared_area(x, z), 2.56, 1e-9);
    // A door in x's wall leads into z, standing free there with room to pass.
    EXPECT_TRUE(design::door_possible(x, z));
    // Turned by 30 degrees: a prism, the same area and width.
    along_x.angle = M_PI / 6;
    const design::RoomGeom t = design::room_geom(along_x);
    EXPECT_FALSE(t.box);
    EXPECT_NEAR(t.area, 6.4, 1e-2);
    EXPECT_DOUBLE_EQ(design::shape_width(along_x), 1.6);
}

TEST(GenerateGoals, AnLAndACorridorAreTiledByTheirPieces) {
    design::Shape l;
    l.kind = design::Shape::Kind::L;
    l.u0 = 0, l.u1 = 4, l.v0 = 0, l.v1 = 2;
    l.arm_side = 0, l.arm_width = 1.5, l.arm_length = 1.0;
    const design::RoomGeom lg = design::room_geom(l);
    EXPECT_EQ(lg.outline.size(), 6u);
    EXPECT_NEAR(lg.area, 8.0 + 1.5, 1e-9);
    EXPECT_DOUBLE_EQ(design::shape_width(l), 1.5);
    // Turned, rounded to millimetres: the pieces still share the outline's
    // corners, so they tile it exactly (no sliver for overlaps to miss).
    l.angle = 0.3;
    const design::RoomGeom turned = design::room_geom(l);
    EXPECT_NEAR(math::area(turned.pieces[0]) + math::area(turned.pieces[1]), turned.area, 1e-12);
    design::Shape arc;
    arc.kind = design::Shape::Kind::Arc;
    arc.r0 = 2, arc.r1 = 3.6, arc.a0 = 0, arc.a1 = M_PI / 2;
    const design::RoomGeom ag = design::room_geom(arc);
    EXPECT_GT(ag.outline.size(), 10u);  // walls of at most 12 degrees on both arcs
    double pieces = 0.0;
    for (const math::Polygon2& p : ag.pieces) pieces += math::area(p);
    EXPECT_NEAR(pieces, ag.area, 1e-9);
    EXPECT_NEAR(ag.area, M_PI / 4 * (3.6 * 3.6 - 4.0), 0.1);
    EXPECT_GT(design::shape_width(arc), 1.5);
}

}  // namespace
}  // namespace design_test
