// render and trace with --time, --hands and --path FILE --frame K (cli.md,
// "Time, hands and lights"): every wrong combination is a usage error (exit
// 2) of one line naming the options or the counts, before any file is written.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// Three poses through the default layout's door, the second with hands.
const char* kPathFrameWalk =
    "0 1.6 1 0 0 0\n"
    "0 1.6 0.2 0 0 0   -0.2 1.3 0 0 0 0   0.2 1.3 -0.3 0 0 0\n"
    "0 1.6 -0.3 0 0 0\n";

TEST_F(Hostile, PathExcludesPoseRoomTimeAndHands) {
    spit(dir_ / "walk.txt", kPathFrameWalk);
    for (const std::string command : {"render", "trace"}) {
        for (const std::string other :
             {"--pose 0,1.6,0,0,0,0", "--room hall", "--time 1", "--hands 0,1,0,0,0,0,0,1,0,0,0,0"}) {
            const Outcome r = run("$BIN " + command + " lay.json --size 8x8 --path walk.txt --frame 1 " + other);
            expect_refused(r, 2, "--path and " + other.substr(0, other.find(' ')) + " exclude each other");
        }
        expect_refused(run("$BIN " + command + " lay.json --size 8x8 --frame 1"), 2, "--frame needs --path FILE");
        expect_refused(run("$BIN " + command + " lay.json --size 8x8 --fps 30"), 2, "--fps needs --path FILE");
        expect_refused(run("$BIN " + command + " lay.json --size 8x8 --path walk.txt"), 2, "--path needs --frame K");
        // Three poses: frames 0..2; 3 is past the end.
        expect_refused(run("$BIN " + command + " lay.json --size 8x8 --path walk.txt --frame 3"), 2,
                       "--frame 3: walk.txt holds 3 poses (frames 0..2)");
        EXPECT_EQ(listing(dir_), "lay.json\nwalk.txt\n") << command;
    }
}

TEST_F(Hostile, TimeHandsAndFpsValuesAreChecked) {
    spit(dir_ / "walk.txt", kPathFrameWalk);
    expect_refused(run("$BIN render lay.json --size 8x8 --time nan"), 1, "--time: 'nan' is not a finite number");
    expect_refused(run("$BIN render lay.json --size 8x8 --hands 0,1,0,0,0,0,0,1,0,0,0"), 1,
                   "--hands: expected 12 comma-separated numbers, got 11");
    expect_refused(run("$BIN trace lay.json --size 8x8 --hands 0,1,0,0,0,0,0,1,0,0,0,2e7"), 1,
                   "--hands: 0,1,0,0,0,0,0,1,0,0,0,2e7 has a value beyond 1e7");
    expect_refused(run("$BIN render lay.json --size 8x8 --path walk.txt --frame 1 --fps 0"), 1,
                   "--fps: 0 is not in 0.001..1000000");
    expect_refused(run("$BIN render lay.json --size 8x8 --path walk.txt --frame -1"), 1, "--frame: -1 is out of range");
    // A path file that is not one: the reader's error, and nothing written.
    spit(dir_ / "bad.txt", "0 1.6 1 0 0 0 1 2 3\n");
    const Outcome bad = run("$BIN render lay.json --size 8x8 --path bad.txt --frame 0");
    EXPECT_EQ(bad.status, 1) << bad.err;
    EXPECT_EQ(bad.err_lines(), 1) << bad.err;
    EXPECT_NE(bad.err.find("bad.txt:1:"), std::string::npos) << bad.err;
    // --out over the path file it reads: a usage error.
    expect_refused(run("$BIN render lay.json --size 8x8 --path walk.txt --frame 0 --out walk.txt"), 2, "walk.txt");
    EXPECT_EQ(slurp(dir_ / "walk.txt"), kPathFrameWalk);
    EXPECT_EQ(listing(dir_), "bad.txt\nlay.json\nwalk.txt\n");
}

TEST_F(Hostile, ValidTimeHandsAndPathFramesRender) {
    spit(dir_ / "walk.txt", kPathFrameWalk);
    for (const std::string command : {"render", "trace"}) {
        const Outcome r = run("$BIN " + command +
                              " lay.json --size 16x8 --out a.png --time -2.5 --hands 0,1,0,0,0,0,0,1,0,0,0,0 && $BIN " +
                              command + " lay.json --size 16x8 --out b.png --path walk.txt --frame 2 --fps 30");
        EXPECT_EQ(r.status, 0) << command << ": " << r.err;
        EXPECT_EQ(r.err, "") << command;
        EXPECT_EQ(listing(dir_), "a.png\nb.png\nlay.json\nwalk.txt\n") << command;
        fs::remove(dir_ / "a.png");
        fs::remove(dir_ / "b.png");
    }
}

}  // namespace
}  // namespace impossible::hostile
