// --fov-angles and --hmd (docs/headsets.md): every bad profile or angle is
// refused with one line (a profile's problem as FILE:LINE:COLUMN: field:
// message), status 1, no file written; --fov, --fov-angles and --hmd exclude
// each other (status 2); render, trace, preview and bench all take them.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// A valid profile, small: a square visible area that hides the corners.
std::string hmd_profile(const std::string& left_fov, const std::string& right_size = "[16, 12]",
                        const std::string& area = "[[0.1, 0], [0.9, 0], [1, 0.5], [0.9, 1], [0.1, 1], [0, 0.5]]",
                        const std::string& extra = "") {
    return "{\n"
           "  \"name\": \"test\",\n"
           "  \"source\": \"made up\",\n"
           "  \"ipd\": 0.063," +
           extra +
           "\n"
           "  \"left\": {\"fov\": " +
           left_fov +
           ", \"resolution\": [16, 12],\n"
           "    \"visible_area\": " +
           area +
           "},\n"
           "  \"right\": {\"fov\": {\"left\": -40, \"right\": 50, \"up\": 40, \"down\": -45}, \"resolution\": " +
           right_size + "}\n}\n";
}

const std::string kGoodFov = R"({"left": -50, "right": 40, "up": 40, "down": -45})";

TEST_F(Hostile, HmdProfileRendersAndTraces) {
    spit(dir_ / "hmd.json", hmd_profile(kGoodFov));
    for (const std::string command : {"render", "trace"}) {
        const Outcome r = run("$BIN " + command + " lay.json --hmd hmd.json --out o.png --ids i.png");
        EXPECT_EQ(r.status, 0) << r.err;
        // The profile's size: 16x12 per eye.
        EXPECT_EQ(slurp(dir_ / "o.png").substr(16, 8), std::string("\0\0\0\x20\0\0\0\x0c", 8)) << command;
    }
    const Outcome b = run("$BIN bench lay.json --hmd hmd.json --size 16x12 --frames 2");
    EXPECT_EQ(b.status, 0) << b.err;
    const Outcome a = run("$BIN render lay.json --fov-angles -50,40,40,-45 --size 16x12 --out a.png");
    EXPECT_EQ(a.status, 0) << a.err;
    const Outcome a8 = run("$BIN trace lay.json --fov-angles -50,40,40,-45,-40,50,40,-45 --size 16x12 --out a8.png");
    EXPECT_EQ(a8.status, 0) << a8.err;
}

TEST_F(Hostile, BadHmdProfilesAreRefusedWithTheirPlace) {
    struct Case {
        std::string text, words;
    };
    const Case cases[] = {
        {"{\"name\": \"x\",", "hmd.json:1:"},
        {hmd_profile(kGoodFov, "[16, 12]", "[[0, 0], [1, 0], [1, 1]]", "\n  \"colour\": 1,"),
         "hmd.json:5:3: colour: unknown field"},
        {hmd_profile(R"({"left": -90, "right": 40, "up": 40, "down": -45})"),
         "hmd.json:5:28: left.fov.left: -90 is not within ±89.5 degrees"},
        {hmd_profile(R"({"left": 40, "right": 30, "up": 40, "down": -45})"),
         "hmd.json:5:19: left.fov: right (30) must be at least 1 degree right of left (40)"},
        {hmd_profile(R"({"left": -40, "right": 30, "up": -50, "down": -45})"), "must be at least 1 degree above down"},
        {hmd_profile(R"({"left": -40, "right": 30, "up": 40})"), "left.fov: missing"},
        {hmd_profile(kGoodFov, "[16, 13]"),
         "hmd.json:7:85: right.resolution: the eyes' resolutions differ (16x12 and 16x13)"},
        {hmd_profile(kGoodFov, "[16, 12]", "[[0, 0], [1, 1], [1, 0], [0, 1]]"),
         "left.visible_area[2]: the visible area must be a simple polygon"},
        {hmd_profile(kGoodFov, "[16, 12]", "[[1.5, 0], [2, 0], [2, 1]]"),
         "left.visible_area: no part of the visible area lies inside the image"},
        {hmd_profile(kGoodFov, "[16, 12]", "[[0, 0], [1, 0]]"), "a polygon needs at least 3 corners"},
        {hmd_profile(kGoodFov, "[0, 12]"), "right.resolution[0]: expected a whole number of pixels, 1..8192"},
        {hmd_profile(R"({"left": NaN, "right": 30, "up": 40, "down": -45})"), "hmd.json:5:28: invalid JSON"},
        {hmd_profile(R"({"left": "-40", "right": 30, "up": 40, "down": -45})"), "left.fov.left"},
    };
    for (const Case& c : cases) {
        spit(dir_ / "hmd.json", c.text);
        for (const std::string command : {"render", "trace", "bench"}) {
            const std::string out = command == "bench" ? "" : " --out o.png";
            expect_refused(run("$BIN " + command + " lay.json --hmd hmd.json" + out), 1, c.words);
        }
        EXPECT_EQ(listing(dir_), "hmd.json\nlay.json\n") << c.text;
    }
    expect_refused(run("$BIN render lay.json --hmd missing.json"), 1, "missing.json: does not exist");
    expect_refused(run("$BIN render lay.json --hmd ."), 1, ".: is a directory");
    EXPECT_EQ(listing(dir_), "hmd.json\nlay.json\n");
}

