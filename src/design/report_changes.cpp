// What validate says of the changes; see report_changes.hpp.
#include "design/report_changes.hpp"

#include <cstdio>
#include <deque>

namespace impossible::design {

namespace {

// Each room's doors (pairing-independent).
std::vector<std::vector<int>> room_doors(const layout::Layout& layout) {
    std::vector<std::vector<int>> doors(layout.rooms.size());
    for (std::size_t p = 0; p < layout.portals.size(); ++p)
        if (layout.portals[p].kind == layout::PortalKind::Door)
            doors[static_cast<std::size_t>(layout.portals[p].room)].push_back(static_cast<int>(p));
    return doors;
}

std::vector<char> reachable_by(const layout::Layout& layout, const std::vector<std::vector<int>>& doors,
                               const changes::Pairing& pairing, const std::vector<int>& from) {
    std::vector<char> seen(layout.rooms.size(), 0);
    std::deque<int> queue;
    for (const int r : from)
        if (r >= 0 && !seen[static_cast<std::size_t>(r)]) {
            seen[static_cast<std::size_t>(r)] = 1;
            queue.push_back(r);
        }
    while (!queue.empty()) {
        const int room = queue.front();
        queue.pop_front();
        for (const int p : doors[static_cast<std::size_t>(room)]) {
            const int t = pairing.target[static_cast<std::size_t>(p)];
            if (t < 0) continue;  // closed
            const int next = layout.portals[static_cast<std::size_t>(t)].room;
            if (seen[static_cast<std::size_t>(next)]) continue;
            seen[static_cast<std::size_t>(next)] = 1;
            queue.push_back(next);
        }
    }
    return seen;
}

}  // namespace

std::vector<char> reachable_rooms(const layout::Layout& layout, const changes::Pairing& pairing,
                                  const std::vector<int>& from) {
    return reachable_by(layout, room_doors(layout), pairing, from);
}

ChangesReach changes_reach(const layout::Layout& layout) {
    ChangesReach out;
    const std::size_t rooms = layout.rooms.size();
    out.after_change.assign(rooms, -1);
    changes::Pairing pairing = changes::loaded_pairing(layout);
    const std::vector<std::vector<int>> doors = room_doors(layout);
    out.reachable = reachable_by(layout, doors, pairing, {layout.start.room});
    for (std::size_t c = 0; c < layout.changes.size(); ++c) {
        const layout::Change& change = layout.changes[c];
        ChangeReach reach;
        reach.affected = changes::affected_doors(change, pairing);
        const int enter = change.when.enter, after = change.when.after;
        if (enter >= 0 && !out.reachable[static_cast<std::size_t>(enter)]) reach.can_happen = false;
        if (after >= 0 && !out.changes[static_cast<std::size_t>(after)].can_happen) reach.can_happen = false;
        if (reach.can_happen) {
            changes::make_change(change, pairing);
            std::vector<int> from;
            if (enter >= 0) {
                from.push_back(enter);
            } else {
                for (std::size_t r = 0; r < rooms; ++r)
                    if (out.reachable[r]) from.push_back(static_cast<int>(r));
            }
            const std::vector<char> now = reachable_by(layout, doors, pairing, from);
            for (std::size_t r = 0; r < rooms; ++r)
                if (now[r] && !out.reachable[r]) {
                    out.reachable[r] = 1;
                    out.after_change[r] = static_cast<int>(c);
                    reach.makes_reachable.push_back(static_cast<int>(r));
                }
        }
        out.changes.push_back(std::move(reach));
    }
    return out;
}

std::string condition_text(const layout::Layout& layout, const layout::Change& change) {
    std::string out;
    auto add = [&out](const std::string& part) { out += (out.empty() ? "" : ", ") + part; };
    if (change.when.enter >= 0) add("enter " + layout.rooms[static_cast<std::size_t>(change.when.enter)].id);
    if (change.when.after >= 0) add("after " + layout.changes[static_cast<std::size_t>(change.when.after)].id);
    if (change.when.time) {
        char text[64];
        std::snprintf(text, sizeof text, "time %g s", *change.when.time);
        add(text);
    }
    return out;
}

}  // namespace impossible::design
