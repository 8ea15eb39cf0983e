// The tracer's tree over a room's prop boxes against the linear scan: the
// same nearest box (index, t and normal, bit for bit) on random and
// adversarial boxes and rays, with and without a clip plane and a limit, and
// the same frames with and without the tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "trace/bvh.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::expect_same_nearest;
using test::kInf;

PropBox box(dvec3 lo, dvec3 hi) {
    PropBox b;
    b.min = lo;
    b.max = hi;
    return b;
}

// Random boxes of all sizes, a floor of touching unit-step boxes on exact
// binary coordinates (shared faces: rays down an axis meet several at one
// t), boxes nested in others, exact duplicates, thin slabs and a far-off
// cluster; shuffled, so that duplicates land in both orders.
std::vector<PropBox> adversarial_boxes(std::mt19937_64& rng, dvec3 offset, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0), v(0.0, 1.0);
    std::vector<PropBox> boxes;
    for (int k = 0; k < 150; ++k) {
        const dvec3 c = offset + scale * dvec3(u(rng), u(rng), u(rng));
        const dvec3 half = scale * (k % 2 ? 0.3 : 0.03) * dvec3(v(rng), v(rng), v(rng)) + dvec3(1e-6 * scale);
        boxes.push_back(box(c - half, c + half));
    }
    for (int i = -4; i < 4; ++i)
        for (int j = -4; j < 4; ++j)
            boxes.push_back(box(offset + scale * dvec3(0.25 * i, -1.0, 0.25 * j),
                                offset + scale * dvec3(0.25 * (i + 1), -0.75, 0.25 * (j + 1))));
    for (int k = 0; k < 20; ++k) {  // nested
        const PropBox& outer = boxes[rng() % 150];
        const dvec3 c = 0.5 * (outer.min + outer.max), half = 0.25 * (outer.max - outer.min);
        boxes.push_back(box(c - half, c + half));
    }
    for (int k = 0; k < 20; ++k) {  // thin slabs
        const dvec3 c = offset + scale * dvec3(u(rng), u(rng), u(rng));
        boxes.push_back(box(c - scale * dvec3(0.4, 1e-9, 0.4), c + scale * dvec3(0.4, 1e-9, 0.4)));
    }
    for (int k = 0; k < 10; ++k) {  // far off
        const dvec3 c = offset + scale * dvec3(1e3, 0.0, 0.0) + scale * dvec3(u(rng), u(rng), u(rng));
        boxes.push_back(box(c - dvec3(0.1 * scale), c + dvec3(0.1 * scale)));
    }
    const size_t before = boxes.size();
    for (int k = 0; k < 60; ++k) boxes.push_back(boxes[rng() % before]);  // duplicates
    std::shuffle(boxes.begin(), boxes.end(), rng);
    return boxes;
}

struct BoxTally {
    int rays = 0;
    int hits = 0;
    int ties = 0;  // rays whose nearest t is shared by two or more boxes
};

void expect_same(const std::vector<PropBox>& boxes, const Bvh& bvh, const dvec3& origin, const dvec3& dir,
                 const ClipPlane& clip, double t_limit, BoxTally& tally) {
    const BoxHit scan = nearest_box_scan(boxes, origin, dir, clip, t_limit);
    const BoxHit tree = nearest_box(bvh, boxes, origin, dir, clip, t_limit);
    expect_same_nearest(scan, tree, origin, dir, tally);
    if (::testing::Test::HasFatalFailure() || !scan.hit) return;
    int at_t = 0;
    for (const PropBox& b : boxes) {
        const std::optional<SurfaceHit> h = hit_prop_box(b, origin, dir, clip);
        if (h && h->t == scan.hit->t) ++at_t;
    }
    if (at_t > 1) ++tally.ties;
}

