// `impossible preview` end to end: the test starts its own Xvfb (so the
// window gets Mesa's llvmpipe through GLX whatever desktop runs the tests),
// replays a path through a portal in scripted mode, and checks the saved
// frames against `impossible render` of the same virtual poses, and the
// poses against `impossible walk` of the same path.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/png.hpp"
#include "common/program_run.hpp"
#include "common/temp_dir.hpp"

namespace impossible {
namespace {

namespace fs = std::filesystem;

using testing::ProgramRun;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Runs the program with `args` (already quoted) and `env` (e.g. "DISPLAY=:5").
ProgramRun run_program(const std::string& env, const std::string& args, const fs::path& dir) {
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string cmd =
        "env " + env + " '" IMPOSSIBLE_BINARY "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int raw = std::system(cmd.c_str());
    ProgramRun r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

// An Xvfb server on a display number it picks itself (-displayfd): it writes
// the number once it accepts connections. Killed by the destructor.
struct Xvfb {
    pid_t pid = -1;
    std::string display;  // ":N", empty if it did not start
    std::string error;

    Xvfb() {
        int fds[2];
        if (pipe(fds) != 0) {
            error = "pipe failed";
            return;
        }
        pid = fork();
        if (pid == 0) {
            close(fds[0]);
            const int null = open("/dev/null", O_WRONLY);
            if (null >= 0) {
                dup2(null, 1);
                dup2(null, 2);
            }
            const std::string fd = std::to_string(fds[1]);
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        if (pid < 0) {
            error = "fork failed";
            close(fds[0]);
            return;
        }
        std::string number;
        pollfd p{fds[0], POLLIN, 0};
        char c = 0;
        while (poll(&p, 1, 15000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        close(fds[0]);
        if (number.empty())
            error = "Xvfb did not start (is Debian's xvfb package installed? scripts/setup.sh installs it)";
        else
            display = ":" + number;
    }
    ~Xvfb() {
        if (pid > 0) {
            kill(pid, SIGTERM);
            waitpid(pid, nullptr, 0);
        }
    }
};

using Preview = test::TempDirTest;

std::vector<nlohmann::json> json_lines(const std::string& text) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

constexpr int kEyeW = 160, kEyeH = 120;

// Frame `i` of a scripted preview (its PNGs under `shots`) against
// `render --backend osmesa` with `view` (a pose and room, or --path and
// --frame) at the test's size.
void expect_frame_equals_render(const std::string& view, size_t i, const fs::path& layout, const fs::path& shots,
                                const fs::path& dir);

// Frame `i` of a scripted preview (its record and PNGs under `shots`)
// against `render` at the frame's virtual pose and room.
void expect_frame_matches_render(const nlohmann::json& f, size_t i, const fs::path& layout, const fs::path& shots,
                                 const fs::path& dir) {
    std::string pose;
    for (int k = 0; k < 6; ++k) pose += (k ? "," : "") + f["pose"][k].dump();
    expect_frame_equals_render("--pose=" + pose + " --room " + f["room"].get<std::string>(), i, layout, shots, dir);
}

void expect_frame_equals_render(const std::string& view, size_t i, const fs::path& layout, const fs::path& shots,
                                const fs::path& dir) {
    // OSMesa is llvmpipe everywhere, like GLX under Xvfb, even where EGL finds a GPU.
    const ProgramRun r =
        run_program("",
                    "render --backend osmesa " + q(layout) + " " + view + " --size " + std::to_string(kEyeW) + "x" +
                        std::to_string(kEyeH) + " --out " + q(dir / "r.png") + " --ids " + q(dir / "r-ids.png"),
                    dir);
    ASSERT_EQ(r.status, 0) << r.err;
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04zu", i);
    const image::Pixels colour = testing::read_png_ok((shots / (std::string(name) + ".png")).string());
    const image::Pixels ids = testing::read_png_ok((shots / (std::string(name) + "-ids.png")).string());
    const image::Pixels ref_colour = testing::read_png_ok((dir / "r.png").string());
    const image::Pixels ref_ids = testing::read_png_ok((dir / "r-ids.png").string());
    ASSERT_EQ(colour.width, 2 * kEyeW);
    ASSERT_EQ(colour.height, kEyeH);
    ASSERT_EQ(ids.width, ref_ids.width);
    ASSERT_EQ(colour.data.size(), ref_colour.data.size());

    // The centres of both eyes: the same cell and the same colour.
    for (int eye = 0; eye < 2; ++eye) {
        const size_t p = static_cast<size_t>(kEyeH / 2) * (2 * kEyeW) + eye * kEyeW + kEyeW / 2;
        EXPECT_EQ(ids.data[p], ref_ids.data[p]) << "eye " << eye;
        EXPECT_NE(ids.data[p], 0) << "eye " << eye;
        for (int c = 0; c < 3; ++c) EXPECT_EQ(colour.data[p * 3 + c], ref_colour.data[p * 3 + c]);
    }
    // And the whole image: the same renderer on the same driver (llvmpipe).
    int id_diffs = 0, colour_diffs = 0;
    for (size_t p = 0; p < ids.data.size(); ++p) {
        id_diffs += ids.data[p] != ref_ids.data[p];
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(colour.data[p * 3 + c]) - int(ref_colour.data[p * 3 + c])) > 2) {
                ++colour_diffs;
                break;
            }
    }
    EXPECT_LE(id_diffs, 0);
    EXPECT_LE(colour_diffs, 0);
}

TEST_F(Preview, ScriptedWalkThroughAPortalMatchesRenderAndWalk) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const fs::path layout = fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/rotated.json";
    const fs::path path = fs::path(IMPOSSIBLE_TEST_DATA) / "preview/through_rotated_door.txt";
    const fs::path shots = dir_ / "shots";
    const ProgramRun run = run_program("DISPLAY=" + x.display,
                                       "preview " + q(layout) + " --path " + q(path) + " --screenshots " + q(shots) +
                                           " --frames 7 --size " + std::to_string(kEyeW) + "x" + std::to_string(kEyeH),
                                       dir_);
    ASSERT_EQ(run.status, 0) << run.err;

    // The poses against `walk` of the same path: same rooms, teleports,
    // virtual positions and view directions.
    const std::vector<nlohmann::json> frames = json_lines(slurp(shots / "frames.jsonl"));
    const ProgramRun walk = run_program("", "walk " + q(layout) + " --path " + q(path), dir_);
    ASSERT_EQ(walk.status, 0) << walk.err;
    const std::vector<nlohmann::json> walked = json_lines(walk.out);
    ASSERT_EQ(frames.size(), 7u);
    ASSERT_EQ(walked.size(), 7u);
    int teleports = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        EXPECT_EQ(frames[i]["room"], walked[i]["room"]);
        EXPECT_EQ(frames[i]["teleports"], walked[i]["teleports"]);
        teleports += static_cast<int>(frames[i]["teleports"].size());
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(frames[i]["position"][k].get<double>(), walked[i]["position"][k].get<double>(), 1e-12);
            EXPECT_NEAR(frames[i]["forward"][k].get<double>(), walked[i]["forward"][k].get<double>(), 1e-12);
            EXPECT_NEAR(frames[i]["pose"][k].get<double>(), walked[i]["position"][k].get<double>(), 1e-12);
        }
    }
    EXPECT_EQ(teleports, 1);
    EXPECT_EQ(frames.back()["room"], "gallery");
    // The rotated door turns the view: the virtual yaw is not the physical one.
    EXPECT_GT(std::abs(frames.back()["pose"][3].get<double>() - frames.back()["physical"][3].get<double>()), 45.0);

