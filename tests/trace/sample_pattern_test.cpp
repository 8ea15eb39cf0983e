// The tracer's supersampling (trace --samples N): the sample pattern itself,
// and that a supersampled pixel is the resolve-style mean of its samples'
// bytes with the centre ray's id. No GL context needed.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "layout/layout.hpp"
#include "math/projection.hpp"
#include "trace/sample_pattern.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::load_default;

TEST(SamplePattern, StandardCountsOnly) {
    for (int n : {1, 2, 4, 8, 16}) EXPECT_EQ(sample_pattern(n).size(), static_cast<size_t>(n)) << n;
    for (int n : {0, 3, 5, 6, 12, 32, -4}) EXPECT_TRUE(sample_pattern(n).empty()) << n;
}

TEST(SamplePattern, OneSampleIsThePixelCentre) {
    ASSERT_EQ(sample_pattern(1).size(), 1u);
    EXPECT_EQ(sample_pattern(1)[0].x, 0.5);
    EXPECT_EQ(sample_pattern(1)[0].y, 0.5);
}

// Every position inside the pixel, on the 1/16 grid, and (as in every
// standard pattern) no two samples share a column or a row.
TEST(SamplePattern, PositionsAreOnTheGridWithDistinctRowsAndColumns) {
    for (int n : {2, 4, 8, 16}) {
        std::set<double> xs, ys;
        for (const SamplePosition& s : sample_pattern(n)) {
            EXPECT_GE(s.x, 0.0);
            EXPECT_LT(s.x, 1.0);
            EXPECT_GE(s.y, 0.0);
            EXPECT_LT(s.y, 1.0);
            EXPECT_EQ(s.x * 16.0, std::floor(s.x * 16.0));
            EXPECT_EQ(s.y * 16.0, std::floor(s.y * 16.0));
            xs.insert(s.x);
            ys.insert(s.y);
        }
        EXPECT_EQ(xs.size(), static_cast<size_t>(n)) << n;
        EXPECT_EQ(ys.size(), static_cast<size_t>(n)) << n;
    }
}

// What llvmpipe reports through glGetMultisamplefv(GL_SAMPLE_POSITION) for
// its only count, 4 (checked against the driver in tests/gl/multisample_test.cpp).
TEST(SamplePattern, FourSamplesAreTheRotatedGrid) {
    const std::span<const SamplePosition> p = sample_pattern(4);
    const double expected[4][2] = {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}};
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(p[k].x, expected[k][0]) << k;
        EXPECT_EQ(p[k].y, expected[k][1]) << k;
    }
}

TraceDesc start_view(const layout::Layout& l, int samples) {
    TraceDesc desc;
    desc.head.position = l.start.position;
    desc.head.yaw_deg = l.start.yaw_deg;
    desc.head.roll_deg = 7.0;  // edges not aligned with the pixel grid
    desc.room = l.start.room;
    desc.eye_width = 48;
    desc.eye_height = 30;
    desc.samples = samples;
    return desc;
}

// A pixel traced by hand: one ray per sample at (i + x, j + 1 - y) of the
// image (rows from the top), bytes averaged and rounded half up.
std::array<int, 3> by_hand(const Scene& scene, const TraceDesc& desc, int eye, int i, int j) {
    math::Frustum frustum;
    frustum.fov_y_deg = desc.fov_y_deg;
    const math::Eye e = math::eyes_of(desc.head, desc.ipd)[eye];
    std::array<int, 3> sum{0, 0, 0};
    for (const SamplePosition& s : sample_pattern(desc.samples)) {
        const dvec3 d = math::image_point_ray_eye(frustum, desc.eye_width, desc.eye_height, i + s.x, j + 1.0 - s.y);
        const TraceHit hit = trace_ray(scene, e.position, glm::normalize(e.rotation * d), desc.room, desc.max_depth);
        for (int c = 0; c < 3; ++c) sum[c] += to_byte(hit.color[c]);
    }
    const int n = desc.samples;
    for (int& v : sum) v = (2 * v + n) / (2 * n);
    return sum;
}

TEST(TracerSupersampling, PixelsAreTheMeanOfTheirSamplesAndIdsTheCentreRays) {
    const layout::Layout l = load_default();
    const Scene scene = prepare_scene(l).value();
    const image::Image one = trace_frame(scene, start_view(l, 1)).value();
    for (int n : {2, 4, 8, 16}) {
        const TraceDesc desc = start_view(l, n);
        const image::Image many = trace_frame(scene, desc).value();
        EXPECT_EQ(many.ids, one.ids) << n;
        int edges = 0, checked = 0;
        for (int j = 0; j < desc.eye_height; j += 3)
            for (int x = 0; x < many.width; x += 2) {
                const int eye = x / desc.eye_width, i = x % desc.eye_width;
                const std::array<int, 3> expected = by_hand(scene, desc, eye, i, j);
                const size_t at = 3 * (static_cast<size_t>(j) * many.width + x);
                for (int c = 0; c < 3; ++c) EXPECT_EQ(many.rgb[at + c], expected[c]) << n << " " << x << "," << j;
                ++checked;
                edges += x + 1 < many.width && one.ids[at / 3] != one.ids[at / 3 + 1];
            }
        EXPECT_GT(checked, 100);
        EXPECT_GT(edges, 0) << "the checked pixels should include the door's edge";
    }
}

TEST(TracerSupersampling, ACountWithoutAPatternIsRefused) {
    const layout::Layout l = load_default();
    EXPECT_EQ(trace_frame(l, start_view(l, 3)).error(), "trace: no sample pattern for 3 samples");
}

}  // namespace
}  // namespace impossible::trace
