// The designer commands on prism rooms (layout-format.md, "Rooms of any
// shape": overlap, reachability and fit use the polygon): validate measures
// an L, plan draws it, tour walks round its inner corner; two floors whose
// walls cross everywhere are measured in bounded time.
#include <cmath>
#include <regex>
#include <sstream>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// An L of two 2 m arms, 6 m long (its notch is x > 2, z > 2), a box room
// "den" beyond a door at the end of the arm along z, and `extra` rooms.
std::string ell_file(
    const std::string& extra = "",
    const std::string& play_area = "{ \"polygon\": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 8], [0, 8]] }") {
    return "{ \"format\": \"impossible-layout\", \"version\": 1,\n"
           "  \"play_area\": " +
           play_area +
           ",\n"
           "  \"start\": { \"room\": \"ell\", \"position\": [5.5, 1.6, 1], \"yaw_deg\": 90 },\n"
           "  \"rooms\": [\n"
           "    { \"id\": \"ell\", \"floor\": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 6], [0, 6]], \"y\": [0, 3] },\n"
           "    { \"id\": \"den\", \"min\": [0, 0, 6], \"max\": [2, 3, 8] }" +
           extra +
           "\n  ],\n"
           "  \"portals\": [\n"
           "    { \"id\": \"out\", \"room\": \"ell\", \"center\": [1, 1.05, 6], \"normal\": [0, 0, -1], \"width\": 0.9,"
           " \"height\": 2.1, \"target\": \"in\" },\n"
           "    { \"id\": \"in\", \"room\": \"den\", \"center\": [1, 1.05, 6], \"normal\": [0, 0, 1], \"width\": 0.9,"
           " \"height\": 2.1, \"target\": \"out\" }\n  ]\n}\n";
}

using HostilePrismDesign = Hostile;

TEST_F(HostilePrismDesign, ValidateMeasuresOverlapAndFitByThePolygon) {
    // A 2 x 2 m box over the L's inner corner: 3 m² shared (4 by the L's
    // bounding box), and 1 m² of it in the notch, outside the play area.
    spit(dir_ / "ell.json", ell_file(",\n    { \"id\": \"box\", \"min\": [1, 0, 1], \"max\": [3, 3, 3] }"));
    const Outcome r = run("$BIN validate ell.json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("  ell / box: 3.00 m2, 75.0 % (limit 56 %) noticeable\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rooms outside the play area as walked: box\n"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("room \"box\" reaches 1.00 m2 outside the play area"), std::string::npos) << r.err;
    const Outcome j = run("$BIN validate ell.json --json");
    EXPECT_EQ(j.status, 0) << j.err;
    // The L's physical floor is its six corners, counter-clockwise.
    std::string compact = j.out;
    std::erase_if(compact, [](char c) { return c == ' ' || c == '\n'; });
    EXPECT_NE(compact.find("\"physical_floor\":[[0.0,0.0],[6.0,0.0],[6.0,2.0],[2.0,2.0],[2.0,6.0],[0.0,6.0]]"),
              std::string::npos)
        << j.out;
}

TEST_F(HostilePrismDesign, PlanDrawsThePolygon) {
    spit(dir_ / "ell.json", ell_file());
    const Outcome r = run("$BIN plan ell.json --out plan.svg --png plan.png");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir_ / "plan.svg");
    // The room's fill and outline: polygons of six points each.
    const std::regex room("<polygon points=\"([^\"]*)\"[^>]*data-name=\"ell\"/>");
    int polygons = 0;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), room); it != std::sregex_iterator(); ++it) {
        std::istringstream points((*it)[1].str());
        std::string point;
        int n = 0;
        while (points >> point) ++n;
        EXPECT_EQ(n, 6) << (*it)[0].str();
        ++polygons;
    }
    EXPECT_EQ(polygons, 2) << svg;
    EXPECT_TRUE(fs::file_size(dir_ / "plan.png") > 0);
}

