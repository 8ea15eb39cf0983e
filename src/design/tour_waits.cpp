// The tour of a layout with changes: waiting for a change, and the end;
// see tour.hpp (plan_tour_with_changes) and tour_changes.hpp.
#include <algorithm>
#include <cmath>

#include "design/report_changes.hpp"
#include "design/tour_changes.hpp"

namespace impossible::design::detail {

std::string ChangePlanner::door_ids(int change) const {
    std::string out;
    for (const int d : changes::affected_doors(base_.changes[static_cast<std::size_t>(change)], sim_.pairing()))
        out += (out.empty() ? "" : ", ") + base_.portals[static_cast<std::size_t>(d)].id;
    return out;
}

// The first change, in file order, not made nor given up, that the walk can
// arm from here: its `after` made, its room reachable. Gives up those whose
// `after` was given up.
int ChangePlanner::next_change() {
    const std::vector<changes::ChangeStatus>& status = sim_.changes().status();
    for (std::size_t c = 0; c < base_.changes.size(); ++c) {
        if (status[c].made_frame >= 0 || !given_up_[c].empty()) continue;
        const layout::ChangeWhen& when = base_.changes[c].when;
        if (when.after >= 0 && status[static_cast<std::size_t>(when.after)].made_frame < 0) {
            if (!given_up_[static_cast<std::size_t>(when.after)].empty())
                given_up_[c] = "it waits for change \"" + base_.changes[static_cast<std::size_t>(when.after)].id +
                               "\", which cannot happen on the tour's route";
            continue;
        }
        if (when.enter >= 0 && (!stage_.reachable[when.enter] || failed_.count(when.enter))) continue;
        return static_cast<int>(c);
    }
    return -1;
}

// Turns on the spot in steps of kTurnDeg, at `pitch`, until a change is made.
Went ChangePlanner::turn_round(double pitch) {
    for (int k = 0; k < static_cast<int>(360.0 / kTurnDeg); ++k) {
        yaw_ = std::remainder(yaw_ + kTurnDeg, 360.0);
        if (pose({last_, yaw_, pitch, 0.0}) == Went::Changed) return Went::Changed;
    }
    return Went::Ok;
}

// Walks to the change's room, waits for its time and turns on the spot
// (here, the room's middle, near its corners; level, then looking down)
// until it is made. Gives it up if it is not.
Went ChangePlanner::wait_for(int c) {
    const layout::Change& change = base_.changes[static_cast<std::size_t>(c)];
    const int room = change.when.enter >= 0 ? change.when.enter : sim_.room();
    std::string why;
    if (sim_.room() != room) {
        const Went w = leg(room, why);
        if (w == Went::Changed) return w;
        if (w == Went::Failed) {
            failed_[room] = why;
            given_up_[static_cast<std::size_t>(c)] =
                "the tour cannot walk to its room \"" + base_.rooms[room].id + "\": " + why;
            return w;
        }
    }
    const double now = static_cast<double>(sim_.frame()) / layout::kDefaultPathFps;
    const double until = change.when.time.value_or(0.0);
    std::string note = "waits in " + base_.rooms[room].id + " for change " + change.id + ": ";
    if (until > now)
        note += "stands still until " + std::to_string(static_cast<long long>(std::ceil(until))) + " s, then ";
    t_.notes.push_back({t_.poses.size(), note + "turns away from its doors"});
    if (until > now + kMaxTourWait) {
        given_up_[static_cast<std::size_t>(c)] = "its time, " +
                                                 std::to_string(static_cast<long long>(std::ceil(until))) +
                                                 " s, is more than " + std::to_string(static_cast<int>(kMaxTourWait)) +
                                                 " s after the tour comes to room \"" + base_.rooms[room].id + "\"";
        return Went::Failed;
    }
    while (static_cast<double>(sim_.frame()) / layout::kDefaultPathFps < until)
        if (pose({last_, yaw_, 0.0, 0.0}) == Went::Changed) return Went::Changed;
    const layout::Room& box = sim_.current().rooms[room];
    const glm::dvec2 lo{box.min.x + 0.5, box.min.z + 0.5}, hi{box.max.x - 0.5, box.max.z - 0.5};
    const glm::dvec2 spots[] = {here(), 0.5 * (lo + hi), lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    for (const glm::dvec2& spot : spots) {
        glm::dvec2 at = here();
        const std::optional<glm::dvec2> free = grid(room).nearest_free(spot);
        if (!free) continue;
        const Went w = walk_to(room, at, *free);
        if (w == Went::Changed) return w;
        if (w == Went::Failed) continue;
        for (const double pitch : {0.0, -75.0})
            if (turn_round(pitch) == Went::Changed) return Went::Changed;
    }
    given_up_[static_cast<std::size_t>(c)] = "in room \"" + base_.rooms[room].id + "\" an eye sees one of its doors (" +
                                             door_ids(c) + ") wherever the tour stands and turns";
    return Went::Failed;
}

Result<Tour> ChangePlanner::run() {
    const layout::Start& s = base_.start;
    restage();
    last_ = {s.position.x, o_.grid.head_height, s.position.z};
    yaw_ = s.yaw_deg;
    pose({last_, yaw_, 0.0, 0.0});
    const std::optional<glm::dvec2> first = grid(sim_.room()).nearest_free(here());
    if (!first) return Error{"the start room \"" + base_.rooms[s.room].id + "\" has no room to walk"};
    glm::dvec2 at = here();
    walk_to(sim_.room(), at, *first);
    for (std::size_t guard = 0; guard < 100'000 && t_.poses.size() <= kMaxPoses; ++guard) {
        bool done = true;
        for (std::size_t r = 0; r < goal_.size(); ++r) done = done && (!goal_[r] || visited(static_cast<int>(r)));
        if (done) break;
        if (stage_.root != sim_.room()) restage(false);  // the ways start where the head is
        if (const int target = next_room(); target >= 0) {
            std::string why;
            if (leg(target, why) == Went::Failed) why_[target] = failed_[target] = why;
            continue;
        }
        const int c = next_change();
        if (c < 0) break;
        wait_for(c);
    }
    settle();
    return finish();
}

// Every room visited: a change armed but not yet made is waited for where
// the head stands (turning, level and looking down), so that the walk ends
// with it made; one that is not made there is left (no room needs it).
void ChangePlanner::settle() {
    const std::vector<changes::ChangeStatus>& status = sim_.changes().status();
    for (std::size_t c = 0; c < base_.changes.size() && t_.poses.size() <= kMaxPoses; ++c) {
        if (!status[c].armed || status[c].made_frame >= 0) continue;
        t_.notes.push_back({t_.poses.size(), "waits in " + base_.rooms[sim_.room()].id + " for change " +
                                                 base_.changes[c].id + ": turns away from its doors"});
        for (const double pitch : {0.0, -75.0})
            if (turn_round(pitch) == Went::Changed) break;
    }
}

// Why change c, not made, did not happen on the route.
std::string ChangePlanner::never_why(int c) const {
    if (!given_up_[static_cast<std::size_t>(c)].empty()) return given_up_[static_cast<std::size_t>(c)];
    const layout::ChangeWhen& when = base_.changes[static_cast<std::size_t>(c)].when;
    if (when.after >= 0 && sim_.changes().status()[static_cast<std::size_t>(when.after)].made_frame < 0)
        return "it waits for change \"" + base_.changes[static_cast<std::size_t>(when.after)].id +
               "\", which the tour never makes";
    if (when.enter >= 0) {
        const auto why = why_.find(when.enter);
        if (why != why_.end())
            return "the tour cannot walk to its room \"" + base_.rooms[when.enter].id + "\": " + why->second;
        return "no door leads to its room \"" + base_.rooms[when.enter].id + "\" on the tour's route";
    }
    return "the tour never waited for it";
}

Result<Tour> ChangePlanner::finish() {
    std::vector<int> missing;
    for (std::size_t r = 0; r < goal_.size(); ++r)
        if (goal_[r] && !visited(static_cast<int>(r))) missing.push_back(static_cast<int>(r));
    // A room doors lead to with the pairing in force was missed on the way
    // (a blocked door, the poses' limit), not for want of a change.
    if (stage_.root != sim_.room()) restage(false);
    const auto is_missing = [&](int r) {
        return !stage_.reachable[r] && std::find(missing.begin(), missing.end(), r) != missing.end();
    };
    const std::vector<changes::ChangeStatus>& status = sim_.changes().status();
    const ChangesReach reach = changes_reach(base_);
    // A room left out for a change that did not happen: the change it needs,
    // the one that makes it reachable, or else one whose pairs name its door.
    for (const bool by_pairs : {false, true})
        for (std::size_t c = 0; c < base_.changes.size(); ++c) {
            if (status[c].made_frame >= 0) continue;
            int room = -1;
            for (const int r : reach.changes[c].makes_reachable)
                if (room < 0 && is_missing(r)) room = r;
            if (by_pairs)
                for (const auto& pair : base_.changes[c].pairs)
                    for (const int d : pair)
                        if (room < 0 && is_missing(base_.portals[static_cast<std::size_t>(d)].room))
                            room = base_.portals[static_cast<std::size_t>(d)].room;
            if (room < 0) continue;
            return Error{"the tour cannot visit room \"" + base_.rooms[room].id + "\": it needs change \"" +
                         base_.changes[c].id +
                         "\", which can never happen on its route: " + never_why(static_cast<int>(c))};
        }
    t_.missed = missing;
    for (const int r : missing) {
        const auto why = why_.find(r);
        if (why == why_.end() && t_.poses.size() > kMaxPoses) {
            t_.why.push_back("the tour stopped at its limit of " + std::to_string(kMaxPoses) + " poses");
            continue;
        }
        t_.why.push_back(why != why_.end() ? why->second
                                           : "no door leads to it with the pairing the changes made left");
    }
    return t_;
}

}  // namespace impossible::design::detail

namespace impossible::design {

Result<Tour> plan_tour_with_changes(const layout::Layout& layout, const TourOptions& options) {
    return detail::ChangePlanner(layout, options).run();
}

}  // namespace impossible::design
