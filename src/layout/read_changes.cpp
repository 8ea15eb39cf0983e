// layout-format.md, "Changes while walking": the top-level `changes`. Each
// change names its condition (`when`) by room and change ids and its new
// pairs by door ids, so it is read once the portals are paired and the
// start's room is known.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"

namespace impossible::layout::detail {

namespace {

// What the changes name, found among the rest of the layout.
struct ChangeContext {
    const std::vector<PortalDraft>& portals;
    std::map<std::string, int> portal_index;  // portal draft indices
    std::map<std::string, int> room_index;
    bool rooms_known = false;
};

struct ChangeDraft {
    Change change;  // its pairs hold portal draft indices until the end
    Path path;
    bool has_id = false;
    std::optional<std::string> after_id;  // linked once every change's id is known
};

// "width × height m" of a door, for messages.
std::string size_text(const math::PortalRect& rect) {
    return format_number(rect.width) + " x " + format_number(rect.height) + " m";
}

// `when`: at least one of `enter`, `after` and `time`.
void read_when(Checker& check, const Path& at, const json& value, const ChangeContext& context, ChangeDraft& draft) {
    if (!check.expect_object(at, value)) return;
    check.check_fields(at, value, {"enter", "after", "time"}, {});
    // An object with only unknown fields has had them reported; comments
    // ("_...") alone leave it empty.
    bool empty = true;
    for (auto it = value.begin(); it != value.end(); ++it) empty = empty && !it.key().empty() && it.key()[0] == '_';
    if (empty) {
        check.error(at, "needs at least one of \"enter\" (a room id), \"after\" (a change id) and \"time\" (seconds)");
    }
    ChangeWhen& when = draft.change.when;
    if (const json* v = field(value, "enter")) {
        if (const auto id = check.read_string(at / "enter", *v)) {
            const auto it = context.room_index.find(*id);
            if (it != context.room_index.end()) {
                when.enter = it->second;
            } else if (context.rooms_known) {
                check.error(at / "enter", "no room has the id " + quote(*id));
            }
        }
    }
    if (const json* v = field(value, "after")) draft.after_id = check.read_string(at / "after", *v);
    if (const json* v = field(value, "time")) when.time = check.read_number(at / "time", *v, NumberKind::Time);
}

// One door of a pair: its portal draft index, or -1 (reported, unless the
// portal's own kind could not be read).
int read_door(Checker& check, const Path& at, const json& value, const ChangeContext& context) {
    const auto id = check.read_string(at, value);
    if (!id) return -1;
    const auto it = context.portal_index.find(*id);
    if (it == context.portal_index.end()) {
        check.error(at, "no portal has the id " + quote(*id));
        return -1;
    }
    const PortalDraft& portal = context.portals[static_cast<std::size_t>(it->second)];
    const bool door = !portal.volume && portal.portal.kind == PortalKind::Door;
    if (portal.kind_ok && !door) {
        const std::string kind = portal.volume ? "volume" : kind_name(portal.portal.kind);
        check.error(at,
                    quote(*id) + " is a " + kind + "; a change re-pairs doors only (not mirrors, windows or volumes)");
        return -1;
    }
    return portal.kind_ok ? it->second : -1;
}

// Pair `i` of `pairs` at `at`; `used` maps each door already in a pair of
// this change to that pair's index.
void read_pair(Checker& check, const Path& at, const json& value, std::size_t i, const ChangeContext& context,
               std::map<int, std::size_t>& used, ChangeDraft& draft) {
    if (!value.is_array() || value.size() != 2) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        check.error(at, "must be an array of 2 door ids (got " + got + ")");
        return;
    }
    std::array<int, 2> doors{read_door(check, at / 0, value[0], context), read_door(check, at / 1, value[1], context)};
    bool ok = doors[0] >= 0 && doors[1] >= 0;
    if (ok && doors[0] == doors[1]) {
        check.error(at / 1, "names the door " + quote(context.portals[static_cast<std::size_t>(doors[1])].portal.id) +
                                " twice (a door cannot target itself)");
        return;
    }
    for (std::size_t k = 0; k < 2; ++k) {
        if (doors[k] < 0) continue;
        const auto [it, inserted] = used.emplace(doors[k], i);
        if (!inserted) {
            const std::string& id = context.portals[static_cast<std::size_t>(doors[k])].portal.id;
            check.error(at / k, "the door " + quote(id) + " is already in pairs[" + std::to_string(it->second) +
                                    "] of this change (a door is in at most one pair of a change)");
            ok = false;
        }
    }
    if (!ok) return;
    const PortalDraft& a = context.portals[static_cast<std::size_t>(doors[0])];
    const PortalDraft& b = context.portals[static_cast<std::size_t>(doors[1])];
    if (a.rect_ok && b.rect_ok &&
        (std::abs(a.portal.rect.width - b.portal.rect.width) > limits::kPairSizeTolerance ||
         std::abs(a.portal.rect.height - b.portal.rect.height) > limits::kPairSizeTolerance)) {
        check.error(at, "the doors " + quote(a.portal.id) + " (" + size_text(a.portal.rect) + ") and " +
                            quote(b.portal.id) + " (" + size_text(b.portal.rect) +
                            ") differ in size (the doors of a pair must have the same width and height, within " +
                            format_number(limits::kPairSizeTolerance) + " m)");
        return;
    }
    draft.change.pairs.push_back(doors);
}

void read_pairs(Checker& check, const Path& at, const json& value, const ChangeContext& context, ChangeDraft& draft) {
    if (!check.expect_array(at, value, limits::kMaxPortals)) return;
    if (value.empty()) {
        check.error(at, "must list at least one pair of door ids");
        return;
    }
    std::map<int, std::size_t> used;
    for (std::size_t i = 0; i < value.size(); ++i) read_pair(check, at / i, value[i], i, context, used, draft);
}

ChangeDraft read_change(Checker& check, const Path& at, const json& value, const ChangeContext& context) {
    ChangeDraft draft;
    draft.path = at;
    if (!check.expect_object(at, value)) return draft;
    check.check_fields(at, value, {"id", "when", "pairs"}, {"id", "when", "pairs"});
    if (const json* v = field(value, "id")) {
        if (auto id = check.read_id(at / "id", *v)) {
            draft.change.id = std::move(*id);
            draft.has_id = true;
        }
    }
    if (const json* v = field(value, "when")) read_when(check, at / "when", *v, context, draft);
    if (const json* v = field(value, "pairs")) read_pairs(check, at / "pairs", *v, context, draft);
    return draft;
}

// Each `after` names an earlier change: changes are considered in file
// order, so a change can only wait for one already considered (and no
// cycle can be written).
void link_afters(Checker& check, std::vector<ChangeDraft>& drafts, bool ids_reliable) {
    std::map<std::string, int> index;
    bool all_ids = ids_reliable;
    for (std::size_t i = 0; i < drafts.size(); ++i) {
        if (drafts[i].has_id) index.emplace(drafts[i].change.id, static_cast<int>(i));
        all_ids = all_ids && drafts[i].has_id;
    }
    for (std::size_t i = 0; i < drafts.size(); ++i) {
        ChangeDraft& draft = drafts[i];
        if (!draft.after_id) continue;
        const Path at = draft.path / "when" / "after";
        const auto it = index.find(*draft.after_id);
        if (it == index.end()) {
            if (all_ids) check.error(at, "no change has the id " + quote(*draft.after_id));
        } else if (static_cast<std::size_t>(it->second) == i) {
            check.error(at,
                        "names this change itself; \"after\" must name an earlier change (changes are "
                        "considered in file order)");
        } else if (static_cast<std::size_t>(it->second) > i) {
            check.error(at, "names a later change, changes[" + std::to_string(it->second) +
                                "]; \"after\" must name an earlier change (changes are considered in file "
                                "order): move " +
                                quote(*draft.after_id) + " before this one");
        } else {
            draft.change.when.after = it->second;
        }
    }
}

// The rooms a head could ever be in: those reached from `start_room` through
// doors paired in the layout or by any change, each pair walked both ways
// (more than walking allows, so that a warning is never wrong).
std::vector<bool> reachable_rooms(const std::vector<PortalDraft>& portals, std::size_t room_count, int start_room,
                                  const std::vector<ChangeDraft>& drafts) {
    std::vector<std::vector<int>> next(room_count);
    const auto join = [&](int a, int b) {
        const int ra = portals[static_cast<std::size_t>(a)].portal.room;
        const int rb = portals[static_cast<std::size_t>(b)].portal.room;
        if (ra < 0 || rb < 0) return;  // reported
        next[static_cast<std::size_t>(ra)].push_back(rb);
        next[static_cast<std::size_t>(rb)].push_back(ra);
    };
    for (std::size_t i = 0; i < portals.size(); ++i) {
        const PortalDraft& p = portals[i];
        if (!p.volume && p.portal.kind == PortalKind::Door && p.portal.target >= 0)
            join(static_cast<int>(i), p.portal.target);
    }
    for (const ChangeDraft& draft : drafts) {
        for (const auto& pair : draft.change.pairs) join(pair[0], pair[1]);
    }
    std::vector<bool> seen(room_count, false);
    std::deque<int> queue{start_room};
    seen[static_cast<std::size_t>(start_room)] = true;
    while (!queue.empty()) {
        const int room = queue.front();
        queue.pop_front();
        for (const int to : next[static_cast<std::size_t>(room)]) {
            if (!seen[static_cast<std::size_t>(to)]) {
                seen[static_cast<std::size_t>(to)] = true;
                queue.push_back(to);
            }
        }
    }
    return seen;
}

// Warnings for a change that can never happen (its room cannot be reached,
// or it waits for a change that can never happen) and for one that changes
// nothing: each of its pairs is a pair of the layout, and no other change
// names any of its doors (so they are still paired so when it is made).
void warn_changes(Checker& check, const std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                  int start_room, const std::vector<ChangeDraft>& drafts) {
    if (start_room < 0) return;  // reported
    const std::vector<bool> reachable = reachable_rooms(portals, rooms.size(), start_room, drafts);
    std::map<int, int> naming;  // door → how many changes name it
    for (const ChangeDraft& draft : drafts) {
        for (const auto& pair : draft.change.pairs) ++naming[pair[0]], ++naming[pair[1]];
    }
    std::vector<bool> possible(drafts.size(), true);
    for (std::size_t i = 0; i < drafts.size(); ++i) {
        const ChangeWhen& when = drafts[i].change.when;
        const Path at = drafts[i].path / "when";
        if (when.enter >= 0 && !reachable[static_cast<std::size_t>(when.enter)]) {
            possible[i] = false;
            check.warning(at / "enter", "this change can never happen: no door leads from the start to the room " +
                                            quote(rooms[static_cast<std::size_t>(when.enter)].room.id) +
                                            " (with the layout's pairs or any change's)");
        }
        if (when.after >= 0 && !possible[static_cast<std::size_t>(when.after)]) {
            possible[i] = false;
            check.warning(at / "after", "this change can never happen: it waits for " +
                                            quote(drafts[static_cast<std::size_t>(when.after)].change.id) +
                                            ", which can never happen");
        }
        const auto& pairs = drafts[i].change.pairs;
        const bool same = std::all_of(pairs.begin(), pairs.end(), [&](const std::array<int, 2>& pair) {
            return portals[static_cast<std::size_t>(pair[0])].portal.target == pair[1] && naming[pair[0]] == 1 &&
                   naming[pair[1]] == 1;
        });
        if (same) {
            check.warning(drafts[i].path / "pairs",
                          "changes nothing: each of its pairs is already paired so in the layout, and no other "
                          "change re-pairs these doors");
        }
    }
}

}  // namespace

