// Oblique near-plane clipping (Lengyel 2005), standard and reversed-Z.
#include <cmath>

#include <glm/geometric.hpp>

#include "math/oblique_projection.hpp"
#include "math/portal.hpp"
#include "math/pose.hpp"
#include "math/projection.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

const Frustum kFrustum{90.0, 16.0 / 9.0, 0.05};
constexpr double kFar = 200.0;

// An eye-space plane, eye behind it: 1.2 m away along a tilted normal.
dvec4 tilted_plane() {
    const dvec3 n = glm::normalize(dvec3(0.3, -0.2, -1.0));  // facing away from the eye
    const dvec3 on = 1.2 * glm::normalize(dvec3(0.1, 0.05, -1.0));
    return dvec4(n, -glm::dot(n, on));
}

double plane_value(const dvec4& plane, const dvec3& p) { return glm::dot(plane, dvec4(p, 1.0)); }

// Points spread through the original frustum, from just past the near plane
// to `far` (directions over the whole image, corners included).
std::vector<dvec3> frustum_points(double far) {
    std::vector<dvec3> pts;
    const double t = std::tan(radians(0.5 * kFrustum.fov_y_deg));
    for (double dist : {0.06, 0.5, 1.0, 1.3, 2.0, 10.0, 50.0, far}) {
        for (double sx = -1.0; sx <= 1.0; sx += 0.25)
            for (double sy = -1.0; sy <= 1.0; sy += 0.25)
                pts.push_back(dist * dvec3(sx * t * kFrustum.aspect, sy * t, -1.0));
    }
    return pts;
}

// A point on the plane reached along the eye ray through (x, y, -1).
dvec3 on_plane(const dvec4& plane, const dvec3& dir) {
    const double s = -plane.w / glm::dot(dvec3(plane), dir);
    return s * dir;
}

TEST(ObliqueStandard, PlaneBecomesTheNearPlane) {
    const dmat4 proj = perspective_standard(kFrustum, kFar);
    const dvec4 plane = tilted_plane();
    const dmat4 m = oblique_standard(proj, plane);
    for (dvec3 dir : {dvec3(0, 0, -1), dvec3(0.5, 0.3, -1), dvec3(-1.2, -0.8, -1)}) {
        const dvec4 c = m * dvec4(on_plane(plane, dir), 1.0);
        EXPECT_NEAR(c.z / c.w, -1.0, 1e-12);
    }
    int inside = 0, behind = 0;
    for (const dvec3& p : frustum_points(kFar)) {
        const dvec4 c = m * dvec4(p, 1.0);
        const double v = plane_value(plane, p);
        if (v > 1e-9) {
            // In front of the plane and inside the original frustum: kept,
            // the far plane included (nothing of the original frustum is lost).
            EXPECT_GE(c.z, -c.w) << p.x << "," << p.y << "," << p.z;
            EXPECT_LE(c.z, c.w * (1.0 + 1e-12)) << p.x << "," << p.y << "," << p.z;
            ++inside;
        } else if (v < -1e-9) {
            EXPECT_LT(c.z, -c.w) << p.x << "," << p.y << "," << p.z;  // clipped by the near plane
            ++behind;
        }
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(behind, 100);
}

TEST(ObliqueStandard, FarCornerKeepsDepthOneAndXYUnchanged) {
    const dmat4 proj = perspective_standard(kFrustum, kFar);
    const dvec4 plane = tilted_plane();  // normal has +x, -y: the far corner is (+x, -y)
    const dmat4 m = oblique_standard(proj, plane);
    const double t = std::tan(radians(0.5 * kFrustum.fov_y_deg));
    const dvec3 corner = kFar * dvec3(t * kFrustum.aspect, -t, -1.0);
    const dvec4 c = m * dvec4(corner, 1.0);
    EXPECT_NEAR(c.z / c.w, 1.0, 1e-9);
    // Beyond the original far corner: clipped by the new far plane.
    const dvec4 beyond = m * dvec4(1.01 * corner, 1.0);
    EXPECT_GT(beyond.z, beyond.w);
    // x, y and w rows are untouched: same image position as before.
    for (const dvec3& p : {dvec3(0.3, 0.2, -5.0), dvec3(-40.0, 17.0, -150.0), corner}) {
        const dvec4 a = proj * dvec4(p, 1.0);
        const dvec4 b = m * dvec4(p, 1.0);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.y, b.y);
        EXPECT_EQ(a.w, b.w);
    }
}

