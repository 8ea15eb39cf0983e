// The overlap sweep's limits (design/overlap.hpp): the listed pairs are the
// first in order of (a, b) whatever order the sweep meets them in, the
// count is exact while no limit is reached and a lower bound after, and the
// report says so in text and JSON with one summary line.
#include "design_test_util.hpp"

#include <cstdint>
#include <nlohmann/json.hpp>

#include "design/overlap.hpp"
#include "design/report.hpp"

namespace design_test {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

// Every pair that shares floor, by testing every pair.
Pairs every_pair(const std::vector<math::Polygon2>& floors) {
    Pairs out;
    for (std::size_t i = 0; i < floors.size(); ++i)
        for (std::size_t j = i + 1; j < floors.size(); ++j)
            if (design::overlap_of(floors[i], floors[j]).area > design::kMinSharedArea)
                out.emplace_back(static_cast<int>(i), static_cast<int>(j));
    return out;
}

Pairs listed(const design::Overlaps& o) {
    Pairs out;
    for (const design::Overlap& v : o.listed) out.emplace_back(v.a, v.b);
    return out;
}

// Rectangles and rotated squares scattered over a small floor.
std::vector<math::Polygon2> scattered(int n, std::uint64_t seed) {
    const auto next = [&] {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(seed >> 11) / static_cast<double>(1ull << 53);
    };
    std::vector<math::Polygon2> floors;
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 c{std::round(next() * 30.0) / 2.0, std::round(next() * 30.0) / 2.0};
        const double w = 0.5 + std::round(next() * 8.0) / 2.0, d = 0.5 + std::round(next() * 8.0) / 2.0;
        if (i % 3 == 0) {
            const double a = next() * 3.0, s = 0.5 * w;
            const glm::dvec2 u{std::cos(a) * s, std::sin(a) * s}, v{-u.y, u.x};
            floors.push_back({c - u - v, c + u - v, c + u + v, c - u + v});
        } else {
            floors.push_back(math::rectangle(c, c + glm::dvec2(w, d)));
        }
    }
    return floors;
}

TEST(OverlapCap, TheFirstPairsAreListedAndAllAreCounted) {
    const std::vector<math::Polygon2> floors = scattered(150, 99);
    const Pairs all = every_pair(floors);
    ASSERT_GT(all.size(), 200u);
    design::OverlapLimits limits;
    limits.listed = 40;
    const design::Overlaps o = design::room_overlaps(floors, limits);
    EXPECT_EQ(listed(o), Pairs(all.begin(), all.begin() + 40));
    EXPECT_EQ(o.pairs, all.size());
    EXPECT_TRUE(o.exact);
    EXPECT_TRUE(o.truncated());
    // The figures of a listed pair are those of the pair alone.
    for (const design::Overlap& v : o.listed) {
        const design::Overlap alone = design::overlap_of(floors[v.a], floors[v.b]);
        EXPECT_EQ(v.area, alone.area);
        EXPECT_EQ(v.percent, alone.percent);
        EXPECT_EQ(v.shared, alone.shared);
    }
}

TEST(OverlapCap, PairsMetInDescendingOrderAreStillListedFirstToLast) {
    // Room i lies left of room i - 1, so the sweep (by x) meets the pairs
    // with the largest indices first.
    std::vector<math::Polygon2> floors;
    for (int i = 0; i < 120; ++i) floors.push_back(math::rectangle({-0.01 * i, 0.0}, {4.0 - 0.01 * i, 3.0}));
    design::OverlapLimits limits;
    limits.listed = 25;
    const design::Overlaps o = design::room_overlaps(floors, limits);
    const Pairs all = every_pair(floors);
    EXPECT_EQ(all.size(), 120u * 119 / 2);
    EXPECT_EQ(listed(o), Pairs(all.begin(), all.begin() + 25));
    EXPECT_EQ(o.pairs, all.size());
    EXPECT_TRUE(o.exact);
}

