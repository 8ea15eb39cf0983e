// impossible preview [LAYOUT]: a window for layout designers (docs/preview.md).
//
// Each frame: input → physical head → walker (teleports as `walk`) → the
// virtual pose → the renderer's side-by-side frame → the window (parallel,
// cross or anaglyph) with the boundary grid, HUD and minimap drawn over it.
// The state lives in a PreviewSession (session.hpp); this file holds the
// steps of one frame.
#include "preview/preview_command.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <ostream>
#include <string>
#include <vector>

#include "cli/errors.hpp"
#include "cli/field_flags.hpp"
#include "cli/view_options.hpp"
#include "gl/gl.hpp"
#include "math/eyes.hpp"
#include "math/projection.hpp"
#include "preview/grid.hpp"
#include "preview/hud.hpp"
#include "preview/hud_text.hpp"
#include "preview/keys.hpp"
#include "preview/minimap.hpp"
#include "preview/session.hpp"

namespace impossible::preview {

using cli::check;
using cli::kExitOk;

namespace {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double eye_aspect(const PreviewOptions& o) { return double(o.frame.eye_width) / o.frame.eye_height; }

// The frame's key presses and clicks: options toggled, the cursor captured or
// released. What is left to do is returned.
KeyEffects apply_keys(PreviewSession& s) {
    PreviewWindow& window = *s.window;
    const KeyEffects keys =
        apply_actions(window.input.actions, cursor_captured(window), s.options, s.shown.session->layout().exposure);
    if (keys.release_cursor) capture_cursor(window, false);
    if (!keys.quit && window.input.clicked && !cursor_captured(window)) capture_cursor(window, true);
    return keys;
}

// The physical head: the path while it lasts, then the keys and mouse.
math::HeadPose next_physical_head(const PreviewSession& s, long frame, double dt) {
    if (static_cast<std::size_t>(frame) < s.path.size()) return s.path[static_cast<std::size_t>(frame)].head;
    const WindowInput& in = s.window->input;
    const MoveInput move = move_input(in.held, dt, cursor_captured(*s.window), in.mouse_dx, in.mouse_dy);
    return move_head(s.physical, move, s.shown.session->layout().play_area);
}

// The physical hands: the path's line's while the path lasts and the line
// has them, else the hand G holds out, else none.
walk::HandPoses physical_hands(const PreviewSession& s, long frame) {
    const std::size_t k = static_cast<std::size_t>(frame);
    if (k < s.path.size() && s.path[k].hands) return s.path[k].hands;
    if (s.options.hand) return held_hands(s.physical, s.options.hand_distance);
    return std::nullopt;
}

// The time of moving props: frame / fps with --path (during the path and
// after it), else the seconds since the preview started.
double frame_time(const PreviewSession& s, long frame) {
    if (s.options.path_file)
        return walk::line_time(static_cast<std::size_t>(frame), s.options.fps.value_or(layout::kDefaultPathFps));
    return seconds_since(s.clock.start);
}

// The options' frame with the walker's head, room and hands, at the frame's
// time. Screenshots are taken at --size, as `render --size` draws;
// otherwise the eyes are drawn at the size they have in the window.
render::FrameDesc frame_desc(const PreviewSession& s, long frame, const PixelRect& eye) {
    render::FrameDesc desc = s.options.frame;
    walk::set_walked_view(desc, s.shown.driver->walker(), s.physical_hands);
    desc.time = frame_time(s, frame);
    if (!s.options.screenshots) {
        desc.eye_width = eye.width;
        desc.eye_height = eye.height;
    }
    return desc;
}

FrameRecord frame_record(const PreviewSession& s, long frame, const render::FrameDesc& desc,
                         const session::WalkedFrame& walked) {
    const layout::Layout& lay = s.shown.session->layout();  // as loaded: the walked frame's indices are its
    FrameRecord r;
    r.frame = frame;
    r.room = lay.rooms[desc.room].id;
    for (int p : walked.teleports) r.teleports.push_back(lay.portals[p].id);
    for (int c : walked.changes) r.changes.push_back(lay.changes[static_cast<std::size_t>(c)].id);
    r.pose = desc.head;
    r.physical = s.physical;
    r.position = s.shown.driver->walker().position();
    r.forward = s.shown.driver->walker().forward();
    r.eye_width = desc.eye_width;
    r.eye_height = desc.eye_height;
    return r;
}

// With --screenshots: the renderer's image and the frame's line. Returns the
// seconds spent saving (not part of the frame time; the drawing it waits for is).
double save_rendered_frame(PreviewSession& s, long frame, const render::FrameDesc& desc,
                           const session::WalkedFrame& walked) {
    if (!s.files.every_frame) return 0.0;
    glFinish();
    const Clock::time_point start = Clock::now();
    save_frame(s.files, render::read_target(*s.state, s.shown.renderer->target()),
               frame_record(s, frame, desc, walked));
    return seconds_since(start);
}

// The boundary grid, per eye, seen by the physical eyes.
void draw_boundary_grids(PreviewSession& s, const WindowLayout& places, int fb_w, int fb_h) {
    const std::optional<layout::PlayArea>& area = s.shown.session->layout().play_area;
    if (!area) return;
    math::Frustum frustum;
    frustum.fov_y_deg = s.options.frame.fov_y_deg;
    frustum.aspect = eye_aspect(s.options);
    const std::array<math::Eye, 2> eyes = math::eyes_of(s.options.frame, s.physical);
    for (int e = 0; e < 2; ++e) {
        // Each eye's own angles with a headset profile (--fov-angles, --hmd).
        if (s.options.frame.eye_optics)
            frustum.tangents = math::fov_tangents((*s.options.frame.eye_optics)[static_cast<size_t>(e)].fov);
        const math::dmat4 projection = math::perspective_reversed_z(frustum);
        OverlayBatch grid;
        if (add_boundary_grid(grid, *area, s.physical.position, eyes[e], projection) == 0) break;
        const PixelRect& r = places.eye_rects[e];
        s.state->viewport({r.x, r.y, r.width, r.height});
        draw_overlay(
            s.overlay, *s.state, grid,
            s.options.view == PreviewView::Anaglyph ? gl::color_channels(e == 0, e == 1, e == 1, true) : gl::kColorAll);
    }
    s.state->viewport({0, 0, fb_w, fb_h});
}

HudFacts hud_facts(const PreviewSession& s, const render::FrameDesc& desc) {
    HudFacts f;
    f.title = s.title;
    f.median_ms = median_ms(s.clock.frame_ms);
    f.timed_frames = s.clock.frame_ms.size();
    f.eye_width = desc.eye_width;
    f.eye_height = desc.eye_height;
    f.room = s.shown.session->layout().rooms[desc.room].id;
    f.portal_passes_drawn = s.stats.portal_passes_drawn;
    f.portal_passes_culled = s.stats.portal_passes_culled;
    f.max_level_reached = s.stats.max_level_reached;
    f.physical = s.physical;
    f.cursor_captured = cursor_captured(*s.window);
    f.time = desc.time;
    const layout::Layout& layout = s.shown.session->layout();
    f.lit = layout.lighting == layout::Lighting::Lights;
    f.room_lights = static_cast<int>(layout.rooms[desc.room].lights.size());
    f.light_images = s.stats.light_images;
    f.light_depth = desc.light_depth.value_or(layout.light_depth);
    f.exposure = desc.exposure.value_or(layout.exposure);
    if (const changes::ChangeWalk* walk = s.shown.driver->changes())
        f.changes = changes_line(layout, *walk, s.shown.driver->seen_passes());
    return f;
}

// The renderer's image in the window, then the grid, HUD and minimap over it.
void draw_window(PreviewSession& s, const WindowLayout& places, const render::FrameDesc& desc, int fb_w, int fb_h) {
    present(s.presenter, *s.state, s.shown.renderer->target(), places, s.options.view, fb_w, fb_h);
    draw_boundary_grids(s, places, fb_w, fb_h);

    OverlayBatch batch;
    batch.width = fb_w;
    batch.height = fb_h;
    const float scale = hud_scale(fb_h);
    add_hud(batch, fit_hud(hud_text(s.options, hud_facts(s, desc), s.reload_errors), fb_w, fb_h, scale), scale);
    if (s.options.minimap) {
        const float side = std::min(0.42f * float(fb_h), 0.3f * float(fb_w));
        // The layout with the pairing in force: its doors are the walker's.
        const walk::Walker& walker = s.shown.driver->walker();
        const MinimapInput map{&s.shown.driver->session().layout(), desc.room, walker.physical_to_virtual(),
                               &walker.links().transfer, s.physical};
        add_minimap(batch, map, {float(fb_w) - side - 8.0f, float(fb_h) - side - 8.0f}, side);
    }
    draw_overlay(s.overlay, *s.state, batch);
}

// window-NNNN.png with --screenshots, screenshot-NNNN.png after P or F12.
// Returns the seconds spent.
double save_window_files(PreviewSession& s, long frame, bool screenshot, int fb_w, int fb_h, std::ostream& err) {
    if (s.files.every_frame) glFinish();
    const Clock::time_point start = Clock::now();
    if (s.files.every_frame) save_window(s.files, frame, fb_w, fb_h, read_window(*s.state, fb_w, fb_h));
    if (screenshot) err << "saved " << save_screenshot(s.files, fb_w, fb_h, read_window(*s.state, fb_w, fb_h)) << "\n";
    return seconds_since(start);
}

// One frame; false when the preview ends.
bool run_frame(PreviewSession& s, long frame, std::ostream& err) {
    poll_input(*s.window);
    if (should_close(*s.window)) return false;
    const KeyEffects keys = apply_keys(s);
    if (keys.quit) return false;
    const Clock::time_point now = Clock::now();
    const double dt = tick(s.clock, frame, now);
    poll_reload(s, now);
    if (keys.reset) reset_walk(s);
    s.physical = next_physical_head(s, frame, dt);
    // The options' frame places the eyes of the changes' seen test.
    const session::WalkedFrame walked =
        walk_shown(s.shown, *s.state, s.physical, frame_time(s, frame), s.options.frame);
    s.physical_hands = physical_hands(s, frame);

    int fb_w = 0, fb_h = 0;
    framebuffer_size(*s.window, fb_w, fb_h);
    if (fb_w <= 0 || fb_h <= 0) return true;  // minimised
    const WindowLayout places = window_layout(fb_w, fb_h, eye_aspect(s.options), s.options.view);
    const render::FrameDesc desc = frame_desc(s, frame, places.eye_rects[0]);
    check(cli::with_flags(s.shown.renderer->draw(desc, &s.stats)));
    s.clock.io_seconds = save_rendered_frame(s, frame, desc, walked);
    draw_window(s, places, desc, fb_w, fb_h);
    s.clock.io_seconds += save_window_files(s, frame, keys.screenshot, fb_w, fb_h, err);
    // As the renderer does: nothing stays bound between frames, so an object
    // deleted by a reload cannot leave the cache believing its name bound.
    s.state->release_bindings();
    swap_buffers(*s.window);
    return true;
}

}  // namespace

int run_preview_command(const cli::Args& args, std::ostream& out, std::ostream& err) {
    bool help = false;
    PreviewOptions options = parse_preview_options(args, &help);
    if (help) {
        out << preview_help();
        return kExitOk;
    }
    PreviewSession session;
    open_session(session, std::move(options));
    err << cli::model_warnings_text(*session.shown.session)
        << cli::light_options_warning(*session.shown.session, session.options.frame.light_depth,
                                      session.options.shadow_options);
    for (long frame = 0; !session.options.frames || frame < *session.options.frames; ++frame)
        if (!run_frame(session, frame, err)) break;
    return kExitOk;
}

}  // namespace impossible::preview
