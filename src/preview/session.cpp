#include "preview/session.hpp"

#include <algorithm>

#include "cli/errors.hpp"
#include "cli/layout_source.hpp"

namespace impossible::preview {

using cli::value_or_throw;

Result<Shown> build_shown(gl::StateCache& state, layout::Layout layout, const std::string& room_id,
                          const math::View& eyes) {
    Shown s;
    s.session = std::make_unique<session::Session>(std::move(layout));
    Result<render::Renderer> made = s.session->make_renderer(state);
    if (!made) return made;
    s.renderer = std::make_unique<render::Renderer>(std::move(*made));
    s.driver = std::make_unique<session::WalkDriver>(*s.session, eyes);
    s.driver->start_in(layout::find_room(s.session->layout(), room_id));
    return s;
}

session::WalkedFrame walk_shown(Shown& shown, gl::StateCache& state, const math::HeadPose& physical, double time,
                                const math::View& eyes) {
    shown.driver->set_view(eyes);
    session::WalkedFrame f = shown.driver->step(physical, std::nullopt, time);
    if (!f.changes.empty())  // the same programs: the change costs no compile
        shown.renderer = std::make_unique<render::Renderer>(
            value_or_throw(shown.driver->session().make_renderer(state, shown.renderer->programs())));
    return f;
}

math::HeadPose start_pose(const layout::Layout& layout) {
    math::HeadPose p;
    p.position = layout.start.position;
    p.yaw_deg = layout.start.yaw_deg;
    return p;
}

double tick(FrameClock& clock, long frame, Clock::time_point now) {
    const double dt = std::chrono::duration<double>(now - clock.last).count();
    clock.last = now;
    if (frame > 0) {
        clock.frame_ms.push_back(std::max(0.0, dt - clock.io_seconds) * 1000.0);
        if (clock.frame_ms.size() > kTimedFrames) clock.frame_ms.pop_front();
    }
    return dt;
}

namespace {

std::unique_ptr<PreviewWindow> open_preview_window(const PreviewOptions& o, const std::string& title) {
    const render::FrameDesc& f = o.frame;
    const int width = o.view == PreviewView::Anaglyph ? f.eye_width : 2 * f.eye_width;
    return value_or_throw(open_window(width, f.eye_height, title, o.vsync && !o.screenshots));
}

}  // namespace

void open_session(PreviewSession& s, PreviewOptions options) {
    s.options = std::move(options);
    const PreviewOptions& o = s.options;
    // The files read, against those --screenshots would write over.
    cli::CommandOutputs files;
    if (o.layout_path) files.input("the layout", *o.layout_path);
    if (o.path_file) files.input("--path", *o.path_file);
    if (o.hmd) files.input("--hmd", *o.hmd);
    declare_frame_files(files, o.screenshots);
    layout::Layout first = cli::load_layout_or_default(o.layout_path, files);
    if (o.path_file) s.path = value_or_throw(layout::read_path_frames_file(*o.path_file));
    s.files = open_frame_files(o.screenshots);

    s.title = "impossible preview - " + (first.name.empty() ? first.source : first.name);
    s.window = open_preview_window(o, s.title);
    s.state = std::make_unique<gl::StateCache>();
    s.shown = value_or_throw(build_shown(*s.state, std::move(first), "", o.frame));
    s.overlay = value_or_throw(build_overlay_program());
    s.presenter = value_or_throw(build_presenter());

    if (o.layout_path) s.watcher = watch_layout(*o.layout_path);
    s.physical = start_pose(s.shown.session->layout());
    if (!o.path_file) capture_cursor(*s.window, true);
    s.clock.last = s.clock.last_poll = s.clock.start = Clock::now();
}

void poll_reload(PreviewSession& s, Clock::time_point now) {
    if (!s.watcher || std::chrono::duration<double>(now - s.clock.last_poll).count() < kReloadPollSeconds) return;
    s.clock.last_poll = now;
    ReloadPoll r = poll_layout(*s.watcher);
    if (r.kind == ReloadPoll::Failed) s.reload_errors = r.errors;
    if (r.kind != ReloadPoll::Reloaded) return;
    const walk::Walker& walker = s.shown.driver->walker();
    const std::string room_id = s.shown.session->layout().rooms[walker.room()].id;
    const bool walking = walker.started();
    const math::dmat4 w = walker.physical_to_virtual();
    Result<Shown> built = build_shown(*s.state, std::move(*r.layout), room_id, s.options.frame);
    if (!built) {
        s.reload_errors = {"the reloaded layout cannot be drawn: " + built.error()};
        return;
    }
    Shown& next = *built;
    // Walk on where the head was: same room (if it still exists) and the
    // same physical-to-virtual mapping; the changes start over from the
    // reloaded layout's pairing.
    const int room = layout::find_room(next.session->layout(), room_id);
    if (walking && room >= 0) next.driver->resume(room, w, s.physical);
    s.shown = std::move(next);
    s.reload_errors.clear();
}

void reset_walk(PreviewSession& s) {
    // The changes start over too: the renderer draws the loaded pairing again.
    const bool paired = &s.shown.driver->session() != s.shown.session.get();
    s.shown.driver = std::make_unique<session::WalkDriver>(*s.shown.session, s.options.frame);
    if (paired)
        s.shown.renderer = std::make_unique<render::Renderer>(
            value_or_throw(s.shown.session->make_renderer(*s.state, s.shown.renderer->programs())));
    s.physical = start_pose(s.shown.session->layout());
}

}  // namespace impossible::preview
