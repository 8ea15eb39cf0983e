// bench's options: the view options without the image files and --stats,
// then its own; both tables together name each option once.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "bench/options.hpp"

namespace impossible::bench {
namespace {

BenchOptions parse(const cli::Args& args) {
    return parse_bench_options(cli::parse_args(args, 1, bench_view_options(), bench_options()));
}

TEST(BenchOptions, TheViewOptionsLackTheImageFilesAndStats) {
    std::set<std::string> names;
    for (const auto& o : bench_view_options().own) EXPECT_TRUE(names.insert(o.name).second) << o.name;
    for (const auto& o : bench_view_options().frame) EXPECT_TRUE(names.insert(o.name).second) << o.name;
    for (const auto& o : bench_options()) EXPECT_TRUE(names.insert(o.name).second) << o.name;
    for (const char* gone : {"--out", "--ids", "--stats"}) {
        EXPECT_EQ(names.count(gone), 0u) << gone;
        EXPECT_THROW(parse({gone, "x"}), cli::UsageError) << gone;
    }
    EXPECT_EQ(names.count("--pose"), 1u);
    EXPECT_EQ(names.count("--sweep"), 1u);
}

TEST(BenchOptions, EachOptionReachesItsField) {
    const BenchOptions o = parse({"lay.json",  "--size",
                                  "64x32",     "--frames",
                                  "5",         "--warmup",
                                  "0",         "--profile-frames",
                                  "1",         "--path",
                                  "walk.txt",  "--portals",
                                  "2",         "--sweep",
                                  "depth:1,4", "--reference-depth",
                                  "9",         "--reference-samples",
                                  "4",         "--json",
                                  "b.json",    "--csv",
                                  "b.csv",     "--no-cull"});
    EXPECT_EQ(o.view.layout_path, "lay.json");
    EXPECT_EQ(o.view.frame.eye_width, 64);
    EXPECT_FALSE(o.view.frame.cull_portals);
    EXPECT_EQ(o.frames, 5);
    EXPECT_EQ(o.warmup, 0);
    EXPECT_EQ(o.profile_frames, 1);
    EXPECT_EQ(o.path, "walk.txt");
    EXPECT_EQ(o.portals, 2);
    EXPECT_EQ(o.sweep, "depth:1,4");
    EXPECT_FALSE(o.error);
    EXPECT_EQ(o.reference_depth, 9);
    EXPECT_EQ(o.reference_samples, 4);
    EXPECT_EQ(o.json, "b.json");
    EXPECT_EQ(o.csv, "b.csv");
}

TEST(BenchOptions, TechniquesImplyTheError) {
    EXPECT_TRUE(parse({"--sweep", "techniques"}).error);
    EXPECT_TRUE(parse({"--error"}).error);
    EXPECT_FALSE(parse({}).error);
}

TEST(BenchOptions, BadValuesAndCombinations) {
    EXPECT_THROW(parse({"--frames", "0"}), cli::InputError);
    EXPECT_THROW(parse({"--sweep", "colours:1"}), cli::InputError);
    EXPECT_THROW(parse({"--path", "w.txt", "--pose", "0,1.6,0,0,0,0"}), cli::InputError);
    EXPECT_THROW(parse({"--path", "w.txt", "--time", "1"}), cli::UsageError);
    EXPECT_THROW(parse({"--path", "w.txt", "--hands", "0,1,0,0,0,0,0,1,0,0,0,0"}), cli::UsageError);
    EXPECT_THROW(parse({"--fps", "30"}), cli::UsageError);
    EXPECT_THROW(parse({"--path", "w.txt", "--frame", "1"}), cli::UsageError);  // render's, not bench's
    EXPECT_THROW(parse({"--path", "w.txt", "--fps", "0"}), cli::InputError);
    const BenchOptions o = parse({"--path", "w.txt", "--fps", "30"});
    EXPECT_EQ(o.fps, 30.0);
    EXPECT_EQ(parse({"--time", "2", "--hands", "0,1,0,0,0,0,0,1,0,0,0,0"}).view.frame.time, 2.0);
}

// A sweep's items are read with the options, before any layout is loaded,
// by the frame rows' parsers, and a bad one names --sweep KIND.
TEST(BenchOptions, SweepItemsAreParsedByTheRowsAndNameTheSweep) {
    const auto message = [](const cli::Args& args) {
        try {
            parse(args);
        } catch (const cli::InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message({"--sweep", "samples:1,3"}), "--sweep samples: 3 is not 1, 2, 4, 8 or 16");
    EXPECT_EQ(message({"--sweep", "depth:251"}), "--sweep depth: 251 is out of range 0..250");
    EXPECT_EQ(message({"--sweep", "shadow-size:4097"}), "--sweep shadow-size: 4097 is out of range 0..4096");
    EXPECT_NE(message({"--sweep", "size:9000x10"}).find("--sweep size: "), std::string::npos);
    const BenchOptions o = parse({"--sweep", "boxes:10,10/all-faces"});
    ASSERT_EQ(o.sweep_items.size(), 2u);
    EXPECT_EQ(o.sweep_items[1].n, 10);
    EXPECT_EQ(o.sweep_items[1].suffix, "all-faces");
    EXPECT_EQ(o.sweep_items[1].name, "boxes=10/all-faces");
}

}  // namespace
}  // namespace impossible::bench