TEST_F(HostilePrismDesign, TourGoesRoundTheInnerCornerAndStaysInThePlayArea) {
    spit(dir_ / "ell.json", ell_file());
    const Outcome r = run("$BIN tour ell.json --out tour.txt");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("rooms visited: 2 of 2 reachable: ell den\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rooms missed: none\n"), std::string::npos) << r.out;
    std::istringstream lines(slurp(dir_ / "tour.txt"));
    std::string line;
    int poses = 0, in_far_arm = 0;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        double x = 0, y = 0, z = 0;
        std::istringstream(line) >> x >> y >> z;
        ++poses;
        // Never in the notch, never within the body radius of the L's walls
        // (but for the door), never outside the play area.
        EXPECT_FALSE(x > 1.75 && z > 2.25 && z < 6.0) << line;
        EXPECT_TRUE(x >= 0.25 - 1e-6 && x <= 5.75 + 1e-6 && z >= 0.25 - 1e-6 && z <= 7.75 + 1e-6) << line;
        in_far_arm += x < 1.75 && z > 2.25 && z < 5.0;
    }
    EXPECT_GT(poses, 100);
    EXPECT_GT(in_far_arm, 10);  // it went up the other arm
}

// A saw of 497 teeth (997 corners) as a prism floor, turned or not.
std::string saw_floor(bool turn) {
    std::string out = "[";
    auto add = [&](double x, double z) {
        char text[64];
        std::snprintf(text, sizeof text, "%s[%.4f, %.4f]", out.size() > 1 ? ", " : "", turn ? z + 0.5 : x,
                      turn ? x : z);
        out += text;
    };
    for (int i = 0; i < 497; ++i) add(i * 10.0 / 497, 0), add((i + 0.5) * 10.0 / 497, 10);
    add(10, 0), add(10, -1), add(0, -1);
    return out + "]";
}

TEST_F(HostilePrismDesign, FloorsWhoseWallsCrossEverywhereAreMeasuredInBoundedTime) {
    // About 250,000 crossings between two rooms' walls: Boost.Geometry alone
    // took minutes; validate and plan answer in seconds.
    spit(dir_ / "saws.json",
         "{ \"format\": \"impossible-layout\", \"version\": 1,\n"
         "  \"start\": { \"room\": \"a\", \"position\": [5, 1.6, -0.5] },\n"
         "  \"rooms\": [ { \"id\": \"a\", \"floor\": " +
             saw_floor(false) + ", \"y\": [0, 3] },\n    { \"id\": \"b\", \"floor\": " + saw_floor(true) +
             ", \"y\": [0, 3] } ] }\n");
    const Outcome r = run("$BIN validate saws.json && $BIN plan saws.json --out saws.svg", 60);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_LT(r.seconds, 30.0);
    EXPECT_NE(r.out.find("  a / b: "), std::string::npos) << r.out;
}

TEST_F(HostilePrismDesign, TourInARoomOfAThousandWallsIsQuick) {
    // A half ring of radii 2 and 10 m, 500 walls a side: its grid of 400 x
    // 200 cells took 2 s tested cell by wall; now a few hundredths.
    std::string floor = "[";
    for (int i = 0; i < 1000; ++i) {
        const double a = M_PI * (i < 500 ? i : 999 - i) / 499, r = i < 500 ? 10.0 : 2.0;
        char text[64];
        std::snprintf(text, sizeof text, "%s[%.4f, %.4f]", i ? ", " : "", r * std::cos(a), r * std::sin(a));
        floor += text;
    }
    spit(dir_ / "arc.json",
         "{ \"format\": \"impossible-layout\", \"version\": 1,\n"
         "  \"start\": { \"room\": \"arc\", \"position\": [6, 1.6, 0.5] },\n"
         "  \"rooms\": [ { \"id\": \"arc\", \"floor\": " +
             floor + "], \"y\": [0, 3] } ] }\n");
    const Outcome r = run("$BIN tour arc.json --out arc.txt");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_LT(r.seconds, 1.5);  // 0.03 s on the development machine
    EXPECT_NE(r.out.find("rooms visited: 1 of 1 reachable: arc\n"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace impossible::hostile
