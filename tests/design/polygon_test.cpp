// Floor polygons (math/polygon.hpp): areas, containment, simplicity, clipping.
#include <gtest/gtest.h>

#include "math/polygon.hpp"

namespace {

using impossible::math::Polygon2;
namespace m = impossible::math;

// An L: a 4 x 4 square without its 2 x 2 north-east quarter (12 m²).
const Polygon2 kL = {{-2, -2}, {2, -2}, {2, 0}, {0, 0}, {0, 2}, {-2, 2}};

TEST(Polygon, AreaOfEitherWinding) {
    EXPECT_DOUBLE_EQ(m::area(kL), 12.0);
    Polygon2 reversed(kL.rbegin(), kL.rend());
    EXPECT_DOUBLE_EQ(m::area(reversed), 12.0);
    EXPECT_DOUBLE_EQ(m::signed_area(reversed), -m::signed_area(kL));
}

TEST(Polygon, ContainsWithEdgesIncluded) {
    EXPECT_TRUE(m::contains(kL, {-1, -1}));
    EXPECT_TRUE(m::contains(kL, {2, -1}));  // on an edge
    EXPECT_TRUE(m::contains(kL, {0, 0}));   // the inner corner
    EXPECT_FALSE(m::contains(kL, {1, 1}));  // the missing quarter
    EXPECT_FALSE(m::contains(kL, {3, 0}));
    EXPECT_DOUBLE_EQ(m::distance_to_boundary(kL, {-1, -1}), 1.0);
}

TEST(Polygon, SimplePolygonProblems) {
    EXPECT_FALSE(m::simple_polygon_problem(kL).has_value());
    const auto bowtie = m::simple_polygon_problem({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
    ASSERT_TRUE(bowtie.has_value());
    EXPECT_NE(bowtie->message.find("intersects itself"), std::string::npos) << bowtie->message;
    const auto repeated = m::simple_polygon_problem({{0, 0}, {1, 0}, {1, 1}, {1, 0}, {0, 1}});
    ASSERT_TRUE(repeated.has_value());
    EXPECT_EQ(repeated->corner, 3);
    EXPECT_NE(repeated->message.find("repeats corner 1"), std::string::npos) << repeated->message;
    EXPECT_TRUE(m::simple_polygon_problem({{0, 0}, {1, 0}}).has_value());
    EXPECT_TRUE(m::simple_polygon_problem({{0, 0}, {1, 0}, {2, 0}}).has_value());  // no area
    // A spike back along the previous edge.
    EXPECT_TRUE(m::simple_polygon_problem({{0, 0}, {2, 0}, {1, 0}, {1, 1}}).has_value());
}

TEST(Polygon, ClippingGivesTheSharedArea) {
    const Polygon2 a = m::rectangle({0, 0}, {4, 4}), b = m::rectangle({2, 1}, {6, 3});
    EXPECT_NEAR(m::intersection_area(a, b), 4.0, 1e-12);
    EXPECT_NEAR(m::intersection_area(kL, m::rectangle({-1, -1}, {1, 1})), 3.0, 1e-12);
    EXPECT_TRUE(m::convex_inside(m::rectangle({-2, -2}, {0, 2}), kL));
    EXPECT_FALSE(m::convex_inside(m::rectangle({-1, -1}, {1, 1}), kL));
}

TEST(Polygon, SegmentsInsideANonConvexPolygon) {
    EXPECT_TRUE(m::segment_inside(kL, {-1, 1}, {-1, -1}));
    EXPECT_TRUE(m::segment_inside(kL, {-1, -1}, {1, -1}));
    EXPECT_FALSE(m::segment_inside(kL, {-1, 1.5}, {1.5, -1}));  // cuts across the missing quarter
    EXPECT_TRUE(m::segments_intersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_FALSE(m::segments_intersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));
}

}  // namespace