TEST(ObliqueReversedZ, PlaneBecomesTheNearPlaneAndInfinityIsKept) {
    const dmat4 proj = perspective_reversed_z(kFrustum);
    const dvec4 plane = tilted_plane();
    const dmat4 m = oblique_reversed_z(proj, plane);
    for (dvec3 dir : {dvec3(0, 0, -1), dvec3(0.5, 0.3, -1), dvec3(-1.2, -0.8, -1)}) {
        const dvec4 c = m * dvec4(on_plane(plane, dir), 1.0);
        EXPECT_NEAR(c.z / c.w, 1.0, 1e-12);
    }
    int inside = 0, behind = 0;
    for (const dvec3& p : frustum_points(1e7)) {
        const dvec4 c = m * dvec4(p, 1.0);
        const double v = plane_value(plane, p);
        if (v > 1e-9) {
            EXPECT_LE(c.z, c.w) << p.x << "," << p.y << "," << p.z;
            EXPECT_GT(c.z, 0.0) << p.x << "," << p.y << "," << p.z;  // never far-clipped
            ++inside;
        } else if (v < -1e-9) {
            EXPECT_GT(c.z, c.w) << p.x << "," << p.y << "," << p.z;
            ++behind;
        }
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(behind, 100);
    // Depth is monotonic along a ray in front of the plane: farther is smaller.
    const dvec3 dir(0.2, -0.1, -1.0);
    double last = 2.0;
    for (double s = 1.3; s < 1e6; s *= 3.0) {
        const dvec4 c = m * dvec4(s * dir, 1.0);
        EXPECT_LT(c.z / c.w, last);
        last = c.z / c.w;
    }
    // The far corner direction at infinity lands on depth 0.
    const double t = std::tan(radians(0.5 * kFrustum.fov_y_deg));
    const dvec4 corner_at_infinity = m * dvec4(t * kFrustum.aspect, -t, -1.0, 0.0);
    EXPECT_NEAR(corner_at_infinity.z / corner_at_infinity.w, 0.0, 1e-12);
}

TEST(ObliqueReversedZ, FarPointsKeepTheirXY) {
    const dmat4 proj = perspective_reversed_z(kFrustum);
    const dmat4 m = oblique_reversed_z(proj, tilted_plane());
    for (const dvec3& p : {dvec3(0.3, 0.2, -5.0), dvec3(-4e4, 1.7e4, -1.5e5), dvec3(1e6, 0, -1e6)}) {
        const dvec4 a = proj * dvec4(p, 1.0);
        const dvec4 b = m * dvec4(p, 1.0);
        EXPECT_EQ(a.x / a.w, b.x / b.w);
        EXPECT_EQ(a.y / a.w, b.y / b.w);
    }
}

TEST(Oblique, EyeNotBehindThePlaneLeavesTheProjectionAlone) {
    const dmat4 std_proj = perspective_standard(kFrustum, kFar);
    const dmat4 rev_proj = perspective_reversed_z(kFrustum);
    const dvec4 facing_eye(0.0, 0.0, 1.0, 2.0);  // eye at d = 2 in front
    const dvec4 through_eye(0.0, 0.0, -1.0, 0.0);
    for (const dvec4& plane : {facing_eye, through_eye}) {
        EXPECT_EQ(oblique_standard(std_proj, plane), std_proj);
        EXPECT_EQ(oblique_reversed_z(rev_proj, plane), rev_proj);
    }
}

TEST(Oblique, PortalPlaneThroughAView) {
    // The use in the renderer: a virtual eye 0.3 m behind portal B, looking
    // through it, clip plane = B's plane in eye space.
    PortalRect b;
    b.center = {4.0, 1.5, -2.0};
    b.normal = glm::normalize(dvec3(-1.0, 0.0, -1.0));
    b.up = {0, 1, 0};
    const Eye eye{b.center - 0.3 * b.normal + dvec3(0.0, 0.1, 0.0),
                  head_rotation(HeadPose{{}, -135.0 + 180.0 + 10.0, 5.0, 0.0})};
    const dmat4 view = view_matrix(eye);
    const dvec4 plane_eye = transform_plane(view, portal_plane(b));
    EXPECT_LT(plane_eye.w, 0.0);
    const dmat4 m = oblique_reversed_z(perspective_reversed_z(kFrustum), plane_eye) * view;
    // A point of B's room 2 m in front of B is drawn; one between the eye
    // and B's plane is not; B's centre is on the near plane.
    const dvec4 front = m * dvec4(b.center + 2.0 * b.normal, 1.0);
    EXPECT_GT(front.z, 0.0);
    EXPECT_LT(front.z, front.w);
    const dvec4 between = m * dvec4(b.center - 0.1 * b.normal, 1.0);
    EXPECT_GT(between.z, between.w);
    const dvec4 on = m * dvec4(b.center, 1.0);
    EXPECT_NEAR(on.z / on.w, 1.0, 1e-12);
}

}  // namespace
}  // namespace impossible::math
