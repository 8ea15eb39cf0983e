// The bounding-volume hierarchy's tree: every triangle once in a leaf that
// holds it, the same tree for the same input, small leaves where no plane
// separates the triangles; and a large model traces the same with and
// without the tree. The tree against the scan ray by ray: bvh_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "trace/bvh.hpp"
#include "trace/bvh_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::adversarial_soup;
using test::kInf;
using test::triangle;

TEST(Bvh, EveryTriangleOnceInLeavesThatHoldIt) {
    std::mt19937_64 rng(7);
    const std::vector<PropTriangle> soup = adversarial_soup(rng, dvec3(1.0, 2.0, 3.0), 2.0);
    const Bvh bvh = build_bvh(soup);
    std::vector<int> seen(soup.size(), 0);
    // Walk the tree: children inside their parent, leaves small and
    // holding their triangles' vertices.
    struct Visit {
        int node, depth;
    };
    std::vector<Visit> todo = {{0, 0}};
    while (!todo.empty()) {
        const Visit v = todo.back();
        todo.pop_back();
        const BvhNode& n = bvh.nodes[v.node];
        ASSERT_LE(v.depth, kBvhMaxDepth);
        if (n.count > 0) {
            EXPECT_TRUE(n.count <= kBvhLeafSize || v.depth == kBvhMaxDepth);
            for (int k = n.first; k < n.first + n.count; ++k) {
                const int index = bvh.order[k];
                ++seen[index];
                for (const dvec3& p : soup[index].position) {
                    EXPECT_TRUE(glm::all(glm::lessThan(n.lo, p)) && glm::all(glm::lessThan(p, n.hi)));
                }
            }
            continue;
        }
        for (int child : {v.node + 1, n.first}) {
            const BvhNode& c = bvh.nodes[child];
            EXPECT_TRUE(glm::all(glm::lessThanEqual(n.lo, c.lo)) && glm::all(glm::lessThanEqual(c.hi, n.hi)));
            todo.push_back({child, v.depth + 1});
        }
    }
    for (int index : bvh.slivers) ++seen[index];
    for (int count : seen) EXPECT_EQ(count, 1);
    // The slivers are the degenerate and needle triangles only (4 · 40 and
    // any duplicates of them: none are duplicated before they are added).
    EXPECT_EQ(bvh.slivers.size(), 160u);
}

TEST(Bvh, SameInputSameTree) {
    std::mt19937_64 rng(5);
    const std::vector<PropTriangle> soup = adversarial_soup(rng, dvec3(0.0), 1.0);
    const Bvh a = build_bvh(soup), b = build_bvh(soup);
    EXPECT_EQ(a.order, b.order);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        EXPECT_EQ(a.nodes[k].lo, b.nodes[k].lo);
        EXPECT_EQ(a.nodes[k].hi, b.nodes[k].hi);
        EXPECT_EQ(a.nodes[k].first, b.nodes[k].first);
        EXPECT_EQ(a.nodes[k].count, b.nodes[k].count);
    }
}

TEST(Bvh, AllCentresTheSameSplitsByPosition) {
    // 100 copies of one triangle: no plane separates them, yet leaves stay
    // small, and the first copy is the one hit.
    const std::vector<PropTriangle> soup(100, triangle({-1, 0, -1}, {0, 0, 1}, {1, 0, -1}));
    const Bvh bvh = build_bvh(soup);
    for (const BvhNode& n : bvh.nodes) EXPECT_LE(n.count, kBvhLeafSize);
    const TriangleHit hit = nearest_triangle(bvh, soup, {}, {0.1, 2.0, 0.1}, {0.0, -1.0, 0.0}, ClipPlane{}, kInf);
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.index, 0);
    EXPECT_EQ(hit.hit->t, 2.0);
}

TEST(Bvh, NoTrianglesNoTree) { EXPECT_TRUE(build_bvh({}).nodes.empty()); }

// A bumpy sphere of about `triangles` triangles (stacks × 2 stacks
// quads, one triangle at each pole's quads), radius about `radius`, with
// smooth vertex normals of the unbumped sphere.
std::vector<assets::ModelTriangle> bumpy_sphere(int triangles, double radius) {
    const int stacks = static_cast<int>(std::sqrt(triangles / 4.0));
    const int slices = 2 * stacks;
    const double pi = std::acos(-1.0);
    auto unit = [&](int i, int j) {
        const double theta = pi * i / stacks, phi = 2.0 * pi * j / slices;
        return dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
    };
    auto vertex = [&](int i, int j) {
        const dvec3 n = unit(i, j);
        return radius * (1.0 + 0.03 * std::sin(17.0 * n.x) * std::sin(13.0 * n.y + 11.0 * n.z)) * n;
    };
    std::vector<assets::ModelTriangle> out;
    auto add = [&](int i0, int j0, int i1, int j1, int i2, int j2) {
        assets::ModelTriangle t;
        t.position = {vertex(i0, j0), vertex(i1, j1), vertex(i2, j2)};
        t.normal = {unit(i0, j0), unit(i1, j1), unit(i2, j2)};
        t.color = dvec3(0.3 + 0.4 * (i0 % 2), 0.5, 0.2 + 0.5 * (j0 % 3 == 0));
        out.push_back(t);
    };
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            if (i > 0) add(i, j, i + 1, j, i, j + 1);  // outward: counter-clockwise seen from outside
            if (i + 1 < stacks) add(i, j + 1, i + 1, j, i + 1, j + 1);
        }
    }
    return out;
}

TEST(Bvh, LargeModelTracesTheSameWithAndWithoutTheTree) {
    // A room with a 50k-triangle model, a prop box in front of part of it
    // and a mirror behind it (whose reflected rays meet the model's back,
    // clipped by the mirror's plane). The scan without the tree is most of
    // the time: 200k triangles took 8 s, 50k take under 1 s.
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(test::make_room("room", {-3, 0, -4}, {3, 3, 3}));
    layout::GltfProp model;
    model.position = {0.0, 1.5, -2.0};
    model.yaw_deg = 20.0;
    model.triangles = bumpy_sphere(50'000, 1.0);
    ASSERT_GT(model.triangles.size(), 45'000u);
    l.rooms[0].props.push_back(model);
    layout::BoxProp box;
    box.min = {0.3, 0.0, -1.2};
    box.max = {0.8, 1.3, -0.9};
    l.rooms[0].props.push_back(box);
    l.portals.push_back(test::make_mirror("mirror", 0, {0.0, 1.5, -4.0}, {0.0, 0.0, 1.0}, 5.0, 2.6));
    l.start.room = 0;

    const Scene with = prepare_scene(l).value();
    Scene without = with;
    without.rooms[0].bvh = {};
    TraceDesc desc;
    desc.head.position = {0.2, 1.6, 1.5};
    desc.eye_width = 24;
    desc.eye_height = 14;
    test::expect_same_frames(with, without, desc);

    // And ray by ray, through the mirror: the same end point and colour.
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int k = 0; k < 100; ++k) {
        const dvec3 origin(0.2, 1.6, 1.5);
        const dvec3 target = dvec3(0.0, 1.5, -2.0) + 1.1 * glm::normalize(dvec3(g(rng), g(rng), g(rng)));
        const TraceHit p = trace_ray(with, origin, target - origin, 0, 8);
        const TraceHit q = trace_ray(without, origin, target - origin, 0, 8);
        EXPECT_EQ(p.point, q.point);
        EXPECT_EQ(p.color, q.color);
        EXPECT_EQ(p.portals_passed, q.portals_passed);
    }
}

}  // namespace
}  // namespace impossible::trace
