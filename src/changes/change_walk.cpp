#include "changes/change_walk.hpp"

#include <algorithm>

namespace impossible::changes {

ChangeWalk::ChangeWalk(const layout::Layout& layout)
    : layout_(&layout), pairing_(loaded_pairing(layout)), status_(layout.changes.size()) {}

bool ChangeWalk::pending() const {
    return std::any_of(status_.begin(), status_.end(), [](const ChangeStatus& s) { return s.made_frame < 0; });
}

bool ChangeWalk::condition(const layout::Change& change, int frame, int room, double time) const {
    const layout::ChangeWhen& when = change.when;
    if (when.enter >= 0 && when.enter != room) return false;
    if (when.after >= 0) {
        const int made = status_[static_cast<std::size_t>(when.after)].made_frame;
        if (made < 0 || made >= frame) return false;
    }
    return !when.time || time >= *when.time;
}

std::vector<int> ChangeWalk::consider(int frame, int room, double time,
                                      const std::function<std::vector<char>()>& seen) {
    std::vector<int> made;
    std::vector<char> seen_doors;
    bool asked = false;
    for (std::size_t c = 0; c < status_.size(); ++c) {
        ChangeStatus& s = status_[c];
        if (s.made_frame >= 0) continue;
        const layout::Change& change = layout_->changes[c];
        if (!s.armed) s.armed = condition(change, frame, room, time);
        if (!s.armed) continue;
        if (!asked) {
            seen_doors = seen();
            asked = true;
        }
        const std::vector<int> affected = affected_doors(change, pairing_);
        const bool any_seen = std::any_of(affected.begin(), affected.end(), [&](int d) {
            return d < 0 || static_cast<std::size_t>(d) >= seen_doors.size() || seen_doors[static_cast<std::size_t>(d)];
        });
        if (any_seen) continue;
        make_change(change, pairing_);
        s.made_frame = frame;
        made.push_back(static_cast<int>(c));
    }
    return made;
}

}  // namespace impossible::changes
