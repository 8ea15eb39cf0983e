// walk/prop_walks.hpp: a PropWalks gives, for any sequence of times, the
// states walk_prop gives, bit for bit, and both are those of the walk from
// t = 0 that walk_prop made before PropWalks existed (copied below as the
// reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "links/portal_links.hpp"
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"
#include "walk/walk_test_layouts.hpp"

namespace impossible::walk {
namespace {

using glm::dvec3;
using namespace testing;

// walk_prop as it was (objects.cpp before PropWalks): every key from t = 0.
dvec3 ref_keys_to(Walker& walker, const DynamicProp& p, double t) {
    const std::vector<layout::MotionKey>& keys = p.motion.keys;
    std::size_t i = 1;
    for (; i < keys.size() && keys[i].t <= t; ++i) walker.step(math::HeadPose{p.anchor + keys[i].offset});
    if (i == keys.size()) return keys.back().offset;
    const double s = (t - keys[i - 1].t) / (keys[i].t - keys[i - 1].t);
    const dvec3 offset = keys[i - 1].offset + (keys[i].offset - keys[i - 1].offset) * s;
    walker.step(math::HeadPose{p.anchor + offset});
    return offset;
}

void ref_periods(Walker& walker, const DynamicProp& p, double periods) {
    struct State {
        int room;
        math::dmat4 w;
    };
    std::vector<State> seen = {{walker.room(), walker.physical_to_virtual()}};
    const dvec3 first = p.anchor + p.motion.keys.front().offset;
    for (double done = 0.0; done < std::min(periods, kMaxWalkedPeriods);) {
        ref_keys_to(walker, p, p.motion.keys.back().t);
        walker.step(math::HeadPose{first});
        done += 1.0;
        const State now{walker.room(), walker.physical_to_virtual()};
        for (std::size_t k = 0; k < seen.size() && seen.size() <= kMaxRememberedPeriods; ++k) {
            if (seen[k].room != now.room || seen[k].w != now.w) continue;
            const double left = std::fmod(periods - done, done - static_cast<double>(k));
            for (double j = 0.0; j < left; j += 1.0) {
                ref_keys_to(walker, p, p.motion.keys.back().t);
                walker.step(math::HeadPose{first});
            }
            return;
        }
        if (seen.size() <= kMaxRememberedPeriods) seen.push_back(now);
    }
}

PropState ref_walk_prop(const ObjectSet& set, int prop, double time) {
    const DynamicProp& p = set.props[static_cast<std::size_t>(prop)];
    PropState state;
    state.room = p.room;
    const std::vector<layout::MotionKey>& keys = p.motion.keys;
    if (keys.empty()) return state;
    const double t = std::isnan(time) || time < 0.0 ? 0.0 : time;
    Walker walker(*set.walk_layout, p.room, set.walk_links);
    walker.step(math::HeadPose{p.anchor + keys.front().offset});
    if (p.motion.loop && keys.size() > 1) {
        const double period = keys.back().t;
        const double periods = std::floor(t / period);
        ref_periods(walker, p, periods);
        state.offset = ref_keys_to(walker, p, t - periods * period);
    } else {
        state.offset = ref_keys_to(walker, p, t);
    }
    state.room = walker.room();
    state.w = walker.physical_to_virtual();
    return state;
}

layout::BoxProp pw_box(const std::string& id, std::vector<layout::MotionKey> keys, bool loop) {
    layout::BoxProp b;
    b.min = {0.5, 0.0, -0.2};
    b.max = {0.9, 0.4, 0.2};
    b.id = id;
    b.motion.keys = std::move(keys);
    b.motion.loop = loop;
    return b;
}

// Five props of the hall, each through the turned door: many keys there and
// back (not looping); the same looping (a repeat after one period); a loop
// that goes through and comes back past the door, through the wall, so it
// stays in the annex (a repeat after two periods, of one); a loop that
// never crosses; a prop of one key.
ObjectSet pw_set() {
    layout::Layout l = turned_door();
    std::vector<layout::MotionKey> zigzag;
    for (int k = 0; k <= 40; ++k)
        zigzag.push_back({0.25 * k, {k % 4 == 1 || k % 4 == 2 ? 3.0 : 0.2 * (k % 3), 0.0, 0.05 * (k % 5)}});
    l.rooms[0].props = {pw_box("zigzag", zigzag, false), pw_box("zigzag_loop", zigzag, true),
                        pw_box("stays", {{0.0, {0, 0, 0}}, {1.0, {3, 0, 0}}, {1.5, {3, 0, 1.5}}}, true),
                        pw_box("inside", {{0.0, {0, 0, 0}}, {0.3, {0.5, 0, 0}}, {0.7, {0, 0, 0.5}}}, true),
                        pw_box("still", {{0.0, {0.1, 0, 0}}}, false)};
    return build_object_set(l, links::link_portals(l));
}

void expect_same(const PropState& a, const PropState& b, const char* what, int prop, double time) {
    EXPECT_EQ(a.room, b.room) << what << " prop " << prop << " at " << time;
    EXPECT_EQ(a.w, b.w) << what << " prop " << prop << " at " << time;
    EXPECT_EQ(a.offset, b.offset) << what << " prop " << prop << " at " << time;
}

TEST(PropWalks, TheSetWalksThroughTheDoorAndTheLoopsRepeatAsIntended) {
    const ObjectSet set = pw_set();
    ASSERT_EQ(set.props.size(), 5u);
    EXPECT_EQ(walk_prop(set, 0, 0.25).room, 1);     // in the annex
    EXPECT_EQ(walk_prop(set, 0, 0.75).room, 0);     // and back
    EXPECT_EQ(walk_prop(set, 2, 1.5 * 7).room, 1);  // stays in the annex after a period
    EXPECT_NE(walk_prop(set, 2, 1.5 * 7).w, walk_prop(set, 2, 0.0).w);
    EXPECT_EQ(walk_prop(set, 3, 100.1).room, 0);
}

TEST(PropWalks, FreshWalksAreThoseOfTheWalkFromZero) {
    const ObjectSet set = pw_set();
    const std::vector<double> times = {-1.0, 0.0,  0.1,   0.25, 0.3,       1.0,   1.5,       2.9,  3.0,
                                       9.99, 10.0, 10.01, 17.3, 1e3 + 0.7, 4.5e4, 1e7 + 0.3, 1e12, std::nan("")};
    for (int p = 0; p < 5; ++p)
        for (double t : times) expect_same(walk_prop(set, p, t), ref_walk_prop(set, p, t), "fresh", p, t);
}

// Random sequences: mostly growing by a frame or a few keys, sometimes
// jumping back (a restart) or far ahead, sometimes the same time again.
TEST(PropWalks, AnySequenceOfTimesGivesTheFreshStatesBitForBit) {
    const ObjectSet set = pw_set();
    std::mt19937_64 random(22);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int run = 0; run < 20; ++run) {
        PropWalks walks(set);
        double t = 0.0;
        for (int frame = 0; frame < 300; ++frame) {
            const double r = unit(random);
            if (r < 0.6)
                t += 1.0 / 90.0;
            else if (r < 0.75)
                t += 2.0 * unit(random);
            else if (r < 0.85)
                t = std::max(-0.5, t - 3.0 * unit(random));
            else if (r < 0.9)
                t += 1e4 * unit(random);
            else if (r < 0.95)
                t = 0.25 * std::floor(t / 0.25 + 1.0);  // on a key
            for (int p = 0; p < 5; ++p) expect_same(walks.at(p, t), ref_walk_prop(set, p, t), "kept", p, t);
            if (HasFailure()) return;
        }
    }
}

// The props visited in a different order each frame, some skipped: each
// prop's walk is its own.
TEST(PropWalks, PropsAreKeptApart) {
    const ObjectSet set = pw_set();
    PropWalks walks(set);
    for (int frame = 0; frame < 400; ++frame) {
        const double t = frame * 0.037;
        for (int k = 0; k < 5; ++k) {
            const int p = (frame + 3 * k) % 5;
            if ((frame + p) % 3 == 0) continue;
            expect_same(walks.at(p, t), walk_prop(set, p, t), "kept", p, t);
        }
    }
}

TEST(PropWalks, PlaceObjectsGivesTheSameInstancesWithOrWithoutWalks) {
    const ObjectSet set = pw_set();
    PropWalks walks(set);
    for (int frame = 0; frame < 200; ++frame) {
        math::View view;
        view.room = 0;
        view.head.position = {0, 1.6, 1};
        view.time = frame / 30.0;
        const std::vector<ObjectInstance> kept = place_objects(set, view, &walks);
        const std::vector<ObjectInstance> fresh = place_objects(set, view);
        ASSERT_EQ(kept.size(), fresh.size());
        for (std::size_t k = 0; k < kept.size(); ++k) {
            EXPECT_EQ(kept[k].cell, fresh[k].cell);
            EXPECT_EQ(kept[k].to_cell, fresh[k].to_cell);
            EXPECT_EQ(kept[k].cut_count, fresh[k].cut_count);
        }
    }
}

// A long motion walked frame by frame costs the keys passed, not all the
// keys from t = 0 each frame: 20 000 frames of a 10 000-key motion.
TEST(PropWalks, SuccessiveFramesOfALongMotionWalkOnlyTheNewKeys) {
    layout::Layout l = turned_door();
    std::vector<layout::MotionKey> keys;
    for (int k = 0; k < 10000; ++k) keys.push_back({0.01 * k, {(k % 2) * 0.1, 0.0, 0.0}});
    l.rooms[0].props = {pw_box("long", keys, false)};
    const ObjectSet set = build_object_set(l, links::link_portals(l));
    PropWalks walks(set);
    std::vector<PropState> checked;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < 20000; frame += 1) {
        const PropState s = walks.at(0, frame * 0.005);
        if (frame % 4999 == 0) checked.push_back(s);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // From t = 0 each frame: 20 000 frames of ~5 000 keys, ~20 s.
    EXPECT_LT(seconds, IMPOSSIBLE_SANITIZED ? 20.0 : 2.0);
    for (std::size_t k = 0; k < checked.size(); ++k)
        expect_same(checked[k], ref_walk_prop(set, 0, 4999 * k * 0.005), "long", 0, 4999 * k * 0.005);
}

}  // namespace
}  // namespace impossible::walk
