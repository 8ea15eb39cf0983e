// Reports and plans of layouts that are large but inside every documented
// limit (issue 26, defects 2, 3 and 6f): 10,000 identical rooms (every pair
// overlaps, 49,995,000 pairs) and a play area of 10,000 corners. Before,
// `validate` and `plan` of the rooms ran past 60 s and 7.5 GB printing
// nothing, 1,000 rooms printed 500,000 overlap warnings (70 MB), `plan --png`
// of the star took 7 GB at 8192 px, and `generate` on a spiky star took 10 s
// per 1,000 corners. Overlaps are now listed up to a cap with one summary
// line (docs/designer.md, "Limits of the report"), the plan is rasterised
// by scanlines a strip at a time, and generate tests rooms against a grid.
//
// Each run is measured in a child process of its own: wall time and the
// peak resident memory of the commands it ran (getrusage of its children).
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

struct Measured {
    int status = -1;
    double seconds = 0;
    long peak_mb = 0;  // the largest resident set of any process the script ran
};

// Runs `script` in `cwd` (as run_script does) from a forked child, so that
// the child's RUSAGE_CHILDREN holds only this script's processes. The
// script should send its output to files.
Measured measured(const std::string& script, const fs::path& cwd, int limit_s) {
    int fds[2];
    if (::pipe(fds) != 0) return {};
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        const Outcome o = run_script(script, cwd, static_cast<int>(limit_s * (IMPOSSIBLE_SANITIZED ? 4 : 1)));
        rusage usage{};
        ::getrusage(RUSAGE_CHILDREN, &usage);
        const double report[3] = {static_cast<double>(o.status), o.seconds, static_cast<double>(usage.ru_maxrss)};
        const ssize_t written = ::write(fds[1], report, sizeof report);
        ::_exit(written == sizeof report ? 0 : 1);
    }
    ::close(fds[1]);
    double report[3] = {-1, 0, 0};
    const ssize_t got = ::read(fds[0], report, sizeof report);
    ::close(fds[0]);
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    if (got != sizeof report) return {};
    const Measured m{static_cast<int>(report[0]), report[1], std::lround(report[2] / 1024.0)};
    std::printf("[ measured ] %.2f s, %ld MB: %s\n", m.seconds, m.peak_mb, script.c_str());
    return m;
}

