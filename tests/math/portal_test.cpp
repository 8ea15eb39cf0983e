// Portal frames, transfer matrices, planes, columns and box corners.
#include <cmath>

#include <glm/geometric.hpp>

#include "math/portal.hpp"
#include "math/pose.hpp"
#include "math/rigid.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

using testing::apply;
using testing::apply_dir;
using testing::kEps;
using testing::near_mat;
using testing::near_vec;

PortalRect rect(dvec3 center, dvec3 normal, dvec3 up = {0, 1, 0}, double w = 1.0, double h = 2.0) {
    PortalRect p;
    p.center = center;
    p.normal = normal;
    p.up = up;
    p.width = w;
    p.height = h;
    return p;
}

// A portal with a general orientation: normal and up from yaw/pitch angles.
PortalRect general_rect(dvec3 center, double yaw, double pitch, double roll) {
    const dmat3 r = head_rotation(HeadPose{{}, yaw, pitch, roll});
    return rect(center, r[2], r[1], 0.9, 2.1);
}

TEST(PortalFrame, ColumnsAreRightUpNormalCenter) {
    const PortalRect p = rect({2, 1.1, 0}, {-1, 0, 0});
    EXPECT_EQ(portal_right(p), dvec3(0, 0, 1));  // u × n = y × (-x) = +z
    const dmat4 t = portal_frame(p);
    EXPECT_EQ(dvec3(t[0]), dvec3(0, 0, 1));
    EXPECT_EQ(dvec3(t[1]), dvec3(0, 1, 0));
    EXPECT_EQ(dvec3(t[2]), dvec3(-1, 0, 0));
    EXPECT_EQ(t[3], dvec4(2, 1.1, 0, 1));
    EXPECT_EQ(glm::dvec4(t[0][3], t[1][3], t[2][3], t[3][3]), dvec4(0, 0, 0, 1));
}

TEST(PortalFrame, InverseIsExactTransposeForm) {
    for (const PortalRect& p :
         {general_rect({1.5, -2.25, 7.125}, 37.0, 11.0, -3.0), general_rect({-100.0, 3.0, 0.5}, -150.0, 80.0, 45.0)}) {
        const dmat4 t = portal_frame(p);
        const dmat4 inv = portal_frame_inverse(p);
        const double scale = 1.0 + glm::length(p.center);
        EXPECT_TRUE(near_mat(inv * t, dmat4(1.0), 8 * kEps * scale));
        EXPECT_TRUE(near_mat(t * inv, dmat4(1.0), 8 * kEps * scale));
        EXPECT_TRUE(near_mat(inv, rigid_inverse(t), 4 * kEps * scale));
        // The portal's centre is the origin of its frame, the normal its +z.
        EXPECT_TRUE(near_vec(apply(inv, p.center), dvec3(0.0), 4 * kEps * scale));
        EXPECT_TRUE(near_vec(apply(inv, p.center + p.normal), dvec3(0, 0, 1), 8 * kEps * scale));
    }
}

TEST(SignedDistance, PositiveInFront) {
    const PortalRect p = rect({2, 1.1, 0}, {-1, 0, 0});
    EXPECT_EQ(signed_distance(p, {1.5, 0, 0}), 0.5);
    EXPECT_EQ(signed_distance(p, {2.5, 7, 3}), -0.5);
    EXPECT_EQ(signed_distance(p, {2.0, -4, 9}), 0.0);
    const dvec4 plane = portal_plane(p);
    for (dvec3 q : {dvec3(1.5, 0, 0), dvec3(2.5, 7, 3), dvec3(-3, 1, 1)})
        EXPECT_DOUBLE_EQ(glm::dot(plane, dvec4(q, 1.0)), signed_distance(p, q));
}

TEST(TransferMatrix, CoincidentOppositePortalsGiveIdentity) {
    // The heart of an impossible space: same centre, opposite normals.
    const PortalRect a = rect({2, 1.1, 0.3}, {-1, 0, 0});
    const PortalRect b = rect({2, 1.1, 0.3}, {1, 0, 0});
    EXPECT_EQ(transfer_matrix(a, b), dmat4(1.0));
    EXPECT_EQ(transfer_matrix(b, a), dmat4(1.0));
    // Also for a general orientation (normal and up not axis-aligned).
    PortalRect c = general_rect({0.1, 1.7, -3.3}, 37.0, 12.0, 5.0);
    PortalRect d = c;
    d.normal = -c.normal;
    EXPECT_TRUE(near_mat(transfer_matrix(c, d), dmat4(1.0), 1e-15));
    EXPECT_TRUE(near_mat(transfer_matrix(d, c), dmat4(1.0), 1e-15));
}

