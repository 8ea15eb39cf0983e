// The one way the program writes a number for people and for its JSON lines:
// the shortest decimal that reads back to the same double, integers below
// 1e15 without a fraction or exponent ("100000", not "1e+05"), -0 as "0".
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace impossible {

inline std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
    if (value == 0.0) return "0";  // also -0
    char buffer[40];
    if (value == std::floor(value) && std::abs(value) < 1e15) {
        std::snprintf(buffer, sizeof buffer, "%.0f", value);
        return buffer;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
}

}  // namespace impossible
