// Moving props walked over successive frames (prop_walks.hpp).
#include "walk/prop_walks.hpp"

#include <cmath>

#include "math/pose.hpp"

namespace impossible::walk {

namespace {

using math::dvec3;

dvec3 lerp_offset(const layout::MotionKey& a, const layout::MotionKey& b, double t) {
    const double s = (t - a.t) / (b.t - a.t);
    return a.offset + (b.offset - a.offset) * s;
}

math::HeadPose key_pose(const DynamicProp& p, std::size_t key) {
    return math::HeadPose{p.anchor + p.motion.keys[key].offset};
}

}  // namespace

PropWalks::PropWalks(const ObjectSet& set) : set_(&set), cursors_(set.props.size()) {}

// Placed at the first key (no crossing test); no period walked.
void PropWalks::start(Cursor& c, const DynamicProp& p) const {
    c = Cursor{};
    c.walker.emplace(*set_->walk_layout, p.room, set_->walk_links);
    c.walker->step(key_pose(p, 0));
    c.seen.push_back(Seen{c.walker->room(), c.walker->physical_to_virtual()});
}

namespace {

// Steps the keys after c.key while their time is at most `t`.
template <class Cursor>
void step_keys(Cursor& c, const DynamicProp& p, double t) {
    const std::vector<layout::MotionKey>& keys = p.motion.keys;
    while (c.key + 1 < keys.size() && keys[c.key + 1].t <= t) {
        ++c.key;
        c.walker->step(key_pose(p, c.key));
    }
}

// Whether the keys stepped lie past what `periods` whole periods and then
// the keys up to `rest` step.
template <class Cursor>
bool walked_past(const Cursor& c, const DynamicProp& p, double periods, double rest) {
    if (c.periods != periods) return c.periods > periods;
    return c.key > 0 && !(p.motion.keys[c.key].t <= rest);
}

}  // namespace

// How many periods a looping motion's walk takes for `periods` whole ones:
// once a repeat is known, those up to it and then the rest of the cycle;
// before, at most kMaxWalkedPeriods.
double PropWalks::target_periods(const Cursor& c, double periods, std::size_t keys) const {
    if (c.repeats && periods > c.repeat_at) {
        const double left = std::fmod(periods - c.repeat_at, c.cycle);
        return c.repeat_at + (left > 0.0 ? std::ceil(left) : 0.0);
    }
    // A motion that never repeats walks at most kMaxWalkedKeySteps walker
    // steps in whole periods (each its keys and the wrap), and never more
    // than kMaxWalkedPeriods periods.
    const double by_steps = std::max(1.0, std::floor(kMaxWalkedKeySteps / static_cast<double>(keys)));
    return std::min(periods, std::min(kMaxWalkedPeriods, by_steps));
}

// Walks whole periods (each the rest of the keys, then the wrap to the first
// key's offset) up to the target; after each, until a repeat is found, its
// state is compared with those after the earlier periods.
void PropWalks::walk_periods(Cursor& c, const DynamicProp& p, double periods) const {
    const std::vector<layout::MotionKey>& keys = p.motion.keys;
    while (c.periods < target_periods(c, periods, keys.size())) {
        step_keys(c, p, keys.back().t);
        c.walker->step(key_pose(p, 0));
        c.periods += 1.0;
        c.key = 0;
        if (c.repeats) continue;
        const Seen now{c.walker->room(), c.walker->physical_to_virtual()};
        for (std::size_t k = 0; k < c.seen.size() && c.seen.size() <= kMaxRememberedPeriods; ++k) {
            if (c.seen[k].room != now.room || c.seen[k].w != now.w) continue;
            c.repeats = true;  // periods k .. c.periods repeat
            c.repeat_at = c.periods;
            c.cycle = c.periods - static_cast<double>(k);
            c.at_repeat = c.walker;
            break;
        }
        if (!c.repeats && c.seen.size() <= kMaxRememberedPeriods) c.seen.push_back(now);
    }
}

PropState PropWalks::at(int prop, double time) {
    const DynamicProp& p = set_->props[static_cast<std::size_t>(prop)];
    PropState state;
    state.room = p.room;
    const std::vector<layout::MotionKey>& keys = p.motion.keys;
    if (keys.empty()) return state;
    const double t = std::isnan(time) || time < 0.0 ? 0.0 : time;
    Cursor& c = cursors_[static_cast<std::size_t>(prop)];
    if (!c.walker) start(c, p);
    double periods = 0.0;
    double rest = t;
    if (p.motion.loop && keys.size() > 1) {
        const double period = keys.back().t;
        periods = std::floor(t / period);
        rest = t - periods * period;
        if (walked_past(c, p, target_periods(c, periods, keys.size()), rest)) {
            const double target = target_periods(c, periods, keys.size());
            if (c.repeats && target >= c.repeat_at) {
                c.walker = c.at_repeat;
                c.periods = c.repeat_at;
                c.key = 0;
            } else {
                start(c, p);
            }
        }
        walk_periods(c, p, periods);
    } else if (walked_past(c, p, 0.0, rest)) {
        start(c, p);
    }
    step_keys(c, p, rest);
    if (c.key + 1 == keys.size()) {
        state.offset = keys.back().offset;
        state.room = c.walker->room();
        state.w = c.walker->physical_to_virtual();
        return state;
    }
    state.offset = lerp_offset(keys[c.key], keys[c.key + 1], rest);
    Walker between = *c.walker;
    between.step(math::HeadPose{p.anchor + state.offset});
    state.room = between.room();
    state.w = between.physical_to_virtual();
    return state;
}

PropState walk_prop(const ObjectSet& set, int prop, double time) { return PropWalks(set).at(prop, time); }

}  // namespace impossible::walk
