// impossible preview [LAYOUT]: a window for layout designers (docs/preview.md).
//
// Each frame: input → physical head → walker (teleports as `walk`) → the
// virtual pose → the renderer's side-by-side frame → the window (parallel,
// cross or anaglyph) with the boundary grid, HUD and minimap drawn over it.
#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>

#include "gl/gl.hpp"  // before GLFW, which must not include GL itself
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/cli_args.hpp"
#include "app/cmd_walk.hpp"
#include "app/commands.hpp"
#include "app/layout_source.hpp"
#include "app/png_io.hpp"
#include "app/preview_grid.hpp"
#include "app/preview_head.hpp"
#include "app/preview_hud.hpp"
#include "app/preview_minimap.hpp"
#include "app/preview_options.hpp"
#include "app/preview_overlay.hpp"
#include "app/preview_path.hpp"
#include "app/preview_present.hpp"
#include "app/preview_reload.hpp"
#include "app/preview_window.hpp"
#include "math/projection.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "scene/walk.hpp"

namespace impossible::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kTimedFrames = 60;
constexpr double kReloadPollSeconds = 0.25;

// The layout being shown and what is built from it. The walker points into
// the layout, so both live on the heap and are replaced together.
struct Shown {
    std::unique_ptr<layout::Layout> layout;
    std::unique_ptr<render::Renderer> renderer;
    std::unique_ptr<scene::Walker> walker;
};

// Builds the renderer and a walker for `layout`, in the room named `room_id`
// if it still exists (else the start room). Empty renderer and `error` on failure.
Shown build_shown(gl::StateCache& state, layout::Layout layout, const std::string& room_id, std::string& error) {
    Shown s;
    s.layout = std::make_unique<layout::Layout>(std::move(layout));
    Result<render::Renderer> made = render::Renderer::create(state, *s.layout, scene::build_scene(*s.layout));
    if (!made) {
        error = made.error();
        return {};
    }
    s.renderer = std::make_unique<render::Renderer>(std::move(*made));
    const int room = layout::find_room(*s.layout, room_id);
    s.walker = room >= 0 ? std::make_unique<scene::Walker>(*s.layout, room) : std::make_unique<scene::Walker>(*s.layout);
    return s;
}

math::HeadPose start_pose(const layout::Layout& layout) {
    math::HeadPose p;
    p.position = layout.start.position;
    p.yaw_deg = layout.start.yaw_deg;
    return p;
}

std::string numbered(const fs::path& dir, const char* stem, long n, const char* suffix = ".png") {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%04ld%s", stem, n, suffix);
    return (dir / name).string();
}

std::string json_numbers(std::initializer_list<double> values) {
    std::string s = "[";
    for (double v : values) s += (s.size() > 1 ? "," : "") + format_number(v);
    return s + "]";
}

std::string pose_json(const math::HeadPose& p) {
    return json_numbers({p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg});
}

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

void write_or_throw(const std::string& path, int w, int h, int channels, const std::vector<std::uint8_t>& pixels) {
    if (std::string e = write_png(path, w, h, channels, pixels); !e.empty()) throw InputError(e);
}

}  // namespace