// n identical rooms r0 ... r{n-1}, `side` m square (4 by default), on a
// play area 1 m wider all round; no doors.
std::string identical_rooms(int n, int side = 4) {
    const std::string s = std::to_string(side), edge = std::to_string(side + 1);
    std::string rooms;
    for (int i = 0; i < n; ++i)
        rooms += std::string(i ? "," : "") + "{\"id\":\"r" + std::to_string(i) + "\",\"min\":[0,0,0],\"max\":[" + s +
                 ",2.5," + s + "]}";
    return "{\"format\":\"impossible-layout\",\"version\":1,\"play_area\":{\"min\":[-1,-1],\"max\":[" + edge + "," +
           edge + "]},\"start\":{\"room\":\"r0\",\"position\":[2,1.6,2],\"yaw_deg\":0},\"rooms\":[" + rooms +
           "],\"portals\":[]}";
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// Goals: 10 s and 1 GB; the bounds leave room for a loaded two-core machine.
// The sanitizer build (several times slower, with shadow memory and red
// zones) checks the same runs for memory errors against bounds kSlowdown
// times as wide; the goals are the plain build's.
constexpr double kSlowdown = IMPOSSIBLE_SANITIZED ? 4.0 : 1.0;
constexpr double kSeconds = 30.0 * kSlowdown;
constexpr long kMegabytes = static_cast<long>(1024 * kSlowdown);

TEST_F(Hostile, TenThousandIdenticalRoomsValidateWithinLimits) {
    spit(dir_ / "rooms.json", identical_rooms(10000));
    const Measured m = measured("$BIN validate rooms.json >out.txt 2>err.txt", dir_, 60);
    ASSERT_EQ(m.status, 0) << slurp(dir_ / "err.txt").substr(0, 2000);
    EXPECT_LT(m.seconds, kSeconds);
    EXPECT_LT(m.peak_mb, kMegabytes);
    const std::string out = slurp(dir_ / "out.txt"), err = slurp(dir_ / "err.txt");
    EXPECT_NE(out.find("  r0 / r1: 16.00 m2, 100.0 % (limit 56 %) noticeable\n"), std::string::npos);
    EXPECT_EQ(count(out, " noticeable\n"), 1000u);
    EXPECT_NE(out.find("\n  ... and 49994000 more pairs (the report lists the first 1000)\n"), std::string::npos)
        << out.substr(out.size() - std::min<std::size_t>(out.size(), 2000));
    EXPECT_LT(out.size(), 1u << 20);
    EXPECT_EQ(count(err, "overlap by 100.0 %"), 1000u);
    EXPECT_NE(err.find("rooms.json: 49995000 pairs of rooms overlap; the report lists the first 1000"),
              std::string::npos);
    EXPECT_LT(err.size(), 2u << 20);  // a line per unreachable room, 1,000 overlaps
}

TEST_F(Hostile, TenThousandIdenticalRoomsValidateAsJsonWithinLimits) {
    spit(dir_ / "rooms.json", identical_rooms(10000));
    const Measured m = measured("$BIN validate rooms.json --json >out.json 2>err.txt", dir_, 60);
    ASSERT_EQ(m.status, 0) << slurp(dir_ / "err.txt").substr(0, 2000);
    EXPECT_LT(m.seconds, kSeconds);
    EXPECT_LT(m.peak_mb, kMegabytes);
    const nlohmann::json j = nlohmann::json::parse(slurp(dir_ / "out.json"), nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["overlaps"].size(), 1000u);
    EXPECT_EQ(j["overlaps"][999]["rooms"], nlohmann::json({"r0", "r1000"}));  // (0, 1) ... (0, 1000)
    EXPECT_EQ(j["overlaps_truncated"], true);
    EXPECT_EQ(j["overlap_pairs"], 49995000);
    EXPECT_EQ(j["overlap_pairs_exact"], true);
    EXPECT_EQ(j["rooms"].size(), 10000u);
}

TEST_F(Hostile, TenThousandIdenticalRoomsPlanWithinLimits) {
    spit(dir_ / "rooms.json", identical_rooms(10000));
    const Measured m = measured("$BIN plan rooms.json --out p.svg --png p.png >out.txt 2>err.txt", dir_, 60);
    ASSERT_EQ(m.status, 0) << slurp(dir_ / "err.txt").substr(0, 2000);
    EXPECT_LT(m.seconds, kSeconds);
    EXPECT_LT(m.peak_mb, kMegabytes);
    const std::string svg = slurp(dir_ / "p.svg");
    EXPECT_EQ(count(svg, "data-name=\"r0/r"), 1000u);  // the overlaps drawn: the 1,000 listed
    // The title, the 33 names that find a free spot (the centre and 32 moves
    // down; the rest would be drawn over them and are left out) and the
    // legend's 29 lines (24 rooms, "... and 9976 more rooms", play area,
    // shared floor, shared floor likely noticed, start).
    EXPECT_EQ(count(svg, "<text "), 1u + 33u + 29u);
    EXPECT_LT(svg.size(), 64u << 20);
    EXPECT_GT(fs::file_size(dir_ / "p.png"), 1000u);
    EXPECT_NE(slurp(dir_ / "err.txt").find("plan: 10000 rooms, 49995000 overlapping pairs (1000 drawn)"),
              std::string::npos)
        << slurp(dir_ / "err.txt");
}

TEST_F(Hostile, FiveThousandLargeUnreachableRoomsPlanWithinLimits) {
    // Each outline is dashed (the rooms are unreachable): 600 dashes of
    // 0.12 m a room, kept as where each starts. 10,000 rooms (6 million
    // dashes) took 228 MB on the development machine (1.1 GB with a polygon
    // per dash) against a bound of 512 MB, and 8 to 21 s against kSeconds.
    // Time and the dashes' memory grow with the dashes, so half the rooms
    // (3 million dashes) are held to half the time and, over the 60 MB the
    // program takes for anything, half the memory: 140 MB and 4 s now, about
    // 580 MB with a polygon per dash.
    spit(dir_ / "rooms.json", identical_rooms(5000, 30));
    const Measured m = measured("$BIN plan rooms.json --out p.png >out.txt 2>err.txt", dir_, 120);
    ASSERT_EQ(m.status, 0) << slurp(dir_ / "err.txt").substr(0, 2000);
    EXPECT_LT(m.seconds, kSeconds / 2);
    EXPECT_LT(m.peak_mb, (60 + (512 - 60) / 2) * kSlowdown);
    EXPECT_GT(fs::file_size(dir_ / "p.png"), 1000u);
}

TEST_F(Hostile, AThousandIdenticalRoomsPrintABoundedReport) {
    spit(dir_ / "rooms.json", identical_rooms(1000));
    const Outcome r = run("$BIN validate rooms.json", 60);
    ASSERT_EQ(r.status, 0) << r.err.substr(0, 2000);
    EXPECT_LT(r.out.size(), 200u << 10);  // 70 MB before, with stderr
    EXPECT_LT(r.err.size(), 200u << 10);
    EXPECT_NE(r.out.find("\n  ... and 498500 more pairs (the report lists the first 1000)\n"), std::string::npos);
    EXPECT_LT(r.seconds, 10.0);
}

TEST_F(Hostile, AStarOf10000CornersPlotsAt4096PixelsWithinLimits) {
    // At --max-size 8192 (the largest) this took 7.2 GB and 39 s before
    // (the rasteriser held the 3 x 3 larger image), 454 MB and 9 to 17 s now,
    // against kMegabytes and kSeconds. Memory and time are those of the
    // image, so at 4096, a quarter of the pixels, the bounds are a quarter:
    // 159 MB and 3 to 4 s now, about 1.8 GB and 10 s before.
    spit(dir_ / "star.json",
         "{\"format\":\"impossible-layout\",\"version\":1,\"play_area\":{\"polygon\":" + star_polygon(10000, 50, 40) +
             "},\"start\":{\"room\":\"a\",\"position\":[0,1.6,0],\"yaw_deg\":0},"
             "\"rooms\":[{\"id\":\"a\",\"min\":[-2,0,-2],\"max\":[2,2.5,2]}],\"portals\":[]}");
    const Measured m = measured("$BIN plan star.json --out p.png --max-size 4096 >out.txt 2>err.txt", dir_, 120);
    ASSERT_EQ(m.status, 0) << slurp(dir_ / "err.txt");
    EXPECT_LT(m.seconds, kSeconds / 4);
    EXPECT_LT(m.peak_mb, kMegabytes / 4);
    const std::string png = slurp(dir_ / "p.png");
    ASSERT_GT(png.size(), 24u);
    // IHDR: width and height, big-endian, at bytes 16 and 20.
    auto be32 = [&](std::size_t at) {
        return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
               (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
    };
    EXPECT_EQ(be32(16), 4096);
    EXPECT_GT(be32(20), 4096);  // and the title above
}

TEST_F(Hostile, GenerateOnAStarOf10000CornersTakesSeconds) {
    // Spikes from 0.7 m to 50 m: no room of 1.5 m fits, so every try fails.
    // (From 2 m, the core holds two rooms: generate_packing_test.cpp.)
    spit(dir_ / "spiky.json", star_polygon(10000, 50, 0.7));
    const Outcome spiky = run("$BIN generate --play-area-file spiky.json --rooms 2 --seed 1", 120);
    expect_refused(spiky, 1, "no room 1.5 m wide fits in this play area");
    EXPECT_LT(spiky.seconds, kSeconds);  // over 60 s before
    spit(dir_ / "star.json", "{\"polygon\": " + star_polygon(10000, 50, 40) + "}");
    const Outcome fits = run("$BIN generate --play-area-file star.json --rooms 8 --seed 3 --out g.json", 120);
    ASSERT_EQ(fits.status, 0) << fits.err;
    EXPECT_LT(fits.seconds, kSeconds);
    const Outcome valid = run("$BIN validate g.json");
    EXPECT_EQ(valid.status, 0) << valid.err;
    EXPECT_NE(valid.out.find("rooms outside the play area as walked: none"), std::string::npos) << valid.out;
}

TEST_F(Hostile, APlayAreaFileRefusesUnknownFields) {
    spit(dir_ / "a.json", "{\"polygon\": [[0, 0], [4, 0], [4, 4], [0, 4]],\n \"scale\": 2}");
    expect_refused(run("$BIN generate --play-area-file a.json --rooms 2 --seed 1"), 1,
                   "a.json:2:2: scale: unknown field \"scale\"");
    spit(dir_ / "b.json", "{\"play_area\": {\"polygn\": [[0, 0], [4, 0], [4, 4], [0, 4]]}}");
    expect_refused(run("$BIN generate --play-area-file b.json --rooms 2 --seed 1"), 1,
                   "b.json:1:16: play_area.polygn: unknown field \"polygn\" (did you mean \"polygon\"?)");
    // A layout's own fields are known: a layout's play area may be used.
    spit(dir_ / "c.json",
         "{\"format\": \"impossible-layout\", \"version\": 1, \"name\": \"x\", \"rooms\": [],"
         " \"_note\": 1, \"play_area\": {\"polygon\": [[0, 0], [4, 0], [4, 4], [0, 4]]}}");
    const Outcome c = run("$BIN generate --play-area-file c.json --rooms 2 --seed 1 --out g.json");
    EXPECT_EQ(c.status, 0) << c.err;
    EXPECT_EQ(listing(dir_), "a.json\nb.json\nc.json\ng.json\nlay.json\n");
}

}  // namespace
}  // namespace impossible::hostile
