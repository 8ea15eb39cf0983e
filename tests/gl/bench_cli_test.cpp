// `impossible bench` as scripts call it: a couple of tiny frames, the JSON
// and CSV parsed back, keys present and counts consistent with the layout.
// No timing is ever asserted (only that times are positive numbers).
#include <gtest/gtest.h>

#include <cmath>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/options.hpp"
#include "common/temp_dir.hpp"
#include "math/pose.hpp"

namespace impossible {
namespace {

namespace fs = std::filesystem;

struct BenchRun {
    int status = -1;
    std::string err;
};

class BenchCli : public test::TempDirTest {
protected:
    BenchRun run(const std::string& args) {
        const std::string command =
            "cd '" + dir_.string() + "' && '" IMPOSSIBLE_BINARY "' bench " + args + " >stdout.txt 2>stderr.txt";
        const int raw = std::system(command.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text("stderr.txt")};
    }
    std::string text(const std::string& name) {
        std::ifstream in(dir_ / name);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    nlohmann::json json(const std::string& name) { return nlohmann::json::parse(text(name)); }
};

const char* kQuick = "--size 64x36 --frames 2 --warmup 1 --profile-frames 1";

TEST_F(BenchCli, WritesTheDocumentedKeysWithSaneCounts) {
    const BenchRun r = run(std::string(kQuick) + " --json b.json --csv b.csv");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = json("b.json");
    for (const char* key :
         {"frame_ms_median", "frame_ms_p90", "fragments_per_pixel", "draw_calls", "portal_passes_drawn",
          "portal_passes_culled", "submit_ms_median", "triangles", "portals", "configs", "gl_renderer"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_GT(j["frame_ms_median"].get<double>(), 0.0);
    EXPECT_GE(j["frame_ms_p90"].get<double>(), j["frame_ms_median"].get<double>());
    EXPECT_EQ(j["frames"].get<int>(), 2);
    // The default layout from its start: the hall, one door seen (the annex
    // door behind it is culled), one instanced draw per mesh.
    EXPECT_EQ(j["portal_passes_drawn"].get<double>(), 1.0);
    EXPECT_EQ(j["portal_passes_culled"].get<double>(), 1.0);
    EXPECT_GT(j["draw_calls"].get<double>(), 2.0);
    EXPECT_GT(j["triangles"].get<double>(), 12.0);
    // Every output pixel is written at least once; overdraw stays small.
    EXPECT_GE(j["fragments_per_pixel"].get<double>(), 1.0);
    EXPECT_LT(j["fragments_per_pixel"].get<double>(), 3.0);
    ASSERT_EQ(j["portals"].size(), 1u);
    EXPECT_EQ(j["portals"][0]["portal"], "hall_door");
    EXPECT_GT(j["portals"][0]["fragments_per_pixel"].get<double>(), 0.0);
    EXPECT_LT(j["portals"][0]["fragments_per_pixel"].get<double>(), j["fragments_per_pixel"].get<double>());
    const std::string csv = text("b.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2) << csv;
    EXPECT_EQ(csv.rfind("name,group,", 0), 0u) << csv;
}

TEST_F(BenchCli, TechniqueSweepMeasuresEveryConfigurationWithItsError) {
    const BenchRun r = run(std::string(kQuick) + " --sweep techniques --json t.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = json("t.json");
    std::map<std::string, nlohmann::json> by_name;
    for (const nlohmann::json& c : j["configs"]) by_name[c["name"]] = c;
    ASSERT_EQ(by_name.size(), 23u);
    // The seeds' techniques, each with its error: hybrid at full scale is
    // exact; z-clear draws one level (compare it with depth=1).
    for (const char* name : {"hybrid=1", "hybrid=2", "hybrid=4", "z-clear"}) {
        ASSERT_TRUE(by_name[name].contains("id_mismatch_percent")) << name << by_name[name];
        EXPECT_EQ(by_name[name]["group"], "technique") << name;
    }
    EXPECT_EQ(by_name["hybrid=1"]["id_mismatch_percent"], by_name["base"]["id_mismatch_percent"]);
    EXPECT_EQ(by_name["z-clear"]["max_depth"], 1);
    EXPECT_EQ(by_name["z-clear"]["id_mismatch_percent"], by_name["depth=1"]["id_mismatch_percent"]);
    EXPECT_EQ(by_name["z-clear"]["psnr_db"], by_name["depth=1"]["psnr_db"]);
    // Render-to-texture at full scale is exact; a quarter-size texture blurs.
    EXPECT_EQ(by_name["texture=1"]["id_mismatch_percent"], by_name["base"]["id_mismatch_percent"]);
    auto psnr = [](const nlohmann::json& v) { return v.is_null() ? HUGE_VAL : v.get<double>(); };  // null: identical
    EXPECT_LT(psnr(by_name["texture=0.25"]["psnr_db"]), psnr(by_name["texture=1"]["psnr_db"]));
    EXPECT_EQ(by_name["occlusion=on"]["id_mismatch_percent"], by_name["base"]["id_mismatch_percent"]);
    // One draw per batch instead of a multi-draw: the same image.
    EXPECT_EQ(by_name["multi-draw=off"]["id_mismatch_percent"], by_name["base"]["id_mismatch_percent"]);
    EXPECT_EQ(by_name["multi-draw=off"]["psnr_db"], by_name["base"]["psnr_db"]);
    EXPECT_GE(by_name["multi-draw=off"]["draw_calls"].get<double>(), by_name["base"]["draw_calls"].get<double>());
    // A volume's room by the discarding variant over the whole level: the
    // same image (this layout has no volume: the same frame).
    EXPECT_EQ(by_name["volumes=one-variant"]["id_mismatch_percent"], by_name["base"]["id_mismatch_percent"]);
    EXPECT_EQ(by_name["volumes=one-variant"]["group"], "volumes");
    const nlohmann::json& base = by_name["base"];
    // Two passes issue every draw once per eye.
    EXPECT_EQ(by_name["stereo=two-pass"]["draw_calls"].get<double>(), 2 * base["draw_calls"].get<double>());
    for (const auto& [name, c] : by_name) {
        if (c.contains("error")) continue;  // a stereo mode the driver cannot do
        ASSERT_TRUE(c.contains("id_mismatch_percent")) << name;
        // Every configuration draws the right rooms (the one door is one
        // level deep, so depth 1 is exact here too).
        EXPECT_LE(c["id_mismatch_percent"].get<double>(), 2.0) << name;
        EXPECT_GE(c["portal_passes_drawn"].get<double>(), 1.0) << name;
    }
}

// Multisampling swept: every count the driver offers is measured, with
// fragments per pixel sample as with one sample and a smaller error against
// the anti-aliased tracer; a count it lacks is that configuration's error.
TEST_F(BenchCli, SampleSweepMeasuresOfferedCountsAndReportsTheOthers) {
    const BenchRun r =
        run(std::string(kQuick) + " --sweep samples:1,4,16 --error --reference-samples 16 --json s.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = json("s.json");
    EXPECT_EQ(j["reference_samples"], 16);
    std::map<std::string, nlohmann::json> by_name;
    for (const nlohmann::json& c : j["configs"]) by_name[c["name"]] = c;
    ASSERT_EQ(by_name.size(), 4u);
    EXPECT_EQ(by_name["samples=1"]["samples"], 1);
    for (const char* name : {"samples=4", "samples=16"}) {
        const nlohmann::json& c = by_name[name];
        if (c.contains("error")) {
            EXPECT_NE(c["error"].get<std::string>().find("offers"), std::string::npos) << c["error"];
            continue;
        }
        EXPECT_GT(c["frame_ms_median"].get<double>(), 0.0) << name;
        // About one per sample: props are drawn before the faces behind them,
        // so little is overdrawn (a few samples in 10^5 fall on seams).
        EXPECT_GE(c["fragments_per_pixel"].get<double>(), 0.999) << name;
        EXPECT_LT(c["fragments_per_pixel"].get<double>(), 3.0) << name;
        EXPECT_EQ(c["id_mismatch_percent"].get<double>(), 0.0) << name;
        EXPECT_GT(c["psnr_db"].get<double>(), by_name["samples=1"]["psnr_db"].get<double>()) << name;
    }
}

TEST_F(BenchCli, ClosedPortalsAndDepthSweep) {
    const std::string corridor = "'" IMPOSSIBLE_SOURCE_DIR "/layouts/corridor.json'";
    ASSERT_EQ(run(corridor + " " + kQuick + " --portals 0 --json c.json").status, 0);
    const nlohmann::json closed = json("c.json");
    EXPECT_EQ(closed["portal_passes_drawn"].get<double>(), 0.0);
    EXPECT_EQ(closed["portals"].size(), 0u);

    ASSERT_EQ(run(corridor + " " + kQuick + " --sweep depth:1,4 --json d.json").status, 0);
    const nlohmann::json d = json("d.json");
    ASSERT_EQ(d["configs"].size(), 3u);
    EXPECT_EQ(d["configs"][1]["portal_passes_drawn"].get<double>(), 1.0);
    // Depth 4 draws three passes, not four: at 64x36 the fourth door down
    // the corridor covers no pixel centre, so it is not drawn at all.
    EXPECT_EQ(d["configs"][2]["portal_passes_drawn"].get<double>(), 3.0);
    EXPECT_EQ(d["configs"][1]["portal_fills"].get<double>(), 1.0);

    // Scene triangles: 10 extra boxes on the floor add 12 triangles each to
    // the head's room, drawn for both eyes, with every face ("N/all-faces").
    // By default the faces no eye sees from the front are left out.
    // "10/all" draws the same boxes without per-object culling: here all ten
    // are in view, so the counts agree with every face; the image, and so the
    // error, too. "10/separate" draws them with a draw per run instead of a
    // multi-draw.
    ASSERT_EQ(run(std::string(kQuick) +
                  " --portals 0 --sweep boxes:0,0/all-faces,10,10/all,10/separate,10/all-faces --json b.json")
                  .status,
              0);
    const nlohmann::json b = json("b.json");
    ASSERT_EQ(b["configs"].size(), 7u);
    const auto triangles = [&](int c) { return b["configs"][c]["triangles"].get<double>(); };
    EXPECT_EQ(b["configs"][6]["name"], "boxes=10/all-faces");
    EXPECT_EQ(triangles(6) - triangles(2), 10 * 12 * 2);
    EXPECT_GT(triangles(3) - triangles(1), 0.0);
    EXPECT_LT(triangles(3) - triangles(1), 10 * 12 * 2);  // without their back faces
    EXPECT_EQ(b["configs"][4]["name"], "boxes=10/all");
    EXPECT_EQ(triangles(4), triangles(6));
    EXPECT_EQ(b["configs"][5]["name"], "boxes=10/separate");
    EXPECT_EQ(triangles(5), triangles(3));
    EXPECT_EQ(run(std::string(kQuick) + " --sweep boxes:10/bogus").status, 1);
}

TEST_F(BenchCli, ScriptedWalkMeasuresEveryPose) {
    {
        std::ofstream path(dir_ / "walk.txt");
        path << "0 1.6 1 0 0 0\n0 1.6 0.2 0 0 0\n0 1.6 -0.3 0 0 0\n";
    }
    const BenchRun r = run(std::string(kQuick) + " --path walk.txt --json w.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = json("w.json");
    EXPECT_EQ(j["poses"].get<int>(), 3);
    EXPECT_EQ(j["frames"].get<int>(), 6);
}

TEST_F(BenchCli, BadInputAndUsageErrors) {
    for (const char* args :
         {"--frames 0", "--sweep bogus", "--sweep depth:x", "--path missing.txt", "--portals -1", "missing.json"})
        EXPECT_EQ(run(args).status, 1) << args;
    for (const char* args : {"--out x.png", "--frames", "--bogus"}) EXPECT_EQ(run(args).status, 2) << args;
    // Six doors without culling at depth 8: once refused (every portal at
    // every level, exponentially many passes); the pixel rule now decides
    // which portals are drawn with culling off too.
    const BenchRun unculled = run("'" IMPOSSIBLE_SOURCE_DIR "/layouts/vr_study.json' --no-cull --frames 1");
    EXPECT_EQ(unculled.status, 0) << unculled.err;
    EXPECT_EQ(unculled.err.find("portal passes"), std::string::npos) << unculled.err;
    EXPECT_EQ(run("--help").status, 0);
    EXPECT_NE(text("stdout.txt").find("usage: impossible bench"), std::string::npos);
}

}  // namespace
}  // namespace impossible
