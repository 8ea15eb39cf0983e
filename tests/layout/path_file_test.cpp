// Path files (layout/path_file.hpp): the poses of `walk`, `preview --path`,
// `bench --path` and `plan --path`.
#include <gtest/gtest.h>

#include <sstream>

#include "layout/path_file.hpp"

namespace impossible::layout {
namespace {

TEST(PathFile, ReadsPosesAndReportsTheBadLine) {
    std::istringstream good("# comment\n\n1 1.6 2 90 0 0\r\n+0 1.5 -1 0 -5 3\n");
    const PathFile ok = read_path_stream(good, "p.txt");
    ASSERT_TRUE(ok);
    ASSERT_EQ(ok->size(), 2u);
    EXPECT_EQ((*ok)[0].yaw_deg, 90.0);
    EXPECT_EQ((*ok)[1].roll_deg, 3.0);
    std::istringstream bad("1 2 3 0 0 0\n1 2 x 0 0 0\n");
    EXPECT_EQ(read_path_stream(bad, "p.txt").error(), "p.txt:2: Z: 'x' is not a finite number");
    std::istringstream empty("# nothing\n");
    EXPECT_EQ(read_path_stream(empty, "p.txt").error(), "p.txt: the path file holds no poses");
    EXPECT_FALSE(read_path_file("/nonexistent/p.txt"));
}

TEST(PathFile, AFileMustHoldAPoseAndNotBeAFolder) { EXPECT_EQ(read_path_file("/tmp").error(), "/tmp: is a directory"); }

// A bad field is quoted printably: control bytes, a NUL and bytes that are
// not UTF-8 never reach the message (found by path_fuzzer).
TEST(PathFile, ABadFieldIsQuotedPrintably) {
    std::istringstream escape("0 1.6 \x1b[2J 0 0 0\n");
    EXPECT_EQ(read_path_stream(escape, "p.txt").error(), "p.txt:1: Z: '\\x1b[2J' is not a finite number");
    std::istringstream binary(std::string("0 1.6 1\xff\x01 0 0 0\n", 16));
    EXPECT_EQ(read_path_stream(binary, "p.txt").error(), "p.txt:1: Z: '1\\xff\\x01' is not a finite number");
    std::istringstream huge("0 1.6 1e9\x7f 0 0 0\n");
    EXPECT_EQ(read_path_stream(huge, "p.txt").error(), "p.txt:1: Z: '1e9\\x7f' is not a finite number");
}

// Issue 26: one sign only, a UTF-8 byte order mark skipped, UTF-16 and NUL
// bytes named.
TEST(PathFile, SignsByteOrderMarksAndWideText) {
    for (const char* text : {"+-0.3 1.6 1 0 0 0\n", "0 1.6 1 0 0 ++1\n", "0 1.6 1 0 0 +\n"}) {
        std::istringstream in(text);
        EXPECT_NE(read_path_stream(in, "p.txt").error().find("is not a finite number"), std::string::npos) << text;
    }
    std::istringstream bom(
        "\xEF\xBB\xBF"
        "1 1.6 2 0 0 0\n");
    const PathFile skipped = read_path_stream(bom, "p.txt");
    ASSERT_TRUE(skipped) << skipped.error();
    EXPECT_EQ((*skipped)[0].position.x, 1.0);
    std::istringstream utf16le(
        std::string("\xFF\xFE"
                    "0\0 \0"
                    "1\0\n\0",
                    10));
    EXPECT_EQ(read_path_stream(utf16le, "p.txt").error(), "p.txt: is UTF-16 text; save it as UTF-8 or ASCII");
    std::istringstream utf16be(
        std::string("\xFE\xFF\0"
                    "0\0 \n",
                    7));
    EXPECT_EQ(read_path_stream(utf16be, "p.txt").error(), "p.txt: is UTF-16 text; save it as UTF-8 or ASCII");
    std::istringstream nul(std::string("0 1.6 1 0 0 0\n0\0 1.6 1 0 0 0\n", 29));
    EXPECT_EQ(read_path_stream(nul, "p.txt").error(),
              "p.txt:2: holds a NUL byte; a path file is text (ASCII or UTF-8, not UTF-16)");
}

}  // namespace
}  // namespace impossible::layout
