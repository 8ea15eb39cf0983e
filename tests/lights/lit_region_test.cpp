// lights::lit_region: every point a light image's path reaches lies in its
// truncated pyramid (checked against lights::segment_passes, the exact CPU
// test, on random points of random chains of rooms with mirrors, windows
// and doors turned every way); an image whose light would have to pass its
// first aperture from behind reaches nothing; a room's own lights may reach
// all of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "common/segment_box.hpp"
#include "lights/lights_test_layouts.hpp"
#include "lights/lit_region.hpp"

namespace impossible::lights {
namespace {

using namespace testing;
using glm::dvec3;

// Whether p lies in the convex hull of the region's corners (near rectangle
// 0..3, far one 4..7), within a relative tolerance: inside each face plane,
// each plane oriented by the hull's centroid.
bool in_hull(const std::array<dvec3, 8>& c, const dvec3& p) {
    static constexpr int kFaces[6][3] = {{0, 1, 2}, {4, 5, 6}, {0, 1, 5}, {1, 2, 6}, {2, 3, 7}, {3, 0, 4}};
    dvec3 centre(0.0);
    for (const dvec3& v : c) centre += v / 8.0;
    for (const auto& f : kFaces) {
        const dvec3 a = c[f[0]], b = c[f[1]], d = c[f[2]];
        dvec3 n = glm::normalize(glm::cross(b - a, d - a));
        if (glm::dot(n, centre - a) > 0.0) n = -n;  // outward
        if (glm::dot(n, p - a) > 1e-9 * (1.0 + glm::length(p - a))) return false;
    }
    return true;
}

TEST(LitRegion, EveryPointAPathReachesLiesInItsPyramid) {
    std::mt19937_64 rng(39);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int pyramids = 0, nowhere = 0, reached = 0;
    for (int chain = 0; chain < 24; ++chain) {
        const layout::Layout l = random_chain(rng, chain % 2 == 1);
        const std::vector<RoomLights> rooms = light_images(l, links::link_portals(l), 2);
        for (size_t c = 0; c < rooms.size(); ++c) {
            const layout::Room& room = l.rooms[c];
            for (const LightImage& image : rooms[c].images) {
                const LitRegion region = lit_region(image, room.min, room.max);
                if (image.apertures.empty()) {
                    EXPECT_EQ(region.kind, LitRegion::Kind::Everywhere);
                    continue;
                }
                pyramids += region.kind == LitRegion::Kind::Pyramid;
                nowhere += region.kind == LitRegion::Kind::Nowhere;
                for (int k = 0; k < 400; ++k) {
                    const dvec3 p = room.min + dvec3(unit(rng), unit(rng), unit(rng)) * (room.max - room.min);
                    if (!segment_passes(image, p)) continue;
                    ++reached;
                    ASSERT_NE(region.kind, LitRegion::Kind::Nowhere) << "chain " << chain << ", room " << c;
                    if (region.kind == LitRegion::Kind::Pyramid) {
                        EXPECT_TRUE(in_hull(region.corners, p)) << "chain " << chain << ", room " << c;
                    }
                }
            }
        }
    }
    // The check meant something: pyramids, and points their light reaches.
    EXPECT_GT(pyramids, 50);
    EXPECT_GT(reached, 1000);
    RecordProperty("nowhere", nowhere);
}

TEST(LitRegion, ThePyramidStartsAtTheFirstApertureAndReachesPastTheRoom) {
    layout::Layout l = doorway();
    add_light(l, 1, {4.5, 2.0, 0.5});
    const std::vector<RoomLights> rooms = light_images(l, links::link_portals(l), 1);
    ASSERT_EQ(rooms[0].images.size(), 1u);
    const LightImage& image = rooms[0].images[0];
    const LitRegion region = lit_region(image, l.rooms[0].min, l.rooms[0].max);
    ASSERT_EQ(region.kind, LitRegion::Kind::Pyramid);
    // The near rectangle is the door's (x = 2); the far one lies beyond the
    // hall's far wall (x = -2), on rays from the lamp through the door.
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(region.corners[static_cast<size_t>(k)].x, 2.0, 1e-12);
        EXPECT_LT(region.corners[static_cast<size_t>(k) + 4].x, -2.0);
        const dvec3 a = glm::normalize(region.corners[static_cast<size_t>(k)] - image.position);
        const dvec3 b = glm::normalize(region.corners[static_cast<size_t>(k) + 4] - image.position);
        EXPECT_NEAR(glm::dot(a, b), 1.0, 1e-12);
    }
    // The hall's floor under the door is lit; its corner behind the wall
    // beside the door is not, and lies outside the pyramid.
    EXPECT_TRUE(segment_passes(image, {1.0, 0.0, 0.2}));
    EXPECT_TRUE(in_hull(region.corners, {1.0, 0.0, 0.2}));
    EXPECT_FALSE(in_hull(region.corners, {1.9, 2.9, 1.9}));
}

TEST(LitRegion, ALightInFrontOfItsFirstApertureReachesNothing) {
    // The image of a lamp that stands in front of the door it would have to
    // pass: no segment from the room passes the door from its front.
    layout::Layout l = doorway();
    add_light(l, 1, {4.5, 2.0, 0.5});
    std::vector<RoomLights> rooms = light_images(l, links::link_portals(l), 1);
    ASSERT_EQ(rooms[0].images.size(), 1u);
    LightImage image = rooms[0].images[0];
    image.position = {1.0, 2.0, 0.3};  // on the hall's side of the door
    EXPECT_EQ(lit_region(image, l.rooms[0].min, l.rooms[0].max).kind, LitRegion::Kind::Nowhere);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
        const dvec3 p = l.rooms[0].min + dvec3(unit(rng), unit(rng), unit(rng)) * (l.rooms[0].max - l.rooms[0].min);
        ASSERT_FALSE(segment_passes(image, p));
    }
    // In its plane: as wide as the room.
    image.position = {2.0, 2.0, 0.3};
    EXPECT_EQ(lit_region(image, l.rooms[0].min, l.rooms[0].max).kind, LitRegion::Kind::Everywhere);
}