TEST(OverlapCap, RectanglesThatOnlyTouchOrBarelyShareAreJudgedAsClippingJudgesThem) {
    // Shared areas with the first of 0 (touching), within rounding of
    // kMinSharedArea (clipped to decide), just under and just over it.
    const std::vector<math::Polygon2> floors = {
        math::rectangle({0, 0}, {1, 1}),         math::rectangle({1, 0}, {2, 1}),
        math::rectangle({0.999999, 0}, {2, 1}),  math::rectangle({0, 0.9999990001}, {1, 2}),
        math::rectangle({0, 0.9999989}, {1, 2}), math::rectangle({0.9999, 0.99}, {1.5, 1.5}),
    };
    const Pairs all = every_pair(floors);
    const design::Overlaps o = design::room_overlaps(floors);
    EXPECT_EQ(listed(o), all);
    EXPECT_EQ(o.pairs, all.size());
    EXPECT_FALSE(o.truncated());
}

TEST(OverlapCap, TheSearchStopsAtItsLimitsAndSaysTheCountIsALowerBound) {
    // Rotated squares on one spot: every pair must be clipped.
    std::vector<math::Polygon2> floors;
    for (int i = 0; i < 60; ++i) {
        const double a = 0.01 * (i + 1);
        const glm::dvec2 u{std::cos(a), std::sin(a)}, v{-u.y, u.x};
        floors.push_back({-u - v, u - v, u + v, -u + v});
    }
    design::OverlapLimits limits;
    limits.listed = 10;
    limits.clipped = 100;
    const design::Overlaps clipped = design::room_overlaps(floors, limits);
    EXPECT_FALSE(clipped.exact);
    EXPECT_TRUE(clipped.truncated());
    EXPECT_EQ(clipped.pairs, 100u);  // each clipped pair shares floor
    EXPECT_EQ(clipped.listed.size(), 10u);
    limits = {};
    limits.candidates = 500;
    const design::Overlaps candidates = design::room_overlaps(floors, limits);
    EXPECT_FALSE(candidates.exact);
    EXPECT_EQ(candidates.pairs, 500u);
    EXPECT_EQ(design::room_overlaps(floors).pairs, 60u * 59 / 2);
    EXPECT_TRUE(design::room_overlaps(floors).exact);
}

// 50 identical rooms: 1,225 pairs, more than the report lists.
layout::Layout identical_rooms(int n) {
    std::string rooms;
    for (int i = 0; i < n; ++i) rooms += (i ? ",\n" : "") + room("r" + std::to_string(i), 0, 0, 3, 3);
    return load("", "r0", rooms, "");
}

TEST(OverlapCap, AReportOfMorePairsThanItListsEndsWithOneSummaryLine) {
    const layout::Layout l = identical_rooms(50);
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.overlaps.size(), design::kMaxListedOverlaps);
    EXPECT_EQ(r.overlap_pairs, 1225u);
    EXPECT_TRUE(r.overlaps_exact);
    EXPECT_TRUE(design::overlaps_truncated(r));
    EXPECT_EQ(r.overlaps.back().a, 28);  // (0, 1) ... (27, 49) are 994 pairs, then (28, 29) ... (28, 34)
    EXPECT_EQ(r.overlaps.back().b, 34);
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("  r28 / r34: 9.00 m2, 100.0 % (limit 56 %) noticeable\n"
                        "  ... and 225 more pairs (the report lists the first 1000)\n"),
              std::string::npos)
        << text;
    // A finding per listed noticeable pair, one for the rest, one per unreachable room.
    EXPECT_EQ(r.findings.size(), 1000u + 1 + 49);
    EXPECT_EQ(std::count(r.findings.begin(), r.findings.end(),
                         "1225 pairs of rooms overlap; the report lists the first 1000"),
              1);
    const nlohmann::ordered_json j = design::report_json(l, r, {});
    EXPECT_EQ(j["overlaps"].size(), 1000u);
    EXPECT_EQ(j["overlaps_truncated"], true);
    EXPECT_EQ(j["overlap_pairs"], 1225);
    EXPECT_EQ(j["overlap_pairs_exact"], true);
}

TEST(OverlapCap, AReportWithinTheListHasNoSummaryAndNoNewFields) {
    const layout::Layout l = identical_rooms(4);
    const design::Report r = design::make_report(l);
    EXPECT_EQ(r.overlaps.size(), 6u);
    EXPECT_FALSE(design::overlaps_truncated(r));
    EXPECT_EQ(design::report_text(l, r).find("..."), std::string::npos);
    const nlohmann::ordered_json j = design::report_json(l, r, {});
    EXPECT_FALSE(j.contains("overlaps_truncated"));
    EXPECT_FALSE(j.contains("overlap_pairs"));
}

}  // namespace
}  // namespace design_test
