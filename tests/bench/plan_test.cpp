// keep_first_portals: closing portals for the bench's portal sweep keeps
// pairs whole, mirrors (which have no target) and renumbers targets.
#include <gtest/gtest.h>

#include "bench/plan.hpp"

namespace impossible::bench {
namespace {

layout::Portal portal(const std::string& id, int target, layout::PortalKind kind) {
    layout::Portal p;
    p.id = id;
    p.room = 0;
    p.target = target;
    p.kind = kind;
    return p;
}

TEST(BenchPlan, KeepFirstPortalsKeepsMirrorsAndWholePairs) {
    layout::Layout l;
    l.rooms.resize(1);
    using layout::PortalKind;
    l.portals = {portal("mirror", -1, PortalKind::Mirror), portal("a", 3, PortalKind::Door),
                 portal("w", 4, PortalKind::Window),       portal("b", 1, PortalKind::Door),
                 portal("x", 2, PortalKind::Window),       portal("late_mirror", -1, PortalKind::Mirror)};
    // The first four: the mirror and the door pair; w's partner is beyond.
    const layout::Layout four = keep_first_portals(l, 4);
    ASSERT_EQ(four.portals.size(), 3u);
    EXPECT_EQ(four.portals[0].id, "mirror");
    EXPECT_EQ(four.portals[0].target, -1);
    EXPECT_EQ(four.portals[1].id, "a");
    EXPECT_EQ(four.portals[1].target, 2);
    EXPECT_EQ(four.portals[2].id, "b");
    EXPECT_EQ(four.portals[2].target, 1);
    // All of them.
    const layout::Layout all = keep_first_portals(l, 6);
    ASSERT_EQ(all.portals.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(all.portals[i].target, l.portals[i].target);
    // None.
    EXPECT_TRUE(keep_first_portals(l, 0).portals.empty());
}

}  // namespace
}  // namespace impossible::bench
