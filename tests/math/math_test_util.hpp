// Helpers shared by the math tests.
#pragma once

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "math/conventions.hpp"

namespace impossible::math::testing {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

inline ::testing::AssertionResult near_vec(const dvec3& a, const dvec3& b, double tol) {
    for (int k = 0; k < 3; ++k)
        if (!(std::abs(a[k] - b[k]) <= tol))
            return ::testing::AssertionFailure()
                   << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z
                   << "), component " << k << " differs by " << std::abs(a[k] - b[k]) << " > " << tol;
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult near_mat(const dmat4& a, const dmat4& b, double tol) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!(std::abs(a[c][r] - b[c][r]) <= tol))
                return ::testing::AssertionFailure()
                       << "entry [col " << c << "][row " << r << "]: " << a[c][r] << " vs " << b[c][r]
                       << " (differs by " << std::abs(a[c][r] - b[c][r]) << " > " << tol << ")";
    return ::testing::AssertionSuccess();
}

inline dvec3 apply(const dmat4& m, const dvec3& p) { return dvec3(m * dvec4(p, 1.0)); }
inline dvec3 apply_dir(const dmat4& m, const dvec3& v) { return dvec3(m * dvec4(v, 0.0)); }

}  // namespace impossible::math::testing
