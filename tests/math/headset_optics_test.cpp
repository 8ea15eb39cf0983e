// Asymmetric frusta (headset optics, math::FovAngles) and the hidden-area
// mask's pixel rule (math/hidden_area.hpp).
#include <cmath>
#include <random>

#include "math/hidden_area.hpp"
#include "math/projection.hpp"
#include "math/view.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

glm::dvec2 ndc_of(const dmat4& p, const dvec3& eye_point) {
    const dvec4 c = p * dvec4(eye_point, 1.0);
    return {c.x / c.w, c.y / c.w};
}

// Symmetric angles whose tangents are those of a symmetric frustum.
Frustum symmetric_as_tangents(const Frustum& f) {
    const double t = std::tan(radians(0.5 * f.fov_y_deg));
    Frustum a = f;
    a.tangents = FovTangents{-t * f.aspect, t * f.aspect, t, -t};
    return a;
}

TEST(AsymmetricFrustum, SymmetricTangentsGiveTheSymmetricProjectionAndRays) {
    const Frustum f{75.0, 1.25, 0.02};
    const Frustum a = symmetric_as_tangents(f);
    const dmat4 ps = perspective_reversed_z(f), pa = perspective_reversed_z(a);
    const dmat4 ss = perspective_standard(f, 500.0), sa = perspective_standard(a, 500.0);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(ps[c][r], pa[c][r], 1e-12) << c << "," << r;
            EXPECT_NEAR(ss[c][r], sa[c][r], 1e-12) << c << "," << r;
        }
    for (int j : {0, 7, 39})
        for (int i : {0, 13, 49}) {
            const dvec3 rs = pixel_ray_eye(f, 50, 40, i, j), ra = pixel_ray_eye(a, 50, 40, i, j);
            EXPECT_NEAR(rs.x, ra.x, 1e-12);
            EXPECT_NEAR(rs.y, ra.y, 1e-12);
            EXPECT_EQ(ra.z, -1.0);
        }
}

TEST(AsymmetricFrustum, ImageEdgesAreTheAnglesTangents) {
    Frustum f;
    const FovAngles angles{-54.41, 46.75, 55.67, -55.91};
    f.tangents = fov_tangents(angles);
    const dvec3 top_left = image_point_ray_eye(f, 64, 48, 0.0, 0.0);
    const dvec3 bottom_right = image_point_ray_eye(f, 64, 48, 64.0, 48.0);
    EXPECT_NEAR(std::atan(top_left.x) * 180.0 / kPi, -54.41, 1e-12);
    EXPECT_NEAR(std::atan(top_left.y) * 180.0 / kPi, 55.67, 1e-12);
    EXPECT_NEAR(std::atan(bottom_right.x) * 180.0 / kPi, 46.75, 1e-12);
    EXPECT_NEAR(std::atan(bottom_right.y) * 180.0 / kPi, -55.91, 1e-12);
    // Each pixel's ray projects to its centre in NDC, both depth modes.
    f.near = 0.01;
    for (const dmat4& p : {perspective_reversed_z(f), perspective_standard(f, 100.0)})
        for (int j : {0, 5, 47})
            for (int i : {0, 31, 63}) {
                const glm::dvec2 ndc = ndc_of(p, 3.0 * pixel_ray_eye(f, 64, 48, i, j));
                EXPECT_NEAR(ndc.x, (2.0 * i + 1.0) / 64 - 1.0, 1e-12);
                EXPECT_NEAR(ndc.y, 1.0 - (2.0 * j + 1.0) / 48, 1e-12);
            }
}

TEST(AsymmetricFrustum, MirroredAnglesAndTheViewsFrusta) {
    const FovAngles left{-50, 40, 45, -48};
    const FovAngles right = mirrored(left);
    EXPECT_EQ(right, (FovAngles{-40, 50, 45, -48}));
    View v;
    v.eye_width = 30;
    v.eye_height = 20;
    EXPECT_FALSE(eye_frustum(v, 0).tangents.has_value());
    EXPECT_FALSE(has_hidden_area(v));
    v.eye_optics = std::array<EyeOptics, 2>{EyeOptics{left, {}}, EyeOptics{right, {}}};
    EXPECT_NEAR(eye_frustum(v, 1).tangents->right, std::tan(radians(50.0)), 1e-15);
    EXPECT_NEAR(eye_frustum(v, 0).tangents->left, std::tan(radians(-50.0)), 1e-15);
    EXPECT_FALSE(has_hidden_area(v));
    (*v.eye_optics)[1].visible_area = {{0, 0}, {1, 0}, {1, 1}};
    EXPECT_TRUE(has_hidden_area(v));
}

TEST(HiddenArea, EmptyPolygonHidesNothingAndTheFullImageHidesNothing) {
    EXPECT_FALSE(pixel_hidden({}, 10, 10, 3, 3));
    for (std::uint8_t h : hidden_pixels({}, 7, 5)) EXPECT_EQ(h, 0);
    const Polygon2 full{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (std::uint8_t h : hidden_pixels(full, 9, 6)) EXPECT_EQ(h, 0);
}

TEST(HiddenArea, PixelCentresOutsideTheVisibleAreaAreHidden) {
    // The left half of the image (u < 0.5): columns 0..4 of 10 visible.
    const Polygon2 left{{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}};
    for (int i = 0; i < 10; ++i) EXPECT_EQ(pixel_hidden(left, 10, 4, i, 2), i >= 5) << i;
    // A triangle: the top-right corner hidden (v < u, rows from the top).
    const Polygon2 lower{{0, 0}, {1, 1}, {0, 1}};
    EXPECT_TRUE(pixel_hidden(lower, 8, 8, 7, 0));
    EXPECT_FALSE(pixel_hidden(lower, 8, 8, 0, 7));
    EXPECT_FALSE(pixel_hidden(lower, 8, 8, 2, 5));
    EXPECT_TRUE(pixel_hidden(lower, 8, 8, 5, 2));
}

TEST(HiddenArea, TheRowRuleEqualsThePixelRuleOnRandomPolygons) {
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 40; ++n) {
        // A star-shaped polygon about a random centre (simple by construction).
        const glm::dvec2 c{unit(rng), unit(rng)};
        Polygon2 poly;
        const int corners = 3 + n % 20;
        for (int k = 0; k < corners; ++k) {
            const double a = 2.0 * kPi * k / corners;
            const double r = 0.1 + 0.6 * unit(rng);
            poly.push_back({std::clamp(c.x + r * std::cos(a), 0.0, 1.0), std::clamp(c.y + r * std::sin(a), 0.0, 1.0)});
        }
        const int w = 17 + n, h = 11 + 2 * n;
        const std::vector<std::uint8_t> rows = hidden_pixels(poly, w, h);
        int hidden = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const bool one = pixel_hidden(poly, w, h, i, j);
                ASSERT_EQ(rows[static_cast<size_t>(j * w + i)] != 0, one) << n << ": " << i << "," << j;
                hidden += one;
            }
        EXPECT_LT(hidden, w * h) << n;
    }
}

TEST(HiddenArea, ACircleHidesAboutItsComplement) {
    Polygon2 circle;
    for (int k = 0; k < 256; ++k)
        circle.push_back({0.5 + 0.5 * std::cos(2 * kPi * k / 256), 0.5 + 0.5 * std::sin(2 * kPi * k / 256)});
    int hidden = 0;
    for (std::uint8_t h : hidden_pixels(circle, 400, 400)) hidden += h;
    EXPECT_NEAR(hidden / 160000.0, 1.0 - kPi / 4.0, 0.002);
}

}  // namespace
}  // namespace impossible::math
