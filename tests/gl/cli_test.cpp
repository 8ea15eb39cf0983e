// The program as users and scripts call it (cli.md): outputs, determinism,
// exit statuses, and no partial files on bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/png.hpp"
#include "common/program_run.hpp"
#include "common/temp_dir.hpp"

namespace impossible {
namespace {

namespace fs = std::filesystem;

using testing::ProgramRun;

// Runs the built program with `args` in directory `cwd`.
ProgramRun run_program(const std::string& args, const fs::path& cwd) {
    const fs::path out_file = cwd / "stdout.txt", err_file = cwd / "stderr.txt";
    const std::string command = "cd '" + cwd.string() + "' && '" IMPOSSIBLE_BINARY "' " + args + " >'" +
                                out_file.string() + "' 2>'" + err_file.string() + "'";
    const int raw = std::system(command.c_str());
    ProgramRun run;
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    auto slurp = [](const fs::path& p) {
        std::ifstream in(p);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    run.out = slurp(out_file);
    run.err = slurp(err_file);
    fs::remove(out_file);
    fs::remove(err_file);
    return run;
}

class Cli : public test::TempDirTest {
protected:
    std::string bytes(const std::string& name) {
        std::ifstream in(dir_ / name, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    // Files in the directory, to check nothing partial was left behind.
    size_t file_count() { return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), {})); }
};

TEST_F(Cli, RenderWithoutArgumentsWritesStereoPngOfTheDefaultLayout) {
    const ProgramRun run = run_program("render --size 160x90", dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    const image::Pixels png = testing::read_png_ok((dir_ / "stereo.png").string());
    EXPECT_EQ(png.width, 320);
    EXPECT_EQ(png.height, 90);
    EXPECT_EQ(png.channels, 3);
}

TEST_F(Cli, DefaultSizeIs1280x720PerEye) {
    const ProgramRun run = run_program("render --out big.png", dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    const image::Pixels png = testing::read_png_ok((dir_ / "big.png").string());
    EXPECT_EQ(png.width, 2560);
    EXPECT_EQ(png.height, 720);
}

TEST_F(Cli, RenderIsDeterministic) {
    ASSERT_EQ(run_program("render --size 200x120 --out a.png --ids a-ids.png", dir_).status, 0);
    ASSERT_EQ(run_program("render --size 200x120 --out b.png --ids b-ids.png", dir_).status, 0);
    EXPECT_EQ(bytes("a.png"), bytes("b.png"));
    EXPECT_EQ(bytes("a-ids.png"), bytes("b-ids.png"));
    EXPECT_FALSE(bytes("a.png").empty());
}

TEST_F(Cli, IdsMapIsGreyWithRoomNumbers) {
    ASSERT_EQ(run_program("render --size 64x48 --ids ids.png --backend osmesa", dir_).status, 0);
    const image::Pixels ids = testing::read_png_ok((dir_ / "ids.png").string());
    EXPECT_EQ(ids.channels, 1);
    for (std::uint8_t v : ids.data) EXPECT_TRUE(v == 1 || v == 2) << int(v);
}

TEST_F(Cli, PoseValueMayStartWithAMinus) {
    const ProgramRun run = run_program("render --size 32x32 --pose -1.5,1.6,0.5,90,0,0 --room hall", dir_);
    EXPECT_EQ(run.status, 0) << run.err;
    const ProgramRun eq = run_program("render --size 32x32 --pose=-1.5,1.6,0.5,90,0,0 --room=hall", dir_);
    EXPECT_EQ(eq.status, 0) << eq.err;
}

TEST_F(Cli, PoseInSeveralRoomsNeedsRoom) {
    const ProgramRun run = run_program("render --size 32x32 --pose 0,1.6,1,0,0,0", dir_);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("several rooms"), std::string::npos) << run.err;
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, BadInputExitsOneWithOneLineAndNoFile) {
    const char* cases[] = {
        "render --size 0x10",       "render --size 10", "render --pose 1,2,3",        "render --pose 1,2,3,4,5,nan",
        "render --room nowhere",    "render --fov 0",   "render --max-depth -1",      "render --backend vulkan",
        "render missing-file.json", "render --ipd abc", "validate missing-file.json",
    };
    for (const char* args : cases) {
        const ProgramRun run = run_program(args, dir_);
        EXPECT_EQ(run.status, 1) << args << ": " << run.err;
        EXPECT_FALSE(run.err.empty()) << args;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << args << ": " << run.err;
        EXPECT_EQ(file_count(), 0u) << args;
    }
}

TEST_F(Cli, UsageErrorsExitTwo) {
    for (const char* args : {"", "frobnicate", "render --bogus", "render --pose", "validate", "render a.json b.json",
                             "walk", "render --stats=1"}) {
        const ProgramRun run = run_program(args, dir_);
        EXPECT_EQ(run.status, 2) << "'" << args << "': " << run.err;
        EXPECT_FALSE(run.err.empty()) << args;
        EXPECT_EQ(file_count(), 0u) << args;
    }
}

TEST_F(Cli, EveryCommandHasHelp) {
    for (const char* command : {"render", "validate", "walk", "trace", "compare"}) {
        const ProgramRun run = run_program(std::string(command) + " --help", dir_);
        EXPECT_EQ(run.status, 0) << command;
        EXPECT_NE(run.out.find("usage: impossible " + std::string(command)), std::string::npos) << run.out;
    }
    EXPECT_EQ(run_program("--help", dir_).status, 0);
}

TEST_F(Cli, UnwritableOutputIsAnErrorWithoutPartialFile) {
    const ProgramRun run = run_program("render --size 16x16 --out no/such/dir/x.png", dir_);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("x.png"), std::string::npos) << run.err;
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, ValidatePrintsTheSummary) {
    const ProgramRun run = run_program("validate '" IMPOSSIBLE_SOURCE_DIR "/layouts/default.json'", dir_);
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("expansion"), std::string::npos) << run.out;
}

TEST_F(Cli, StatsReportPortalPasses) {
    const ProgramRun run = run_program("render --size 64x36 --stats", dir_);
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.err.find("portal_passes_drawn=1"), std::string::npos) << run.err;
}

