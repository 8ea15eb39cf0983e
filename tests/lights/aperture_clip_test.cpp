// The convex polygon helpers of the aperture test (lights/aperture_clip.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "lights/aperture_clip.hpp"
#include "lights/lights_test_layouts.hpp"

namespace impossible::lights {
namespace {

using glm::dvec3;

TEST(ApertureClip, RectPolygonHasTheFourCornersGrown) {
    const math::PortalRect rect = testing::make_rect({1, 2, 3}, {0, 0, 1}, 2.0, 4.0);
    const Polygon3 poly = rect_polygon(rect, 0.5);
    ASSERT_EQ(poly.size(), 4u);
    for (const dvec3& c : poly) {
        EXPECT_DOUBLE_EQ(std::abs(c.x - 1), 1.5);
        EXPECT_DOUBLE_EQ(std::abs(c.y - 2), 2.5);
        EXPECT_DOUBLE_EQ(c.z, 3);
    }
}

TEST(ApertureClip, HalfSpaceKeepsTheSideAndTheTolerance) {
    const Polygon3 square = rect_polygon(testing::make_rect({0, 0, 0}, {0, 0, 1}, 2.0, 2.0), 0.0);
    const Polygon3 half = clip_half_space(square, {1, 0, 0}, -0.5, 0.0);  // x >= 0.5
    ASSERT_EQ(half.size(), 4u);
    for (const dvec3& c : half) EXPECT_GE(c.x, 0.5 - 1e-15);
    EXPECT_TRUE(clip_half_space(square, {1, 0, 0}, -1.5, 0.0).empty());
    EXPECT_FALSE(clip_half_space(square, {1, 0, 0}, -1.5, 0.6).empty());  // within the tolerance
}

TEST(ApertureClip, ConeFromAnApexThroughAWindow) {
    // A 1 × 1 window at z = -1, seen from the origin: on the plane z = -2
    // the cone covers the 2 × 2 square.
    const Polygon3 window = rect_polygon(testing::make_rect({0, 0, -1}, {0, 0, 1}, 1.0, 1.0), 0.0);
    const Polygon3 big = rect_polygon(testing::make_rect({0.9, 0, -2}, {0, 0, 1}, 4.0, 4.0), 0.0);
    const Polygon3 cut = clip_to_cone(big, {0, 0, 0}, window, 0.0);
    ASSERT_GE(cut.size(), 3u);
    for (const dvec3& c : cut) {
        EXPECT_LE(std::abs(c.x), 1.0 + 1e-12);
        EXPECT_LE(std::abs(c.y), 1.0 + 1e-12);
    }
    const Polygon3 aside = rect_polygon(testing::make_rect({3, 0, -2}, {0, 0, 1}, 1.0, 1.0), 0.0);
    EXPECT_TRUE(clip_to_cone(aside, {0, 0, 0}, window, 0.0).empty());
    // The other nappe (behind the apex) is not in the cone.
    const Polygon3 behind = rect_polygon(testing::make_rect({0, 0, 2}, {0, 0, 1}, 1.0, 1.0), 0.0);
    EXPECT_TRUE(clip_to_cone(behind, {0, 0, 0}, window, 0.0).empty());
}

TEST(ApertureClip, TheSmallestAngleFromAnAxisToAPolygon) {
    // A 2 × 2 square at z = -1 (x, y in -1..1), seen from the origin.
    const Polygon3 square = rect_polygon(testing::make_rect({0, 0, -1}, {0, 0, 1}, 2.0, 2.0), 0.0);
    EXPECT_DOUBLE_EQ(max_cos_to_polygon({0, 0, 0}, {0, 0, -1}, square), 1.0);  // the axis meets it
    // Along +x: nearest at the edge x = 1, at its middle (y = 0): 45°.
    EXPECT_NEAR(max_cos_to_polygon({0, 0, 0}, {1, 0, 0}, square), std::sqrt(0.5), 1e-12);
    // Diagonal, beyond a corner: the corner (1, 1, -1).
    const dvec3 diagonal = glm::normalize(dvec3(1, 1, 0));
    EXPECT_NEAR(max_cos_to_polygon({0, 0, 0}, diagonal, square), glm::dot(diagonal, glm::normalize(dvec3(1, 1, -1))),
                1e-12);
    EXPECT_LT(max_cos_to_polygon({0, 0, 0}, {0, 0, 1}, square), 0.0);  // facing away
}

TEST(ApertureClip, DistanceToAPolygonInsideAndOutsideItsOutline) {
    const Polygon3 square = rect_polygon(testing::make_rect({0, 0, 0}, {0, 0, 1}, 2.0, 2.0), 0.0);
    EXPECT_NEAR(distance_to_polygon({0.5, 0.5, 3}, square), 3.0, 1e-12);
    EXPECT_NEAR(distance_to_polygon({4, 1, 0}, square), 3.0, 1e-12);
    EXPECT_NEAR(distance_to_polygon({4, 5, 0}, square), 5.0, 1e-12);
    EXPECT_NEAR(distance_to_polygon({1, 2, 3}, Polygon3{{1, 2, 0}}), 3.0, 1e-12);
}

}  // namespace
}  // namespace impossible::lights
