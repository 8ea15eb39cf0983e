// The swept segment-versus-portal test.
#include <cmath>

#include <glm/geometric.hpp>

#include "math/crossing.hpp"
#include "math/pose.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

using testing::near_vec;

// At the origin facing +Z, 1 m wide (x), 2 m high (y).
PortalRect door() {
    PortalRect p;
    p.center = {0, 0, 0};
    p.normal = {0, 0, 1};
    p.up = {0, 1, 0};
    p.width = 1.0;
    p.height = 2.0;
    return p;
}

TEST(SegmentCrossing, FrontToBackThroughTheMiddle) {
    const auto c = segment_crossing(door(), {0.1, 0.2, 1.0}, {0.1, 0.2, -3.0});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->t, 0.25);
    EXPECT_EQ(c->point, dvec3(0.1, 0.2, 0.0));
}

TEST(SegmentCrossing, OnlyFrontToBack) {
    EXPECT_FALSE(segment_crossing(door(), {0, 0, -1}, {0, 0, 1}));   // back to front
    EXPECT_FALSE(segment_crossing(door(), {0, 0, 1}, {0, 0, 0.5}));  // stays in front
    EXPECT_FALSE(segment_crossing(door(), {0, 0, -1}, {0, 0, -2}));  // stays behind
    EXPECT_FALSE(segment_crossing(door(), {0, 0, 1}, {0, 0, 1}));    // no motion
}

TEST(SegmentCrossing, OnThePlaneIsInFront) {
    // Ending on the plane is not a crossing; starting on it and going behind is.
    EXPECT_FALSE(segment_crossing(door(), {0, 0, 1}, {0, 0, 0}));
    const auto c = segment_crossing(door(), {0, 0, 0}, {0, 0, -1});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->t, 0.0);
    EXPECT_EQ(c->point, dvec3(0, 0, 0));
    // The smallest step behind counts.
    EXPECT_TRUE(segment_crossing(door(), {0, 0, 0}, {0, 0, -std::numeric_limits<double>::denorm_min()}));
    EXPECT_FALSE(segment_crossing(door(), {0, 0, -0.0}, {0, 0, 0.0}));
}

TEST(SegmentCrossing, EdgesIncluded) {
    EXPECT_TRUE(segment_crossing(door(), {0.5, 1.0, 1}, {0.5, 1.0, -1}));  // a corner
    EXPECT_TRUE(segment_crossing(door(), {-0.5, -1.0, 1}, {-0.5, -1.0, -1}));
    EXPECT_TRUE(segment_crossing(door(), {0.0, 1.0, 1}, {0.0, 1.0, -1}));  // the top edge
    const double just_out = std::nextafter(0.5, 1.0);
    EXPECT_FALSE(segment_crossing(door(), {just_out, 0, 1}, {just_out, 0, -1}));
    EXPECT_FALSE(segment_crossing(door(), {0, std::nextafter(-1.0, -2.0), 1}, {0, std::nextafter(-1.0, -2.0), -1}));
}

TEST(SegmentCrossing, ObliqueSegmentUsesThePlanePoint) {
    // Both ends beside the rectangle but meeting the plane within it: counts.
    // Starting over it but meeting the plane beside it: no.
    EXPECT_TRUE(segment_crossing(door(), {-2.0, 0, 2.0}, {2.0, 0, -2.0}));  // meets z=0 at x=0
    EXPECT_FALSE(segment_crossing(door(), {0.0, 0, 1.0}, {2.0, 0, -1.0}));  // meets z=0 at x=1
    const auto c = segment_crossing(door(), {-1.0, 0.5, 3.0}, {1.0, 0.5, -1.0});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->t, 0.75);
    EXPECT_TRUE(near_vec(c->point, {0.5, 0.5, 0.0}, 0.0));  // on the right edge: included
}

TEST(SegmentCrossing, FastStepThroughASmallPortal) {
    PortalRect p = door();
    p.width = 0.5;
    p.height = 0.5;
    EXPECT_TRUE(segment_crossing(p, {0, 0, 1.0}, {0, 0, -1.0}));  // 2 m in one step
    EXPECT_FALSE(segment_crossing(p, {0.3, 0, 1.0}, {0.3, 0, -1.0}));
}

