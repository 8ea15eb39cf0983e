// Statistics of timing samples, shared by `impossible bench` and the
// benchmark programs under bench/: percentiles by nearest rank, as
// bench/README.md ("Method") describes them.
#pragma once

#include <vector>

namespace impossible::bench {

// The p-th quantile (p in [0, 1]) of a sorted, non-empty sample by nearest
// rank: the value at index round(p · (n − 1)).
double nearest_rank(const std::vector<double>& sorted, double p);

// The same of an unsorted sample; 0 for an empty one.
double percentile(std::vector<double> values, double p);

// Median, 10th and 90th percentile (nearest rank); zeros for an empty sample.
struct Spread {
    double median = 0.0, p10 = 0.0, p90 = 0.0;
};
Spread spread_of(std::vector<double> values);

}  // namespace impossible::bench