TEST(TransferMatrix, Rotated90AndTranslated) {
    // A at the origin facing +Z; B at (5, 0, 0) facing +X, right = y × x = -z.
    const PortalRect a = rect({0, 0, 0}, {0, 0, 1});
    const PortalRect b = rect({5, 0, 0}, {1, 0, 0});
    const dmat4 m = transfer_matrix(a, b);
    // Hand-computed: p_A local (x, y, z) → B local (-x, y, -z) → world
    // c_B + (-x)·r_B + y·u_B + (-z)·n_B = (5 - z, y, x).
    EXPECT_TRUE(near_vec(apply(m, {0, 0, 1}), {4, 0, 0}, 0.0));  // in front of A → behind B
    EXPECT_TRUE(near_vec(apply(m, {1, 0, 0}), {5, 0, 1}, 0.0));
    EXPECT_TRUE(near_vec(apply(m, {0.25, 0.5, -2}), {7, 0.5, 0.25}, 0.0));
    // Walking into A (along -Z) comes out of B along its normal (+X).
    EXPECT_TRUE(near_vec(apply_dir(m, {0, 0, -1}), {1, 0, 0}, 0.0));
    EXPECT_TRUE(near_vec(apply_dir(m, {0, 1, 0}), {0, 1, 0}, 0.0));
    // And the way back.
    const dmat4 back = transfer_matrix(b, a);
    EXPECT_TRUE(near_vec(apply(back, {7, 0.5, 0.25}), {0.25, 0.5, -2}, 0.0));
    EXPECT_TRUE(near_mat(m * back, dmat4(1.0), 0.0));
}

TEST(TransferMatrix, TranslatedOnly) {
    // A at z = 0 facing +Z; B at (10, 0, -3) facing -Z: a pure translation
    // by (10, 0, -3) (the pair of a doorway moved elsewhere).
    const PortalRect a = rect({0, 1, 0}, {0, 0, 1});
    const PortalRect b = rect({10, 1, -3}, {0, 0, -1});
    dmat4 expected(1.0);
    expected[3] = dvec4(10, 0, -3, 1);
    EXPECT_TRUE(near_mat(transfer_matrix(a, b), expected, 0.0));
}

TEST(TransferMatrix, RoundTripIsIdentity) {
    const PortalRect a = general_rect({1.41421356237, 0.7320508, -2.2360679}, 37.0, 0.0, 0.0);
    const PortalRect b = general_rect({-31.415926535, 2.7182818, 14.142135}, -113.0, 23.0, 7.0);
    const dmat4 ab = transfer_matrix(a, b);
    const dmat4 ba = transfer_matrix(b, a);
    const double scale = 1.0 + glm::length(a.center) + glm::length(b.center);
    EXPECT_TRUE(near_mat(ab * ba, dmat4(1.0), 8 * kEps * scale));
    EXPECT_TRUE(near_mat(ba * ab, dmat4(1.0), 8 * kEps * scale));
    EXPECT_TRUE(near_mat(ba, rigid_inverse(ab), 8 * kEps * scale));
    EXPECT_LT(orthonormality_error(ab), 8 * kEps);
    // Matches the definition T_B · R_y(180°) · T_A⁻¹.
    dmat4 ry180(1.0);
    ry180[0][0] = -1.0;
    ry180[2][2] = -1.0;
    EXPECT_TRUE(near_mat(ab, portal_frame(b) * ry180 * portal_frame_inverse(a), 8 * kEps * scale));
}

TEST(TransferMatrix, FrontOfAMapsBehindBAndTheRectangleOntoItself) {
    const PortalRect a = general_rect({1.0, 1.5, -2.0}, 37.0, 0.0, 0.0);
    const PortalRect b = general_rect({-4.0, 1.5, 6.0}, 200.0, 0.0, 0.0);
    const dmat4 m = transfer_matrix(a, b);
    const dvec3 ra = portal_right(a), rb = portal_right(b);
    for (double d : {0.001, 0.5, 3.0}) {
        for (double x : {-0.4, 0.0, 0.3}) {
            const dvec3 p = a.center + x * ra + 0.2 * a.up + d * a.normal;
            const dvec3 q = apply(m, p);
            EXPECT_NEAR(signed_distance(b, q), -d, 1e-14);
            // Mirrored across: A's right side lands on B's left side.
            EXPECT_NEAR(glm::dot(q - b.center, rb), -x, 1e-14);
            EXPECT_NEAR(glm::dot(q - b.center, b.up), 0.2, 1e-14);
            const dvec3 back = apply(m, a.center - d * a.normal);
            EXPECT_NEAR(signed_distance(b, back), d, 1e-14);
        }
    }
    // Normals: A's normal maps to minus B's normal.
    EXPECT_TRUE(near_vec(apply_dir(m, a.normal), -b.normal, 4 * kEps));
}

