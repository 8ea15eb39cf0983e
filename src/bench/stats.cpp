#include "bench/stats.hpp"

#include <algorithm>
#include <cstddef>

namespace impossible::bench {

double nearest_rank(const std::vector<double>& sorted, double p) {
    return sorted[static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1) + 0.5)];
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return nearest_rank(v, p);
}

Spread spread_of(std::vector<double> v) {
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    return {nearest_rank(v, 0.5), nearest_rank(v, 0.1), nearest_rank(v, 0.9)};
}

}  // namespace impossible::bench
