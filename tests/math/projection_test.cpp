// Perspective projections and pixel rays.
#include <cmath>

#include "math/projection.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

using testing::kEps;

dvec4 clip(const dmat4& p, const dvec3& eye_point) { return p * dvec4(eye_point, 1.0); }
double depth(const dmat4& p, const dvec3& eye_point) {
    const dvec4 c = clip(p, eye_point);
    return c.z / c.w;
}

TEST(ReversedZ, NearPlaneIsOneAndInfinityIsZero) {
    const Frustum f{90.0, 16.0 / 9.0, 0.05};
    const dmat4 p = perspective_reversed_z(f);
    EXPECT_DOUBLE_EQ(depth(p, {0, 0, -0.05}), 1.0);
    EXPECT_DOUBLE_EQ(depth(p, {0.3, -0.2, -0.05}), 1.0);
    EXPECT_DOUBLE_EQ(depth(p, {0, 0, -0.1}), 0.5);
    EXPECT_GT(depth(p, {0, 0, -1e6}), 0.0);
    EXPECT_LT(depth(p, {0, 0, -1e6}), 1e-7);
    // Points at infinity (w = 0 in eye space) land exactly on depth 0.
    const dvec4 inf = p * dvec4(0.3, 0.1, -1.0, 0.0);
    EXPECT_EQ(inf.z, 0.0);
    EXPECT_GT(inf.w, 0.0);
    // Closer than the near plane: depth > 1, clipped.
    EXPECT_GT(depth(p, {0, 0, -0.04}), 1.0);
    // Depth decreases with distance.
    EXPECT_GT(depth(p, {0, 0, -1.0}), depth(p, {0, 0, -1.001}));
}

TEST(Standard, NearIsMinusOneFarIsOne) {
    const Frustum f{60.0, 4.0 / 3.0, 0.1};
    const dmat4 p = perspective_standard(f, 100.0);
    EXPECT_NEAR(depth(p, {0, 0, -0.1}), -1.0, 4 * kEps);
    EXPECT_NEAR(depth(p, {1, 2, -100.0}), 1.0, 4 * kEps);
    EXPECT_LT(depth(p, {0, 0, -0.09}), -1.0);
    EXPECT_GT(depth(p, {0, 0, -101.0}), 1.0);
}

TEST(Projection, FrustumEdgesMapToNdcEdges) {
    const Frustum f{90.0, 2.0, 0.01};
    const double t = std::tan(radians(45.0));
    for (const dmat4& p : {perspective_reversed_z(f), perspective_standard(f, 50.0)}) {
        const dvec4 c = clip(p, {-t * 2.0 * 3.0, t * 3.0, -3.0});  // top-left corner direction
        EXPECT_NEAR(c.x / c.w, -1.0, 4 * kEps);
        EXPECT_NEAR(c.y / c.w, 1.0, 4 * kEps);
        EXPECT_EQ(c.w, 3.0);
    }
}

TEST(PixelRay, CentrePixelOfOddImageIsStraightAhead) {
    const Frustum f{90.0, 1.0, 0.01};
    EXPECT_EQ(pixel_ray_eye(f, 641, 361, 320, 180), dvec3(0, 0, -1));
    EXPECT_EQ(pixel_ray_eye(f, 1, 1, 0, 0), dvec3(0, 0, -1));
}

TEST(PixelRay, ImageCornersAtTanHalfFov) {
    const Frustum f{70.0, 0.0 /* unused by the rays */, 0.01};
    const int w = 320, h = 200;
    const double t = std::tan(radians(35.0));
    const double a = 320.0 / 200.0;
    using testing::near_vec;
    EXPECT_TRUE(near_vec(image_point_ray_eye(f, w, h, 0, 0), {-t * a, t, -1}, 4 * kEps));
    EXPECT_TRUE(near_vec(image_point_ray_eye(f, w, h, w, 0), {t * a, t, -1}, 4 * kEps));
    EXPECT_TRUE(near_vec(image_point_ray_eye(f, w, h, 0, h), {-t * a, -t, -1}, 4 * kEps));
    EXPECT_TRUE(near_vec(image_point_ray_eye(f, w, h, w, h), {t * a, -t, -1}, 4 * kEps));
    // Row 0 is the top row: its rays point up; column 0 is on the left.
    const dvec3 first = pixel_ray_eye(f, w, h, 0, 0);
    EXPECT_LT(first.x, 0.0);
    EXPECT_GT(first.y, 0.0);
    EXPECT_TRUE(near_vec(first, {-t * a * (1.0 - 1.0 / w), t * (1.0 - 1.0 / h), -1}, 4 * kEps));
}

TEST(PixelRay, ProjectsBackOntoThePixelCentre) {
    // The rasteriser and the rays agree: every sampled pixel's ray lands, through
    // both projections, at the NDC of that pixel's centre.
    const int w = 37, h = 23;
    const Frustum f{75.0, double(w) / h, 0.02};
    for (const dmat4& p : {perspective_reversed_z(f), perspective_standard(f, 10.0)}) {
        for (int j = 0; j < h; j += 5) {
            for (int i = 0; i < w; i += 4) {
                const dvec3 ray = pixel_ray_eye(f, w, h, i, j);
                const dvec4 c = clip(p, 2.5 * ray);
                const double px = (c.x / c.w + 1.0) * 0.5 * w;  // pixels from the left
                const double py = (1.0 - c.y / c.w) * 0.5 * h;  // pixels from the top
                EXPECT_NEAR(px, i + 0.5, 1e-12) << i << "," << j;
                EXPECT_NEAR(py, j + 0.5, 1e-12) << i << "," << j;
            }
        }
    }
}

}  // namespace
}  // namespace impossible::math
