// The generator: valid, connected layouts inside the play area, within the
// overlap limit, toured room by room; the same seed gives the same bytes.
#include "design_test_util.hpp"

#include "design/generate.hpp"
#include "design/report.hpp"
#include "design/tour.hpp"

namespace design_test {
namespace {

layout::Layout load_text(const std::string& text) {
    const layout::LoadResult r = layout::load_layout_text(text, "generated.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors << text;
    EXPECT_TRUE(r.warnings.empty());
    return r.layout.value_or(layout::Layout{});
}

void check_generated(const design::GenerateOptions& o) {
    SCOPED_TRACE("seed " + std::to_string(o.seed) + ", " + std::to_string(o.rooms) + " rooms");
    const auto text = design::generate_layout(o);
    ASSERT_TRUE(text.has_value()) << text.error();
    const layout::Layout l = load_text(*text);
    ASSERT_EQ(static_cast<int>(l.rooms.size()), o.rooms);
    const design::Report r = design::make_report(l);
    EXPECT_TRUE(r.unreachable.empty());
    EXPECT_TRUE(r.rooms_outside.empty());
    EXPECT_TRUE(r.doors_outside.empty());
    for (const design::Overlap& ov : r.overlaps)
        EXPECT_LE(ov.percent, (o.max_overlap ? *o.max_overlap : ov.limit) + 1e-9);
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value()) << tour.error();
    EXPECT_EQ(static_cast<int>(tour->visited.size()), o.rooms);
    EXPECT_TRUE(tour->missed.empty());
    EXPECT_GE(tour->closest_edge, 0.0);
}

TEST(Generate, SquareFloorsFromThreeToEightMetres) {
    const std::pair<double, int> floors[] = {{3, 2}, {4, 3}, {6, 5}, {8, 6}};
    for (const auto& [side, rooms] : floors)
        for (std::uint64_t seed : {1u, 7u, 42u}) {
            design::GenerateOptions o;
            o.play_area = math::rectangle({-side / 2, -side / 2}, {side / 2, side / 2});
            o.rectangle = true;
            o.rooms = rooms;
            o.seed = seed;
            check_generated(o);
        }
}

TEST(Generate, AnLShapedFloorAndAnOverlapLimit) {
    design::GenerateOptions o;
    o.play_area = {{-3, -3}, {3, -3}, {3, 0}, {0, 0}, {0, 3}, {-3, 3}};
    o.rooms = 4;
    o.max_overlap = 40.0;
    for (std::uint64_t seed : {2u, 3u, 5u}) {
        o.seed = seed;
        check_generated(o);
    }
}

TEST(Generate, TheSameSeedWritesTheSameBytes) {
    design::GenerateOptions o;
    o.play_area = math::rectangle({-2.5, -2.5}, {2.5, 2.5});
    o.rectangle = true;
    o.rooms = 5;
    o.seed = 11;
    const auto a = design::generate_layout(o), b = design::generate_layout(o);
    ASSERT_TRUE(a.has_value() && b.has_value());
    EXPECT_EQ(*a, *b);
    o.seed = 12;
    EXPECT_NE(*design::generate_layout(o), *a);
}

TEST(Generate, AFloorTooSmallIsAnError) {
    design::GenerateOptions o;
    o.play_area = math::rectangle({-0.5, -0.5}, {0.5, 0.5});
    o.rooms = 2;
    const auto r = design::generate_layout(o);
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error(), "a room cannot be 1.5 m wide on a 1 x 1 m floor (it needs 1.52 m across)");
    // Wide enough, but too many rooms for the overlap limit: no lattice or
    // grown rooms fit, and it says so.
    o.play_area = math::rectangle({-1, -1}, {1, 1});
    o.rooms = 5;
    const auto many = design::generate_layout(o);
    ASSERT_FALSE(many.has_value());
    EXPECT_NE(many.error().find("could not fit 5 rooms of at least 1.5 m"), std::string::npos) << many.error();
}

}  // namespace
}  // namespace design_test
