// Moving props walked over successive frames (objects.hpp, walk_prop): the
// same states as walk_prop, bit for bit, without walking every key from
// t = 0 again each frame.
//
// A PropWalks keeps, per prop, the walker after the last whole key it has
// walked (and, for a looping motion, walk_prop's period bookkeeping: the
// states after the first periods and, once a period repeats, the walker at
// the repeat). at(prop, time) walks on from there only the keys passed since
// and steps a copy of the walker to the point between keys. A time whose
// keys lie before the kept ones starts that prop again: from t = 0, or, for a
// looping motion that repeats, from the walker at the repeat. So for times
// that do not decrease, a frame costs the keys passed since the last one;
// walk_prop itself is a fresh PropWalks's at(), so the two cannot differ.
//
// Not thread safe: one per thread that walks successive frames.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "math/conventions.hpp"
#include "walk/objects.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {

class PropWalks {
public:
    // For `set`, which must outlive it and stay where it is.
    explicit PropWalks(const ObjectSet& set);

    // walk_prop(set(), prop, time), bit for bit, for any sequence of times.
    PropState at(int prop, double time);

    const ObjectSet& set() const { return *set_; }

private:
    struct Seen {
        int room = -1;
        math::dmat4 w{1.0};
    };
    struct Cursor {
        std::optional<Walker> walker;     // placed at the first key, then walked on
        double periods = 0.0;             // whole periods of a looping motion walked (walk_prop's count)
        std::size_t key = 0;              // the last key of the current period stepped (0: none after the first)
        std::vector<Seen> seen;           // the states after periods 0, 1, ... (at most kMaxRememberedPeriods + 1)
        bool repeats = false;             // a period's state repeated an earlier one:
        double repeat_at = 0.0;           //   after this many periods
        double cycle = 0.0;               //   with this period count
        std::optional<Walker> at_repeat;  // the walker after repeat_at periods
    };

    void start(Cursor& c, const DynamicProp& p) const;
    double target_periods(const Cursor& c, double periods, std::size_t keys) const;
    void walk_periods(Cursor& c, const DynamicProp& p, double periods) const;

    const ObjectSet* set_;
    std::vector<Cursor> cursors_;
};

}  // namespace impossible::walk
