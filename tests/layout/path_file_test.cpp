// Path files (layout/path_file.hpp): the poses of `walk`, `preview --path`,
// `bench --path` and `plan --path`.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>

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

// Issue 22: a line of 18 numbers is the head, then the left and the right
// hand; one file may mix 6- and 18-number lines; the heads-only readers keep
// the heads of both.
TEST(PathFile, EighteenNumberLinesCarryTheHands) {
    const std::string text =
        "0 1.6 1 0 0 0\n"
        "1 1.6 2 90 0 0  -0.2 1.2 0.5 10 20 30\t0.2 1.1 0.4 -10 -20 -30\r\n"
        "# a comment\n"
        "2 1.5 3 0 -5 3\n";
    std::istringstream in(text);
    const PathFrames frames = read_path_frames_stream(in, "p.txt");
    ASSERT_TRUE(frames) << frames.error();
    ASSERT_EQ(frames->size(), 3u);
    EXPECT_FALSE((*frames)[0].hands);
    EXPECT_FALSE((*frames)[2].hands);
    ASSERT_TRUE((*frames)[1].hands);
    const auto& hands = *(*frames)[1].hands;
    EXPECT_EQ((*frames)[1].head.yaw_deg, 90.0);
    EXPECT_EQ(hands[0].position.x, -0.2);
    EXPECT_EQ(hands[0].roll_deg, 30.0);
    EXPECT_EQ(hands[1].position.z, 0.4);
    EXPECT_EQ(hands[1].pitch_deg, -20.0);
    std::istringstream heads_in(text);
    const PathFile heads = read_path_stream(heads_in, "p.txt");
    ASSERT_TRUE(heads) << heads.error();
    ASSERT_EQ(heads->size(), 3u);
    EXPECT_EQ((*heads)[1].position.z, 2.0);
    EXPECT_EQ((*heads)[2].roll_deg, 3.0);
}

TEST(PathFile, OtherFieldCountsAndBadHandFieldsAreNamed) {
    const std::string expected =
        "expected 6 or 18 numbers (X Y Z YAW PITCH ROLL of the head, then of the left and the right hand), found ";
    const std::pair<const char*, std::string> cases[] = {
        {"0 1.6 1 0 0 0 9\n", "p.txt:1: " + expected + "7 fields"},
        {"0 1.6 1 0 0 0\n0 1.6 1 0 0 0 1 1 1 0 0 0\n", "p.txt:2: " + expected + "12 fields"},
        {"0 1.6 1 0 0 0 1 1 1 0 0 0 1 1 1 0 0 0 0\n", "p.txt:1: " + expected + "19 fields"},
        {"0 1.6 1 0 0 0 1 1 1 x 0 0 1 1 1 0 0 0\n", "p.txt:1: left hand YAW: 'x' is not a finite number"},
        {"0 1.6 1 0 0 0 1 1 1 0 0 0 1 1 2e6 0 0 0\n", "p.txt:1: right hand Z: 2e6 is out of range (|Z| <= 1e6 m)"},
        {"0 1.6 1 0 0 0 1 1 1 0 0 0 1 1 1 0 0 +-3\n", "p.txt:1: right hand ROLL: '+-3' is not a finite number"},
        {"0 1.6 y 0 0 0 1 1 1 0 0 0 1 1 1 0 0 0\n", "p.txt:1: Z: 'y' is not a finite number"},
    };
    for (const auto& [text, message] : cases) {
        std::istringstream frames_in(text);
        EXPECT_EQ(read_path_frames_stream(frames_in, "p.txt").error(), message) << text;
        std::istringstream heads_in(text);
        EXPECT_EQ(read_path_stream(heads_in, "p.txt").error(), message) << text;
    }
}

TEST(PathFile, TheFramesFileReaderSharesTheFileRules) {
    EXPECT_EQ(read_path_frames_file("/tmp").error(), "/tmp: is a directory");
    EXPECT_FALSE(read_path_frames_file("/nonexistent/p.txt"));
    std::istringstream bom(
        "\xEF\xBB\xBF"
        "1 1.6 2 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
    const PathFrames skipped = read_path_frames_stream(bom, "p.txt");
    ASSERT_TRUE(skipped) << skipped.error();
    EXPECT_TRUE((*skipped)[0].hands);
    std::istringstream empty("# nothing\n\n");
    EXPECT_EQ(read_path_frames_stream(empty, "p.txt").error(), "p.txt: the path file holds no poses");
}

}  // namespace
}  // namespace impossible::layout
