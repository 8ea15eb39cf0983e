// The bounding-volume hierarchy against the linear scan: the same nearest
// triangle (index, t and normal, bit for bit) on random and adversarial
// triangle soups and rays, with and without masked and double-sided
// materials. The tree's shape and whole frames: bvh_tree_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <vector>

#include "trace/bvh.hpp"
#include "trace/bvh_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::adversarial_soup;
using test::expect_same_nearest;
using test::kInf;
using test::triangle;

// Every point that a ray is aimed at: vertices, edge midpoints, centroids.
std::vector<dvec3> targets_of(const std::vector<PropTriangle>& soup) {
    std::vector<dvec3> targets;
    for (const PropTriangle& t : soup) {
        for (int k = 0; k < 3; ++k) {
            targets.push_back(t.position[k]);
            targets.push_back(0.5 * (t.position[k] + t.position[(k + 1) % 3]));
        }
        targets.push_back((t.position[0] + t.position[1] + t.position[2]) / 3.0);
    }
    return targets;
}

struct Tally {
    int rays = 0;
    int hits = 0;
    int ties = 0;   // rays whose nearest t is shared by two or more triangles
    int backs = 0;  // rays whose nearest hit is a triangle's back (double-sided)
};

// The scan and the tree on one ray: the same triangle, t and normal.
void expect_same(const std::vector<PropTriangle>& soup, std::span<const PropMaterial> materials, const Bvh& bvh,
                 const dvec3& origin, const dvec3& dir, const ClipPlane& clip, double t_limit, Tally& tally) {
    const TriangleHit scan = nearest_triangle_scan(soup, materials, origin, dir, clip, t_limit);
    const TriangleHit tree = nearest_triangle(bvh, soup, materials, origin, dir, clip, t_limit);
    expect_same_nearest(scan, tree, origin, dir, tally);
    if (::testing::Test::HasFatalFailure() || !scan.hit) return;
    ASSERT_EQ(scan.hit->barycentric, tree.hit->barycentric);
    const PropTriangle& hit = soup[scan.index];
    if (glm::dot(dir, glm::cross(hit.position[1] - hit.position[0], hit.position[2] - hit.position[0])) > 0.0) {
        ++tally.backs;
        EXPECT_GE(hit.material, 0);
        EXPECT_TRUE(materials[hit.material].double_sided);
        EXPECT_LT(glm::dot(dir, scan.hit->normal), 0.0);  // the normal reversed, towards the eye
    }
    int at_t = 0;
    for (const PropTriangle& t : soup) {
        const std::optional<SurfaceHit> h = hit_triangle(t, materials, origin, dir, clip);
        if (h && h->t == scan.hit->t) ++at_t;
    }
    if (at_t > 1) ++tally.ties;
}

