// Culling of light images: the aperture test (a path whose apertures no
// straight shadow ray passes in order is dropped), the range, the 1/256
// factor rule, and the property that culling never drops a path that some
// shadow ray from a point of the room passes (segment_passes, the exact
// test of the lit shader).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>

#include "lights/light_images.hpp"
#include "lights/lights_test_layouts.hpp"
#include "shading/lighting.hpp"

namespace impossible::lights {
namespace {

using namespace testing;
using glm::dvec3;

// "c" (x -2..2), a corridor (x 2..6) behind a small door in c's +x wall at
// z = door_z, and two rooms overlapping at x 6..10 behind two doors in the
// corridor's far wall at z = far_a and z = far_b, each with a light in line
// with its door.
layout::Layout two_doors(double door_z = -1.5, double far_a = -1.5, double far_b = 1.5) {
    layout::Layout l = lit_layout("two doors");
    const int c = add_room(l, "c", {-2, 0, -2}, {2, 3, 2});
    const int corridor = add_room(l, "corridor", {2, 0, -2}, {6, 3, 2});
    const int a = add_room(l, "a", {6, 0, -2}, {10, 3, 2});
    const int b = add_room(l, "b", {6, 0, -2}, {10, 3, 2});
    add_pair(l, "c_east", c, make_rect({2, 1, door_z}, {-1, 0, 0}, 0.5, 1.0), kPosX, "corridor_west", corridor,
             make_rect({2, 1, door_z}, {1, 0, 0}, 0.5, 1.0), kNegX);
    add_pair(l, "corridor_a", corridor, make_rect({6, 1, far_a}, {-1, 0, 0}, 0.5, 1.0), kPosX, "a_west", a,
             make_rect({6, 1, far_a}, {1, 0, 0}, 0.5, 1.0), kNegX);
    add_pair(l, "corridor_b", corridor, make_rect({6, 1, far_b}, {-1, 0, 0}, 0.5, 1.0), kPosX, "b_west", b,
             make_rect({6, 1, far_b}, {1, 0, 0}, 0.5, 1.0), kNegX);
    add_light(l, a, {8, 1, far_a});
    add_light(l, b, {8, 1, far_b});
    l.start = {c, {0, 1.6, 0}, 0.0};
    return l;
}

TEST(LightCulling, APathThatNoStraightRayPassesIsDropped) {
    const layout::Layout l = two_doors();
    const links::PortalLinks links = links::link_portals(l);
    const PathKey in_line{2, 0, {{0, false}, {2, false}}};
    const PathKey around_a_corner{3, 0, {{0, false}, {4, false}}};
    const auto culled = light_images(l, links, 2);
    const auto all = light_images(l, links, 2, LightImageOptions{false});
    EXPECT_TRUE(has_path(culled[0], in_line));
    EXPECT_FALSE(has_path(culled[0], around_a_corner));
    EXPECT_TRUE(has_path(all[0], in_line));
    EXPECT_TRUE(has_path(all[0], around_a_corner));
}

TEST(LightCulling, ALightOutOfRangeOfTheApertureIsDropped) {
    layout::Layout l = doorway();
    add_light(l, 1, {5, 2, 0}, 2.9);  // 3 m from the door's nearest point
    add_light(l, 1, {5, 2, 0}, 3.1);
    add_light(l, 1, {3, 2, 0}, 0.01);
    const auto rooms = light_images(l, links::link_portals(l), 1);
    EXPECT_FALSE(has_path(rooms[0], PathKey{1, 0, {{0, false}}}));
    EXPECT_TRUE(has_path(rooms[0], PathKey{1, 1, {{0, false}}}));
    EXPECT_FALSE(has_path(rooms[0], PathKey{1, 2, {{0, false}}}));
    // A light is never dropped in its own room.
    EXPECT_EQ(rooms[1].images.size(), 3u);
}

TEST(LightCulling, ASpotThatLightsNoneOfTheApertureIsDropped) {
    layout::Layout l = doorway();
    add_light(l, 1, {4, 2.5, 0});
    add_light(l, 1, {4, 2.5, 0});
    add_light(l, 1, {4, 2.5, 0});
    l.rooms[1].lights[0].spot = layout::Spot{{0, -1, 0}, 20.0, 30.0};  // straight down: misses the door (38.7°)
    l.rooms[1].lights[1].spot = layout::Spot{{-1, 0, 0}, 20.0, 40.0};  // at the door
    l.rooms[1].lights[2].spot = layout::Spot{{0, -1, 0}, 20.0, 89.0};  // wide enough
    const auto rooms = light_images(l, links::link_portals(l), 1);
    EXPECT_FALSE(has_path(rooms[0], PathKey{1, 0, {{0, false}}}));
    EXPECT_TRUE(has_path(rooms[0], PathKey{1, 1, {{0, false}}}));
    EXPECT_TRUE(has_path(rooms[0], PathKey{1, 2, {{0, false}}}));
    EXPECT_EQ(rooms[1].images.size(), 3u);  // never in its own room
}

// A window pair on the -z and +z walls of one room (the camera and the TV).
layout::Layout facing_windows(double reflectance, double tint) {
    layout::Layout l = lit_layout("facing windows");
    const int room = add_room(l, "room", {-2, 0, -2}, {2, 3, 2});
    const int w = add_pair(l, "south", room, make_rect({0, 1.5, -2}, {0, 0, 1}, 1.0, 1.0), kNegZ, "north", room,
                           make_rect({0, 1.5, 2}, {0, 0, -1}, 1.0, 1.0), kPosZ, layout::PortalKind::Window);
    for (int i = w; i <= w + 1; ++i) {
        l.portals[static_cast<std::size_t>(i)].reflectance = reflectance;
        l.portals[static_cast<std::size_t>(i)].tint = dvec3(tint);
    }
    add_light(l, room, {0, 1.5, 0});
    l.start = {room, {0, 1.6, 0}, 0.0};
    return l;
}

TEST(LightCulling, APathBelowOneStepIn256IsNotFollowed) {
    const layout::Layout half = facing_windows(0.5, 1.0);  // every step halves the factor
    const auto rooms = light_images(half, links::link_portals(half), layout::kMaxLightDepth);
    std::size_t longest = 0;
    for (const LightImage& image : rooms[0].images) {
        longest = std::max(longest, image.apertures.size());
        EXPECT_GE(std::max({image.factor.x, image.factor.y, image.factor.z}), shading::kMinLightFactor);
    }
    EXPECT_EQ(longest, 8u);  // 2^-8 is exactly 1/256
    const PathKey straight8{0, 0, std::vector<std::pair<int, bool>>(8, {0, false})};
    EXPECT_TRUE(has_path(rooms[0], straight8));
    // Through the tinted glass a step is 0.495: seven steps straight on, but
    // eight reflections (0.5 each, untinted) alternating between the two.
    const layout::Layout tinted = facing_windows(0.5, 0.99);
    const auto tinted_rooms = light_images(tinted, links::link_portals(tinted), layout::kMaxLightDepth);
    EXPECT_FALSE(has_path(tinted_rooms[0], straight8));
    EXPECT_TRUE(has_path(tinted_rooms[0], PathKey{0, 0, std::vector<std::pair<int, bool>>(7, {0, false})}));
    std::vector<std::pair<int, bool>> bounces;
    for (int i = 0; i < 8; ++i) bounces.emplace_back(i % 2, true);
    EXPECT_TRUE(has_path(tinted_rooms[0], PathKey{0, 0, bounces}));
}

// A 2 m cube whose six faces are 2 × 2 m windows, each paired with the
// opposite face, reflectance 0.5: every path splits in two at every face.
layout::Layout window_cube() {
    layout::Layout l = lit_layout("window cube");
    const int r = add_room(l, "cube", {-1, 0, -1}, {1, 2, 1});
    const int faces[] = {kNegX, kPosX, static_cast<int>(layout::Face::Floor), static_cast<int>(layout::Face::Ceiling),
                         kNegZ, kPosZ};
    const dvec3 centers[] = {{-1, 1, 0}, {1, 1, 0}, {0, 0, 0}, {0, 2, 0}, {0, 1, -1}, {0, 1, 1}};
    const dvec3 normals[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 6; i += 2) {
        const dvec3 up = i == 2 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
        const int a = add_pair(l, "a" + std::to_string(i), r, make_rect(centers[i], normals[i], 2, 2, up), faces[i],
                               "b" + std::to_string(i), r, make_rect(centers[i + 1], normals[i + 1], 2, 2, up),
                               faces[i + 1], layout::PortalKind::Window);
        l.portals[static_cast<std::size_t>(a)].reflectance = 0.5;
        l.portals[static_cast<std::size_t>(a) + 1].reflectance = 0.5;
    }
    add_light(l, r, {0.3, 1.2, 0.1});
    l.start = {r, {0, 1, 0}, 0.0};
    return l;
}

std::size_t total_images(const std::vector<RoomLights>& rooms) {
    std::size_t n = 0;
    for (const RoomLights& room : rooms) n += light_path_count(room);
    return n;
}

TEST(LightCulling, TheDepthWithinABudgetOfPaths) {
    const layout::Layout cube = window_cube();
    const links::PortalLinks links = links::link_portals(cube);
    const int depth = light_depth_within(cube, links, layout::kMaxLightDepth, 1000);
    ASSERT_GE(depth, 1);
    ASSERT_LT(depth, layout::kMaxLightDepth);
    EXPECT_LE(total_images(light_images(cube, links, depth)), 1000u);
    EXPECT_GT(total_images(light_images(cube, links, depth + 1)), 1000u);
    EXPECT_EQ(light_depth_within(cube, links, 2, 1000000), 2);
    EXPECT_EQ(light_depth_within(cube, links, 5, 0), 5);  // no limit
    EXPECT_EQ(light_depth_within(cube, links, 3, 1), 0);  // the light itself
    layout::Layout fixed = cube;
    fixed.lighting = layout::Lighting::Fixed;
    EXPECT_EQ(light_depth_within(fixed, links, 3, 1), 3);
}

TEST(LightCulling, AFreeStandingDoorBlocksFromItsFrontOnly) {
    layout::Layout l = lit_layout("free door");
    const int room = add_room(l, "room", {-2, 0, -2}, {2, 3, 2});
    const int other = add_room(l, "other", {10, 0, -2}, {14, 3, 2});
    add_pair(l, "free", room, make_rect({0, 1.5, 0}, {0, 0, 1}, 1.0, 1.0), -1, "other_side", other,
             make_rect({12, 1.5, 0}, {0, 0, -1}, 1.0, 1.0), -1);
    add_light(l, room, {0, 1.5, -1});
    add_light(l, room, {0, 1.5, 1});
    const auto rooms = light_images(l, links::link_portals(l), 0);
    ASSERT_EQ(rooms[0].images.size(), 2u);
    const LightImage& behind = rooms[0].images[0];
    const LightImage& before = rooms[0].images[1];
    ASSERT_EQ(behind.blockers.size(), 1u);
    EXPECT_EQ(behind.blockers[0].portal, 0);
    EXPECT_EQ(behind.blockers[0].leg, 0);
    EXPECT_FALSE(segment_passes(behind, {0, 1.5, 1.5}));    // through the door's front
    EXPECT_TRUE(segment_passes(behind, {1.5, 1.5, 1.5}));   // beside it
    EXPECT_TRUE(segment_passes(before, {0, 1.5, -1.5}));    // through it from behind
    EXPECT_TRUE(segment_passes(before, {0.2, 1.5, -0.2}));  // behind it
    // The other room sees the light in front of the door through it: the
    // portals the path passes are no blockers of their own legs.
    const auto deeper = light_images(l, links::link_portals(l), 1);
    ASSERT_TRUE(has_path(deeper[1], PathKey{0, 1, {{1, false}}}));
    for (const LightImage& image : deeper[1].images) {
        if (image.light != 1) continue;
        EXPECT_TRUE(image.blockers.empty());
        EXPECT_TRUE(segment_passes(image, {12, 1.5, -1}));
    }
}

// A light in the plane of a free-standing door (no ray passes the door
// towards it but at a graze, which the tolerance keeps): a straight ray
// crosses that plane once, so the door and its partner, which lie in the
// same plane, are never passed one after the other.
TEST(LightCulling, NoPathPassesTheSamePlaneTwice) {
    layout::Layout l = lit_layout("door in the light's plane");
    const int c = add_room(l, "c", {-2, 0, -2}, {2, 3, 2});
    const int other = add_room(l, "other", {-2, 0, -2}, {2, 3, 2});
    add_pair(l, "free", c, make_rect({0, 1.5, 0}, {0, 0, 1}, 1.0, 1.0), -1, "free_back", other,
             make_rect({0, 1.5, 0}, {0, 0, -1}, 1.0, 1.0), -1);
    add_light(l, c, {1.5, 1.5, 0});
    const auto rooms = light_images(l, links::link_portals(l), 4);
    EXPECT_EQ(rooms[0].images.size(), 1u);
    for (const RoomLights& room : rooms) {
        for (const LightImage& image : room.images) EXPECT_LE(image.apertures.size(), 1u);
    }
}

TEST(LightCulling, AFreeStandingDoorInTheNextRoomBlocksTheSecondLeg) {
    layout::Layout l = doorway();
    const int far = add_room(l, "far", {20, 0, -2}, {24, 3, 2});
    add_pair(l, "free", 1, make_rect({4, 1.8, 0}, {-1, 0, 0}, 1.0, 0.4), -1, "free_back", far,
             make_rect({22, 1.5, 0}, {1, 0, 0}, 1.0, 0.4), -1);
    add_light(l, 1, {5, 1.8, 0});
    const auto rooms = light_images(l, links::link_portals(l), 1);
    ASSERT_TRUE(has_path(rooms[0], PathKey{1, 0, {{0, false}}}));
    const LightImage& image = rooms[0].images[0];
    ASSERT_EQ(image.blockers.size(), 1u);  // not the door it comes in by
    EXPECT_EQ(image.blockers[0].portal, 2);
    EXPECT_EQ(image.blockers[0].leg, 1);
    EXPECT_FALSE(segment_passes(image, {0, 1.8, 0}));  // meets the free door's front
    EXPECT_FALSE(segment_passes(image, {0, 1.0, 0}));
    EXPECT_TRUE(segment_passes(image, {0, 0.5, 0}));  // passes below it
}

TEST(LightCulling, SegmentPassesTheAperturesInOrderOnly) {
    const layout::Layout l = two_doors();
    const auto all = light_images(l, links::link_portals(l), 2, LightImageOptions{false});
    const LightImage* in_line = nullptr;
    for (const LightImage& image : all[0].images) {
        if (path_key(image) == PathKey{2, 0, {{0, false}, {2, false}}}) in_line = &image;
    }
    ASSERT_NE(in_line, nullptr);
    EXPECT_TRUE(segment_passes(*in_line, {-1, 1, -1.5}));
    EXPECT_FALSE(segment_passes(*in_line, {-1, 1, 1.0}));   // misses the first door
    EXPECT_FALSE(segment_passes(*in_line, {-1, 2, -1.5}));  // above both doors' tops (y 0.5..1.5)
}

// Every path that some shadow ray from a point of C passes, and that ends
// within the light's range and its spot's cone there, survives culling, whatever the doors'
// places; and culling does drop some.
void expect_conservative(const layout::Layout& l, int depth, std::mt19937_64& rng, int points, int& passed,
                         int& dropped) {
    const links::PortalLinks links = links::link_portals(l);
    const auto culled = light_images(l, links, depth);
    const auto all = light_images(l, links, depth, LightImageOptions{false});
    for (std::size_t c = 0; c < l.rooms.size(); ++c) {
        const layout::Room& room = l.rooms[c];
        for (const LightImage& image : culled[c].images) EXPECT_TRUE(has_path(all[c], path_key(image)));
        std::uniform_real_distribution<double> ux(room.min.x, room.max.x), uy(room.min.y, room.max.y),
            uz(room.min.z, room.max.z);
        for (const LightImage& image : all[c].images) {
            const bool kept = has_path(culled[c], path_key(image));
            dropped += kept ? 0 : 1;
            for (int i = 0; i < points; ++i) {
                const dvec3 p(ux(rng), uy(rng), uz(rng));
                // The light as the image carries it (its spot's axis in C's coordinates).
                layout::Light light =
                    l.rooms[static_cast<std::size_t>(image.light_room)].lights[static_cast<std::size_t>(image.light)];
                if (light.spot) light.spot->direction = image.spot_direction;
                const double d = glm::length(image.position - p);
                if (light.range > 0.0 && d >= light.range) continue;
                if (shading::spot_factor(light, (image.position - p) / d) <= 0.0) continue;
                if (!segment_passes(image, p)) continue;
                ++passed;
                EXPECT_TRUE(kept) << "room " << c << " light " << image.light_room << "/" << image.light << " k "
                                  << image.apertures.size() << " p " << p.x << " " << p.y << " " << p.z;
                break;
            }
        }
    }
}

TEST(LightCulling, CullingNeverDropsAPathThatAShadowRayPasses) {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> place(-1.7, 1.7);
    int passed = 0;
    int dropped = 0;
    for (int trial = 0; trial < 40; ++trial) {
        layout::Layout l = two_doors(place(rng), place(rng), place(rng));
        add_light(l, 0, {place(rng), 2.5, place(rng)});
        add_light(l, 1, {3 + place(rng) * 0.5, 0.5, place(rng)});
        expect_conservative(l, 3, rng, 400, passed, dropped);
    }
    layout::Layout mirrored = turned_door();
    add_portal(mirrored, "annex_mirror", 1, make_rect({12, 1.5, 2}, {0, 0, -1}, 2.0, 2.0), layout::PortalKind::Mirror,
               kPosZ);
    add_light(mirrored, 0, {0, 2, 0.5});
    add_light(mirrored, 1, {11, 1, 0});
    expect_conservative(mirrored, 3, rng, 2000, passed, dropped);
    const layout::Layout windows = facing_windows(0.3, 0.9);
    expect_conservative(windows, 3, rng, 2000, passed, dropped);
    for (int trial = 0; trial < 40; ++trial)
        expect_conservative(random_chain(rng, trial % 2 == 1), 3, rng, 400, passed, dropped);
    EXPECT_GT(passed, 100);
    EXPECT_GT(dropped, 100);
}

}  // namespace
}  // namespace impossible::lights
