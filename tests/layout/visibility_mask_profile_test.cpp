// A headset profile's visibility mask (docs/headsets.md, "Visibility
// masks"): OpenXR's line loop or visible triangles in each eye's tangent
// space become the visible area in the normalised image, clipped to it; a
// visible_area reaching past the image is clipped too.
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "layout/hmd_profile.hpp"
#include "layout_test_util.hpp"
#include "math/hidden_area.hpp"
#include "math/polygon.hpp"

namespace layout_test {
namespace {

using impossible::Result;
namespace math = impossible::math;

// A profile whose left eye has `left_area` (a field and its value), the
// right eye none. Angles ±45° horizontally, +45 / -45 vertically: tangents ±1.
std::string profile(const std::string& left_area) {
    return R"({"name": "t", "source": "made up",
  "left": {"fov": {"left": -45, "right": 45, "up": 45, "down": -45}, "resolution": [40, 40],
    )" + left_area +
           R"(},
  "right": {"fov": {"left": -45, "right": 45, "up": 45, "down": -45}, "resolution": [40, 40]}
})";
}

Result<HmdProfile> parse(const std::string& left_area) { return parse_hmd_profile(profile(left_area), "hmd.json"); }

void expect_near(const math::Polygon2& got, const math::Polygon2& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_NEAR(got[k].x, want[k].x, 1e-12) << k;
        EXPECT_NEAR(got[k].y, want[k].y, 1e-12) << k;
    }
}

TEST(VisibilityMaskProfile, ALineLoopInTangentSpaceBecomesTheVisibleArea) {
    // Tangents ±1 span the image: x -0.5 is u 0.25, y 0.5 (up) is v 0.25.
    const Result<HmdProfile> p =
        parse(R"("visibility_mask": {"line_loop": [[-0.5, 0.5], [0.5, 0.5], [0.5, -0.5], [-0.5, -0.5]]})");
    ASSERT_TRUE(p) << p.error();
    expect_near(p->eyes[0].visible_area, {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}});
    EXPECT_TRUE(p->eyes[1].visible_area.empty());
}

TEST(VisibilityMaskProfile, ALineLoopPastTheImageIsClippedToIt) {
    // A diamond reaching 0.2 (tangent) past each edge: the part inside.
    const Result<HmdProfile> p =
        parse(R"("visibility_mask": {"line_loop": [[0, 1.4], [1.4, 0], [0, -1.4], [-1.4, 0]]})");
    ASSERT_TRUE(p) << p.error();
    const math::Polygon2& area = p->eyes[0].visible_area;
    EXPECT_EQ(area.size(), 8u);
    EXPECT_NEAR(math::area(area), 1.0 - 4 * 0.5 * 0.3 * 0.3, 1e-12);
    for (const glm::dvec2& c : area) {
        EXPECT_TRUE(c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1) << c.x << "," << c.y;
    }
}

TEST(VisibilityMaskProfile, VisibleTrianglesBecomeTheirOutline) {
    // Two triangles (a square, u and v 0.25..0.75), and a fan about the axis
    // whose corners repeat as a runtime's vertex buffer may.
    const Result<HmdProfile> square =
        parse(R"("visibility_mask": {"vertices": [[-0.5, 0.5], [0.5, 0.5], [0.5, -0.5], [-0.5, -0.5]],
                                     "indices": [0, 1, 2, 0, 2, 3]})");
    ASSERT_TRUE(square) << square.error();
    EXPECT_NEAR(math::area(square->eyes[0].visible_area), 0.25, 1e-12);
    const Result<HmdProfile> fan = parse(R"("visibility_mask": {"vertices": [[0, 0], [-0.5, 0.5], [0.5, 0.5],
        [0, 0], [0.5, 0.5], [0.5, -0.5], [0, 0], [0.5, -0.5], [-0.5, -0.5], [0, 0], [-0.5, -0.5], [-0.5, 0.5]],
        "indices": [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]})");
    ASSERT_TRUE(fan) << fan.error();
    EXPECT_EQ(fan->eyes[0].visible_area.size(), 4u);
    EXPECT_EQ(math::hidden_pixels(fan->eyes[0].visible_area, 40, 40),
              math::hidden_pixels(square->eyes[0].visible_area, 40, 40));
}

TEST(VisibilityMaskProfile, AVisibleAreaPastTheImageIsClipped) {
    // Refused before ("must be in 0..1"): now the part inside the image.
    const Result<HmdProfile> p = parse(R"("visible_area": [[-0.03, 0.5], [0.5, -0.1], [1.2, 0.5], [0.5, 1]])");
    ASSERT_TRUE(p) << p.error();
    for (const glm::dvec2& c : p->eyes[0].visible_area) {
        EXPECT_TRUE(c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1) << c.x << "," << c.y;
    }
    // One inside the image is kept as given.
    const Result<HmdProfile> q = parse(R"("visible_area": [[0.1, 0.5], [0.5, 0], [1, 0.5], [0.5, 1]])");
    ASSERT_TRUE(q) << q.error();
    EXPECT_EQ(q->eyes[0].visible_area, (math::Polygon2{{0.1, 0.5}, {0.5, 0}, {1, 0.5}, {0.5, 1}}));
}