void check_soup(const std::vector<PropTriangle>& soup, std::span<const PropMaterial> materials, std::mt19937_64& rng,
                dvec3 offset, double scale, Tally& tally) {
    const Bvh bvh = build_bvh(soup);
    ASSERT_FALSE(bvh.nodes.empty());
    const std::vector<dvec3> targets = targets_of(soup);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    auto origin_near = [&] { return offset + 2.0 * scale * dvec3(u(rng), u(rng), u(rng)); };
    const ClipPlane none;
    for (int k = 0; k < 400; ++k) {
        const dvec3 o = origin_near();
        // Random directions.
        expect_same(soup, materials, bvh, o, dvec3(g(rng), g(rng), g(rng)), none, kInf, tally);
        // At a vertex, an edge's midpoint or a centroid.
        const dvec3 target = targets[rng() % targets.size()];
        expect_same(soup, materials, bvh, o, target - o, none, kInf, tally);
        // Down an axis, from an origin on the grids' lines (exact t ties
        // at shared vertices and edges; origins on the boxes' planes).
        const int axis = static_cast<int>(rng() % 3);
        dvec3 on_grid = offset + scale * (0.25 * dvec3(std::round(4.0 * u(rng)), std::round(4.0 * u(rng)),
                                                       std::round(4.0 * u(rng))));
        on_grid[axis] = offset[axis] + 2.0 * scale;
        dvec3 down(0.0);
        down[axis] = -1.0;
        expect_same(soup, materials, bvh, on_grid, down, none, kInf, tally);
        // One or two zero components, or a subnormal one.
        dvec3 d(g(rng), g(rng), g(rng));
        d[rng() % 3] = 0.0;
        if (k % 3 == 0) d[rng() % 3] = 0.0;
        if (k % 5 == 0) d[rng() % 3] = 1e-310;
        if (d != dvec3(0.0)) expect_same(soup, materials, bvh, o, d, none, kInf, tally);
        // Grazing: almost in the plane y = 0, from just above it.
        const dvec3 graze_o = offset + scale * dvec3(u(rng), 1e-12 * (u(rng) + 1.0), u(rng));
        expect_same(soup, materials, bvh, graze_o, dvec3(g(rng), -1e-9 * std::abs(g(rng)), g(rng)), none, kInf, tally);
        // With a clip plane, and with t_limit: random, and exactly the
        // nearest t (a tie that t_limit wins: nothing is kept).
        ClipPlane clip;
        clip.active = true;
        const dvec3 n = glm::normalize(dvec3(g(rng), g(rng), g(rng)));
        clip.plane = dvec4(n, -glm::dot(n, origin_near()));
        clip.tolerance = 1e-9;
        expect_same(soup, materials, bvh, o, target - o, clip, kInf, tally);
        const TriangleHit first = nearest_triangle_scan(soup, materials, o, target - o, none, kInf);
        if (first.hit) {
            expect_same(soup, materials, bvh, o, target - o, none, first.hit->t, tally);
            expect_same(soup, materials, bvh, o, target - o, none, first.hit->t * (0.5 + 0.5 * (u(rng) + 1.0)), tally);
        }
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(Bvh, NearestTriangleIsTheScansOnAdversarialSoups) {
    std::mt19937_64 rng(13);
    Tally tally;
    const struct {
        dvec3 offset;
        double scale;
    } places[] = {{dvec3(0.0), 1.0},
                  {dvec3(3e4, -2e4, 5e4), 1.0},
                  {dvec3(0.25, 1.5, -0.5), 1e-3},
                  {dvec3(-7.0, 2.0, 3.0), 300.0}};
    for (const auto& place : places) {
        for (int round = 0; round < 2; ++round) {
            const std::vector<PropTriangle> soup = adversarial_soup(rng, place.offset, place.scale);
            check_soup(soup, {}, rng, place.offset, place.scale, tally);
            ASSERT_FALSE(HasFatalFailure());
        }
    }
    // The rays met triangles, and many met several at the same t.
    EXPECT_GT(tally.hits, tally.rays / 4);
    EXPECT_GT(tally.ties, 300);
    EXPECT_EQ(tally.backs, 0);
}

// Materials for a soup: double-sided; masked by a texture with holes
// (nearest, repeat); masked and double-sided (linear, mirrored); masked by
// COLOR_0's alpha alone; and a plain one.
std::vector<PropMaterial> soup_materials() {
    auto holes = std::make_shared<image::Pixels>();
    holes->width = 2;
    holes->height = 2;
    holes->data = {255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 0, 255, 255, 255, 255};
    std::vector<PropMaterial> m(5);
    m[0].double_sided = true;
    m[1].mask = true;
    m[1].texture.image = holes;
    m[1].texture.sampler.mag_filter = assets::sampler_code::kNearest;
    m[2] = m[1];
    m[2].double_sided = true;
    m[2].texture.sampler.mag_filter = assets::sampler_code::kLinear;
    m[2].texture.sampler.wrap_s = assets::sampler_code::kMirroredRepeat;
    m[2].alpha_cutoff = 0.3;
    m[3].mask = true;
    m[3].alpha = 0.9;
    return m;
}

// Gives most of the soup's triangles one of soup_materials() and random
// uv (from -1.5 to 2.5: every wrap) and COLOR_0 alphas.
void dress(std::vector<PropTriangle>& soup, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.5, 2.5), a(0.0, 1.0);
    for (PropTriangle& t : soup) {
        t.material = static_cast<int>(rng() % 6) - 1;  // -1 … 4
        for (int k = 0; k < 3; ++k) {
            t.uv[k] = glm::dvec2(u(rng), u(rng));
            t.vertex_color[k].a = a(rng);
        }
    }
}

TEST(Bvh, NearestTriangleIsTheScansWithMasksAndDoubleSidedTriangles) {
    std::mt19937_64 rng(29);
    Tally tally;
    const std::vector<PropMaterial> materials = soup_materials();
    const struct {
        dvec3 offset;
        double scale;
    } places[] = {{dvec3(0.0), 1.0}, {dvec3(3e4, -2e4, 5e4), 1.0}, {dvec3(-7.0, 2.0, 3.0), 300.0}};
    for (const auto& place : places) {
        std::vector<PropTriangle> soup = adversarial_soup(rng, place.offset, place.scale);
        dress(soup, rng);
        check_soup(soup, materials, rng, place.offset, place.scale, tally);
        ASSERT_FALSE(HasFatalFailure());
    }
    EXPECT_GT(tally.hits, tally.rays / 4);
    EXPECT_GT(tally.ties, 100);
    EXPECT_GT(tally.backs, 100);  // double-sided triangles were met from behind
}

TEST(Bvh, MaskAndDoubleSidedChangeWhatIsHit) {
    // Two squares facing +y, one above the other, each two triangles with uv
    // spanning [0, 1]²: the upper one masked by a 2 × 2 texture whose texels
    // (1, 0) and (0, 1) are clear. Looking down: the upper square where its
    // texel is opaque, the lower one through the holes. From below, the
    // lower square is seen only once it is double-sided.
    const std::vector<PropMaterial> materials = soup_materials();
    std::vector<PropTriangle> soup;
    for (double y : {1.0, 0.0}) {
        PropTriangle a = triangle({0, y, 0}, {0, y, 1}, {1, y, 1});
        a.uv = {glm::dvec2(0, 0), glm::dvec2(0, 1), glm::dvec2(1, 1)};
        PropTriangle b = triangle({0, y, 0}, {1, y, 1}, {1, y, 0});
        b.uv = {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(1, 0)};
        a.material = b.material = y > 0.5 ? 1 : -1;
        soup.push_back(a);
        soup.push_back(b);
    }
    // Only front faces are seen from above: (0, 1, 0) · dir < 0.
    const Bvh bvh = build_bvh(soup);
    auto down_at = [&](double x, double z) {
        const TriangleHit scan = nearest_triangle_scan(soup, materials, {x, 3.0, z}, {0, -1, 0}, ClipPlane{}, kInf);
        const TriangleHit tree = nearest_triangle(bvh, soup, materials, {x, 3.0, z}, {0, -1, 0}, ClipPlane{}, kInf);
        EXPECT_EQ(scan.index, tree.index);
        return scan.hit ? scan.hit->t : -1.0;
    };
    // s = x, t = z (the uv above): texel (0, 0) opaque, (1, 0) clear, (0, 1) clear, (1, 1) opaque.
    EXPECT_EQ(down_at(0.25, 0.25), 2.0);
    EXPECT_EQ(down_at(0.75, 0.25), 3.0);
    EXPECT_EQ(down_at(0.25, 0.75), 3.0);
    EXPECT_EQ(down_at(0.75, 0.8), 2.0);
    // From below: nothing, until the lower square is double-sided.
    auto up_at = [&](const std::vector<PropTriangle>& s) {
        return nearest_triangle_scan(s, materials, {0.7, -1.0, 0.2}, {0, 1, 0}, ClipPlane{}, kInf);
    };
    EXPECT_FALSE(up_at(soup).hit);
    std::vector<PropTriangle> two = soup;
    two[2].material = two[3].material = 0;
    const TriangleHit below = up_at(two);
    ASSERT_TRUE(below.hit);
    EXPECT_EQ(below.hit->t, 1.0);
    EXPECT_EQ(below.hit->normal, dvec3(0, -1, 0));  // reversed, towards the eye
}

}  // namespace
}  // namespace impossible::trace