    // Every frame against `render` at the frame's virtual pose and room.
    for (size_t i = 0; i < frames.size(); ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        expect_frame_matches_render(frames[i], i, layout, shots, dir_);
    }
    // The last frame looks into the gallery (room 2) through both eyes.
    const image::Pixels last = testing::read_png_ok((shots / "frame-0006-ids.png").string());
    EXPECT_EQ(last.data[static_cast<size_t>(kEyeH / 2) * (2 * kEyeW) + kEyeW / 2], 2);

    // The window shot is the whole window: both eyes plus the HUD over them.
    const image::Pixels window = testing::read_png_ok((shots / "window-0006.png").string());
    const image::Pixels frame = testing::read_png_ok((shots / "frame-0006.png").string());
    EXPECT_EQ(window.width, 2 * kEyeW);
    EXPECT_EQ(window.height, kEyeH);
    EXPECT_NE(window.data, frame.data);
}

TEST_F(Preview, ReplayedHandsAndTimeMatchRenderOfThePathsFrames) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const fs::path layout = fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/rotated.json";
    // Lines 1 and 3 hold hands (18 numbers); line 1's right hand is through
    // the door ahead of the head, line 2 passes the door.
    const fs::path path = dir_ / "hands.txt";
    std::ofstream(path) << "0.05 1.6 1.0 0 0 0\n"
                           "0.05 1.6 0.4 5 -10 0   -0.25 1.2 0.3 0 0 0   0.2 1.35 -0.1 10 -30 5\n"
                           "0.05 1.6 -0.3 0 0 0\n"
                           "0.1 1.6 -0.7 10 5 2   -0.2 1.3 -0.9 0 0 0   0.25 1.35 -1.1 -20 15 0\n";
    const fs::path shots = dir_ / "shots";
    const ProgramRun run =
        run_program("DISPLAY=" + x.display,
                    "preview " + q(layout) + " --path " + q(path) + " --fps 24 --screenshots " + q(shots) +
                        " --frames 4 --size " + std::to_string(kEyeW) + "x" + std::to_string(kEyeH),
                    dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    for (size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        expect_frame_equals_render("--path " + q(path) + " --frame " + std::to_string(i) + " --fps 24", i, layout,
                                   shots, dir_);
    }
}

TEST_F(Preview, ChangesAreMadeLiveAsWalkMakesThem) {
    // Suma's door swap walked by --path: the preview makes the swap at the
    // frame `walk` does with the same eyes (--size), and draws every frame
    // after it with the new pairing, as `render --path --frame` does.
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const fs::path layout = fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/door_swap.json";
    const fs::path path = fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/door_swap_walk.txt";
    const std::string size = " --size " + std::to_string(kEyeW) + "x" + std::to_string(kEyeH);
    const fs::path shots = dir_ / "shots";
    const ProgramRun run = run_program(
        "DISPLAY=" + x.display,
        "preview " + q(layout) + " --path " + q(path) + " --screenshots " + q(shots) + " --frames 101" + size, dir_);
    ASSERT_EQ(run.status, 0) << run.err;
    const std::vector<nlohmann::json> frames = json_lines(slurp(shots / "frames.jsonl"));
    const ProgramRun walk = run_program("", "walk " + q(layout) + " --path " + q(path) + size, dir_);
    ASSERT_EQ(walk.status, 0) << walk.err;
    const std::vector<nlohmann::json> walked = json_lines(walk.out);
    ASSERT_EQ(frames.size(), 101u);
    ASSERT_GE(walked.size(), frames.size());
    size_t made = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        EXPECT_EQ(frames[i]["room"], walked[i]["room"]);
        EXPECT_EQ(frames[i]["teleports"], walked[i]["teleports"]);
        EXPECT_EQ(frames[i].contains("changes"), walked[i].contains("changes"));
        if (!walked[i].contains("changes")) continue;
        EXPECT_EQ(frames[i]["changes"], walked[i]["changes"]);
        made = i;
    }
    ASSERT_GT(made, 0u);
    // Before, at and after the change (frame 100: turned round, the swapped
    // door in view).
    for (const size_t i : {made - 1, made, size_t{100}}) {
        SCOPED_TRACE("frame " + std::to_string(i));
        expect_frame_equals_render("--path " + q(path) + " --frame " + std::to_string(i), i, layout, shots, dir_);
    }
}