bool in_hull16(const std::array<dvec3, 16>& c, const dvec3& p) {
    // The hull of a box and the same box scaled about L' (t >= 1) is the
    // union of the boxes scaled by every t between: p is in it when p lies
    // in the box scaled by some t in [1, t_max] (checked on a fine grid of t
    // and with a margin, in the box's own coordinates).
    const dvec3 lo = glm::min(c[0], c[7]), hi = glm::max(c[0], c[7]);
    const dvec3 flo = glm::min(c[8], c[15]), fhi = glm::max(c[8], c[15]);
    for (int k = 0; k <= 4000; ++k) {
        const double s = k / 4000.0;
        const dvec3 a = glm::mix(lo, flo, s), b = glm::mix(hi, fhi, s);
        const dvec3 m = 1e-9 + 2e-3 * (b - a);
        if (glm::all(glm::greaterThanEqual(p, a - m)) && glm::all(glm::lessThanEqual(p, b + m))) return true;
    }
    return false;
}

TEST(ShadowRegion, EveryPointABoxShadowsLiesInItsHull) {
    // Axis-aligned boxes (so the hull is easy to test from outside), lights
    // at random places around them, points in a 10 m cube: every point whose
    // segment to the light meets the box lies in the hull.
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int shadowed = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const dvec3 lo(unit(rng) * 2 - 1, unit(rng), unit(rng) * 2 - 1);
        const dvec3 hi = lo + dvec3(0.2 + unit(rng), 0.2 + unit(rng), 0.2 + unit(rng));
        dvec3 light;
        do {
            light = dvec3(unit(rng) * 8 - 4, unit(rng) * 4, unit(rng) * 8 - 4);
        } while (glm::all(glm::greaterThan(light, lo - 0.05)) && glm::all(glm::lessThan(light, hi + 0.05)));
        std::array<dvec3, 16> hull;
        ASSERT_TRUE(shadow_region(light, glm::dmat4(1.0), lo, hi, 20.0, 0.0, hull));
        for (int k = 0; k < 2000; ++k) {
            const dvec3 p(unit(rng) * 10 - 5, unit(rng) * 10 - 5, unit(rng) * 10 - 5);
            if (!impossible::testing::segment_meets_box(light, p, lo, hi)) continue;
            ++shadowed;
            ASSERT_TRUE(in_hull16(hull, p)) << "trial " << trial;
        }
    }
    EXPECT_GT(shadowed, 2000);
    // A light inside the box: its shadow may be anywhere.
    std::array<dvec3, 16> hull;
    EXPECT_FALSE(shadow_region(dvec3(0.5), glm::dmat4(1.0), dvec3(0.0), dvec3(1.0), 20.0, 0.0, hull));
}

}  // namespace
}  // namespace impossible::lights
