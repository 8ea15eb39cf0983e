// Mirrors and windows through the built program: validate counts them, walk
// never teleports through them however fast the head goes, a kind of
// megabytes is one short line, and 10 000 mirrors in one wall (as many as
// the loader's limit of JSON values allows) are checked and walked past in
// bounded time.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

const std::string kMirrorsWindows = q(std::string(IMPOSSIBLE_TEST_DATA) + "/layouts/mirrors_windows.json");

TEST_F(Hostile, ValidateCountsDoorsMirrorsAndWindows) {
    const Outcome r = run("$BIN validate " + kMirrorsWindows);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("portals: 5\npairs: 2\ndoor pairs: 1\nwindow pairs: 1\nmirrors: 1\n"), std::string::npos)
        << r.out;
    const Outcome j = run("$BIN validate " + kMirrorsWindows + " --json");
    EXPECT_EQ(j.status, 0) << j.err;
    EXPECT_NE(j.out.find("\"mirrors\": 1"), std::string::npos) << j.out.substr(0, 600);
}

TEST_F(Hostile, AWalkNeverTeleportsThroughAMirrorOrAWindow) {
    // Through the mirror (z = -2) and the window (x = -2), 900 km in one frame each.
    const std::string path = "printf '0 1.6 0 0 0 0\\n0 1.6 -900000 0 0 0\\n0 1.5 0 0 0 0\\n-900000 1.5 0 0 0 0\\n'";
    const Outcome r = run(path + " > p.txt; $BIN walk " + kMirrorsWindows + " --path p.txt");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 4) << r.out;
    std::size_t halls = 0;
    for (std::size_t at = r.out.find("\"room\":\"hall\",\"teleports\":[]"); at != std::string::npos;
         at = r.out.find("\"room\":\"hall\",\"teleports\":[]", at + 1))
        ++halls;
    EXPECT_EQ(halls, 4u) << r.out;
}

TEST_F(Hostile, AHugeUnknownKindIsOneShortLine) {
    std::string layout = slurp(fs::path(IMPOSSIBLE_TEST_DATA) / "layouts/mirrors_windows.json");
    layout.replace(layout.find("\"mirror\""), 8, "\"" + std::string(3'000'000, 'k') + "\"");
    spit(dir_ / "kind.json", layout);
    const Outcome r = run("$BIN validate kind.json");
    expect_refused(r, 1, "portals[2].kind: unknown kind \"kkkk");
    EXPECT_LT(r.err.size(), 600u);
    EXPECT_NE(r.err.find("(2999900 more bytes)"), std::string::npos) << r.err;
}

TEST_F(Hostile, TenThousandMirrorsInOneWall) {
    // 100 x 100 mirrors of 4 x 3 cm tiling the hall's -z wall, edge to edge.
    std::string portals;
    for (int c = 0; c < 100; ++c) {
        for (int r = 0; r < 100; ++r) {
            char entry[200];
            std::snprintf(entry, sizeof entry,
                          "%s{\"id\":\"m%d_%d\",\"kind\":\"mirror\",\"room\":\"hall\",\"center\":[%.3f,%.3f,-2],"
                          "\"normal\":[0,0,1],\"width\":0.04,\"height\":0.03}",
                          portals.empty() ? "" : ",", c, r, -1.98 + 0.04 * c, 0.015 + 0.03 * r);
            portals += entry;
        }
    }
    spit(dir_ / "many.json",
         "{\"format\":\"impossible-layout\",\"version\":1,\"play_area\":{\"min\":[-2,-2],"
         "\"max\":[2,2]},\"start\":{\"room\":\"hall\",\"position\":[0,1.6,1]},\"rooms\":["
         "{\"id\":\"hall\",\"min\":[-2,0,-2],\"max\":[2,3,2]}],\"portals\":[" +
             portals + "]}");
    const Outcome v = run("$BIN validate many.json");
    EXPECT_EQ(v.status, 0) << v.err.substr(0, 600);
    EXPECT_NE(v.out.find("mirrors: 10000\n"), std::string::npos) << v.out;
    EXPECT_LT(v.seconds, 20.0);
    const Outcome w =
        run("printf '0 1.6 0 0 0 0\\n0 1.6 -5 0 0 0\\n0 1.6 1 0 0 0\\n' > p.txt; "
            "$BIN walk many.json --path p.txt");
    EXPECT_EQ(w.status, 0) << w.err;
    EXPECT_EQ(w.out.find("\"teleports\":[\""), std::string::npos) << w.out;
    EXPECT_LT(w.seconds, 20.0);
}

}  // namespace
}  // namespace impossible::hostile
