// Visibility masks in tangent space (math/visibility_mask.hpp): the map into
// the normalised image, clipping to the image, and the outline of a mask's
// visible triangles, whose pixels are the triangles' union.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>

#include "math/hidden_area.hpp"
#include "math/visibility_mask.hpp"
#include "math_test_util.hpp"

namespace impossible::math {
namespace {

TEST(VisibilityMask, TangentsMapToTheImageRowsFromTheTop) {
    const FovTangents t = fov_tangents({-50.0, 40.0, 45.0, -30.0});
    EXPECT_EQ(tangent_to_image(t, {t.left, t.up}), glm::dvec2(0.0, 0.0));
    EXPECT_EQ(tangent_to_image(t, {t.right, t.down}), glm::dvec2(1.0, 1.0));
    const glm::dvec2 axis = tangent_to_image(t, {0.0, 0.0});  // the view axis
    EXPECT_NEAR(axis.x, -t.left / (t.right - t.left), 1e-15);
    EXPECT_NEAR(axis.y, t.up / (t.up - t.down), 1e-15);
    EXPECT_LT(tangent_to_image(t, {0.0, 0.5}).y, axis.y);  // up is towards row 0
}

TEST(VisibilityMask, AnAreaInsideTheImageIsKeptBitForBit) {
    const Polygon2 inside{{0.1, 0.0}, {0.9, 0.0}, {1.0, 0.5}, {0.9, 1.0}, {0.1, 1.0}, {0.0, 0.5}};
    EXPECT_EQ(clip_to_image(inside), inside);
}

TEST(VisibilityMask, AnAreaPastTheImageIsClippedAndHidesTheSamePixels) {
    // A diamond about the centre reaching past all four edges.
    const Polygon2 diamond{{0.5, -0.2}, {1.2, 0.5}, {0.5, 1.2}, {-0.2, 0.5}};
    const Polygon2 clipped = clip_to_image(diamond);
    EXPECT_EQ(clipped.size(), 8u);
    for (const glm::dvec2& p : clipped) {
        EXPECT_GE(p.x, 0.0);
        EXPECT_LE(p.x, 1.0);
        EXPECT_GE(p.y, 0.0);
        EXPECT_LE(p.y, 1.0);
    }
    EXPECT_FALSE(simple_polygon_problem(clipped).has_value());
    EXPECT_NEAR(area(clipped), 1.0 - 4 * 0.5 * 0.3 * 0.3, 1e-12);
    // Every pixel centre lies inside the image, so the clipped area hides
    // exactly the pixels the whole diamond would.
    for (const auto& [w, h] : {std::pair{64, 48}, std::pair{101, 77}})
        EXPECT_EQ(hidden_pixels(clipped, w, h), hidden_pixels(diamond, w, h));
    EXPECT_TRUE(clip_to_image({{1.5, 0.0}, {2.0, 0.0}, {2.0, 1.0}}).empty());  // wholly outside
}

// A fan about `centre` through `ring` (counter-clockwise or not): one
// triangle per ring edge, each vertex written out again as a runtime may.
void fan(const Polygon2& ring, const glm::dvec2& centre, std::vector<glm::dvec2>& vertices,
         std::vector<std::uint32_t>& indices) {
    for (std::size_t k = 0; k < ring.size(); ++k)
        for (const glm::dvec2& p : {ring[k], ring[(k + 1) % ring.size()], centre}) {
            indices.push_back(static_cast<std::uint32_t>(vertices.size()));
            vertices.push_back(p);
        }
}

TEST(VisibilityMask, AFansOutlineIsItsRingAndItsPixelsTheTrianglesUnion) {
    Polygon2 ring;
    std::mt19937 rng(38);
    std::uniform_real_distribution<double> radius(0.3, 0.6);
    for (int k = 0; k < 27; ++k) {
        const double a = -0.1 * k * 2.0 * 3.141592653589793 / 2.7;  // clockwise
        ring.push_back({0.5 + radius(rng) * std::cos(a), 0.5 + radius(rng) * std::sin(a)});
    }
    std::vector<glm::dvec2> vertices;
    std::vector<std::uint32_t> indices;
    fan(ring, {0.45, 0.52}, vertices, indices);
    const MeshOutline m = triangles_outline(vertices, indices);
    ASSERT_FALSE(m.problem) << m.problem->message;
    ASSERT_EQ(m.outline.size(), ring.size());
    EXPECT_NEAR(area(m.outline), area(ring), 1e-12);
    for (const glm::dvec2& p : ring) EXPECT_NE(std::find(m.outline.begin(), m.outline.end(), p), m.outline.end());
    // A pixel is visible when its centre is in any triangle (each by the same rule).
    const int w = 90, h = 70;
    const std::vector<std::uint8_t> hidden = hidden_pixels(m.outline, w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            bool in_any = false;
            for (std::size_t t = 0; t < indices.size(); t += 3)
                in_any |= !pixel_hidden({vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]]}, w,
                                        h, i, j);
            EXPECT_EQ(hidden[static_cast<std::size_t>(j) * w + i], in_any ? 0 : 1) << i << "," << j;
        }
}

TEST(VisibilityMask, TwoTrianglesMakeASquareWhateverTheirWinding) {
    const std::vector<glm::dvec2> v{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const std::vector<std::uint32_t>& idx :
         {std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}, std::vector<std::uint32_t>{0, 2, 1, 0, 2, 3}}) {
        const MeshOutline m = triangles_outline(v, idx);
        ASSERT_FALSE(m.problem) << m.problem->message;
        EXPECT_EQ(m.outline.size(), 4u);
        EXPECT_DOUBLE_EQ(area(m.outline), 1.0);
    }
}

std::string problem_of(const std::vector<glm::dvec2>& v, const std::vector<std::uint32_t>& idx) {
    const MeshOutline m = triangles_outline(v, idx);
    return m.problem ? std::to_string(m.problem->triangle) + ": " + m.problem->message : "";
}

TEST(VisibilityMask, TrianglesThatAreNotOnePolygonAreRefused) {
    const std::vector<glm::dvec2> v{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {3, 0}, {3, 1}, {0.5, 0}};
    EXPECT_EQ(problem_of(v, {0, 1}), "0: the indices must be whole triangles, three each (got 2)");
    EXPECT_EQ(problem_of(v, {0, 1, 9}), "0: index 9 is past the 8 vertices");
    EXPECT_EQ(problem_of(v, {0, 1, 2, 0, 1, 4}), "1: the triangle is degenerate (its corners are collinear or repeat)");
    EXPECT_EQ(problem_of(v, {0, 1, 2, 0, 1, 3}),
              "1: the triangle overlaps triangle 0 (both lie on the same side of their shared edge)");
    EXPECT_NE(problem_of(v, {0, 1, 2, 4, 5, 6}).find("more than one loop"), std::string::npos);  // two pieces
    EXPECT_EQ(problem_of(v, {0, 7, 3, 7, 1, 2, 7, 2, 3}), "");  // a corner on the outline's edge is fine
    // A T-junction: the corner 3 on the edge 0-1 of a triangle below.
    const std::vector<glm::dvec2> t{{0, 0}, {1, 0}, {0.5, 1}, {0.5, 0}, {0.5, -1}};
    EXPECT_NE(problem_of(t, {0, 3, 2, 3, 1, 2, 0, 4, 1}), "");
    // A hole: a square ring of eight triangles.
    const std::vector<glm::dvec2> r{{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
    EXPECT_NE(problem_of(r, {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7})
                  .find("more than one loop"),
              std::string::npos);
}

}  // namespace
}  // namespace impossible::math
