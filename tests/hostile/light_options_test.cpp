// Lights through the program (cli.md, "Time, hands and lights";
// layout-format.md, "Lights"): --light-depth on a "fixed" layout warns in
// one line and changes nothing else; bad values and bad light fields are
// one-line errors naming the option or FILE:LINE:COL and the field, with no
// output written.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

TEST_F(Hostile, LightDepthOnAFixedLayoutWarnsAndDrawsTheSameImage) {
    const Outcome plain = run("$BIN render lay.json --size 16x8 --out plain.png");
    ASSERT_EQ(plain.status, 0) << plain.err;
    const Outcome deep = run("$BIN render lay.json --size 16x8 --out deep.png --light-depth 5");
    EXPECT_EQ(deep.status, 0) << deep.err;
    EXPECT_EQ(deep.err, "warning: --light-depth has no effect: lay.json's lighting is \"fixed\"\n");
    EXPECT_EQ(slurp(dir_ / "plain.png"), slurp(dir_ / "deep.png"));
    expect_refused(run("$BIN trace lay.json --size 8x8 --out t.png --light-depth 17"), 1,
                   "--light-depth: 17 is out of range 0..16");
    expect_refused(run("$BIN render lay.json --size 8x8 --out t.png --shadow-size 5000"), 1,
                   "--shadow-size: 5000 is out of range 0..4096");
    EXPECT_EQ(listing(dir_), "deep.png\nlay.json\nplain.png\n");
}

TEST_F(Hostile, ABadLightIsOneErrorAtItsField) {
    std::string text = slurp(dir_ / "lay.json");
    text.replace(text.find("\"version\": 1,"), 13, "\"version\": 1, \"lighting\": \"lights\",");
    const std::size_t rooms = text.find("\"rooms\"");
    const std::size_t room = text.find("\"id\"", rooms);
    text.insert(room, "\"lights\": [ { \"position\": [0, -50, 0], \"intensity\": 3 } ], ");
    spit(dir_ / "lit.json", text);
    const Outcome r = run("$BIN render lit.json --size 8x8 --out x.png");
    expect_refused(r, 1, "lit.json:");
    EXPECT_NE(r.err.find(": rooms[0].lights[0].position: the light at [0, -50, 0] is not strictly inside its room"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// A cap on the commands' address space (the plain build only: the
// sanitizers reserve terabytes of shadow memory up front), and how much
// slower the instrumented build may be.
std::string memory_cap(const char* kilobytes) {
    return IMPOSSIBLE_SANITIZED ? std::string() : std::string("ulimit -v ") + kilobytes + "; ";
}
constexpr double kLightSlowdown = IMPOSSIBLE_SANITIZED ? 4.0 : 1.0;

// A 2 m cube of six windows paired face to face (reflectance 0.5), lit by
// one lamp at light depth 16: 1.6 million light paths.
std::string lit_window_cube() {
    std::string portals;
    const char* const specs[][4] = {{"x", "[-1, 1, 0]", "[1, 0, 0]", "[0, 1, 0]"},
                                    {"y", "[0, 0, 0]", "[0, 1, 0]", "[0, 0, 1]"},
                                    {"z", "[0, 1, -1]", "[0, 0, 1]", "[0, 1, 0]"}};
    const char* const far[][2] = {
        {"[1, 1, 0]", "[-1, 0, 0]"}, {"[0, 2, 0]", "[0, -1, 0]"}, {"[0, 1, 1]", "[0, 0, -1]"}};
    for (int i = 0; i < 3; ++i) {
        const std::string n = specs[i][0], up = specs[i][3];
        const auto window = [&](const std::string& id, const std::string& center, const std::string& normal,
                                const std::string& target) {
            return "{\"id\": \"" + id + "\", \"room\": \"cube\", \"kind\": \"window\", \"center\": " + center +
                   ", \"normal\": " + normal + ", \"up\": " + up +
                   ", \"width\": 2, \"height\": 2, \"reflectance\": 0.5, \"target\": \"" + target + "\"}";
        };
        portals += (i ? ",\n" : "") + window("a" + n, specs[i][1], specs[i][2], "b" + n) + ",\n" +
                   window("b" + n, far[i][0], far[i][1], "a" + n);
    }
    return "{\"format\": \"impossible-layout\", \"version\": 1, \"lighting\": \"lights\", \"light_depth\": 16,\n"
           "\"start\": {\"room\": \"cube\", \"position\": [0, 1, 0]},\n"
           "\"rooms\": [{\"id\": \"cube\", \"min\": [-1, 0, -1], \"max\": [1, 2, 1], \"lights\": [{\"position\": "
           "[0.3, 1.2, 0.1]}]}],\n\"portals\": [" +
           portals + "]}\n";
}

TEST_F(Hostile, ValidateBoundsTheLightPathsItCounts) {
    // A 2 m cube of six windows paired face to face (reflectance 0.5) at
    // light depth 16: 1.6 million light paths, 5 GB and 26 s to list them
    // all; validate counts at most 1,024, the paths frames are lit by.
    spit(dir_ / "cube.json", lit_window_cube());
    const Outcome r = run(memory_cap("2000000") + "$BIN validate cube.json", static_cast<int>(10 * kLightSlowdown));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_LT(r.seconds, 5.0 * kLightSlowdown);
    EXPECT_NE(r.out.find("  light paths: more than 1024 in all rooms together; frames are lit at light depth "),
              std::string::npos)
        << r.out;
}

TEST_F(Hostile, FramesAreLitByBoundedLightPaths) {
    // The same cube rendered and traced: both light at light depth 2 (133
    // paths, the deepest within 1,024) and say so; before, render listed all
    // 1.6 million paths (minutes, gigabytes) and trace followed them per hit.
    spit(dir_ / "cube.json", lit_window_cube());
    const std::string warning =
        "warning: light depth 16 gives more than 1024 light paths in cube.json: lit at light depth 2\n";
    for (const char* command : {"render", "trace"}) {
        const Outcome r = run(memory_cap("4000000") + "$BIN " + command +
                                  " cube.json --size 24x16 --max-depth 2 --out " + command + ".png",
                              static_cast<int>(60 * kLightSlowdown));
        EXPECT_EQ(r.status, 0) << command << ": " << r.err;
        EXPECT_EQ(r.err, warning) << command;
        EXPECT_LT(r.seconds, 30.0 * kLightSlowdown) << command;
    }
}

}  // namespace
}  // namespace impossible::hostile
