// `generate` as a new user tries it (issue 23, deliver 5): six rooms on a
// 4 x 4 m floor failed for every seed ("could not fit 6 rooms of at least
// 1.5 m"); now they are packed, the expansion ratio is reported, the same
// seed writes the same bytes, the layout validates and its tour visits every
// room, and a floor too narrow for any room is refused by name.
#include <cmath>
#include <cstdio>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

TEST_F(Hostile, GenerateSixRoomsOnFourByFourReportsTheRatio) {
    const Outcome g = run("$BIN generate --play-area 4x4 --rooms 6 --seed 7 --out g.json");
    ASSERT_EQ(g.status, 0) << g.err;
    EXPECT_NE(g.err.find("generate: wrote 6 rooms to g.json\n"), std::string::npos) << g.err;
    const std::size_t at = g.err.find("generate: expansion ratio ");
    ASSERT_NE(at, std::string::npos) << g.err;
    EXPECT_GE(std::stod(g.err.substr(at + 26)), 2.4) << g.err;
    EXPECT_NE(g.err.find("m2 of room floor on 16.00 m2 of play area)\n"), std::string::npos) << g.err;
    // The same arguments, the same bytes, on standard output too.
    const Outcome again = run("$BIN generate --play-area 4x4 --rooms 6 --seed 7 2>/dev/null | cmp - g.json");
    EXPECT_EQ(again.status, 0) << again.out << again.err;
    const Outcome v = run("$BIN validate g.json");
    EXPECT_EQ(v.status, 0) << v.err;
    EXPECT_NE(v.out.find("reachable rooms: 6 of 6"), std::string::npos) << v.out;
    EXPECT_NE(v.out.find("findings: 0"), std::string::npos) << v.out;
    const Outcome t = run("$BIN tour g.json --out t.txt");
    EXPECT_EQ(t.status, 0) << t.err;
    EXPECT_NE(t.out.find("rooms visited: 6 of 6"), std::string::npos) << t.out;
}

TEST_F(Hostile, GenerateOnAFloorNarrowerThanARoomSaysSo) {
    expect_refused(run("$BIN generate --play-area 1.2x4 --rooms 2 --seed 1 --out g.json"), 1,
                   "a room cannot be 1.5 m wide on a 1.2 x 4 m floor (it needs 1.52 m across)");
    EXPECT_EQ(listing(dir_), "lay.json\n");  // no partial output
    spit(dir_ / "thin.json", "[[0, 0], [6, 0], [6, 1.4], [0, 1.4]]");
    expect_refused(run("$BIN generate --play-area-file thin.json --rooms 1 --seed 1"), 1,
                   "a room cannot be 1.5 m wide on a 6 x 1.4 m floor");
}

// A play area past the loader's limits (10,001 corners, a corner at
// 200,000 m) made generate exit 0 with a layout validate refused; it is now
// refused by those limits, FILE:LINE:COLUMN as the loader says it, with no
// file written (issue 36, item 5).
TEST_F(Hostile, GenerateRefusesAPlayAreaTheLoaderWouldRefuse) {
    std::string many = "[";
    for (int i = 0; i < 10'001; ++i) {
        const double a = 6.283185307179586 * i / 10'001;
        many += (i ? "," : "") + std::string("[") + std::to_string(5 * std::cos(a)) + "," +
                std::to_string(5 * std::sin(a)) + "]";
    }
    spit(dir_ / "many.json", many + "]");
    expect_refused(run("$BIN generate --play-area-file many.json --rooms 2 --seed 1 --out g.json"), 1,
                   "many.json:1:1: has 10001 entries; at most 10000 are allowed");
    spit(dir_ / "far.json", "{\"polygon\": [[0, 0], [6, 0], [200000, 4], [0, 4]]}");
    expect_refused(run("$BIN generate --play-area-file far.json --rooms 2 --seed 1 --out g.json"), 1,
                   "far.json:1:31: polygon[2][0]: 200000 is out of range (|value| must be at most 100000 m)");
    EXPECT_FALSE(fs::exists(dir_ / "g.json"));
}

