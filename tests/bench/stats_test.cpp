// Percentiles of timing samples by nearest rank (bench/README.md, "Method").
#include <gtest/gtest.h>

#include "bench/stats.hpp"

namespace impossible::bench {
namespace {

TEST(BenchStats, NearestRankPercentiles) {
    EXPECT_EQ(percentile({}, 0.5), 0.0);
    EXPECT_EQ(percentile({7.0}, 0.9), 7.0);
    EXPECT_EQ(percentile({4.0, 1.0, 3.0, 2.0}, 0.5), 3.0);  // index round(1.5) = 2
    EXPECT_EQ(percentile({4.0, 1.0, 3.0, 2.0}, 0.0), 1.0);
    EXPECT_EQ(percentile({4.0, 1.0, 3.0, 2.0}, 1.0), 4.0);
    std::vector<double> v;
    for (int i = 10; i >= 0; --i) v.push_back(i);
    const Spread s = spread_of(v);
    EXPECT_EQ(s.median, 5.0);
    EXPECT_EQ(s.p10, 1.0);
    EXPECT_EQ(s.p90, 9.0);
    EXPECT_EQ(spread_of({}).median, 0.0);
}

}  // namespace
}  // namespace impossible::bench
