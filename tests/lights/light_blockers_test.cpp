// The blockers of a light image (lights/light_blockers.hpp) that no shadow
// ray of the image can meet are left out, and only those: a rectangle whose
// plane the image lies in front of, or that lies beyond the light's range.
// At random points every segment's answer (segment_passes, the lit
// shader's test) is that of the same path with every blocker.
#include <gtest/gtest.h>

#include <random>

#include "layout/room_shape.hpp"
#include "lights/light_images.hpp"
#include "lights/lights_test_layouts.hpp"

namespace impossible::lights {
namespace {

using namespace testing;
using glm::dvec3;

const LightImage* find_path(const RoomLights& room, const PathKey& key) {
    for (const LightImage& image : room.images)
        if (path_key(image) == key) return &image;
    return nullptr;
}

// Every image keeps the blockers some shadow ray may meet: at random
// points of its room within the light's range (beyond it the light adds
// nothing, blocked or not), its segment passes exactly when that of the
// same path with every blocker does. Returns the blockers left out.
std::size_t expect_blockers_only_culled(const layout::Layout& l, int depth, std::mt19937_64& rng, int points) {
    const links::PortalLinks links = links::link_portals(l);
    const auto culled = light_images(l, links, depth);
    const auto all = light_images(l, links, depth, LightImageOptions{false});
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::size_t left_out = 0;
    for (std::size_t c = 0; c < culled.size(); ++c) {
        const layout::Room& room = l.rooms[c];
        for (const LightImage& image : culled[c].images) {
            const LightImage* full = find_path(all[c], path_key(image));
            if (full == nullptr) {
                ADD_FAILURE() << l.name << ": a path of room " << c << " is missing without culling";
                continue;
            }
            EXPECT_LE(image.blockers.size(), full->blockers.size());
            left_out += full->blockers.size() - image.blockers.size();
            const double range =
                l.rooms[static_cast<std::size_t>(image.light_room)].lights[static_cast<std::size_t>(image.light)].range;
            for (int i = 0; i < points; ++i) {
                const dvec3 p = room.min + (room.max - room.min) * dvec3(unit(rng), unit(rng), unit(rng));
                if (!layout::room_contains(room, p)) continue;
                if (range > 0.0 && glm::length(image.position - p) >= range) continue;
                EXPECT_EQ(segment_passes(image, p), segment_passes(*full, p))
                    << l.name << " room " << c << " p " << p.x << " " << p.y << " " << p.z;
            }
        }
    }
    return left_out;
}

TEST(LightBlockers, ThoseThatNoShadowRayMeetsAreLeftOut) {
    std::mt19937_64 rng(36);
    // The L's east lamp lies in front of the reflex wall at z = 3 (it can
    // only be crossed towards the lamp from behind) and behind the one at
    // x = 3: the first never blocks it.
    EXPECT_GT(expect_blockers_only_culled(l_flat(), 2, rng, 300), 0u);
    const auto rooms = light_images(l_flat(), links::link_portals(l_flat()), 0);
    ASSERT_EQ(rooms[0].images.size(), 2u);
    ASSERT_EQ(rooms[0].images[0].blockers.size(), 1u);
    EXPECT_EQ(rooms[0].images[0].blockers[0].wall, 3);
    EXPECT_GT(expect_blockers_only_culled(star_room(100, 3), 1, rng, 300), 0u);
    for (int trial = 0; trial < 10; ++trial) expect_blockers_only_culled(random_chain(rng, trial % 2 == 1), 3, rng, 50);
}

// A free-standing door whose front faces away from the lamp, 9 m off:
// within a range of 10 m it may block, within 5 m the light ends before it.
TEST(LightBlockers, ThoseBeyondTheLightsRangeAreLeftOut) {
    layout::Layout l = lit_layout("long hall");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {12, 3, 2});
    const int other = add_room(l, "other", {30, 0, -2}, {34, 3, 2});
    add_pair(l, "free", hall, make_rect({9, 1.5, 0}, {1, 0, 0}, 1.0, 1.0), -1, "free_back", other,
             make_rect({32, 1.5, 0}, {-1, 0, 0}, 1.0, 1.0), -1);
    add_light(l, hall, {0, 1.5, 0}, 10.0);
    add_light(l, hall, {0, 1.5, 0}, 5.0);
    add_light(l, hall, {10, 1.5, 0}, 0.0);  // in front of the door: it never blocks
    const auto rooms = light_images(l, links::link_portals(l), 0);
    ASSERT_EQ(rooms[0].images.size(), 3u);
    EXPECT_EQ(rooms[0].images[0].blockers.size(), 1u);
    EXPECT_TRUE(rooms[0].images[1].blockers.empty());
    EXPECT_TRUE(rooms[0].images[2].blockers.empty());
    EXPECT_FALSE(segment_passes(rooms[0].images[0], {11, 1.5, 0}));  // through the door's front
    std::mt19937_64 rng(9);
    EXPECT_GT(expect_blockers_only_culled(l, 0, rng, 500), 0u);
}

}  // namespace
}  // namespace impossible::lights
