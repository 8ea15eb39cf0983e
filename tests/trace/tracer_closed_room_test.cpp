// "A ray that starts inside a closed room always hits something": random
// closed rooms with doors in their walls (some a hair off the wall's plane,
// within the hole tolerance) and free-standing doors, far from the origin;
// random eyes and rays, many aimed at the edges of the holes and nudged by a
// few ulps. Id 0 may appear only where a clip plane leaves nothing, and the
// eyes here are all in front of every portal, so never.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::add_pair;
using test::make_portal;
using test::make_room;

dvec3 nudged(dvec3 p, std::mt19937_64& rng) {
    for (int c = 0; c < 3; ++c) {
        const int n = static_cast<int>(rng() % 9) - 4;
        for (int k = 0; k < std::abs(n); ++k) p[c] = std::nextafter(p[c], n > 0 ? 1e300 : -1e300);
    }
    return p;
}

TEST(TracerClosedRoom, EveryRayFromInsideHitsSomething) {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    long rays = 0, misses = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const dvec3 a(400.0 * (u(rng) - 0.5), 0.0, 400.0 * (u(rng) - 0.5));  // the cell's floor centre
        const dvec3 b(400.0 * (u(rng) - 0.5), 0.0, 400.0 * (u(rng) - 0.5));  // the far room's
        const double size = 0.01 + 0.2 * u(rng);
        const double off = (trial % 3 == 0 ? 0.0 : trial % 3 == 1 ? 5e-5 : -5e-5);  // off the wall's plane
        layout::Layout l;
        l.rooms.push_back(make_room("cell", a + dvec3(-1, 0, -1), a + dvec3(1, 2.5, 1)));
        l.rooms.push_back(make_room("far", b + dvec3(-3, 0, -3), b + dvec3(3, 3, 3)));
        const dvec3 hole = a + dvec3(0.3 * (u(rng) - 0.5), 1.5, -1.0 - off);
        add_pair(l, make_portal("hole", 0, hole, {0, 0, 1}, size, size),
                 make_portal("peer", 1, b + dvec3(0.5, 1.4, 3.0), {0, 0, -1}, size, size));
        add_pair(l, make_portal("free", 0, a + dvec3(0.5, 1.0, 0.5), {1, 0, 0}, 0.6, 1.8),
                 make_portal("free_back", 1, b + dvec3(-1.0, 1.0, 0.0), {0, 0, 1}, 0.6, 1.8));
        const Scene scene = prepare_scene(l).value();
        // Eyes in front of both of the cell's portals.
        const dvec3 eye = a + dvec3(-0.9 + 1.3 * u(rng), 0.2 + 2.1 * u(rng), -0.99 + 1.4 * u(rng));
        for (int k = 0; k < 3000; ++k) {
            dvec3 dir;
            if (k % 2 == 0) {  // anywhere
                dir = dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
            } else {  // at the hole's border, give or take a few ulps
                double s = size * (u(rng) - 0.5), t = (rng() % 2 ? 0.5 : -0.5) * size;
                if (rng() % 2) std::swap(s, t);
                dir = nudged(hole + dvec3(s, t, off), rng) - eye;
            }
            if (glm::length(dir) == 0.0) continue;
            const TraceHit hit = trace_ray(scene, eye, dir, 0, 8);
            ++rays;
            if (hit.id == kIdNothing) ++misses;
        }
    }
    EXPECT_EQ(misses, 0) << "of " << rays << " rays";
}

}  // namespace
}  // namespace impossible::trace
