// The play area's index for generate (design/area_index.hpp) answers as
// clipping does: boxes over a star of many corners, and boxes flush with
// the edges of an L-shaped floor whose corners lie on the decimetre grid.
#include "design_test_util.hpp"

#include <cmath>
#include <cstdint>

#include "design/area_index.hpp"

namespace design_test {
namespace {

math::Polygon2 spiky_floor(int corners, glm::dvec2 centre, double outer, double inner) {
    math::Polygon2 out;
    for (int k = 0; k < corners; ++k) {
        const double a = 2.0 * math::kPi * k / corners + 0.1234, r = k % 2 ? inner : outer;
        out.push_back(centre + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return out;
}

TEST(AreaIndex, AgreesWithClippingOnBoxesOverAStar) {
    const math::Polygon2 area = spiky_floor(200, {0.3, -0.2}, 6.0, 4.5);
    const design::AreaIndex indexed(area);
    std::uint64_t state = 7;
    auto next = [&](int lo, int hi) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return lo + static_cast<int>((state >> 33) % static_cast<std::uint64_t>(hi - lo + 1));
    };
    int inside = 0;
    for (int i = 0; i < 4000; ++i) {
        const int x0 = next(-70, 60), z0 = next(-70, 60), w = next(5, 50), h = next(5, 50);
        const glm::dvec2 lo{x0 / 10.0, z0 / 10.0}, hi{(x0 + w) / 10.0, (z0 + h) / 10.0};
        const bool expected = math::convex_inside(math::rectangle(lo, hi), area, 1e-9);
        ASSERT_EQ(indexed.box_inside(lo, hi), expected) << lo.x << " " << lo.y << " " << hi.x << " " << hi.y;
        inside += expected;
    }
    EXPECT_GT(inside, 200);
}

TEST(AreaIndex, AgreesWithClippingOnBoxesFlushWithAnLShapedFloor) {
    // Corners on the decimetre grid, so that many boxes touch an edge; the
    // index is forced (the floor has too few corners to get one otherwise).
    const math::Polygon2 area = {{-3, -3}, {3, -3}, {3, 0}, {0, 0}, {0, 3}, {-3, 3}};
    const design::AreaIndex forced(area, true);
    int inside = 0, checked = 0;
    for (int x0 = -32; x0 <= 30; x0 += 2)
        for (int z0 = -32; z0 <= 30; z0 += 2)
            for (const int w : {10, 15, 30, 60})
                for (const int h : {10, 20, 30}) {
                    const glm::dvec2 lo{x0 / 10.0, z0 / 10.0}, hi{(x0 + w) / 10.0, (z0 + h) / 10.0};
                    const bool expected = math::convex_inside(math::rectangle(lo, hi), area, 1e-9);
                    ASSERT_EQ(forced.box_inside(lo, hi), expected) << lo.x << " " << lo.y << " " << w << " " << h;
                    inside += expected, ++checked;
                }
    EXPECT_GT(inside, checked / 10);
}

}  // namespace
}  // namespace design_test
