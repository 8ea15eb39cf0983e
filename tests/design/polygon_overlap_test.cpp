// Overlap of floors of any shape (design/overlap.hpp): Boost.Geometry's
// intersections against known areas and against a second method (ear
// clipping and convex clips), and the overlap figures of non-convex rooms.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "design/overlap.hpp"

namespace {

using impossible::math::Polygon2;
namespace d = impossible::design;
namespace m = impossible::math;

// An L: a 4 x 4 square without its 2 x 2 north-east quarter (12 m²).
const Polygon2 kOverlapL = {{-2, -2}, {2, -2}, {2, 0}, {0, 0}, {0, 2}, {-2, 2}};

Polygon2 turned(const Polygon2& poly, double degrees, glm::dvec2 by = {0, 0}) {
    const double a = degrees * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
    Polygon2 out;
    for (const glm::dvec2& p : poly) out.push_back(glm::dvec2(c * p.x - s * p.y, s * p.x + c * p.y) + by);
    return out;
}

Polygon2 reversed(const Polygon2& poly) { return Polygon2(poly.rbegin(), poly.rend()); }

double pieces_area(const std::vector<Polygon2>& pieces) {
    double sum = 0.0;
    for (const Polygon2& p : pieces) {
        EXPECT_GT(m::signed_area(p), 0.0);  // counter-clockwise
        sum += m::area(p);
    }
    return sum;
}

TEST(PolygonOverlap, LShapeAndRectangle) {
    const Polygon2 square = m::rectangle({-1, -1}, {1, 1});  // 4 m², a quarter of it in the L's missing corner
    EXPECT_NEAR(d::intersection_area(kOverlapL, square), 3.0, 1e-12);
    EXPECT_NEAR(d::intersection_area(square, kOverlapL), 3.0, 1e-12);
    EXPECT_NEAR(d::intersection_area(reversed(kOverlapL), reversed(square)), 3.0, 1e-12);
    EXPECT_NEAR(pieces_area(d::intersection(kOverlapL, square)), 3.0, 1e-12);
    // Inside the L's bounding square but in its missing quarter: nothing shared.
    EXPECT_NEAR(d::intersection_area(kOverlapL, m::rectangle({0.5, 0.5}, {1.5, 1.5})), 0.0, 1e-12);
    EXPECT_TRUE(d::intersection(kOverlapL, m::rectangle({0.5, 0.5}, {1.5, 1.5})).empty());

    const d::Overlap o = d::overlap_of(kOverlapL, square);
    EXPECT_NEAR(o.area, 3.0, 1e-12);
    EXPECT_NEAR(o.percent, 75.0, 1e-9);  // of the smaller floor, the square's 4 m²
    EXPECT_EQ(o.limit, d::kSmallRoomLimit);
    EXPECT_TRUE(o.noticeable);
    ASSERT_EQ(o.shared.size(), 1u);
    EXPECT_NEAR(m::area(o.shared[0]), 3.0, 1e-12);
}

TEST(PolygonOverlap, TurnedShapesKeepTheirArea) {
    // The L and the square turned together by 37° about (5, -3): still 3 m².
    const Polygon2 l = turned(kOverlapL, 37.0, {5, -3}), sq = turned(m::rectangle({-1, -1}, {1, 1}), 37.0, {5, -3});
    EXPECT_NEAR(d::intersection_area(l, sq), 3.0, 1e-9);
    EXPECT_NEAR(d::overlap_of(l, sq).area, 3.0, 1e-9);
    // The L and itself turned by a quarter turn: the square without two quarters.
    const Polygon2 quarter = {{2, -2}, {2, 2}, {0, 2}, {0, 0}, {-2, 0}, {-2, -2}};
    EXPECT_NEAR(d::intersection_area(kOverlapL, quarter), 8.0, 1e-12);
    EXPECT_NEAR(d::overlap_of(kOverlapL, kOverlapL).percent, 100.0, 1e-9);
}

TEST(PolygonOverlap, TwoTurnedRectangles) {
    // A 2 x 2 square and the same square turned by 45° share a regular
    // octagon of area 8 (√2 - 1).
    const Polygon2 a = m::rectangle({-1, -1}, {1, 1}), b = turned(a, 45.0);
    const double octagon = 8.0 * (std::sqrt(2.0) - 1.0);
    EXPECT_NEAR(d::intersection_area(a, b), octagon, 1e-12);
    EXPECT_NEAR(d::overlap_of(a, b).area, octagon, 1e-12);  // two convex floors: clipped as before
    EXPECT_NEAR(pieces_area(d::intersection(a, b)), octagon, 1e-12);
    // A 4 x 1 bar turned by 30° and by 120° (a right angle between them,
    // crossing at their centres): a 1 x 1 square.
    const Polygon2 bar = m::rectangle({-2, -0.5}, {2, 0.5});
    EXPECT_NEAR(d::intersection_area(turned(bar, 30.0, {3, 4}), turned(bar, 120.0, {3, 4})), 1.0, 1e-12);
}

TEST(PolygonOverlap, AUShapeMeetsABarInTwoPieces) {
    // A 3 x 3 U open to +z (7 m²), and a bar across both of its arms.
    const Polygon2 u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    const Polygon2 bar = m::rectangle({-1, 2}, {4, 2.5});
    const std::vector<Polygon2> pieces = d::intersection(u, bar);
    EXPECT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(pieces_area(pieces), 1.0, 1e-12);
    const d::Overlap o = d::overlap_of(bar, u);
    EXPECT_NEAR(o.area, 1.0, 1e-12);
    EXPECT_EQ(o.shared.size(), 2u);
    EXPECT_NEAR(o.percent, 100.0 * 1.0 / 2.5, 1e-9);  // the bar is the smaller floor
}

TEST(PolygonOverlap, FloorsSharingAnEdgeShareNoArea) {
    const Polygon2 right = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};  // against the L's inner corner
    EXPECT_NEAR(d::intersection_area(kOverlapL, m::rectangle({2, -2}, {3, 0})), 0.0, 1e-12);
    EXPECT_NEAR(d::intersection_area(kOverlapL, right), 0.0, 1e-12);
    EXPECT_LE(d::overlap_of(kOverlapL, right).area, d::kMinSharedArea);
}

