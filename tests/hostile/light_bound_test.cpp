// A frame's light work is bounded (docs/bounded-work.md, "Path rectangles"):
// a lit star-shaped room of 1,000 walls with 10 lamps asked each fragment
// to test 10,000 wall rectangles (render at 1280×720 still ran after
// 120 s). Both programs now light it by the lamps whose rectangles fit in
// 1,024, say so in one line, and still agree; validate says it too.
#include <cmath>
#include <cstdio>
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// The star room of tests/lights/lights_test_layouts.hpp (star_room): a
// prism of `corners` corners at radii 5 and 4 m, y 0..3, with `lamps`
// lamps on a ring of radius 2 m at y = 2.
std::string star_json(int corners, int lamps) {
    const double pi = 3.14159265358979323846;
    const auto number = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9f", v);
        return std::string(text);
    };
    std::string floor, lights;
    for (int i = 0; i < corners; ++i) {
        const double a = 2.0 * pi * i / corners, r = i % 2 == 0 ? 5.0 : 4.0;
        floor += (i ? "," : "") + ("[" + number(r * std::cos(a)) + "," + number(r * std::sin(a)) + "]");
    }
    for (int i = 0; i < lamps; ++i) {
        const double a = 2.0 * pi * (i + 0.5) / lamps;
        lights += (i ? "," : "") + ("{\"position\":[" + number(2.0 * std::cos(a)) + ",2," + number(2.0 * std::sin(a)) +
                                    "],\"intensity\":3}");
    }
    return "{\"format\":\"impossible-layout\",\"version\":1,\"lighting\":\"lights\",\"start\":{\"room\":\"star\","
           "\"position\":[0,1.6,0]},\"rooms\":[{\"id\":\"star\",\"floor\":[" +
           floor + "],\"y\":[0,3],\"lights\":[" + lights + "]}],\"portals\":[]}";
}

TEST_F(Hostile, AStarRoomsLightIsBoundedByItsPathRectangles) {
    spit(dir_ / "star.json", star_json(1000, 10));
    const std::string warning =
        "warning: light depth 2 gives more than 1024 path rectangles in star.json: lit at light depth 0 by 2 of "
        "its 10 lights\n";
    for (const std::string command : {"render", "trace"}) {
        const Outcome r = run(
            "$BIN " + command + " star.json --size 64x36 --out " + command + ".png --ids " + command + "-ids.png", 120);
        ASSERT_EQ(r.status, 0) << command << ": " << r.err;
        EXPECT_EQ(r.err, warning) << command;
    }
    const Outcome same = run("$BIN compare render.png trace.png --ids-a render-ids.png --ids-b trace-ids.png");
    EXPECT_EQ(same.status, 0) << same.err;
    EXPECT_NE(same.out.find("id_mismatches=0 "), std::string::npos) << same.out;
    const Outcome report = run("$BIN validate star.json");
    EXPECT_EQ(report.status, 0) << report.err;
    EXPECT_NE(report.out.find("  path rectangles: more than 1024 in all rooms together, even at light depth 0; "
                              "frames are lit at light depth 0 by 2 of the 10 lights\n  star: 10 lights, 2 light "
                              "paths\n"),
              std::string::npos)
        << report.out;
}

TEST_F(Hostile, AStarRoomWithinThePathRectanglesIsLitByAllItsLamps) {
    // 100 walls: each lamp lies behind 30 of them, 300 rectangles in all.
    spit(dir_ / "star.json", star_json(100, 10));
    const Outcome r = run("$BIN render star.json --size 32x18 --out r.png && $BIN validate star.json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("  star: 10 lights, 10 light paths\n"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace impossible::hostile
