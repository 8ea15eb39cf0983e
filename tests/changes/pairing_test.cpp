// The pairing in force and the layout it gives (changes/pairing.hpp).
#include "changes/pairing.hpp"

#include <gtest/gtest.h>

#include "changes/change_layouts.hpp"

namespace impossible::changes {
namespace {

TEST(Pairing, TheLoadedPairingIsThePortalsTargets) {
    const layout::Layout l = testing::door_swap();
    EXPECT_EQ(loaded_pairing(l).target, (std::vector<int>{1, 0, 3, 2}));
}

TEST(Pairing, AChangeAffectsItsDoorsAndTheirPartners) {
    const layout::Layout l = testing::door_swap();
    EXPECT_EQ(affected_doors(l.changes[0], loaded_pairing(l)), (std::vector<int>{0, 1, 2, 3}));
}

TEST(Pairing, MakingAChangePairsItsDoorsAndClosesTheFormerPartners) {
    const layout::Layout l = testing::door_swap();
    Pairing p = loaded_pairing(l);
    make_change(l.changes[0], p);
    EXPECT_EQ(p.target, (std::vector<int>{3, -1, -1, 0}));
    // A closed door named again opens with its new partner.
    layout::Change back;
    back.pairs = {{0, 1}};
    EXPECT_EQ(affected_doors(back, p), (std::vector<int>{0, 1, 3}));
    make_change(back, p);
    EXPECT_EQ(p.target, (std::vector<int>{1, 0, -1, -1}));
}

TEST(Pairing, ThePairedLayoutLeavesClosedDoorsOutAndRenumbersTargets) {
    const layout::Layout l = testing::door_swap();
    Pairing p = loaded_pairing(l);
    make_change(l.changes[0], p);
    const PairedLayout paired = paired_layout(l, p);
    ASSERT_EQ(paired.layout.portals.size(), 2u);
    EXPECT_EQ(paired.base_index, (std::vector<int>{0, 3}));
    EXPECT_EQ(paired.layout.portals[0].id, "hall_east");
    EXPECT_EQ(paired.layout.portals[0].target, 1);
    EXPECT_EQ(paired.layout.portals[1].id, "garden_west");
    EXPECT_EQ(paired.layout.portals[1].target, 0);
    EXPECT_TRUE(paired.layout.changes.empty());
    EXPECT_EQ(paired.layout.rooms.size(), l.rooms.size());
}

TEST(Pairing, TheLoadedPairingGivesTheLayoutItself) {
    const layout::Layout l = testing::door_swap();
    const PairedLayout paired = paired_layout(l, loaded_pairing(l));
    ASSERT_EQ(paired.layout.portals.size(), l.portals.size());
    for (std::size_t k = 0; k < l.portals.size(); ++k) EXPECT_EQ(paired.layout.portals[k].target, l.portals[k].target);
}

}  // namespace
}  // namespace impossible::changes
