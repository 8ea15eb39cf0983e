// Work bounded by pixels: a corridor with N doors at each end, all leading
// into each other (door i of one end to door i of the other), rendered deep.
// Before, 200 doors at 64x48 and depth 250 took 21 s and 1000 doors 304 s;
// a portal that covers no pixel centre is now drawn no further
// (docs/bounded-work.md has the figures).
#include <chrono>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// The corridor of layouts/corridor.json with n doors side by side at each end.
std::string corridor(int n) {
    std::string portals;
    for (int i = 0; i < n; ++i) {
        const double x = -1.0 + (i + 0.5) * 2.0 / n, w = 2.0 / n * 0.9;
        for (int end = 0; end < 2; ++end) {
            const char* me = end ? "s" : "n";
            const char* other = end ? "n" : "s";
            portals += std::string(portals.empty() ? "" : ",\n") + "{\"id\":\"" + me + std::to_string(i) +
                       "\",\"room\":\"c\",\"center\":[" + std::to_string(x) + ",1.05," + (end ? "4" : "-4") +
                       "],\"normal\":[0,0," + (end ? "-1" : "1") + "],\"width\":" + std::to_string(w) +
                       ",\"height\":2.1,\"target\":\"" + other + std::to_string(i) + "\"}";
        }
    }
    return "{\"format\":\"impossible-layout\",\"version\":1,\"play_area\":{\"min\":[-1,-4],\"max\":[1,4]},"
           "\"start\":{\"room\":\"c\",\"position\":[0.25,1.6,2.0],\"yaw_deg\":4.0},"
           "\"rooms\":[{\"id\":\"c\",\"min\":[-1,0,-4],\"max\":[1,2.6,4],\"color\":[0.8,0.76,0.68],\"checker\":1.0}],"
           "\"portals\":[" +
           portals + "]}";
}

TEST_F(Hostile, ACorridorOf1000DoorsAtDepth250RendersInSeconds) {
    spit(dir_ / "c.json", corridor(1000));
    const Outcome r = run("$BIN render c.json --size 64x48 --max-depth 250 --out r.png --ids r-ids.png --stats", 60);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_LT(r.seconds, 15.0);  // 0.96 s on the development machine; 304 s before
    EXPECT_NE(r.err.find("budget_fills=0"), std::string::npos) << r.err;
}

TEST_F(Hostile, ACorridorOf200DoorsMatchesTheTracer) {
    spit(dir_ / "c.json", corridor(200));
    const std::string view = " c.json --size 96x64 --max-depth 250";
    const Outcome r = run("$BIN render" + view + " --out r.png --ids r-ids.png && $BIN trace" + view +
                              " --out t.png --ids t-ids.png && $BIN compare r.png t.png --ids-a r-ids.png --ids-b "
                              "t-ids.png --max-mismatch 0",
                          120);
    EXPECT_EQ(r.status, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("id_mismatches=0"), std::string::npos) << r.out;
}

// A multisampled frame past 2 x 8192 x 8192 samples is refused in one line
// naming --size and --samples, before any buffer is made (it peaked at
// 4.95 GB, or failed after 4.4 GB with an incomplete framebuffer).
TEST_F(Hostile, AFramePastTheSampleBoundIsRefusedBeforeAnyBuffer) {
    const auto start = std::chrono::steady_clock::now();
    const Outcome r = run("$BIN render --size 8192x4096 --samples 4 --out big.png");
    expect_refused(r, 1,
                   "--size 8192x4096 with --samples 4 makes 268435456 samples a frame, more than the "
                   "renderer's bound of 134217728 (2 x 8192 x 8192; docs/bounded-work.md)");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
    EXPECT_FALSE(fs::exists(dir_ / "big.png"));
    expect_refused(run("$BIN render --size 8192x8192 --samples 2 --out big.png"), 1, "with --samples 2 makes");
}

TEST_F(Hostile, ThePortalPassBudgetShowsTheFillAndSaysSo) {
    const std::string corridor_json = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/corridor.json";
    const std::string view = " " + q(corridor_json) + " --size 64x48 --max-depth 250 --stats";
    const Outcome small = run("$BIN render" + view + " --max-portal-passes 3 --out a.png --ids a-ids.png");
    ASSERT_EQ(small.status, 0) << small.err;
    EXPECT_NE(small.err.find("warning: the frame reached its budget of 3 portal passes"), std::string::npos)
        << small.err;
    EXPECT_NE(small.err.find("portal_passes_drawn=3 "), std::string::npos) << small.err;
    // Within the budget (the default, or one just large enough) the image is
    // the same, byte for byte.
    const Outcome big = run("$BIN render" + view + " --out b.png --ids b-ids.png && $BIN render" + view +
                            " --max-portal-passes 1000000 --out c.png --ids c-ids.png");
    ASSERT_EQ(big.status, 0) << big.err;
    EXPECT_EQ(big.err.find("warning"), std::string::npos) << big.err;
    EXPECT_EQ(slurp(dir_ / "b.png"), slurp(dir_ / "c.png"));
    EXPECT_NE(slurp(dir_ / "a-ids.png"), slurp(dir_ / "b-ids.png"));
}

}  // namespace
}  // namespace impossible::hostile