// A random simple polygon: corners at increasing angles round a centre.
Polygon2 star(std::mt19937& rng, glm::dvec2 centre) {
    std::uniform_real_distribution<double> radius(0.3, 3.0);
    std::uniform_int_distribution<int> corners(3, 12);
    const int n = corners(rng);
    Polygon2 out;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * (i + std::uniform_real_distribution<double>(0.0, 0.8)(rng)) / n;
        out.push_back(centre + radius(rng) * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return out;
}

TEST(PolygonOverlap, LibraryAgreesWithEarClipping) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> at(-2.0, 2.0);
    int shared = 0;
    for (int k = 0; k < 400; ++k) {
        const Polygon2 a = star(rng, {at(rng), at(rng)}), b = star(rng, {at(rng), at(rng)});
        const double library = d::intersection_area(a, b), triangles = d::intersection_area_by_triangles(a, b);
        EXPECT_NEAR(library, triangles, 1e-9 * (1.0 + triangles)) << "pair " << k;
        EXPECT_NEAR(pieces_area(d::intersection(a, b)), library, 1e-9 * (1.0 + library)) << "pair " << k;
        EXPECT_NEAR(d::overlap_of(a, b).area, library, 1e-9 * (1.0 + library)) << "pair " << k;
        shared += library > 0.01;
    }
    EXPECT_GT(shared, 200);  // most pairs overlap, so the comparison means something
}