// Issue 38: a visible area's corners are [u, v] (a play area's are [x, z]),
// and a bad ipd is named with its value.
TEST_F(Hostile, HmdProfileMessagesNameCoordinatesAndValues) {
    spit(dir_ / "hmd.json", hmd_profile(kGoodFov, "[16, 12]", "[[0, 0], [1, 0, 0], [1, 1]]"));
    expect_refused(run("$BIN render lay.json --hmd hmd.json --out o.png"), 1,
                   "left.visible_area[1]: must be an array of 2 numbers [u, v] (got an array of 3)");
    std::string ipd = hmd_profile(kGoodFov);
    ipd.replace(ipd.find("0.063"), 5, "12.5");
    spit(dir_ / "hmd.json", ipd);
    expect_refused(run("$BIN render lay.json --hmd hmd.json --out o.png"), 1, "ipd: 12.5 is not in 0..10 m");
    // (A room's floor corners stay [x, z]: tests/layout/prism_rooms_test.cpp.)
}

TEST_F(Hostile, FovAnglesAreChecked) {
    expect_refused(run("$BIN render lay.json --size 8x8 --fov-angles -50,40,40"), 1,
                   "--fov-angles: expected 4 comma-separated numbers, got 3");
    expect_refused(run("$BIN render lay.json --size 8x8 --fov-angles -50,40,40,-45,1,2,3"), 1,
                   "--fov-angles: expected 4 comma-separated numbers, got 7");
    expect_refused(run("$BIN render lay.json --size 8x8 --fov-angles -90,40,40,-45"), 1,
                   "--fov-angles: left eye: -90 is not an angle within ±89.5 degrees");
    // The value as given, not rounded to six places into the bound itself (issue 38).
    expect_refused(run("$BIN render lay.json --size 8x8 --fov-angles -89.50000001,40,40,-45"), 1,
                   "--fov-angles: left eye: -89.50000001 is not an angle within ±89.5 degrees");
    expect_refused(run("$BIN trace lay.json --size 8x8 --fov-angles -50,40,40,-45,-40,50,nan,-45"), 1,
                   "--fov-angles: 'nan' is not a finite number");
    expect_refused(run("$BIN render lay.json --size 8x8 --fov-angles -50,40,40,-45,10,5,40,-45"), 1,
                   "--fov-angles: right eye: right (5) must be at least 1 degree right of left (10)");
    expect_refused(run("$BIN render lay.json --size 8x8 --fov-angles 0,0.5,40,-45"), 1,
                   "right (0.5) must be at least 1 degree right of left (0)");
    EXPECT_EQ(listing(dir_), "lay.json\n");
}

TEST_F(Hostile, FovFovAnglesAndHmdExcludeEachOther) {
    spit(dir_ / "hmd.json", hmd_profile(kGoodFov));
    for (const std::string command : {"render", "trace", "bench", "preview"}) {
        expect_refused(run("$BIN " + command + " lay.json --fov 90 --fov-angles -50,40,40,-45"), 2,
                       "--fov and --fov-angles exclude each other");
        expect_refused(run("$BIN " + command + " lay.json --fov 90 --hmd hmd.json"), 2,
                       "--fov and --hmd exclude each other");
        expect_refused(run("$BIN " + command + " lay.json --fov-angles -50,40,40,-45 --hmd hmd.json"), 2,
                       "--fov-angles and --hmd exclude each other");
    }
    // --out over the profile it reads: a usage error, the profile untouched.
    expect_refused(run("$BIN render lay.json --hmd hmd.json --out hmd.json"), 2, "hmd.json");
    EXPECT_EQ(slurp(dir_ / "hmd.json"), hmd_profile(kGoodFov));
    EXPECT_EQ(listing(dir_), "hmd.json\nlay.json\n");
}

}  // namespace
}  // namespace impossible::hostile