TEST_F(Cli, WalkThroughTheDefaultDoorTeleportsIntoTheAnnex) {
    {
        std::ofstream path(dir_ / "path.txt");
        path << "# x y z yaw pitch roll\n0 1.6 1 0 0 0\n\n0 1.6 0.2 0 0 0\n0 1.6 -0.3 0 0 0\n0 1.6 0.5 0 0 0\n";
    }
    const ProgramRun run = run_program("walk '" IMPOSSIBLE_SOURCE_DIR "/layouts/default.json' --path path.txt", dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    std::istringstream lines(run.out);
    std::string line;
    std::vector<std::string> all;
    while (std::getline(lines, line)) all.push_back(line);
    ASSERT_EQ(all.size(), 4u) << run.out;
    EXPECT_EQ(all[0], R"({"frame":0,"room":"hall","teleports":[],"position":[0,1.6,1],"forward":[0,0,-1]})");
    EXPECT_NE(all[2].find(R"("room":"annex","teleports":["hall_door"])"), std::string::npos) << all[2];
    EXPECT_NE(all[3].find(R"("room":"hall","teleports":["annex_door"])"), std::string::npos) << all[3];
}

TEST_F(Cli, TraceWritesTheSameFilesAsRenderAndAgreesWithIt) {
    ASSERT_EQ(run_program("render --size 120x80 --out r.png --ids r-ids.png", dir_).status, 0);
    const ProgramRun trace = run_program("trace --size 120x80 --out t.png --ids t-ids.png --threads 1", dir_);
    ASSERT_EQ(trace.status, 0) << trace.err;
    ASSERT_EQ(run_program("trace --size 120x80 --out t2.png --ids t2-ids.png --threads 2", dir_).status, 0);
    EXPECT_EQ(bytes("t.png"), bytes("t2.png"));
    EXPECT_EQ(bytes("t-ids.png"), bytes("t2-ids.png"));
    const ProgramRun cmp =
        run_program("compare r.png t.png --ids-a r-ids.png --ids-b t-ids.png --max-mismatch 0.01 --diff d.png", dir_);
    EXPECT_EQ(cmp.status, 0) << cmp.out << cmp.err;
    EXPECT_NE(cmp.out.find("id_mismatches=0"), std::string::npos) << cmp.out;
    EXPECT_FALSE(bytes("d.png").empty());
}

TEST_F(Cli, CompareFailsPastTheLimitAndOnUsageErrors) {
    ASSERT_EQ(run_program("render --size 60x40 --out a.png --ids a-ids.png", dir_).status, 0);
    ASSERT_EQ(run_program("render --size 60x40 --out b.png --ids b-ids.png --pose 0,1.6,-1,180,0,0 --room annex", dir_)
                  .status,
              0);
    EXPECT_EQ(run_program("compare a.png b.png --ids-a a-ids.png --ids-b b-ids.png --max-mismatch 1", dir_).status, 1);
    EXPECT_EQ(run_program("compare a.png a.png --ids-a a-ids.png --ids-b a-ids.png --max-mismatch 0", dir_).status, 0);
    EXPECT_EQ(run_program("compare a.png", dir_).status, 2);
    EXPECT_EQ(run_program("compare a.png missing.png", dir_).status, 1);
}

}  // namespace
}  // namespace impossible