TEST_F(Preview, CrossSwapsTheEyesInTheWindow) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const std::string common = " --frames 1 --no-hud --no-minimap --size 80x60 --screenshots ";
    const ProgramRun parallel = run_program("DISPLAY=" + x.display, "preview" + common + q(dir_ / "p"), dir_);
    ASSERT_EQ(parallel.status, 0) << parallel.err;
    const ProgramRun cross = run_program("DISPLAY=" + x.display, "preview --cross" + common + q(dir_ / "c"), dir_);
    ASSERT_EQ(cross.status, 0) << cross.err;
    const image::Pixels p = testing::read_png_ok((dir_ / "p/window-0000.png").string());
    const image::Pixels c = testing::read_png_ok((dir_ / "c/window-0000.png").string());
    const image::Pixels f = testing::read_png_ok((dir_ / "p/frame-0000.png").string());
    ASSERT_EQ(p.width, 160);
    ASSERT_EQ(c.width, 160);
    // The default layout's start is near the play area's edge (grid shown), so
    // compare the parallel window with the cross one rather than the frame.
    int differing = 0;
    for (int y = 0; y < 60; ++y)
        for (int xx = 0; xx < 80; ++xx)
            for (int k = 0; k < 3; ++k) {
                const size_t left = (static_cast<size_t>(y) * 160 + xx) * 3 + k, right = left + 80 * 3;
                EXPECT_EQ(p.data[left], c.data[right]);
                EXPECT_EQ(p.data[right], c.data[left]);
                differing += f.data[left] != f.data[right];
            }
    EXPECT_GT(differing, 100);  // the eyes do differ, so the swap is seen
}

