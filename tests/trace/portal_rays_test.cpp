// The tracer's brute force of the seen test (trace/portal_rays.hpp): on
// chosen views, and against changes::seen_portals on random views of a few
// layouts: every portal a pixel ray reaches must be seen.
#include "trace/portal_rays.hpp"

#include <random>

#include <gtest/gtest.h>

#include "changes/change_layouts.hpp"
#include "changes/seen.hpp"
#include "links/portal_links.hpp"

namespace impossible::trace {
namespace {

using changes::testing::door_swap;

math::View view_at(int room, math::dvec3 head, double yaw, double pitch = 0.0) {
    math::View v;
    v.room = room;
    v.head = {head, yaw, pitch, 0.0};
    v.eye_width = 160;
    v.eye_height = 90;
    return v;
}

std::vector<char> reached(const layout::Layout& l, const math::View& v, int step = 1) {
    return portal_rays(prepare_scene(l).value(), v, step).reached;
}

TEST(PortalRays, ADoorAheadIsReachedAndOneBehindIsNot) {
    const layout::Layout l = door_swap();
    // From the hall's centre looking east at hall_east (0); through it the
    // study's only door faces away. Looking west, hall_west (2); through it
    // (to garden_west, turned round) the virtual eye looks at garden_west's
    // back: nothing more.
    EXPECT_EQ(reached(l, view_at(0, {0, 1.6, 0}, -90)), (std::vector<char>{1, 0, 0, 0}));
    EXPECT_EQ(reached(l, view_at(0, {0, 1.6, 0}, 90)), (std::vector<char>{0, 0, 1, 0}));
    EXPECT_EQ(reached(l, view_at(0, {0, 1.6, 0}, 0)), (std::vector<char>{0, 0, 0, 0}));
}

TEST(PortalRays, DepthAndTheBudgetBoundThePasses) {
    const layout::Layout l = door_swap();
    // In the study looking west through study_west (1) into the hall, whose
    // west door (2) faces the virtual eye 4 m on.
    math::View v = view_at(1, {3, 1.6, 0}, 90);
    EXPECT_EQ(reached(l, v), (std::vector<char>{0, 1, 1, 0}));
    v.max_depth = 0;  // reached, not passed
    EXPECT_EQ(reached(l, v), (std::vector<char>{0, 1, 0, 0}));
    v.max_depth = 8;
    v.max_portal_passes = 0;  // the tree's budget: none passed either
    EXPECT_EQ(reached(l, v), (std::vector<char>{0, 1, 0, 0}));
}

TEST(PortalRays, AnEyeInTheBoxItReachedThroughTheDoorReachesItsInnerFaces) {
    layout::Layout l = door_swap();
    for (layout::Portal& p : l.portals) p.rect.depth = 0.3;
    // 1 cm in front of hall_east, turned south: the left eye is behind the
    // plane in the box, its rays meet the box's inner faces (as the seen
    // test's reading, docs/changes.md, says it sees the door).
    EXPECT_EQ(reached(l, view_at(0, {1.99, 1.6, 0}, 180))[0], 1);
    EXPECT_EQ(changes::seen_portals(l, links::link_portals(l), view_at(0, {1.99, 1.6, 0}, 180)).seen[0], 1);
    // 2 cm beside the rectangle: no inner faces, nothing reached.
    EXPECT_EQ(reached(l, view_at(0, {1.99, 1.6, 0.52}, 180))[0], 0);
}

TEST(PortalRays, AVisibleAreaAndTheStepLeaveRaysOut) {
    const layout::Layout l = door_swap();
    math::View v = view_at(0, {0, 1.6, 0}, -60);  // hall_east at u 0.64..0.98 of both images
    const Scene scene = prepare_scene(l).value();
    const PortalRays all = portal_rays(scene, v);
    EXPECT_EQ(all.reached[0], 1);
    EXPECT_EQ(all.rays, 2L * 160 * 90);
    EXPECT_EQ(portal_rays(scene, v, 4).rays, 2L * 40 * 23);
    v.eye_optics = std::array<math::EyeOptics, 2>{};
    for (math::EyeOptics& o : *v.eye_optics) {
        o.fov = {-45, 45, 45 * 9.0 / 16.0, -45 * 9.0 / 16.0};
        o.visible_area = {{0.0, 0.0}, {0.6, 0.0}, {0.6, 1.0}, {0.0, 1.0}};  // the left 60 %
    }
    EXPECT_EQ(portal_rays(scene, v).reached[0], 0);
    (*v.eye_optics)[0].visible_area = {{0.6, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.6, 1.0}};
    EXPECT_EQ(portal_rays(scene, v).reached[0], 1);
}

// The door swap with a mirror, a window pair and deep door boxes.
layout::Layout mixed() {
    layout::Layout l = door_swap();
    for (layout::Portal& p : l.portals) p.rect.depth = 0.2;
    l.portals.push_back(impossible::test::make_mirror("hall_mirror", 0, {0, 1.5, -2}, {0, 0, 1}, 1.5, 1.0));
    impossible::test::add_pair(l, impossible::test::make_window("hall_window", 0, {0, 1.5, 2}, {0, 0, -1}, 1.0, 1.0),
                               impossible::test::make_window("study_window", 1, {4, 1.5, 2}, {0, 0, -1}, 1.0, 1.0));
    return l;
}

// Free-standing coincident doors in three overlapping rooms, one pair
// re-paired across the room (a transfer that turns and moves).
layout::Layout overlapping() {
    layout::Layout l;
    const int a = impossible::test::add_room(l, "a", {-4, 0, -4}, {4, 3, 4});
    const int b = impossible::test::add_room(l, "b", {-3.5, 0, -4.5}, {4.5, 3, 3.5});
    const int c = impossible::test::add_room(l, "c", {-4.5, 0, -3.5}, {3.5, 3, 4.5});
    impossible::test::add_pair(l, impossible::test::make_portal("a1", a, {0, 1.1, -2}, {0, 0, 1}, 1.0, 2.2),
                               impossible::test::make_portal("b1", b, {0, 1.1, -2}, {0, 0, -1}, 1.0, 2.2));
    impossible::test::add_pair(l, impossible::test::make_portal("b2", b, {2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2),
                               impossible::test::make_portal("c2", c, {-2, 1.1, 0}, {0, 0, 1}, 1.0, 2.2));
    impossible::test::add_pair(l, impossible::test::make_portal("c3", c, {0, 1.1, 2}, {0, 0, -1}, 1.0, 2.2),
                               impossible::test::make_portal("a3", a, {0, 1.1, 2}, {0, 0, 1}, 1.0, 2.2));
    for (layout::Portal& p : l.portals) p.rect.depth = 0.1;
    return l;
}

TEST(PortalRays, EveryPortalReachedIsSeen) {
    for (const layout::Layout& l : {door_swap(), mixed(), overlapping()}) {
        const links::PortalLinks links = links::link_portals(l);
        const Scene scene = prepare_scene(l).value();
        std::mt19937 random(11);
        std::uniform_real_distribution<double> x(-1.9, 1.9), angle(-180, 180), pitch(-40, 40), y(1.0, 2.0);
        int reached_count = 0, seen_count = 0;
        for (int k = 0; k < 60; ++k) {
            math::View v = view_at(0, {x(random), y(random), x(random)}, angle(random), pitch(random));
            v.max_depth = 1 + k % 4;
            const changes::SeenPortals s = changes::seen_portals(l, links, v);
            ASSERT_FALSE(s.saturated);
            const PortalRays rays = portal_rays(scene, v, 2);
            for (std::size_t p = 0; p < l.portals.size(); ++p) {
                if (rays.reached[p]) {
                    EXPECT_EQ(s.seen[p], 1) << "view " << k << " portal " << l.portals[p].id;
                }
                reached_count += rays.reached[p];
                seen_count += s.seen[p];
            }
        }
        EXPECT_GT(reached_count, 20) << l.portals.size();
        EXPECT_GE(seen_count, reached_count);
    }
}

}  // namespace
}  // namespace impossible::trace
