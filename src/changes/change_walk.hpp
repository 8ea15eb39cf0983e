// When changes are armed and made (layout-format.md, "Changes while
// walking"). After each frame's step the changes are considered in file
// order: a change not yet made is armed once its condition holds (the head
// is in its `enter` room, its `after` change was made at an earlier frame,
// the frame's time is at least its `time`), and an armed change is made at
// the first frame at which neither eye sees any door it affects. The seen
// test of a frame uses the pairing the frame started with, so it is asked
// once a frame, and only when some armed change waits.
//
// One reading of the spec (docs/changes.md): `enter` holds at every frame at
// which the head is in that room, i.e. from the frame whose step put it
// there until a step takes it out.
#pragma once

#include <functional>
#include <vector>

#include "changes/pairing.hpp"
#include "layout/layout.hpp"

namespace impossible::changes {

// What the walk knows of one change.
struct ChangeStatus {
    bool armed = false;
    int made_frame = -1;  // the frame it was made at; -1: not yet
};

class ChangeWalk {
public:
    // The layout must outlive this.
    explicit ChangeWalk(const layout::Layout& layout);

    // Whether some change has not been made yet.
    bool pending() const;
    // Frame `frame` (numbered from 0, at `time` seconds) after its step,
    // with the head in room `room`. `seen` gives, per portal of the loaded
    // layout, whether either eye sees it under the pairing the frame started
    // with; it is called at most once. Returns the indices of the changes
    // made at this frame, in file order (the pairing is then theirs).
    std::vector<int> consider(int frame, int room, double time, const std::function<std::vector<char>()>& seen);

    const Pairing& pairing() const { return pairing_; }
    const std::vector<ChangeStatus>& status() const { return status_; }

private:
    bool condition(const layout::Change& change, int frame, int room, double time) const;

    const layout::Layout* layout_;
    Pairing pairing_;
    std::vector<ChangeStatus> status_;
};

}  // namespace impossible::changes
