// What validate says of a layout's changes (layout-format.md, "Changes while
// walking"): each change's condition and pairs, and the rooms it makes
// reachable.
//
// Reachable with changes: the rooms reachable from the start through doors
// with the layout's pairing, then, for each change in file order, the rooms
// reachable with the pairing after it (the loaded pairing with every change
// up to and including it applied, in file order) from where the walker can
// be when it is made: its `enter` room when it has one, else any room
// reachable so far. A change "makes reachable" the rooms so found that were
// not reachable before it. A change that can never happen (its `enter` room
// is not reachable so far, or its `after` change can never happen) makes
// nothing reachable and is not applied to the later changes' pairing. This
// is an upper bound of what a walk reaches: a room reachable under an
// earlier pairing may be cut off by a later one.
#pragma once

#include <string>
#include <vector>

#include "changes/pairing.hpp"
#include "layout/layout.hpp"

namespace impossible::design {

struct ChangeReach {
    bool can_happen = true;
    std::vector<int> affected;         // changes::affected_doors under the pairing before it
    std::vector<int> makes_reachable;  // rooms, file order
};

struct ChangesReach {
    std::vector<ChangeReach> changes;  // one per layout change
    // For each room: -1 if reachable with the layout's pairing or never;
    // else the change after which it first is.
    std::vector<int> after_change;
    std::vector<char> reachable;  // per room, with changes
};

// Rooms reachable from `from` through doors paired by `pairing`.
std::vector<char> reachable_rooms(const layout::Layout& layout, const changes::Pairing& pairing,
                                  const std::vector<int>& from);

ChangesReach changes_reach(const layout::Layout& layout);

// "enter study, after swap, time 2 s".
std::string condition_text(const layout::Layout& layout, const layout::Change& change);

}  // namespace impossible::design