TEST(SegmentCrossing, TinyDistancesKeepTInRange) {
    // d0 = 1e-300, d1 = -1e-300 and extreme ratios: t stays in [0, 1] and the
    // point stays on the rectangle.
    const PortalRect p = door();
    for (auto [z0, z1] :
         {std::pair{1e-300, -1e-300}, std::pair{1e-300, -1.0}, std::pair{1.0, -1e-300}, std::pair{5e-324, -5e-324}}) {
        const auto c = segment_crossing(p, {0.1, 0.1, z0}, {0.2, 0.1, z1});
        ASSERT_TRUE(c) << z0 << " " << z1;
        EXPECT_GE(c->t, 0.0);
        EXPECT_LE(c->t, 1.0);
        EXPECT_GE(c->point.x, 0.1);
        EXPECT_LE(c->point.x, 0.2);
    }
}

TEST(SegmentCrossing, GeneralOrientation) {
    PortalRect p;
    const dmat3 r = head_rotation(HeadPose{{}, 37.0, 20.0, 10.0});
    p.normal = r[2];
    p.up = r[1];
    p.center = {1.7, 1.3, -2.9};
    p.width = 0.8;
    p.height = 1.9;
    const dvec3 right = portal_right(p);
    const dvec3 target = p.center + 0.3 * right - 0.9 * p.up;
    const dvec3 p0 = target + 0.7 * p.normal + 0.1 * right;
    const dvec3 p1 = target - 0.3 * p.normal - (0.1 * 0.3 / 0.7) * right;
    const auto c = segment_crossing(p, p0, p1);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->t, 0.7, 1e-14);
    EXPECT_TRUE(near_vec(c->point, target, 1e-14));
    EXPECT_NEAR(signed_distance(p, c->point), 0.0, 1e-15);
    // Shifted beyond the side edge (x = 0.4 + 0.01): no crossing.
    const dvec3 shift = 0.11 * right;
    EXPECT_FALSE(segment_crossing(p, p0 + shift, p1 + shift));
}

TEST(SegmentCrossing, NotANumberNeverCrosses) {
    const double nan = std::nan("");
    EXPECT_FALSE(segment_crossing(door(), {0, 0, nan}, {0, 0, -1}));
    EXPECT_FALSE(segment_crossing(door(), {0, 0, 1}, {0, 0, nan}));
    EXPECT_FALSE(segment_crossing(door(), {nan, 0, 1}, {0, 0, -1}));
}

// layout-format.md, "The portal box": an eye has the inner faces when it is
// in the column and the head reaches it through the door.
TEST(InnerFaces, AnEyeInFrontOfThePlaneInTheColumnHasThem) {
    const PortalRect p;  // centre 0, normal +z, 1 × 2 m, 0.25 m deep
    EXPECT_TRUE(has_inner_faces(p, dvec3(0.1, 0.5, 0.3), dvec3(0.1, 0.5, 0.3)));
    EXPECT_TRUE(has_inner_faces(p, dvec3(0.0, 0.0, 0.0), dvec3(5.0, 0.0, 0.0)));   // on the plane: in front
    EXPECT_FALSE(has_inner_faces(p, dvec3(0.6, 0.0, 0.3), dvec3(0.6, 0.0, 0.3)));  // beside the column
}

TEST(InnerFaces, AnEyeBehindThePlaneNeedsTheHeadToReachItThroughTheDoor) {
    const PortalRect p;
    const dvec3 eye(0.0, 0.5, -0.01);
    EXPECT_TRUE(has_inner_faces(p, eye, dvec3(0.03, 0.5, 0.02)));  // the head in front, through the rectangle
    EXPECT_TRUE(has_inner_faces(p, eye, dvec3(0.0, 1.0, 0.0)));    // the head on the plane, at the top edge
    EXPECT_FALSE(has_inner_faces(p, eye, dvec3(0.0, 0.5, -0.1)));  // the head walked round: behind too
    EXPECT_FALSE(has_inner_faces(p, eye, eye));                    // the head at the eye, behind
    EXPECT_FALSE(has_inner_faces(p, eye, dvec3(0.0, 3.5, 0.02)));  // in front, above the door: the segment
                                                                   // meets the plane above the rectangle
    EXPECT_FALSE(has_inner_faces(p, dvec3(0.0, 0.5, -0.3), dvec3(0.0, 0.5, 0.02)));  // behind the back face
}

}  // namespace
}  // namespace impossible::math
