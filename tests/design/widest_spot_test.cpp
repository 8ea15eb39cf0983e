// The widest spot of a play area (design/widest_spot.hpp) and the signed
// distance it measures with (AreaIndex::signed_distance): the distance
// agrees with every edge's, indexed or not, and the spot is the largest
// circle inside rectangles, an L and the cores of stars whose spikes span
// 1000 m, found within the precision and the cell budget.
#include "design_test_util.hpp"

#include <cmath>
#include <cstdint>

#include "design/area_index.hpp"
#include "design/widest_spot.hpp"

namespace design_test {
namespace {

math::Polygon2 star_floor(int corners, double outer, double inner, bool clockwise = false) {
    math::Polygon2 out;
    for (int k = 0; k < corners; ++k) {
        const double a = 2.0 * math::kPi * k / corners * (clockwise ? -1 : 1), r = k % 2 ? inner : outer;
        out.push_back(r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return out;
}

TEST(WidestSpot, SignedDistanceAgreesWithEveryEdge) {
    // 40 corners: asked of every edge, or through a grid forced on it; 400:
    // through the grid.
    for (const int corners : {40, 400})
        for (const bool clockwise : {false, true}) {
            const math::Polygon2 area = star_floor(corners, 6.0, 2.0, clockwise);
            const design::AreaIndex index(area), forced(area, true);
            std::uint64_t state = 11;
            auto next = [&] {
                state = state * 6364136223846793005ull + 1442695040888963407ull;
                return static_cast<double>(state >> 11) * 0x1.0p-53;
            };
            for (int i = 0; i < 2000; ++i) {
                const glm::dvec2 p{14 * next() - 7, 14 * next() - 7};
                const double d = math::distance_to_boundary(area, p);
                const double expected = math::contains(area, p, 0.0) ? d : -d;
                ASSERT_NEAR(index.signed_distance(p), expected, 1e-9) << corners << ": " << p.x << " " << p.y;
                ASSERT_NEAR(forced.signed_distance(p), expected, 1e-9) << corners << ": " << p.x << " " << p.y;
            }
            // Nearest to a corner: inside a reflex (inner) one, outside a convex (outer) one.
            EXPECT_GT(index.signed_distance(area[1] * 0.9), 0.0);
            EXPECT_LT(index.signed_distance(area[0] * 1.1), 0.0);
        }
}

TEST(WidestSpot, IsTheLargestCircleInsideWithinThePrecision) {
    const math::Polygon2 wide = math::rectangle({-3, -1}, {5, 1});
    design::WidestSpot s = design::widest_spot(wide, design::AreaIndex(wide));
    EXPECT_TRUE(s.complete);
    EXPECT_NEAR(s.radius, 1.0, 0.01);
    EXPECT_NEAR(s.centre.y, 0.0, 0.01);
    // An L of arms 2 m wide: the circle in the corner where the arms meet,
    // touching both outer walls and the inner corner (2, 2).
    const math::Polygon2 ell = {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}};
    s = design::widest_spot(ell, design::AreaIndex(ell));
    EXPECT_TRUE(s.complete);
    const double r = 2 * std::sqrt(2.0) / (1 + std::sqrt(2.0));  // 1.17 m
    EXPECT_NEAR(s.radius, r, 0.01);
    EXPECT_NEAR(s.centre.x, r, 0.05);
    EXPECT_NEAR(s.centre.y, r, 0.05);
}

TEST(WidestSpot, FindsTheCoreOfAStarOfLongSpikes) {
    // 10,000 corners, spikes from 2 m to 500 m: the core is a circle 4 m
    // across (its corners lie on it), every spike narrower than 0.4 m.
    const math::Polygon2 area = star_floor(10'000, 500.0, 2.0);
    const design::WidestSpot s = design::widest_spot(area, design::AreaIndex(area));
    EXPECT_TRUE(s.complete);
    EXPECT_NEAR(s.radius, 2.0, 0.011);
    EXPECT_LT(glm::length(s.centre), 0.02);
    // A core 1.4 m across within the same spikes: the cells' budget ends the
    // search first, and the circle found is the core's, inside.
    const math::Polygon2 thin = star_floor(10'000, 500.0, 0.7);
    const design::WidestSpot t = design::widest_spot(thin, design::AreaIndex(thin));
    EXPECT_FALSE(t.complete);
    EXPECT_NEAR(t.radius, 0.7, 0.011);
    EXPECT_LT(glm::length(t.centre), 0.02);
}

}  // namespace
}  // namespace design_test
