// Depth-buffer precision, computed (no GL): how far apart two surfaces must
// be along the view axis to land on different depth values.
#pragma once

#include <cmath>

#include "math/conventions.hpp"

namespace impossible::testing {

// The smallest separation along the view axis, at distance z, that a depth
// buffer can still resolve: one step of its depth format over the slope of
// window depth with distance (both at z). `clip` maps eye space to clip space.
inline double resolvable_separation(const math::dmat4& clip, double z, bool float_depth, bool zero_to_one) {
    auto window_depth = [&](double dist) {
        const math::dvec4 c = clip * math::dvec4(0, 0, -dist, 1);
        const double ndc = c.z / c.w;
        return zero_to_one ? ndc : 0.5 * ndc + 0.5;
    };
    const double h = z * 1e-6;
    const double slope = std::abs(window_depth(z + h) - window_depth(z - h)) / (2 * h);
    const double depth = window_depth(z);
    const double step =
        float_depth ? std::nextafter(static_cast<float>(depth), 2.0f) - static_cast<float>(depth) : 1.0 / 16777215.0;
    return step / slope;
}

}  // namespace impossible::testing
