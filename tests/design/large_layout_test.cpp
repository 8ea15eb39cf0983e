// Large layouts: the 1000-room grid of design/large_layout.hpp loads and
// validates quickly and has the rooms and doors it should; the overlap sweep
// finds exactly the pairs a test of every pair finds.
#include "design_test_util.hpp"

#include <chrono>
#include <cstdint>

#include "design/large_layout.hpp"
#include "design/overlap.hpp"
#include "design/report.hpp"
#include "scene/scene.hpp"

namespace design_test {
namespace {

TEST(LargeLayout, SameRoomsSameBytes) {
    EXPECT_EQ(design::large_layout_text(37), design::large_layout_text(37));
    EXPECT_NE(design::large_layout_text(37), design::large_layout_text(38));
}

TEST(LargeLayout, SmallOnesAreValidAndConnected) {
    for (const int n : {1, 2, 9, 10, 11, 21}) {
        SCOPED_TRACE(std::to_string(n) + " rooms");
        const layout::LoadResult loaded = layout::load_layout_text(design::large_layout_text(n), "large.json", ".");
        std::string errors;
        for (const auto& d : loaded.errors) errors += d.str() + "\n";
        ASSERT_TRUE(loaded.layout.has_value()) << errors;
        EXPECT_TRUE(loaded.warnings.empty());
        EXPECT_EQ(loaded.layout->rooms.size(), static_cast<std::size_t>(n));
        EXPECT_EQ(loaded.layout->portals.size(), static_cast<std::size_t>(2 * (n - 1)));
        for (const layout::Portal& p : loaded.layout->portals) EXPECT_GE(p.hole_face, 0) << p.id;
        const design::Report r = design::make_report(*loaded.layout);
        EXPECT_TRUE(r.findings.empty()) << r.findings.front();
    }
}

// Generous: about 0.1 s on the development machine (bench/README.md, "Large
// layouts"); a load or report that is quadratic in rooms takes far longer.
TEST(LargeLayout, AThousandRoomsLoadAndValidateWithinTenSeconds) {
    const std::string text = design::large_layout_text(1000);
    const auto start = std::chrono::steady_clock::now();
    const layout::LoadResult loaded = layout::load_layout_text(text, "large.json", ".");
    ASSERT_TRUE(loaded.layout.has_value());
    const design::Report r = design::make_report(*loaded.layout);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 10.0);
    EXPECT_EQ(loaded.layout->rooms.size(), 1000u);
    EXPECT_EQ(loaded.layout->portals.size(), 1998u);
    EXPECT_EQ(r.summary.rooms, 1000);
    EXPECT_EQ(r.placement.order.size(), 1000u);
    EXPECT_TRUE(r.unreachable.empty());
    EXPECT_TRUE(r.overlaps.empty());  // neighbours touch, none shares floor
    EXPECT_TRUE(r.findings.empty());
}

TEST(LargeLayout, OverlapSweepFindsEveryPairThatEveryPairFinds) {
    // Rectangles and rotated squares scattered over a small floor, so that
    // many pairs meet, some only touch and some lie apart.
    std::uint64_t state = 12345;
    const auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53);
    };
    std::vector<math::Polygon2> floors;
    for (int i = 0; i < 120; ++i) {
        const glm::dvec2 c{std::round(next() * 40.0) / 2.0, std::round(next() * 40.0) / 2.0};
        const double w = 0.5 + std::round(next() * 8.0) / 2.0, d = 0.5 + std::round(next() * 8.0) / 2.0;
        if (i % 3 == 0) {
            const double a = next() * 3.0, s = 0.5 * w;
            const glm::dvec2 u{std::cos(a) * s, std::sin(a) * s}, v{-u.y, u.x};
            floors.push_back({c - u - v, c + u - v, c + u + v, c - u + v});
        } else {
            floors.push_back(math::rectangle(c, c + glm::dvec2(w, d)));
        }
    }
    std::vector<std::pair<int, int>> expected;
    for (std::size_t i = 0; i < floors.size(); ++i)
        for (std::size_t j = i + 1; j < floors.size(); ++j)
            if (design::overlap_of(floors[i], floors[j]).area > design::kMinSharedArea)
                expected.emplace_back(static_cast<int>(i), static_cast<int>(j));
    std::vector<std::pair<int, int>> found;
    const design::Overlaps overlaps = design::room_overlaps(floors);
    for (const design::Overlap& o : overlaps.listed) found.emplace_back(o.a, o.b);
    EXPECT_GT(expected.size(), 50u);
    EXPECT_EQ(found, expected);
    EXPECT_EQ(overlaps.pairs, expected.size());
    EXPECT_TRUE(overlaps.exact);
}

}  // namespace
}  // namespace design_test