// A saw of `teeth` teeth 10 m high along x over a 1 m strip; turned, a
// second one's teeth cross every tooth of the first.
Polygon2 saw(int teeth, bool turn) {
    Polygon2 p;
    const double dx = 10.0 / teeth;
    for (int i = 0; i < teeth; ++i) {
        p.push_back({i * dx, 0});
        p.push_back({(i + 0.5) * dx, 10});
    }
    for (const glm::dvec2 c : {glm::dvec2(10, 0), glm::dvec2(10, -1), glm::dvec2(0, -1)}) p.push_back(c);
    if (turn)
        for (glm::dvec2& c : p) c = {c.y + 0.5, c.x};
    return p;
}

TEST(PolygonOverlap, BoundariesMeetingEverywhereStayCheap) {
    // 497 teeth a side: about 250,000 crossings, beyond the library's
    // kMaxLibraryMeetings (it took minutes); the triangles take milliseconds.
    const Polygon2 a = saw(497, false), b = saw(497, true);
    const auto start = std::chrono::steady_clock::now();
    const double area = d::intersection_area(a, b);
    const std::vector<Polygon2> pieces = d::intersection(a, b);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);
    EXPECT_NEAR(area, d::intersection_area_by_triangles(a, b), 1e-9);
    EXPECT_NEAR(pieces_area(pieces), area, 1e-9);
    // A few teeth: the library, and the same area as the fallback's.
    const Polygon2 c = saw(3, false), e = saw(3, true);
    EXPECT_NEAR(d::intersection_area(c, e), d::intersection_area_by_triangles(c, e), 1e-9);
    EXPECT_GT(d::intersection_area(c, e), 1.0);
}

TEST(PolygonOverlap, TheSweepStopsAtItsWork) {
    // 30 saws of 99 corners on one spot: 435 pairs of 99² corner pairs each.
    const std::vector<Polygon2> floors(30, saw(48, false));
    d::OverlapLimits limits;
    limits.work = 20 * 99 * 99;  // 20 pairs
    const d::Overlaps o = d::room_overlaps(floors, limits);
    EXPECT_FALSE(o.exact);
    EXPECT_EQ(o.pairs, 20u);
    const d::Overlaps all = d::room_overlaps(floors);  // within the default work
    EXPECT_TRUE(all.exact);
    EXPECT_EQ(all.pairs, 30u * 29 / 2);
    // At the default work, 1000-corner floors stop after 200 pairs.
    const d::Overlaps big = d::room_overlaps(std::vector<Polygon2>(22, saw(498, false)));
    EXPECT_FALSE(big.exact);
    EXPECT_EQ(big.pairs, d::kMaxClipWork / (1000 * 1000));
}

TEST(PolygonOverlap, PolygonInside) {
    EXPECT_TRUE(d::polygon_inside(kOverlapL, m::rectangle({-2, -2}, {2, 2}), 1e-9));
    EXPECT_TRUE(d::polygon_inside(m::rectangle({-2, -2}, {0, 2}), kOverlapL, 1e-9));
    EXPECT_FALSE(d::polygon_inside(m::rectangle({-1, -1}, {1, 1}), kOverlapL, 1e-9));  // a quarter in the notch
    EXPECT_FALSE(d::polygon_inside(kOverlapL, m::rectangle({-2, -2}, {2, 1.9}), 1e-9));
    EXPECT_TRUE(d::is_convex(m::rectangle({0, 0}, {1, 1})));
    EXPECT_FALSE(d::is_convex(kOverlapL));
}

TEST(PolygonOverlap, SweepListsNonConvexPairs) {
    // The L, a square in its notch (sharing nothing), and a square over its corner.
    const std::vector<Polygon2> floors = {kOverlapL, m::rectangle({0.2, 0.2}, {1.8, 1.8}),
                                          m::rectangle({-3, -3}, {-1, -1})};
    const d::Overlaps o = d::room_overlaps(floors);
    ASSERT_EQ(o.listed.size(), 1u);
    EXPECT_EQ(o.listed[0].a, 0);
    EXPECT_EQ(o.listed[0].b, 2);
    EXPECT_NEAR(o.listed[0].area, 1.0, 1e-12);
    EXPECT_TRUE(o.exact);
}

}  // namespace