std::vector<Change> read_changes(Checker& check, const Path& at, const json& changes,
                                 const std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                                 int start_room, bool rooms_known, bool ids_reliable) {
    if (!check.expect_array(at, changes, limits::kMaxChanges)) return {};
    const ChangeContext context{portals, index_by_id(portals), index_by_id(rooms), rooms_known};
    std::vector<ChangeDraft> drafts;
    std::map<std::string, std::size_t> first_use;
    for (std::size_t i = 0; i < changes.size(); ++i) {
        ChangeDraft draft = read_change(check, at / i, changes[i], context);
        if (draft.has_id) {
            const auto [it, inserted] = first_use.emplace(draft.change.id, i);
            if (!inserted) {
                check.error(at / i / "id", "duplicate change id " + quote(draft.change.id) + " (also used by changes[" +
                                               std::to_string(it->second) + "])");
            }
        }
        drafts.push_back(std::move(draft));
    }
    link_afters(check, drafts, ids_reliable);
    if (check.has_errors()) return {};
    warn_changes(check, portals, rooms, start_room, drafts);
    const std::vector<int> index = paired_indices(portals);
    std::vector<Change> out;
    for (ChangeDraft& draft : drafts) {
        for (auto& pair : draft.change.pairs)
            pair = {index[static_cast<std::size_t>(pair[0])], index[static_cast<std::size_t>(pair[1])]};
        out.push_back(std::move(draft.change));
    }
    return out;
}

}  // namespace impossible::layout::detail
