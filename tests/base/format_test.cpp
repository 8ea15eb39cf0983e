// The one number formatter (base/format.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "base/format.hpp"

namespace impossible {
namespace {

TEST(FormatNumber, ShortestRoundTrip) {
    EXPECT_EQ(format_number(0.0), "0");
    EXPECT_EQ(format_number(-0.0), "0");
    EXPECT_EQ(format_number(1.0), "1");
    EXPECT_EQ(format_number(-3.0), "-3");
    EXPECT_EQ(format_number(1.6), "1.6");
    EXPECT_EQ(format_number(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(format_number(1e21), "1e+21");
    EXPECT_EQ(format_number(100000.0), "100000");  // not 1e+05
    EXPECT_EQ(format_number(0.0001), "0.0001");
    EXPECT_EQ(format_number(std::nan("")), "nan");
    EXPECT_EQ(format_number(-INFINITY), "-inf");
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
        const double x = u(rng) * std::pow(10.0, (k % 40) - 20);
        const std::string s = format_number(x);
        EXPECT_EQ(std::stod(s), x) << s;
        EXPECT_EQ(nlohmann::json::parse(s).get<double>(), x) << s;  // valid JSON
    }
}

}  // namespace
}  // namespace impossible
