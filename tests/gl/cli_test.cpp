// The program as users and scripts call it (cli.md): outputs, determinism,
// exit statuses, and no partial files on bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/png_io.hpp"

namespace impossible {
namespace {

namespace fs = std::filesystem;

struct ProgramRun {
    int status = -1;
    std::string out;
    std::string err;
};

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

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("impossible-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string bytes(const std::string& name) {
        std::ifstream in(dir_ / name, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    // Files in the directory, to check nothing partial was left behind.
    size_t file_count() { return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), {})); }
    fs::path dir_;
};

TEST_F(Cli, RenderWithoutArgumentsWritesStereoPngOfTheDefaultLayout) {
    const ProgramRun run = run_program("render --size 160x90", dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    const app::PngImage png = app::read_png((dir_ / "stereo.png").string());
    ASSERT_EQ(png.error, "");
    EXPECT_EQ(png.width, 320);
    EXPECT_EQ(png.height, 90);
    EXPECT_EQ(png.channels, 3);
}

TEST_F(Cli, DefaultSizeIs1280x720PerEye) {
    const ProgramRun run = run_program("render --out big.png", dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    const app::PngImage png = app::read_png((dir_ / "big.png").string());
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
    const app::PngImage ids = app::read_png((dir_ / "ids.png").string());
    ASSERT_EQ(ids.error, "");
    EXPECT_EQ(ids.channels, 1);
    for (std::uint8_t v : ids.pixels) EXPECT_TRUE(v == 1 || v == 2) << int(v);
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
        "render --size 0x10",          "render --size 10",        "render --pose 1,2,3",
        "render --pose 1,2,3,4,5,nan", "render --room nowhere",   "render --fov 0",
        "render --max-depth -1",       "render --backend vulkan", "render missing-file.json",
        "render --ipd abc",            "validate missing-file.json",
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
    for (const char* command : {"render", "validate", "walk"}) {
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

}  // namespace
}  // namespace impossible