// The window's own pixels (read back from the default framebuffer under
// Xvfb) show the frame: none black where the frame is not, and at most the
// boundary grid's lines differ. The renderer's last scissor once stayed set
// while the frame was copied to the window, which then showed only the last
// door's rectangle (51 % black on the default layout, 92-95 % on the tunnel).
TEST_F(Preview, TheWindowShowsTheWholeFrame) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const std::string tunnel = (fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/tunnel.json").string();
    const std::string tour = (fs::path(IMPOSSIBLE_SOURCE_DIR) / "scripts/preview-tour.txt").string();
    const std::string cases[] = {"",
                                 "--stereo two-pass",
                                 "--technique hybrid",
                                 "--samples 4",
                                 q(tunnel) + " --path " + q(tour),
                                 q(tunnel) + " --path " + q(tour) + " --clip oblique"};
    int k = 0;
    for (const std::string& c : cases) {
        SCOPED_TRACE(c);
        const fs::path shots = dir_ / ("s" + std::to_string(k++));
        const ProgramRun run = run_program("DISPLAY=" + x.display,
                                           "preview " + c +
                                               " --frames 3 --no-hud --no-minimap --no-vsync --size 140x105 "
                                               "--screenshots " +
                                               q(shots),
                                           dir_);
        if (run.status != 0 && run.err.find("offers") != std::string::npos) continue;  // no 4-sample buffers
        ASSERT_EQ(run.status, 0) << run.err;
        for (const char* n : {"0000", "0002"}) {
            const image::Pixels window = testing::read_png_ok((shots / (std::string("window-") + n + ".png")).string());
            const image::Pixels frame = testing::read_png_ok((shots / (std::string("frame-") + n + ".png")).string());
            ASSERT_EQ(window.data.size(), frame.data.size());
            long black_only_in_window = 0, differing = 0;
            const std::size_t pixels = window.data.size() / 3;
            for (std::size_t p = 0; p < pixels; ++p) {
                const std::uint8_t* w = &window.data[p * 3];
                const std::uint8_t* f = &frame.data[p * 3];
                black_only_in_window += w[0] + w[1] + w[2] == 0 && f[0] + f[1] + f[2] != 0;
                differing += std::abs(w[0] - f[0]) > 2 || std::abs(w[1] - f[1]) > 2 || std::abs(w[2] - f[2]) > 2;
            }
            EXPECT_EQ(black_only_in_window, 0) << n;
            EXPECT_LE(differing, static_cast<long>(pixels) / 10) << n;  // the grid's lines, where shown
        }
    }
}

// --samples 4: the window's frames are multisampled, the same frame (colour
// and ids) as `render --samples 4` writes.
TEST_F(Preview, MultisampledFramesMatchRender) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const ProgramRun preview =
        run_program("DISPLAY=" + x.display,
                    "preview --samples 4 --frames 1 --no-vsync --size 80x60 --screenshots " + q(dir_ / "s"), dir_);
    if (preview.status != 0 && preview.err.find("offers") != std::string::npos) GTEST_SKIP() << preview.err;
    ASSERT_EQ(preview.status, 0) << preview.err;
    const ProgramRun render = run_program(
        "", "render --samples 4 --size 80x60 --out " + q(dir_ / "r.png") + " --ids " + q(dir_ / "r-ids.png"), dir_);
    ASSERT_EQ(render.status, 0) << render.err;
    EXPECT_EQ(testing::read_png_ok((dir_ / "s/frame-0000.png").string()).data,
              testing::read_png_ok((dir_ / "r.png").string()).data);
    EXPECT_EQ(testing::read_png_ok((dir_ / "s/frame-0000-ids.png").string()).data,
              testing::read_png_ok((dir_ / "r-ids.png").string()).data);
}

