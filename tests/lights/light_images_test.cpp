// The light images of layout-format.md, "Lights": which images of which
// lights a room sees through doors, mirrors and windows, where, with what
// factor, and the apertures mapped into the lit room's coordinates.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "lights/light_images.hpp"
#include "lights/lights_test_layouts.hpp"
#include "math/rigid.hpp"

namespace impossible::lights {
namespace {

using namespace testing;
using glm::dvec3;
using glm::dvec4;

void expect_near(const dvec3& a, const dvec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

dvec3 apply(const glm::dmat4& m, const dvec3& p) { return dvec3(m * dvec4(p, 1.0)); }

TEST(LightImages, FixedLightingHasNone) {
    layout::Layout l = doorway();
    add_light(l, 0, {0, 2, 0});
    l.lighting = layout::Lighting::Fixed;
    EXPECT_TRUE(light_images(l, links::link_portals(l), 2).empty());
}

TEST(LightImages, DepthZeroIsTheRoomsOwnLights) {
    layout::Layout l = doorway();
    l.rooms[0].ambient = dvec3(0.2, 0.3, 0.4);
    add_light(l, 0, {0, 2, 0});
    add_light(l, 0, {-1, 1, 1});
    add_light(l, 1, {4, 2, 0});
    const auto rooms = light_images(l, links::link_portals(l), 0);
    ASSERT_EQ(rooms.size(), 2u);
    expect_near(rooms[0].ambient, dvec3(0.2, 0.3, 0.4), 0.0);
    ASSERT_EQ(light_path_count(rooms[0]), 2u);
    ASSERT_EQ(light_path_count(rooms[1]), 1u);
    for (int i = 0; i < 2; ++i) {
        const LightImage& image = rooms[0].images[static_cast<std::size_t>(i)];
        EXPECT_EQ(image.light_room, 0);
        EXPECT_EQ(image.light, i);
        expect_near(image.position, l.rooms[0].lights[static_cast<std::size_t>(i)].position, 0.0);
        expect_near(image.factor, dvec3(1.0), 0.0);
        EXPECT_TRUE(image.apertures.empty());
        EXPECT_EQ(image.rooms, std::vector<int>{0});
        ASSERT_EQ(image.to_room.size(), 1u);
        EXPECT_EQ(image.to_room[0], glm::dmat4(1.0));
        EXPECT_TRUE(image.blockers.empty());  // the door is a hole in a wall
    }
}

TEST(LightImages, ADoorShowsTheNextRoomsLight) {
    layout::Layout l = doorway();
    add_light(l, 1, {4, 2, 0.5});
    const auto rooms = light_images(l, links::link_portals(l), 1);
    ASSERT_EQ(rooms[0].images.size(), 1u);
    const LightImage& image = rooms[0].images[0];
    EXPECT_EQ(image.light_room, 1);
    expect_near(image.position, dvec3(4, 2, 0.5));  // M = identity
    ASSERT_EQ(image.apertures.size(), 1u);
    EXPECT_EQ(image.apertures[0].portal, 0);
    EXPECT_FALSE(image.apertures[0].reflect);
    expect_near(image.apertures[0].rect.center, l.portals[0].rect.center);
    expect_near(image.apertures[0].rect.normal, l.portals[0].rect.normal);
    EXPECT_EQ(image.rooms, (std::vector<int>{0, 1}));
    EXPECT_EQ(image.apertures[0].rect.depth, 0.0);
    expect_near(image.factor, dvec3(1.0), 0.0);
    // The annex sees its own light only: the way back through the door is
    // the same plane again.
    EXPECT_EQ(rooms[1].images.size(), 1u);
}

TEST(LightImages, ATurnedDoorMapsTheImageAndTheSpotAxis) {
    layout::Layout l = turned_door();
    add_light(l, 1, {13, 2, 1});
    l.rooms[1].lights[0].spot = layout::Spot{{0, 0, -1}, 10.0, 30.0};
    add_light(l, 0, {0, 2, 0.5});
    const links::PortalLinks links = links::link_portals(l);
    const auto rooms = light_images(l, links, 1);
    ASSERT_EQ(rooms[0].images.size(), 2u);
    const LightImage& image = rooms[0].images[1];  // k = 0 first
    ASSERT_EQ(image.apertures.size(), 1u);
    // M maps the hall onto the annex: (x, y, z) -> (12 - z, y, x - 4).
    expect_near(image.position, dvec3(5, 2, -1));
    expect_near(apply(links.transfer[0], image.position), dvec3(13, 2, 1));
    expect_near(image.spot_direction, dvec3(-1, 0, 0));  // the annex's -z is the hall's -x
    expect_near(apply(image.to_room[1], image.position), dvec3(13, 2, 1));
    // And the other way: the hall's light seen from the annex.
    ASSERT_EQ(rooms[1].images.size(), 2u);
    const LightImage& back = rooms[1].images[1];
    expect_near(back.position, apply(math::rigid_inverse(links.transfer[1]), dvec3(0, 2, 0.5)));
    expect_near(back.position, dvec3(11.5, 2, -4));
    expect_near(back.apertures[0].rect.center, l.portals[1].rect.center);
}

TEST(LightImages, AMirrorReflectsTheLightWithItsTint) {
    layout::Layout l = lit_layout("mirror");
    const int room = add_room(l, "room", {-2, 0, -2}, {2, 3, 2});
    const int mirror =
        add_portal(l, "mirror", room, make_rect({0, 1.5, -2}, {0, 0, 1}, 2.0, 2.0), layout::PortalKind::Mirror, kNegZ);
    l.portals[static_cast<std::size_t>(mirror)].tint = dvec3(0.9, 0.8, 0.7);
    add_light(l, room, {0.5, 2, 0});
    l.rooms[0].lights[0].spot = layout::Spot{{0, -0.6, -0.8}, 10.0, 30.0};
    const auto rooms = light_images(l, links::link_portals(l), 4);
    // Seen once directly and once in the mirror: a second reflection would
    // cross the mirror's plane twice.
    ASSERT_EQ(rooms[0].images.size(), 2u);
    const LightImage& image = rooms[0].images[1];
    expect_near(image.position, dvec3(0.5, 2, -4));
    expect_near(image.spot_direction, dvec3(0, -0.6, 0.8));
    expect_near(image.factor, dvec3(0.9, 0.8, 0.7));
    ASSERT_EQ(image.apertures.size(), 1u);
    EXPECT_TRUE(image.apertures[0].reflect);
    EXPECT_EQ(image.rooms, (std::vector<int>{0, 0}));
}

TEST(LightImages, AWindowGivesAThroughAndAReflectedImage) {
    layout::Layout l = doorway();
    const int w = add_pair(l, "hall_window", 0, make_rect({0, 1.5, -2}, {0, 0, 1}, 1.0, 1.0), kNegZ, "annex_window", 1,
                           make_rect({4, 1.5, 2}, {0, 0, -1}, 1.0, 1.0), kPosZ, layout::PortalKind::Window);
    l.portals[static_cast<std::size_t>(w)].reflectance = 0.25;
    l.portals[static_cast<std::size_t>(w)].tint = dvec3(1.0, 0.8, 0.6);
    add_light(l, 0, {-1, 2, 0});
    add_light(l, 1, {4, 2, 0});
    const links::PortalLinks links = links::link_portals(l);
    const auto rooms = light_images(l, links, 1);
    // Own light, then (door) the annex's light, then the window through
    // (the annex's light) and reflected (the hall's own light).
    ASSERT_EQ(rooms[0].images.size(), 4u);
    const LightImage& through = rooms[0].images[2];
    const LightImage& reflected = rooms[0].images[3];
    EXPECT_EQ(through.apertures[0].portal, w);
    EXPECT_FALSE(through.apertures[0].reflect);
    EXPECT_EQ(through.light_room, 1);
    expect_near(through.factor, dvec3(0.75, 0.6, 0.45));
    expect_near(through.position, apply(math::rigid_inverse(links.transfer[static_cast<std::size_t>(w)]), {4, 2, 0}));
    EXPECT_EQ(reflected.apertures[0].portal, w);
    EXPECT_TRUE(reflected.apertures[0].reflect);
    EXPECT_EQ(reflected.light_room, 0);
    expect_near(reflected.factor, dvec3(0.25));
    expect_near(reflected.position, dvec3(-1, 2, -4));
}

// The apertures and legs agree with the portals' matrices on every image.
TEST(LightImages, LegsAndAperturesFollowThePortalMatrices) {
    layout::Layout l = turned_door();
    add_portal(l, "annex_mirror", 1, make_rect({12, 1.5, 2}, {0, 0, -1}, 2.0, 2.0), layout::PortalKind::Mirror, kPosZ);
    add_light(l, 0, {0, 2, 0.5});
    add_light(l, 1, {11, 1, 0});
    const links::PortalLinks links = links::link_portals(l);
    const auto rooms = light_images(l, links, 3);
    bool saw_three = false;
    for (const RoomLights& room : rooms) {
        for (const LightImage& image : room.images) {
            const std::size_t k = image.apertures.size();
            saw_three = saw_three || k == 3;
            ASSERT_EQ(image.rooms.size(), k + 1);
            ASSERT_EQ(image.to_room.size(), k + 1);
            EXPECT_EQ(image.to_room[0], glm::dmat4(1.0));
            for (std::size_t i = 0; i < k; ++i) {
                const Aperture& a = image.apertures[i];
                const layout::Portal& portal = l.portals[static_cast<std::size_t>(a.portal)];
                EXPECT_EQ(portal.room, image.rooms[i]);
                expect_near(apply(image.to_room[i], a.rect.center), portal.rect.center, 1e-12);
                const glm::dmat4 m = a.reflect ? links.reflection[static_cast<std::size_t>(a.portal)]
                                               : links.transfer[static_cast<std::size_t>(a.portal)];
                EXPECT_LT(math::max_abs_difference(image.to_room[i + 1], m * image.to_room[i]), 1e-12);
            }
            const dvec3 light = l.rooms[static_cast<std::size_t>(image.light_room)]
                                    .lights[static_cast<std::size_t>(image.light)]
                                    .position;
            expect_near(apply(image.to_room[k], image.position), light, 1e-12);
        }
    }
    // The hall's light through the door, in the annex's mirror, back
    // through the door.
    EXPECT_TRUE(saw_three);
    EXPECT_TRUE(has_path(rooms[0], PathKey{0, 0, {{0, false}, {2, true}, {1, false}}}));
}

TEST(LightImages, DepthLimitsThePathLength) {
    layout::Layout l = doorway();
    add_portal(l, "annex_mirror", 1, make_rect({6, 1.5, 0}, {-1, 0, 0}, 2.0, 2.0), layout::PortalKind::Mirror, kPosX);
    add_light(l, 0, {-1, 2, 0});
    add_light(l, 1, {4, 2, 0});
    const links::PortalLinks links = links::link_portals(l);
    const std::size_t expected[] = {1, 2, 3, 4, 4};
    for (int depth = 0; depth <= 4; ++depth) {
        const auto rooms = light_images(l, links, depth);
        EXPECT_EQ(rooms[0].images.size(), expected[depth]) << "depth " << depth;
        for (std::size_t i = 1; i < rooms[0].images.size(); ++i) {
            EXPECT_LE(rooms[0].images[i - 1].apertures.size(), rooms[0].images[i].apertures.size());
        }
    }
    const auto rooms = light_images(l, links, 3);
    EXPECT_TRUE(has_path(rooms[0], PathKey{1, 0, {{0, false}, {2, true}}}));
    EXPECT_TRUE(has_path(rooms[0], PathKey{0, 0, {{0, false}, {2, true}, {1, false}}}));
    expect_near(rooms[0].images[2].position, dvec3(8, 2, 0));
}

// A door reaching above its room's ceiling: the ceiling's plane blocks the
// leg into the low room (leg 0) and nothing else does; near the ceiling a
// shadow ray towards the door's top leaves the room first.
TEST(LightImages, ADoorReachingOutsideItsRoomAddsThatFacesPlane) {
    const layout::Layout l = low_ceiling();
    const auto rooms = light_images(l, links::link_portals(l), 1);
    ASSERT_EQ(rooms[1].images.size(), 1u);
    const LightImage& image = rooms[1].images[0];
    ASSERT_EQ(image.blockers.size(), 1u);
    EXPECT_EQ(image.blockers[0].leg, 0);
    EXPECT_EQ(image.blockers[0].face, static_cast<int>(layout::Face::Ceiling));
    expect_near(image.blockers[0].rect.normal, dvec3(0, -1, 0));
    EXPECT_FALSE(segment_passes(image, {0.2, 1.95, -1.5}));  // crosses y = 2 at z = -1.38
    EXPECT_TRUE(segment_passes(image, {0.2, 0.5, -1.5}));    // under the ceiling all the way
    // The high room's door stays inside it: its own lamp's leg meets the
    // door standing free there, and no face's plane.
    for (const LightImage& own : rooms[0].images)
        for (const Blocker& b : own.blockers) EXPECT_EQ(b.face, -1);
}

// A non-convex prism's walls that a shadow ray can cross (the two walls of
// an L's reflex corner) block it on the legs in that room, but for the
// wall the leg enters or leaves the room by (it only ends there), and but
// for a wall whose plane the light's image lies in front of: a segment
// towards the image crosses it only from behind (light_blockers.hpp).
TEST(LightImages, AnLsReflexWallsBlockItsLegsButTheDoorsOwnWall) {
    const layout::Layout l = l_flat();
    const auto rooms = light_images(l, links::link_portals(l), 1);
    const auto walls_of = [](const LightImage& image, int leg) {
        std::vector<int> walls;
        for (const Blocker& b : image.blockers)
            if (b.leg == leg && b.portal == -1) walls.push_back(b.wall);
        return walls;
    };
    // The east arm's lamp (light 0) lies behind wall 3 (x = 3) only, the
    // north arm's (light 1) behind wall 2 (z = 3) only.
    const std::vector<int> behind[] = {{3}, {2}};
    int through_a = 0, through_b = 0;
    for (const LightImage& image : rooms[0].images) {
        if (image.apertures.empty()) {
            EXPECT_EQ(walls_of(image, 0), behind[image.light]);  // the L's own lamps
            continue;
        }
        ASSERT_EQ(image.apertures.size(), 1u);
        const int door = image.apertures[0].portal;
        if (door == 0) ++through_a;
        if (door == 2) ++through_b;
        // Leg 0 runs in the L to the door: the other reflex wall could block
        // it, but the boxes' lamps lie in front of it. Leg 1 runs in a box
        // room: no walls. Both legs of the mirror's paths run in the L:
        // leg 1 towards the lamp, leg 0 towards its image across x = 0,
        // which lies in front of wall 3 (x = 3) too.
        const std::vector<int> leg0 = door == 4 && image.light == 1 ? std::vector<int>{2} : std::vector<int>{};
        const std::vector<int> leg1 = door == 4 ? behind[image.light] : std::vector<int>{};
        EXPECT_EQ(walls_of(image, 0), leg0) << "door " << door;
        EXPECT_EQ(walls_of(image, 1), leg1) << "door " << door;
    }
    EXPECT_EQ(through_a, 1);
    EXPECT_EQ(through_b, 1);
    // A wall blocker is the wall's rectangle, facing into the room.
    const Blocker& w3 = rooms[0].images[0].blockers[0];
    expect_near(w3.rect.center, dvec3(3, 1.5, 4.5));
    expect_near(w3.rect.normal, dvec3(-1, 0, 0));
    EXPECT_DOUBLE_EQ(w3.rect.width, 3.0);
    EXPECT_DOUBLE_EQ(w3.rect.height, 3.0);
    // The boxes see the L's lamps through their doors: on leg 1, in the L,
    // the reflex wall that does not hold that door.
    int l_walls_seen = 0;
    for (std::size_t r = 1; r < rooms.size(); ++r)
        for (const LightImage& image : rooms[r].images)
            for (const Blocker& b : image.blockers) {
                if (b.portal != -1) continue;
                ++l_walls_seen;
                EXPECT_EQ(b.leg, 1);
                EXPECT_EQ(b.wall, r == 1 ? 3 : 2);
            }
    EXPECT_EQ(l_walls_seen, 2);  // one lamp each: the other stands in front of the door
}

}  // namespace
}  // namespace impossible::lights