TEST(TransformPlane, MapsThePlaneOfTheMappedPoints) {
    const PortalRect a = general_rect({1.0, 1.5, -2.0}, 37.0, 10.0, 0.0);
    const PortalRect b = general_rect({-4.0, 1.5, 6.0}, 123.0, -5.0, 20.0);
    const dmat4 m = transfer_matrix(a, b);
    // A's plane (front of A) becomes minus B's plane (behind B).
    const dvec4 mapped = transform_plane(m, portal_plane(a));
    const dvec4 expected = -portal_plane(b);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(mapped[k], expected[k], 1e-14) << k;
    // The value of the plane at a point equals that of the new plane at the mapped point.
    const dvec4 plane(0.6, 0.0, 0.8, -1.25);
    const dvec4 moved = transform_plane(m, plane);
    for (dvec3 p : {dvec3(0, 0, 0), dvec3(1, 2, 3), dvec3(-7, 0.5, 11)})
        EXPECT_NEAR(glm::dot(moved, dvec4(apply(m, p), 1.0)), glm::dot(plane, dvec4(p, 1.0)), 1e-13);
}

TEST(InColumn, EdgesIncluded) {
    PortalRect p = rect({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 2.0, 1.0);
    p.depth = 0.25;
    EXPECT_TRUE(in_column(p, {0, 0, 0}));
    EXPECT_TRUE(in_column(p, {0, 0, 100}));        // far in front, over the rectangle
    EXPECT_TRUE(in_column(p, {1.0, 0.5, -0.25}));  // the corner of the back face
    EXPECT_TRUE(in_column(p, {-1.0, -0.5, 0.0}));
    EXPECT_FALSE(in_column(p, {std::nextafter(1.0, 2.0), 0.0, 0.0}));
    EXPECT_FALSE(in_column(p, {0.0, std::nextafter(-0.5, -1.0), 0.0}));
    EXPECT_FALSE(in_column(p, {0.0, 0.0, std::nextafter(-0.25, -1.0)}));  // behind the back face
    EXPECT_FALSE(in_column(p, {3.0, 0.0, 1.0}));
}

TEST(InColumn, RotatedPortal) {
    // Facing -X: right = +Z, so the width runs along Z.
    PortalRect p = rect({2, 1, 0}, {-1, 0, 0}, {0, 1, 0}, 1.0, 2.0);
    p.depth = 0.5;
    EXPECT_TRUE(in_column(p, {1.0, 1.9, 0.5}));
    EXPECT_TRUE(in_column(p, {2.5, 0.0, -0.5}));
    EXPECT_FALSE(in_column(p, {2.6, 1.0, 0.0}));
    EXPECT_FALSE(in_column(p, {1.0, 1.0, 0.6}));
    EXPECT_FALSE(in_column(p, {1.0, 2.1, 0.0}));
}

TEST(BoxCorners, OrderAndPositions) {
    PortalRect p = rect({2, 1.1, 0}, {-1, 0, 0}, {0, 1, 0}, 1.0, 2.2);
    p.depth = 0.25;
    dvec3 c[8];
    box_corners(p, c);
    // r = +z, u = +y; front at x = 2, back at x = 2.25.
    const dvec3 expected[8] = {{2, 0.0, -0.5},    {2, 0.0, 0.5},    {2, 2.2, 0.5},    {2, 2.2, -0.5},
                               {2.25, 0.0, -0.5}, {2.25, 0.0, 0.5}, {2.25, 2.2, 0.5}, {2.25, 2.2, -0.5}};
    for (int k = 0; k < 8; ++k) EXPECT_TRUE(near_vec(c[k], expected[k], 4 * kEps)) << k;
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(signed_distance(p, c[k]), 0.0, 4 * kEps);
        EXPECT_NEAR(signed_distance(p, c[k + 4]), -0.25, 4 * kEps);
        EXPECT_TRUE(in_column(p, c[k + 4] + 1e-12 * (p.center - c[k + 4])));
    }
}

}  // namespace
}  // namespace impossible::math
