// The light images against the tracer, the oracle (layout-format.md,
// "Lights": "The aperture test ... is exact"): at random points of every
// room, the sum of the contributions of the images whose segment passes
// (segment_passes, the lit shader's test) equals trace::light_sum, which
// follows shadow rays through the rooms on its own.
#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "layout/room_shape.hpp"
#include "lights/light_bound.hpp"
#include "lights/light_images.hpp"
#include "lights/lights_test_layouts.hpp"
#include "shading/lighting.hpp"
#include "trace/light_paths.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::lights {
namespace {

using namespace testing;
using glm::dvec3;

// Σ contribution over the images that light p, as the lit shader sums them.
dvec3 image_sum(const layout::Layout& l, const RoomLights& room, const dvec3& p, const dvec3& n) {
    dvec3 sum(0.0);
    for (const LightImage& image : room.images) {
        if (!segment_passes(image, p)) continue;
        // The spot's axis as the image carries it, in C's coordinates.
        layout::Light light =
            l.rooms[static_cast<std::size_t>(image.light_room)].lights[static_cast<std::size_t>(image.light)];
        if (light.spot) light.spot->direction = image.spot_direction;
        const dvec3 to = image.position - p;
        const double d = glm::length(to);
        sum += shading::light_contribution(light, image.factor, n, to / d, d, to / d);
    }
    return sum;
}

// Returns how many points had some light from a path of at least one portal.
int expect_agreement(const layout::Layout& l, int depth, std::mt19937_64& rng, int points) {
    const auto scene = trace::prepare_scene(l);
    EXPECT_TRUE(scene.has_value());
    if (!scene) return 0;
    // Both cut as the programs cut them (light_bound.hpp): the tracer's
    // scene keeps the lights that light frames, the images are theirs.
    const links::PortalLinks links = links::link_portals(l);
    const layout::Layout lit = with_lit_lights(l, light_bound(l, links));
    const auto rooms = light_images(lit, links, depth);
    int lit_through = 0;
    std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
    for (std::size_t c = 0; c < l.rooms.size(); ++c) {
        const layout::Room& room = l.rooms[c];
        for (int i = 0; i < points; ++i) {
            const dvec3 p = room.min + (room.max - room.min) * dvec3(0.005 + 0.99 * unit(rng), 0.005 + 0.99 * unit(rng),
                                                                     0.005 + 0.99 * unit(rng));
            const dvec3 n = glm::normalize(dvec3(sym(rng), sym(rng), sym(rng)));
            if (!layout::room_contains(room, p)) continue;  // in a prism's bounding box, outside its floor
            const dvec3 mine = image_sum(lit, rooms[c], p, n);
            const dvec3 oracle = trace::light_sum(*scene, nullptr, trace::LitPoint{static_cast<int>(c), p, n}, depth);
            const double scale = 1e-12 + glm::length(mine) + glm::length(oracle);
            EXPECT_LT(glm::length(mine - oracle) / scale, 1e-9)
                << l.name << " room " << c << " p " << p.x << " " << p.y << " " << p.z << " mine " << mine.x
                << " oracle " << oracle.x;
            RoomLights direct;
            for (const LightImage& image : rooms[c].images) {
                if (image.apertures.empty()) direct.images.push_back(image);
            }
            if (glm::length(mine - image_sum(lit, direct, p, n)) > 1e-9) ++lit_through;
        }
    }
    return lit_through;
}

TEST(LightTraceAgreement, RandomChainsOfDoorsWindowsAndMirrors) {
    std::mt19937_64 rng(2027);
    int lit_through = 0;
    for (int trial = 0; trial < 30; ++trial) {
        lit_through += expect_agreement(random_chain(rng, trial % 2 == 1), 3, rng, 200);
    }
    EXPECT_GT(lit_through, 1000);
}

TEST(LightTraceAgreement, ATurnedDoorAndAMirror) {
    layout::Layout l = turned_door();
    add_portal(l, "annex_mirror", 1, make_rect({12, 1.5, 2}, {0, 0, -1}, 2.0, 2.0), layout::PortalKind::Mirror, kPosZ);
    add_light(l, 0, {0, 2, 0.5});
    add_light(l, 1, {11, 1, 0});
    l.rooms[1].lights[0].spot = layout::Spot{glm::normalize(dvec3(0, -0.3, 1)), 5.0, 40.0};
    std::mt19937_64 rng(7);
    EXPECT_GT(expect_agreement(l, 4, rng, 1500), 300);
}

// A door reaching above its room's ceiling: light through its top part
// reaches the room only where the shadow ray stays under the ceiling.
TEST(LightTraceAgreement, ADoorReachingAboveTheCeiling) {
    std::mt19937_64 rng(912);
    EXPECT_GT(expect_agreement(low_ceiling(), 2, rng, 2000), 150);
}

// A star-shaped room whose lamps' walls pass the path rectangles' bound
// (light_bound.hpp): the tracer is lit by the same two of its ten lamps
// that the images are made for, and agrees with them.
TEST(LightTraceAgreement, AStarRoomCutByThePathRectangles) {
    const layout::Layout l = star_room(1000, 10);
    const auto scene = trace::prepare_scene(l);
    ASSERT_TRUE(scene.has_value());
    EXPECT_EQ(scene->max_light_depth, 0);
    EXPECT_EQ(scene->rooms[0].lights.size(), 2u);
    std::mt19937_64 rng(36);
    expect_agreement(l, 0, rng, 400);
}

// A non-convex room's own walls cast shadows: lamps in both arms of an L,
// light from the rooms beyond the doors in the reflex corner's walls, and
// its reflection in a mirror, at random points of the L (and of the rooms).
TEST(LightTraceAgreement, AnLShapedRoomsWallsCastShadows) {
    const layout::Layout l = l_flat();
    std::mt19937_64 rng(23);
    EXPECT_GT(expect_agreement(l, 3, rng, 1500), 300);
    // Without its wall blockers the L would be lit round its corner: the
    // north arm's far end from the east arm's lamp, here.
    const auto rooms = light_images(l, links::link_portals(l), 0);
    ASSERT_EQ(rooms[0].images.size(), 2u);
    const LightImage& east_lamp = rooms[0].images[0];
    EXPECT_FALSE(segment_passes(east_lamp, {1.5, 0, 5.5}));
    LightImage no_walls = east_lamp;
    no_walls.blockers.clear();
    EXPECT_TRUE(segment_passes(no_walls, {1.5, 0, 5.5}));
}

}  // namespace
}  // namespace impossible::lights