// The Valve Index's own masks (profiles/valve-index*.json, docs/headsets.md):
// the line loop reaches past the image and is clipped; the triangles hide
// the published 24.88 % of each eye's area, at pixel centres too.
TEST(VisibilityMaskProfile, TheIndexsMasksHideItsPublishedShare) {
    const struct {
        const char* file;
        double left, right;  // hidden share at 1440x1600, counted when this test was written
    } profiles[] = {{"valve-index.json", 0.2503, 0.2515}, {"valve-index-mesh.json", 0.2489, 0.2489}};
    for (const auto& p : profiles) {
        const Result<HmdProfile> profile =
            read_hmd_profile_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/profiles/" + p.file);
        ASSERT_TRUE(profile) << profile.error();
        ASSERT_EQ(profile->eye_width, 1440);
        ASSERT_EQ(profile->eye_height, 1600);
        for (int e = 0; e < 2; ++e) {
            const math::Polygon2& area = profile->eyes[static_cast<size_t>(e)].visible_area;
            for (const glm::dvec2& c : area) ASSERT_TRUE(c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1);
            long hidden = 0;
            for (std::uint8_t h : math::hidden_pixels(area, 1440, 1600)) hidden += h;
            const double share = static_cast<double>(hidden) / (1440.0 * 1600.0);
            std::printf("  %s %s eye: %zu corners, hidden %.4f %%\n", p.file, e == 0 ? "left" : "right", area.size(),
                        100.0 * share);
            EXPECT_NEAR(share, e == 0 ? p.left : p.right, 0.0002) << p.file << " " << e;
        }
    }
}

TEST(VisibilityMaskProfile, BadMasksAreRefusedWithTheirPlace) {
    const std::pair<std::string, std::string> cases[] = {
        {R"("visibility_mask": {"line_loop": [[0, 1e999], [1, 0], [0, 0]]})", "number overflow parsing '1e999'"},
        {R"("visibility_mask": {"line_loop": [[0, 1], [1, 0]]})",
         "left.visibility_mask.line_loop: a polygon needs at least 3 corners"},
        {R"("visibility_mask": {"line_loop": [[0, 0], [1, 1], [1, 0], [0, 1]]})",
         "left.visibility_mask.line_loop[2]: the line loop must be a simple polygon: edge 2 crosses edge 0"},
        {R"("visibility_mask": {"line_loop": [[2, 2], [3, 2], [3, 3]]})",
         "left.visibility_mask: no part of the visible area lies inside the image"},
        {R"("visibility_mask": {"line_loop": [[0, 0], [1, 1]], "indices": [0, 1, 2]})",
         "left.visibility_mask: give either line_loop or vertices and indices, not both"},
        {R"("visibility_mask": {})", "left.visibility_mask: expected line_loop, or vertices and indices"},
        {R"("visibility_mask": {"vertices": [[0, 0], [1, 0], [1, 1]]})", "left.visibility_mask: missing"},
        {R"("visibility_mask": {"vertices": [[0, 0], [1, 0], [2, 0]], "indices": [0, 1, 2]})",
         "left.visibility_mask.indices[0]: triangle 0: the triangle is degenerate"},
        {R"("visibility_mask": {"vertices": [[0, 0], [1, 0], [1, 1]], "indices": [0, 1, 2, 0]})",
         "left.visibility_mask.indices: expected whole triangles, three indices each (got 4)"},
        {R"("visibility_mask": {"vertices": [[0, 0], [1, 0], [1, 1]], "indices": [0, 1, -2]})",
         "left.visibility_mask.indices[2]: expected an index into vertices"},
        {R"("visibility_mask": {"vertices": [[0, 0], [0.5, 0], [0.5, 0.5], [0.6, 0], [0.9, 0], [0.9, 0.5]],
                                "indices": [0, 1, 2, 3, 4, 5]})",
         "more than one loop"},
        {R"("visible_area": [[0, 0], [1, 0], [1, 1]], "visibility_mask": {"line_loop": [[0, 0], [1, 0], [1, 1]]})",
         "left.visibility_mask: give either visible_area or visibility_mask, not both"},
        {R"("visible_area": [[1.5, 0], [2, 0], [2, 1]])", "left.visible_area: no part of the visible area lies inside"},
        // Two tongues reaching in from outside: two pieces inside the image.
        {R"("visible_area": [[0.2, -0.5], [0.3, 0.5], [0.4, -0.5], [0.6, -0.5], [0.7, 0.5], [0.8, -0.5], [0.9, -1]])",
         "left.visible_area: the visible area's part inside the image is not one simple polygon"},
    };
    for (const auto& [area, words] : cases) {
        const Result<HmdProfile> p = parse(area);
        ASSERT_FALSE(p) << area;
        EXPECT_NE(p.error().find(words), std::string::npos) << p.error() << "\nwanted: " << words;
        EXPECT_EQ(p.error().rfind("hmd.json:", 0), 0u) << p.error();
    }
}

}  // namespace
}  // namespace layout_test
