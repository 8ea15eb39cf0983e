// The seen test (changes/seen.hpp) on chosen views, and against dense rays
// (brute_rays.hpp) on random ones: it never calls a portal unseen that a
// ray reaches.
#include "changes/seen.hpp"

#include <random>

#include <gtest/gtest.h>

#include "changes/brute_rays.hpp"
#include "changes/change_layouts.hpp"
#include "math/hidden_area.hpp"

namespace impossible::changes {
namespace {

using testing::door_swap;

math::View view_at(int room, math::dvec3 head, double yaw, double pitch = 0.0) {
    math::View v;
    v.room = room;
    v.head = {head, yaw, pitch, 0.0};
    v.eye_width = 320;
    v.eye_height = 180;
    return v;
}

std::vector<char> seen(const layout::Layout& l, const math::View& v) {
    return seen_portals(l, links::link_portals(l), v).seen;
}

TEST(Seen, ADoorAheadIsSeenAndOneBehindIsNot) {
    const layout::Layout l = door_swap();
    // Looking east (yaw -90) from the hall's centre: hall_east (0) ahead;
    // hall_west (2) behind. study_west and garden_west face away from the
    // hall's eye through nothing.
    EXPECT_EQ(seen(l, view_at(0, {0, 1.6, 0}, -90)), (std::vector<char>{1, 0, 0, 0}));
    EXPECT_EQ(seen(l, view_at(0, {0, 1.6, 0}, 90)), (std::vector<char>{0, 0, 1, 0}));
    // Looking north (yaw 0) with a 90° field of view: both doors lie at
    // 90° to the side, outside the frustum.
    EXPECT_EQ(seen(l, view_at(0, {0, 1.6, 0}, 0)), (std::vector<char>{0, 0, 0, 0}));
}

TEST(Seen, ThroughADoorTheTargetRoomsDoorsAreSeenFromTheirFront) {
    const layout::Layout l = door_swap();
    // In the study, looking west at study_west (1) from 1 m: it is seen; its
    // target hall_east faces away from the virtual eye; through it, the
    // hall's west door (2) at the far end is seen.
    EXPECT_EQ(seen(l, view_at(1, {3, 1.6, 0}, 90)), (std::vector<char>{0, 1, 1, 0}));
    math::View shallow = view_at(1, {3, 1.6, 0}, 90);
    shallow.max_depth = 0;  // reached, not passed
    EXPECT_EQ(seen(l, shallow), (std::vector<char>{0, 1, 0, 0}));
}

TEST(Seen, AnEyeInsideTheBoxItReachedThroughTheDoorSeesThroughIt) {
    const layout::Layout l = door_swap();
    // The head 1 cm in front of hall_east, turned south (yaw 180): the
    // rectangle lies behind both eyes' frusta, but the left eye (+x, 3.2 cm)
    // is behind the plane, inside the box, reached through the door. Its box
    // shows the study, so hall_east counts as seen.
    EXPECT_EQ(seen(l, view_at(0, {1.99, 1.6, 0}, 180))[0], 1);
    // The same head 2 cm beside the rectangle's edge (z = 0.52): the eye is
    // not over the rectangle, so it has no inner faces.
    EXPECT_EQ(seen(l, view_at(0, {1.99, 1.6, 0.52}, 180))[0], 0);
}

TEST(Seen, AVisibleAreaHidesWhatLiesOutsideIt) {
    const layout::Layout l = door_swap();
    math::View v = view_at(0, {0, 1.6, 0}, -60);  // hall_east at u 0.64..0.98 of both images
    ASSERT_EQ(seen(l, v)[0], 1);
    v.eye_optics = std::array<math::EyeOptics, 2>{};
    for (math::EyeOptics& o : *v.eye_optics) {
        o.fov = {-45, 45, 45 * 9.0 / 16.0, -45 * 9.0 / 16.0};
        o.visible_area = {{0.0, 0.0}, {0.6, 0.0}, {0.6, 1.0}, {0.0, 1.0}};  // the left 60 %
    }
    v.fov_y_deg = 0;  // not read with optics
    testing::BruteRays brute{l, links::link_portals(l)};
    brute.view(v, 2);
    EXPECT_EQ(brute.seen[0], 0);
    EXPECT_EQ(seen(l, v)[0], 0);
    (*v.eye_optics)[0].visible_area = {{0.6, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.6, 1.0}};
    EXPECT_EQ(seen(l, v)[0], 1);
}

// A room of mirrors and windows as well as doors, for random views.
layout::Layout mixed() {
    layout::Layout l = door_swap();
    l.portals.push_back(test::make_mirror("hall_mirror", 0, {0, 1.5, -2}, {0, 0, 1}, 1.5, 1.0));
    test::add_pair(l, test::make_window("hall_window", 0, {0, 1.5, 2}, {0, 0, -1}, 1.0, 1.0),
                   test::make_window("study_window", 1, {4, 1.5, 2}, {0, 0, -1}, 1.0, 1.0));
    return l;
}

TEST(Seen, NeverUnseenWhereADenseRayReachesIt) {
    for (const layout::Layout& l : {door_swap(), mixed()}) {
        const links::PortalLinks links = links::link_portals(l);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> x(-1.9, 1.9), angle(-180, 180), pitch(-40, 40), y(1.0, 2.0);
        int seen_count = 0, unseen_count = 0;
        for (int k = 0; k < 60; ++k) {
            math::View v = view_at(0, {x(random), y(random), x(random)}, angle(random), pitch(random));
            v.max_depth = 1 + k % 4;
            const SeenPortals s = seen_portals(l, links, v);
            ASSERT_FALSE(s.saturated);
            testing::BruteRays brute{l, links};
            brute.view(v, 4);
            for (std::size_t p = 0; p < l.portals.size(); ++p) {
                if (brute.seen[p]) {
                    EXPECT_EQ(s.seen[p], 1) << "view " << k << " portal " << l.portals[p].id;
                }
                (s.seen[p] ? seen_count : unseen_count)++;
            }
        }
        EXPECT_GT(seen_count, 20);
        EXPECT_GT(unseen_count, 20);
    }
}

TEST(Seen, ARoomOfWindowsSaturatesAndThenSeesEverything) {
    layout::Layout l;
    const int r = test::add_room(l, "r", {-1, 0, -1}, {1, 2, 1});
    test::add_pair(l, test::make_window("w", r, {-1, 1, 0}, {1, 0, 0}, 2, 2),
                   test::make_window("e", r, {1, 1, 0}, {-1, 0, 0}, 2, 2));
    test::add_pair(l, test::make_window("n", r, {0, 1, -1}, {0, 0, 1}, 2, 2),
                   test::make_window("s", r, {0, 1, 1}, {0, 0, -1}, 2, 2));
    math::View v = view_at(r, {0.1, 1.1, 0.2}, 20);
    v.max_depth = 250;
    const SeenPortals s = seen_portals(l, links::link_portals(l), v);
    EXPECT_TRUE(s.saturated);
    EXPECT_EQ(s.seen, (std::vector<char>{1, 1, 1, 1}));
}

}  // namespace
}  // namespace impossible::changes
