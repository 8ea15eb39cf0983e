// The one reading of a person's numbers (command-line options, path files).
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

#include "base/number_text.hpp"

namespace impossible {
namespace {

TEST(NumberText, ReadsDecimalNumbers) {
    for (const auto& [text, value] : std::initializer_list<std::pair<const char*, double>>{
             {"1.5", 1.5}, {"+2", 2.0}, {"-3e2", -300.0}, {".5", 0.5}, {"1e300", 1e300}}) {
        const NumberText n = read_number_text(text);
        EXPECT_EQ(n.problem, "") << text;
        EXPECT_EQ(n.value, value) << text;
    }
}

// Issue 38: a subnormal ("1e-320") is a number, too small to use: it reads
// as 0, as anything closer to 0 does.
TEST(NumberText, NumbersBelowTheSmallestNormalDoubleReadAsZero) {
    for (const char* text : {"1e-320", "-1e-320", "1e-400", "4.9e-324", "2e-308"}) {
        const NumberText n = read_number_text(text);
        EXPECT_EQ(n.problem, "") << text;
        EXPECT_EQ(n.value, 0.0) << text;
        EXPECT_FALSE(std::signbit(n.value)) << text;
    }
    EXPECT_EQ(read_number_text("2.3e-308").value, 2.3e-308);
    const std::string tiny = "0." + std::string(400, '0') + "1";
    EXPECT_EQ(read_number_text(tiny).problem, "");
    EXPECT_EQ(read_number_text(tiny).value, 0.0);
    EXPECT_EQ(read_number_text("1" + std::string(400, '0')).problem, "is not a finite number");
}

TEST(NumberText, RefusesWhatIsNotADecimalNumberInWords) {
    for (const char* text : {"0x40", "-0x1p3", "+0X10"})
        EXPECT_EQ(read_number_text(text).problem, "is hexadecimal: write numbers in decimal") << text;
    for (const char* text : {"", "x", "1e400", "-1e400", "inf", "nan", " 1", "1 ", "+-1", "++1", "+", "1e", "1,5"})
        EXPECT_EQ(read_number_text(text).problem, "is not a finite number") << "'" << text << "'";
}

}  // namespace
}  // namespace impossible
