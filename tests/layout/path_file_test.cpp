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
    const PathFile none = read_path_stream(empty, "p.txt");
    ASSERT_TRUE(none);  // a stream may hold no pose (walk prints nothing)
    EXPECT_TRUE(none->empty());
    EXPECT_FALSE(read_path_file("/nonexistent/p.txt"));
}

TEST(PathFile, AFileMustHoldAPoseAndNotBeAFolder) { EXPECT_EQ(read_path_file("/tmp").error(), "/tmp: is a directory"); }

// A bad field is quoted printably: control bytes, a NUL and bytes that are
// not UTF-8 never reach the message (found by path_fuzzer).
TEST(PathFile, ABadFieldIsQuotedPrintably) {
    std::istringstream escape("0 1.6 \x1b[2J 0 0 0\n");
    EXPECT_EQ(read_path_stream(escape, "p.txt").error(), "p.txt:1: Z: '\\x1b[2J' is not a finite number");
    std::istringstream binary(std::string("0 1.6 1\0\xff 0 0 0\n", 16));
    EXPECT_EQ(read_path_stream(binary, "p.txt").error(), "p.txt:1: Z: '1\\x00\\xff' is not a finite number");
    std::istringstream huge("0 1.6 1e9\x7f 0 0 0\n");
    EXPECT_EQ(read_path_stream(huge, "p.txt").error(), "p.txt:1: Z: '1e9\\x7f' is not a finite number");
}

}  // namespace
}  // namespace impossible::layout