void check_boxes(std::mt19937_64& rng, dvec3 offset, double scale, BoxTally& tally) {
    const std::vector<PropBox> boxes = adversarial_boxes(rng, offset, scale);
    const Bvh bvh = build_box_bvh(boxes);
    ASSERT_FALSE(bvh.nodes.empty());
    ASSERT_TRUE(bvh.slivers.empty());
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    const ClipPlane none;
    for (int k = 0; k < 400; ++k) {
        const dvec3 o = offset + 2.0 * scale * dvec3(u(rng), u(rng), u(rng));
        expect_same(boxes, bvh, o, dvec3(g(rng), g(rng), g(rng)), none, kInf, tally);
        // At a corner, an edge's midpoint or a face's centre of some box.
        const PropBox& b = boxes[rng() % boxes.size()];
        const dvec3 corner(rng() % 2 ? b.min.x : b.max.x, rng() % 2 ? b.min.y : b.max.y, rng() % 2 ? b.min.z : b.max.z);
        const dvec3 centre = 0.5 * (b.min + b.max);
        const dvec3 target = k % 3 == 0 ? corner : k % 3 == 1 ? 0.5 * (corner + centre) : centre;
        expect_same(boxes, bvh, o, target - o, none, kInf, tally);
        // Straight down onto the floor of touching boxes from a grid point:
        // the shared edges and corners give exact ties.
        const dvec3 above =
            offset + scale * dvec3(0.125 * std::round(8.0 * u(rng)), 1.5, 0.125 * std::round(8.0 * u(rng)));
        expect_same(boxes, bvh, above, dvec3(0.0, -1.0, 0.0), none, kInf, tally);
        // From inside a box (a box seen from inside hides nothing).
        expect_same(boxes, bvh, centre, dvec3(g(rng), g(rng), g(rng)), none, kInf, tally);
        // A clip plane through the soup, and a finite limit.
        ClipPlane clip;
        clip.active = true;
        const dvec3 n = glm::normalize(dvec3(g(rng), g(rng), g(rng)));
        clip.plane = dvec4(n, -glm::dot(n, offset + 0.5 * scale * dvec3(u(rng), u(rng), u(rng))));
        clip.tolerance = 1e-9 * scale;
        expect_same(boxes, bvh, o, target - o, clip, kInf, tally);
        expect_same(boxes, bvh, o, target - o, none, glm::length(target - o) * (0.5 + 0.5 * u(rng)), tally);
    }
}

TEST(BoxBvh, NearestBoxIsTheScansOnAdversarialBoxes) {
    std::mt19937_64 rng(11);
    BoxTally tally;
    check_boxes(rng, dvec3(0.0), 1.0, tally);
    check_boxes(rng, dvec3(1e4, -3e3, 7e3), 2.0, tally);  // far from the origin
    check_boxes(rng, dvec3(0.0), 1e-3, tally);            // millimetre boxes
    EXPECT_EQ(tally.rays, 3 * 400 * 6);
    EXPECT_GT(tally.hits, tally.rays / 4);
    EXPECT_GT(tally.ties, 50);  // the floor's shared edges and the duplicates
}

TEST(BoxBvh, NoBoxesNoTree) {
    EXPECT_TRUE(build_box_bvh({}).nodes.empty());
    const BoxHit none = nearest_box(Bvh{}, {}, dvec3(0.0), dvec3(0.0, 0.0, -1.0), ClipPlane{}, kInf);
    EXPECT_FALSE(none.hit);
}

TEST(BoxBvh, ACrowdedRoomTracesTheSameWithAndWithoutTheTree) {
    // 900 boxes on the floor, a tower of boxes stacked face to face, and a
    // mirror (reflected rays are clipped by its plane).
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(test::make_room("room", {-3, 0, -4}, {3, 3, 3}));
    for (int i = 0; i < 30; ++i) {
        for (int j = 0; j < 30; ++j) {
            layout::BoxProp b;
            b.min = {-3.0 + 0.2 * i + 0.05, 0.0, -4.0 + 0.2 * j + 0.05};
            b.max = b.min + glm::dvec3(0.1, 0.05 + 0.01 * ((i * 7 + j) % 9), 0.1);
            b.color = {0.2 + 0.02 * (i % 30), 0.5, 0.2 + 0.02 * (j % 30)};
            l.rooms[0].props.push_back(b);
        }
    }
    for (int k = 0; k < 8; ++k) {
        layout::BoxProp b;
        b.min = {0.5, 0.25 * k, -1.0};
        b.max = {1.0, 0.25 * (k + 1), -0.5};
        b.color = {0.9, 0.1 * k, 0.1};
        l.rooms[0].props.push_back(b);
    }
    l.portals.push_back(test::make_mirror("mirror", 0, {0.0, 1.5, -4.0}, {0.0, 0.0, 1.0}, 5.0, 2.6));
    l.start.room = 0;

    const Scene with = prepare_scene(l).value();
    ASSERT_FALSE(with.rooms[0].box_bvh.nodes.empty());
    Scene without = with;
    without.rooms[0].box_bvh = {};
    TraceDesc desc;
    desc.head.position = {0.2, 1.6, 1.5};
    desc.head.pitch_deg = -25.0;
    desc.eye_width = 64;
    desc.eye_height = 36;
    const image::Image a = trace_frame(with, desc).value(), b = trace_frame(without, desc).value();
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.ids, b.ids);
}

}  // namespace
}  // namespace impossible::trace