TEST_F(Hostile, GenerateOnAnLShapedFloorWritesPrismRoomsThatValidate) {
    spit(dir_ / "l.json", "{\"polygon\": [[-3, -3], [3, -3], [3, 0], [0, 0], [0, 3], [-3, 3]]}");
    const Outcome g = run("$BIN generate --play-area-file l.json --rooms 8 --seed 2 --out g.json");
    ASSERT_EQ(g.status, 0) << g.err;
    EXPECT_NE(g.err.find("generate: expansion ratio "), std::string::npos) << g.err;
    const Outcome v = run("$BIN validate g.json");
    EXPECT_EQ(v.status, 0) << v.err;
    EXPECT_NE(v.out.find("reachable rooms: 8 of 8"), std::string::npos) << v.out;
    EXPECT_NE(v.out.find("findings: 0"), std::string::npos) << v.out;
    const Outcome t = run("$BIN tour g.json --out t.txt");
    EXPECT_NE(t.out.find("rooms visited: 8 of 8"), std::string::npos) << t.out << t.err;
}

// A 10,000-corner star of spikes 500 m long around a core 4 m across gave
// "no room 1.5 m wide fits in this play area", though the core holds a
// 1.5 x 2.5 m room: the first room was tried at random across the 1000 m
// bounding box, where the spikes are under 0.4 m wide (issue 36). Now rooms
// are tried on the play area's widest spot too: one room and two fit and
// validate; three do not, and the message says where the floor is widest;
// a core 1.4 m across holds none, and the message says that. Each run
// within seconds (the box tests' work is bounded, design::kMaxBoxWork).
// The sanitizer build runs the same several times slower (about 30 s a run
// on a loaded two-core machine): its bound is kStarSlowdown times as wide.
constexpr double kStarSlowdown = IMPOSSIBLE_SANITIZED ? 4.0 : 1.0;

TEST_F(Hostile, GenerateFitsRoomsInTheCoreOfAStarOfLongSpikes) {
    spit(dir_ / "star.json", star_polygon(10'000, 500, 2));
    for (const int rooms : {1, 2}) {
        const std::string n = std::to_string(rooms);
        const Outcome g = run("$BIN generate --play-area-file star.json --rooms " + n + " --seed 1 --out g.json", 240);
        ASSERT_EQ(g.status, 0) << g.err;
        EXPECT_LT(g.seconds, 20.0 * kStarSlowdown);
        const Outcome v = run("$BIN validate g.json");
        EXPECT_EQ(v.status, 0) << v.err;
        EXPECT_NE(v.out.find("reachable rooms: " + n + " of " + n), std::string::npos) << v.out;
        EXPECT_NE(v.out.find("rooms outside the play area: none"), std::string::npos) << v.out;
        EXPECT_NE(v.out.find("findings: 0"), std::string::npos) << v.out;
    }
    const Outcome three = run("$BIN generate --play-area-file star.json --rooms 3 --seed 1 --out three.json", 240);
    expect_refused(three, 1,
                   "could not fit 3 rooms of at least 1.5 m, joined by doors, in this play area within the overlap "
                   "limit (its widest spot is a circle 4 m across at (0, 0); try fewer rooms, a larger floor or a "
                   "higher --max-overlap)");
    EXPECT_LT(three.seconds, 20.0 * kStarSlowdown);  // 23 s without the bound on the box tests
    EXPECT_FALSE(fs::exists(dir_ / "three.json"));
    spit(dir_ / "thin.json", star_polygon(10'000, 500, 0.7));
    const Outcome thin = run("$BIN generate --play-area-file thin.json --rooms 1 --seed 1", 240);
    expect_refused(thin, 1,
                   "no room 1.5 m wide fits in this play area (1000 x 1000 m across; the widest spot found is a "
                   "circle 1.4 m across at (0, 0))");
    EXPECT_LT(thin.seconds, 20.0 * kStarSlowdown);
}

}  // namespace
}  // namespace impossible::hostile
