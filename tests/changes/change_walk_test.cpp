// When changes are armed and made (changes/change_walk.hpp).
#include "changes/change_walk.hpp"

#include <gtest/gtest.h>

#include "changes/change_layouts.hpp"

namespace impossible::changes {
namespace {

// A seen test that calls the listed portals seen and counts its calls.
struct FakeSeen {
    std::vector<char> seen = std::vector<char>(4, 0);
    int calls = 0;
    std::function<std::vector<char>()> fn() {
        return [this] {
            ++calls;
            return seen;
        };
    }
};

TEST(ChangeWalk, AChangeIsArmedInItsRoomAndMadeWhenItsDoorsAreUnseen) {
    const layout::Layout l = testing::door_swap();
    ChangeWalk walk(l);
    FakeSeen s;
    EXPECT_TRUE(walk.consider(0, 0, 0.0, s.fn()).empty());  // in the hall: not armed
    EXPECT_EQ(s.calls, 0);                                  // nothing armed, nothing asked
    s.seen[1] = 1;                                          // study_west, hall_east's partner, in view
    EXPECT_TRUE(walk.consider(1, 1, 0.1, s.fn()).empty());
    EXPECT_TRUE(walk.status()[0].armed);
    EXPECT_EQ(s.calls, 1);
    s.seen[1] = 0;
    // Armed stays armed when the head leaves the room.
    EXPECT_EQ(walk.consider(2, 0, 0.2, s.fn()), (std::vector<int>{0}));
    EXPECT_EQ(walk.status()[0].made_frame, 2);
    EXPECT_EQ(walk.pairing().target, (std::vector<int>{3, -1, -1, 0}));
    EXPECT_FALSE(walk.pending());
    // Made once.
    EXPECT_TRUE(walk.consider(3, 1, 0.3, s.fn()).empty());
}

TEST(ChangeWalk, AfterNeedsAnEarlierFrameAndTimeNeedsTheTime) {
    layout::Layout l = testing::door_swap();
    l.changes[0].when.enter = -1;
    l.changes[0].when.time = 1.0;
    layout::Change back;
    back.id = "back";
    back.when.after = 0;
    back.pairs = {{0, 1}};
    l.changes.push_back(back);
    ChangeWalk walk(l);
    FakeSeen s;
    EXPECT_TRUE(walk.consider(0, 0, 0.5, s.fn()).empty());
    EXPECT_FALSE(walk.status()[0].armed);
    EXPECT_EQ(walk.consider(1, 0, 1.0, s.fn()), (std::vector<int>{0}));
    EXPECT_FALSE(walk.status()[1].armed);  // swap was made at this very frame
    EXPECT_EQ(walk.consider(2, 0, 1.1, s.fn()), (std::vector<int>{1}));
    EXPECT_EQ(walk.pairing().target, (std::vector<int>{1, 0, -1, -1}));
}

TEST(ChangeWalk, ChangesOfOneFrameAreConsideredInFileOrder) {
    layout::Layout l = testing::door_swap();
    l.changes[0].when.enter = 0;
    layout::Change again = l.changes[0];
    again.id = "again";
    again.pairs = {{0, 1}};  // hall_east back with study_west: affects garden_west, its partner after "swap"
    again.when.time = 1.0;   // armed at frame 2
    l.changes.push_back(again);
    ChangeWalk walk(l);
    FakeSeen s;
    s.seen[3] = 1;  // garden_west in view
    // "swap" affects garden_west too: neither is made.
    EXPECT_TRUE(walk.consider(0, 0, 0.0, s.fn()).empty());
    s.seen[3] = 0;
    s.seen[2] = 1;  // hall_west: swap's partner of garden_west
    EXPECT_TRUE(walk.consider(1, 0, 0.0, s.fn()).empty());
    s.seen[2] = 0;
    EXPECT_EQ(walk.consider(2, 0, 1.0, s.fn()), (std::vector<int>{0, 1}));
    EXPECT_EQ(s.calls, 3);  // once a frame
    // "swap" first, then "again" (the other order would end with swap's).
    EXPECT_EQ(walk.pairing().target, (std::vector<int>{1, 0, -1, -1}));
}

}  // namespace
}  // namespace impossible::changes