int run_preview_command(const Args& args, std::ostream& out, std::ostream& err) {
    bool help = false;
    PreviewOptions o = parse_preview_options(args, &help);
    if (help) {
        out << preview_help();
        return kExitOk;
    }
    // Everything that can be checked without a window is checked first.
    const layout::Layout first = load_layout_or_default(o.layout_path);
    PathFile path;
    if (o.path_file) {
        path = read_path_file(*o.path_file);
        if (!path.error.empty()) throw InputError(path.error);
    }
    const fs::path shots = o.screenshots ? fs::path(*o.screenshots) : fs::path(".");
    std::ofstream frames_log;
    if (o.screenshots) {
        std::error_code ec;
        fs::create_directories(shots, ec);
        if (!fs::is_directory(shots)) throw InputError(*o.screenshots + ": cannot create the screenshot directory");
        frames_log.open(shots / "frames.jsonl", std::ios::binary | std::ios::trunc);
        if (!frames_log) throw InputError((shots / "frames.jsonl").string() + ": cannot write");
    }

    const double aspect = double(o.eye_width) / o.eye_height;
    const std::string title = "impossible preview - " + (first.name.empty() ? first.source : first.name);
    WindowResult opened = open_window(o.view == PreviewView::Anaglyph ? o.eye_width : 2 * o.eye_width,
                                      o.eye_height, title, o.vsync && !o.screenshots);
    if (!opened.window) throw InputError(opened.error);
    PreviewWindow& window = *opened.window;

    // The window context's one state cache, for the renderer and the
    // overlays alike; declared before everything that draws with it.
    gl::StateCache state;
    std::string error;
    Shown shown = build_shown(state, first, "", error);
    if (!shown.renderer) throw InputError(error);
    OverlayProgram overlay = build_overlay_program(error);
    if (!error.empty()) throw InputError(error);
    Presenter presenter = build_presenter(error);
    if (!error.empty()) throw InputError(error);

    std::optional<LayoutWatcher> watcher;
    if (o.layout_path) watcher = watch_layout(*o.layout_path);
    std::vector<std::string> reload_errors;

    math::HeadPose physical = start_pose(*shown.layout);
    if (!o.path_file) capture_cursor(window, true);
    std::deque<double> frame_ms;
    render::FrameStats stats;
    Clock::time_point last = Clock::now(), last_poll = last;
    long shot_number = 0;
    double io_seconds = 0.0;  // spent writing screenshots last frame: not part of the frame time

    for (long frame = 0; !o.frames || frame < *o.frames; ++frame) {
        poll_input(window);
        if (should_close(window)) break;
        const WindowInput& in = window.input;
        bool quit = false, screenshot = false, reset = false;
        for (int key : in.keys_pressed) {
            switch (key) {
                case GLFW_KEY_ESCAPE:
                    if (cursor_captured(window)) capture_cursor(window, false);
                    else quit = true;
                    break;
                case GLFW_KEY_H: o.hud = !o.hud; break;
                case GLFW_KEY_M: o.minimap = !o.minimap; break;
                case GLFW_KEY_V: o.view = next_view(o.view); break;
                case GLFW_KEY_LEFT_BRACKET: o.max_depth = std::max(0, o.max_depth - 1); break;
                case GLFW_KEY_RIGHT_BRACKET: o.max_depth = std::min(250, o.max_depth + 1); break;
                case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: o.ipd = std::max(0.0, o.ipd - 0.002); break;
                case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: o.ipd = std::min(10.0, o.ipd + 0.002); break;
                case GLFW_KEY_C:
                    o.clip = o.clip == render::ClipMode::ClipDistance ? render::ClipMode::Oblique
                                                                      : render::ClipMode::ClipDistance;
                    break;
                case GLFW_KEY_X: o.cull_portals = !o.cull_portals; break;
                case GLFW_KEY_P: case GLFW_KEY_F12: screenshot = true; break;
                case GLFW_KEY_R: reset = true; break;
                default: break;
            }
        }
        if (quit) break;
        if (in.clicked && !cursor_captured(window)) capture_cursor(window, true);

        const Clock::time_point now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        if (frame > 0) {
            frame_ms.push_back(std::max(0.0, dt - io_seconds) * 1000.0);
            if (frame_ms.size() > kTimedFrames) frame_ms.pop_front();
        }

        // Live reload: a good edit replaces the layout, a bad one is listed in the HUD.
        if (watcher && std::chrono::duration<double>(now - last_poll).count() >= kReloadPollSeconds) {
            last_poll = now;
            ReloadResult r = poll_layout(*watcher);
            if (r.kind == ReloadResult::Failed) reload_errors = r.errors;
            if (r.kind == ReloadResult::Reloaded) {
                const std::string room_id = shown.layout->rooms[shown.walker->room()].id;
                const bool walking = shown.walker->started();
                const math::dmat4 w = shown.walker->physical_to_virtual();
                Shown next = build_shown(state, std::move(*r.layout), room_id, error);
                if (next.renderer) {
                    // Walk on where the head was: same room (if it still
                    // exists) and the same physical-to-virtual mapping.
                    if (walking && layout::find_room(*next.layout, room_id) >= 0) next.walker->resume(w, physical);
                    shown = std::move(next);
                    reload_errors.clear();
                } else {
                    reload_errors = {"the reloaded layout cannot be drawn: " + error};
                }
            }
        }
        if (reset) {
            shown.walker = std::make_unique<scene::Walker>(*shown.layout);
            physical = start_pose(*shown.layout);
        }

        // The physical head: the path while it lasts, then the keys and mouse.
        if (o.path_file && static_cast<std::size_t>(frame) < path.poses.size()) {
            physical = path.poses[static_cast<std::size_t>(frame)];
        } else {
            MoveInput move;
            move.dt = std::min(dt, 0.1);
            auto held = [&](int a, int b) { return key_down(window, a) || key_down(window, b); };
            move.forward = int(held(GLFW_KEY_W, GLFW_KEY_UP)) - int(held(GLFW_KEY_S, GLFW_KEY_DOWN));
            move.right = int(held(GLFW_KEY_D, GLFW_KEY_RIGHT)) - int(held(GLFW_KEY_A, GLFW_KEY_LEFT));
            move.up = int(key_down(window, GLFW_KEY_E)) - int(key_down(window, GLFW_KEY_Q));
            move.fast = held(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
            if (cursor_captured(window)) {
                move.mouse_dx = in.mouse_dx;
                move.mouse_dy = in.mouse_dy;
            }
            physical = move_head(physical, move, shown.layout->play_area);
        }
        const std::vector<int> passed = shown.walker->step(physical);
        const layout::Layout& lay = *shown.layout;
        const math::HeadPose pose = pose_of(shown.walker->position(), shown.walker->rotation());

        int fb_w = 0, fb_h = 0;
        framebuffer_size(window, fb_w, fb_h);
        if (fb_w <= 0 || fb_h <= 0) continue;  // minimised
        const WindowLayout places = window_layout(fb_w, fb_h, aspect, o.view);

        render::FrameDesc desc;
        desc.head = pose;
        desc.room = shown.walker->room();
        desc.ipd = o.ipd;
        desc.fov_y_deg = o.fov_y_deg;
        // Screenshots are taken at --size, as `render --size` draws; otherwise
        // the eyes are drawn at the size they have in the window.
        desc.eye_width = o.screenshots ? o.eye_width : places.eye_rects[0].width;
        desc.eye_height = o.screenshots ? o.eye_height : places.eye_rects[0].height;
        desc.max_depth = o.max_depth;
        desc.stereo = o.stereo;
        desc.clip = o.clip;
        desc.cull_portals = o.cull_portals;
        if (Result<void> drawn = shown.renderer->draw(desc, &stats); !drawn) throw InputError(drawn.error());

        // Saving frames is not part of the frame time (the drawing it waits for is).
        if (o.screenshots) glFinish();
        const Clock::time_point io_start = Clock::now();
        if (o.screenshots) {
            const render::Image image = render::read_target(shown.renderer->target());
            write_or_throw(numbered(shots, "frame", frame), image.width, image.height, 3, image.rgb);
            write_or_throw(numbered(shots, "frame", frame, "-ids.png"), image.width, image.height, 1, image.ids);
            std::string line = "{\"frame\":" + std::to_string(frame) + ",\"room\":\"" + lay.rooms[desc.room].id +
                               "\",\"teleports\":[";
            for (std::size_t k = 0; k < passed.size(); ++k)
                line += (k ? ",\"" : "\"") + lay.portals[passed[k]].id + "\"";
            const math::dvec3 p = shown.walker->position(), f = shown.walker->forward();
            line += "],\"pose\":" + pose_json(pose) + ",\"physical\":" + pose_json(physical) +
                    ",\"position\":" + json_numbers({p.x, p.y, p.z}) + ",\"forward\":" + json_numbers({f.x, f.y, f.z}) +
                    ",\"eye_size\":[" + std::to_string(desc.eye_width) + "," + std::to_string(desc.eye_height) + "]}\n";
            frames_log << line << std::flush;
        }
        io_seconds = std::chrono::duration<double>(Clock::now() - io_start).count();

        {
            present(presenter, state, shown.renderer->target(), places, o.view, fb_w, fb_h);

            // The boundary grid, per eye, seen by the physical eyes.
            if (lay.play_area) {
                math::Frustum frustum;
                frustum.fov_y_deg = o.fov_y_deg;
                frustum.aspect = aspect;
                const math::dmat4 projection = math::perspective_reversed_z(frustum);
                const std::array<math::Eye, 2> eyes = math::eyes_of(physical, o.ipd);
                for (int e = 0; e < 2; ++e) {
                    OverlayBatch grid;
                    if (add_boundary_grid(grid, *lay.play_area, physical.position, eyes[e], projection) == 0) break;
                    const PixelRect& r = places.eye_rects[e];
                    state.viewport({r.x, r.y, r.width, r.height});
                    draw_overlay(overlay, state, grid,
                                 o.view == PreviewView::Anaglyph ? gl::color_channels(e == 0, e == 1, e == 1, true)
                                                                 : gl::kColorAll);
                }
                state.viewport({0, 0, fb_w, fb_h});
            }

            OverlayBatch batch;
            batch.width = fb_w;
            batch.height = fb_h;
            const float scale = fb_h < 400 ? 1.0f : fb_h < 800 ? 1.5f : 2.0f;
            HudText hud;
            if (o.hud) {
                const math::dvec3 h = physical.position;
                hud.lines = {
                    title + "   view: " + view_name(o.view),
                    "frame " + fixed(median_ms(frame_ms), 1) + " ms (median of " + std::to_string(frame_ms.size()) +
                        ")   eye " + std::to_string(desc.eye_width) + "x" + std::to_string(desc.eye_height),
                    "room " + lay.rooms[desc.room].id + "   portal passes " + std::to_string(stats.portal_passes_drawn) +
                        " drawn, " + std::to_string(stats.portal_passes_culled) + " culled",
                    "recursion depth " + std::to_string(o.max_depth) + " (reached " +
                        std::to_string(stats.max_level_reached) + ")   IPD " + fixed(o.ipd * 1000.0, 0) + " mm",
                    std::string("clip ") + (o.clip == render::ClipMode::ClipDistance ? "clip-distance" : "oblique") +
                        "   culling " + (o.cull_portals ? "on" : "off"),
                    "physical head " + fixed(h.x, 2) + " " + fixed(h.y, 2) + " " + fixed(h.z, 2) + "  yaw " +
                        fixed(physical.yaw_deg, 0) + "  pitch " + fixed(physical.pitch_deg, 0),
                    cursor_captured(window) ? "Esc releases the mouse" : "click to look around, Esc quits",
                    "WASD/arrows Q/E move  H hud  M map  V view  [ ] depth  - = IPD  C clip  X cull  P shot  R reset",
                };
            }
            if (!reload_errors.empty()) {
                hud.errors.push_back("layout reload failed; still showing the last good layout:");
                for (std::size_t i = 0; i < reload_errors.size() && i < 8; ++i) hud.errors.push_back(reload_errors[i]);
                if (reload_errors.size() > 8)
                    hud.errors.push_back("... and " + std::to_string(reload_errors.size() - 8) + " more");
            }
            add_hud(batch, hud, scale);
            if (o.minimap) {
                const float side = std::min(0.42f * float(fb_h), 0.3f * float(fb_w));
                MinimapInput map{&lay, desc.room, shown.walker->physical_to_virtual(), &shown.walker->links().transfer,
                                 physical};
                add_minimap(batch, map, {float(fb_w) - side - 8.0f, float(fb_h) - side - 8.0f}, side);
            }
            draw_overlay(overlay, state, batch);
        }

        if (o.screenshots) glFinish();
        const Clock::time_point io_resume = Clock::now();
        if (o.screenshots) write_or_throw(numbered(shots, "window", frame), fb_w, fb_h, 3, read_window(fb_w, fb_h));
        if (screenshot) {
            while (fs::exists(numbered(shots, "screenshot", shot_number))) ++shot_number;
            const std::string name = numbered(shots, "screenshot", shot_number);
            write_or_throw(name, fb_w, fb_h, 3, read_window(fb_w, fb_h));
            err << "saved " << name << "\n";
        }
        io_seconds += std::chrono::duration<double>(Clock::now() - io_resume).count();
        swap_buffers(window);
    }
    return kExitOk;
}

}  // namespace impossible::app
