// Whether a segment meets a box (the slab test), for tests that check
// shadows against their own geometry.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/vec3.hpp>

namespace impossible::testing {

// Whether the segment from a to b meets the box [lo, hi] (edges included).
inline bool segment_meets_box(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo, const glm::dvec3& hi) {
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double d = b[k] - a[k];
        if (std::abs(d) < 1e-300) {
            if (a[k] < lo[k] || a[k] > hi[k]) return false;
            continue;
        }
        double u = (lo[k] - a[k]) / d, v = (hi[k] - a[k]) / d;
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace impossible::testing
