// Per-eye poses (docs/headsets.md, "Eye poses"): --eye-poses and a
// profile's "position" and "orientation". Bad values and profiles are
// refused with one line (a profile's as FILE:LINE:COLUMN: field: message),
// status 1, nothing written; --eye-poses and --ipd exclude each other
// (status 2) in render, trace, bench and preview.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// A small profile; `left_pose` and `right_pose` are inserted into each eye's
// object (e.g. `"position": [...], "orientation": [...],`), `top` after
// "source".
std::string posed_profile(const std::string& left_pose, const std::string& right_pose, const std::string& top = "") {
    return "{\n"
           "  \"name\": \"canted\",\n"
           "  \"source\": \"made up\"," +
           top +
           "\n"
           "  \"left\": {" +
           left_pose +
           "\"fov\": {\"left\": -50, \"right\": 45, \"up\": 45, \"down\": -45}, \"resolution\": [16, 12]},\n"
           "  \"right\": {" +
           right_pose +
           "\"fov\": {\"left\": -45, \"right\": 50, \"up\": 45, \"down\": -45}, \"resolution\": [16, 12]}\n}\n";
}

// Each eye turned 5° outwards: quaternions (0, ±sin 2.5°, 0, cos 2.5°).
const std::string kLeft =
    R"("position": [-0.032, 0, 0], "orientation": [0, 0.043619387365336, 0, 0.9990482215818578], )";
const std::string kRight =
    R"("position": [0.032, 0, 0], "orientation": [0, -0.043619387365336, 0, 0.9990482215818578], )";
const std::string kCanted = "-0.032,0,0,5,0,0,0.032,0,0,-5,0,0";

TEST_F(Hostile, EyePosesRenderAndTrace) {
    spit(dir_ / "hmd.json", posed_profile(kLeft, kRight));
    for (const std::string command : {"render", "trace"}) {
        const Outcome p = run("$BIN " + command + " lay.json --hmd hmd.json --out p.png");
        EXPECT_EQ(p.status, 0) << p.err;
        const Outcome e = run("$BIN " + command + " lay.json --size 16x12 --eye-poses " + kCanted + " --out e.png");
        EXPECT_EQ(e.status, 0) << e.err;
        // The profile's poses are those angles: the same frame byte for byte.
        const Outcome a = run("$BIN " + command + " lay.json --size 16x12 --fov-angles -50,45,45,-45,-45,50,45,-45 " +
                              "--eye-poses " + kCanted + " --out a.png");
        EXPECT_EQ(a.status, 0) << a.err;
        EXPECT_EQ(slurp(dir_ / "a.png"), slurp(dir_ / "p.png")) << command;
        // --eye-poses replaces the profile's poses, as --size its size.
        const Outcome r =
            run("$BIN " + command + " lay.json --hmd hmd.json --eye-poses " + "0,0,0,0,0,0,0.03,0,0,0,0,0 --out r.png");
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_NE(slurp(dir_ / "r.png"), slurp(dir_ / "p.png")) << command;
    }
    const Outcome b = run("$BIN bench lay.json --hmd hmd.json --frames 2");
    EXPECT_EQ(b.status, 0) << b.err;
}

TEST_F(Hostile, EyePosesAreChecked) {
    expect_refused(run("$BIN render lay.json --size 8x8 --eye-poses 0,0,0,0,0,0"), 1,
                   "--eye-poses: expected 12 comma-separated numbers, got 6");
    expect_refused(run("$BIN trace lay.json --size 8x8 --eye-poses 0,0,0,0,0,0,0,0,nan,0,0,0"), 1,
                   "--eye-poses: 'nan' is not a finite number");
    expect_refused(run("$BIN render lay.json --size 8x8 --eye-poses 0,0,0,0,0,0,0.8,0.8,0,0,0,0"), 1,
                   "--eye-poses: right eye: the position is 1.1313708498984762 m from the head centre, more than 1 m");
    expect_refused(run("$BIN render lay.json --size 8x8 --eye-poses 0,0,0,0,89.50000001,0,0,0,0,0,0,0"), 1,
                   "--eye-poses: left eye: pitch 89.50000001 is not within ±89.5 degrees");
    expect_refused(run("$BIN render lay.json --size 8x8 --eye-poses 0,0,0,2e7,0,0,0,0,0,0,0,0"), 1,
                   "has a value beyond 1e7");
    EXPECT_EQ(listing(dir_), "lay.json\n");
}

TEST_F(Hostile, EyePosesAndIpdExcludeEachOther) {
    for (const std::string command : {"render", "trace", "bench", "preview"})
        expect_refused(run("$BIN " + command + " lay.json --ipd 0.07 --eye-poses " + kCanted), 2,
                       "--eye-poses and --ipd exclude each other");
    // A profile with eye poses has no IPD for --ipd to replace.
    spit(dir_ / "hmd.json", posed_profile(kLeft, kRight));
    expect_refused(run("$BIN render lay.json --hmd hmd.json --ipd 0.07"), 1,
                   "--ipd: hmd.json gives each eye's position and orientation, which --ipd cannot replace; give "
                   "--eye-poses instead");
    EXPECT_EQ(listing(dir_), "hmd.json\nlay.json\n");
}

TEST_F(Hostile, BadEyePosesInProfilesAreRefusedWithTheirPlace) {
    struct Case {
        std::string text, words;
    };
    const std::string no_pose;
    const Case cases[] = {
        {posed_profile(kLeft, no_pose),
         "hmd.json:5:12: right: the left eye has a position and an orientation, so the right eye needs them too"},
        {posed_profile(no_pose, kRight),
         "hmd.json:4:11: left: the right eye has a position and an orientation, so the left eye needs them too"},
        {posed_profile(R"("position": [-0.032, 0, 0], )", kRight),
         "hmd.json:4:12: left.position: an eye's pose needs both position and orientation (orientation is missing)"},
        {posed_profile(R"("orientation": [0, 0, 0, 1], )", kRight),
         "left.orientation: an eye's pose needs both position and orientation (position is missing)"},
        {posed_profile(R"("position": [-0.032, 0, 0], "orientation": [0, 0, 0, 1.000002], )", kRight),
         "hmd.json:4:55: left.orientation: is not a unit quaternion [x, y, z, w]: its length is 1.000002, not 1 "
         "within 1e-6"},
        {posed_profile(R"("position": [-0.032, 0, 0], "orientation": [0, 0, 1], )", kRight),
         "left.orientation: expected a unit quaternion [x, y, z, w]"},
        {posed_profile(R"("position": [-0.032, 0, 0], "orientation": [0, 0, 0, "1"], )", kRight),
         "left.orientation[3]"},
        {posed_profile(kLeft, R"("position": [0, 1.5, 0], "orientation": [0, 0, 0, 1], )"),
         "hmd.json:5:25: right.position: is 1.5 m from the head centre, more than 1 m"},
        {posed_profile(kLeft, R"("position": [0, 0], "orientation": [0, 0, 0, 1], )"), "right.position"},
        {posed_profile(kLeft, kRight, "\n  \"ipd\": 0.064,"),
         "hmd.json:4:3: ipd: the eyes' positions give the distance between them: leave ipd out"},
    };
    for (const Case& c : cases) {
        spit(dir_ / "hmd.json", c.text);
        for (const std::string command : {"render", "trace"})
            expect_refused(run("$BIN " + command + " lay.json --hmd hmd.json --out o.png"), 1, c.words);
        EXPECT_EQ(listing(dir_), "hmd.json\nlay.json\n") << c.text;
    }
}

}  // namespace
}  // namespace impossible::hostile