// The gallery's textures, vertex colours, double-sided screen and cut-outs
// in the window: the same frame as `render` writes.
TEST_F(Preview, MaterialsMatchRender) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const std::string layout = q(fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/gallery.json");
    const ProgramRun preview =
        run_program("DISPLAY=" + x.display,
                    "preview " + layout + " --frames 1 --no-vsync --size 160x90 --screenshots " + q(dir_ / "s"), dir_);
    ASSERT_EQ(preview.status, 0) << preview.err;
    const ProgramRun render = run_program(
        "", "render " + layout + " --size 160x90 --out " + q(dir_ / "r.png") + " --ids " + q(dir_ / "r-ids.png"), dir_);
    ASSERT_EQ(render.status, 0) << render.err;
    EXPECT_EQ(testing::read_png_ok((dir_ / "s/frame-0000.png").string()).data,
              testing::read_png_ok((dir_ / "r.png").string()).data);
    EXPECT_EQ(testing::read_png_ok((dir_ / "s/frame-0000-ids.png").string()).data,
              testing::read_png_ok((dir_ / "r-ids.png").string()).data);
}

// --technique in the window: the same frame as `render` with it, which is
// not the stencil frame (a half-size texture blurs the view through the
// door; z-clear at depth 1 shows the corridor's fill one door deep).
TEST_F(Preview, TechniquesMatchRender) {
    const Xvfb x;
    ASSERT_FALSE(x.display.empty()) << x.error;
    const std::string layout = q(fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/corridor.json");
    const ProgramRun plain = run_program("", "render " + layout + " --size 80x60 --out " + q(dir_ / "plain.png"), dir_);
    ASSERT_EQ(plain.status, 0) << plain.err;
    int k = 0;
    for (const std::string technique :
         {"--technique hybrid --portal-texture 0.5", "--technique z-clear --max-depth 1"}) {
        const std::string shots = "s" + std::to_string(k), out = "r" + std::to_string(k++) + ".png";
        const ProgramRun preview =
            run_program("DISPLAY=" + x.display,
                        "preview " + layout + " " + technique + " --frames 1 --no-vsync --size 80x60 --screenshots " +
                            q(dir_ / shots),
                        dir_);
        ASSERT_EQ(preview.status, 0) << technique << preview.err;
        const ProgramRun render =
            run_program("", "render " + layout + " " + technique + " --size 80x60 --out " + q(dir_ / out), dir_);
        ASSERT_EQ(render.status, 0) << technique << render.err;
        const image::Pixels rendered = testing::read_png_ok((dir_ / out).string());
        EXPECT_EQ(testing::read_png_ok((dir_ / shots / "frame-0000.png").string()).data, rendered.data) << technique;
        EXPECT_NE(rendered.data, testing::read_png_ok((dir_ / "plain.png").string()).data) << technique;
    }
}

TEST_F(Preview, WithoutADisplayFailsWithOneLine) {
    const ProgramRun r = run_program("-u DISPLAY -u WAYLAND_DISPLAY", "preview --frames 1", dir_);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(Preview, BadOptionsAreUsageOrInputErrors) {
    // Checked before any window opens, so no display is needed.
    const std::string env = "-u DISPLAY -u WAYLAND_DISPLAY";
    EXPECT_EQ(run_program(env, "preview --cross --anaglyph", dir_).status, 2);
    EXPECT_EQ(run_program(env, "preview --bogus", dir_).status, 2);
    EXPECT_EQ(run_program(env, "preview --frames 0", dir_).status, 1);
    EXPECT_EQ(run_program(env, "preview --size 100", dir_).status, 1);
    const ProgramRun fps_alone = run_program(env, "preview --fps 30", dir_);
    EXPECT_EQ(fps_alone.status, 2);
    EXPECT_NE(fps_alone.err.find("--fps needs --path FILE"), std::string::npos) << fps_alone.err;
    EXPECT_EQ(run_program(env, "preview " + q(dir_ / "missing.json"), dir_).status, 1);
    std::ofstream(dir_ / "bad-path.txt") << "0 1.6 1 0 0\n";
    const ProgramRun bad_path = run_program(env, "preview --path " + q(dir_ / "bad-path.txt"), dir_);
    EXPECT_EQ(bad_path.status, 1);
    EXPECT_NE(bad_path.err.find("bad-path.txt:1:"), std::string::npos) << bad_path.err;
    const ProgramRun help = run_program(env, "preview --help", dir_);
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("usage: impossible preview"), std::string::npos);
}

}  // namespace
}  // namespace impossible
