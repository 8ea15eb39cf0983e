// The preview's state while it runs: the options as the keys change them,
// the window, the layout shown and what draws it, live reload, the physical
// head and the frame clock; and the steps that open it and keep the layout
// current. run_preview_command (preview_command.cpp) drives it frame by frame.
#pragma once

#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "gl/state.hpp"
#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "math/pose.hpp"
#include "preview/frames_log.hpp"
#include "preview/options.hpp"
#include "preview/overlay.hpp"
#include "preview/present.hpp"
#include "preview/reload.hpp"
#include "preview/window.hpp"
#include "render/frame.hpp"
#include "render/renderer.hpp"
#include "session/session.hpp"
#include "session/walk_driver.hpp"
#include "walk/replay.hpp"
#include "walk/walker.hpp"

namespace impossible::preview {

using Clock = std::chrono::steady_clock;

inline constexpr std::size_t kTimedFrames = 60;  // frames in the HUD's median
inline constexpr double kReloadPollSeconds = 0.25;

// The layout being shown (its session) and what is built from it. The walk
// driver points into the session, so both live on the heap and are replaced
// together. The driver walks with the layout's changes (layout-format.md,
// "Changes while walking"), and a change made swaps its session for one of
// the new pairing: the renderer is then rebuilt from that one.
struct Shown {
    std::unique_ptr<session::Session> session;  // the layout as loaded
    std::unique_ptr<session::WalkDriver> driver;
    std::unique_ptr<render::Renderer> renderer;  // of driver->session()
};

// Builds the renderer and a walk driver for `layout`, in the room named
// `room_id` if it still exists (else the start room), whose seen test
// places the eyes by `eyes` (the options' frame). Needs a current GL
// context, whose state cache is `state`.
Result<Shown> build_shown(gl::StateCache& state, layout::Layout layout, const std::string& room_id,
                          const math::View& eyes);

// One frame's walk: the physical head at `time` (the changes' `time`
// conditions read it), the seen test on the eyes `eyes` places; when it
// makes changes, the renderer is rebuilt for the new pairing. Returns the
// walked frame (teleports and changes index the loaded layout's).
session::WalkedFrame walk_shown(Shown& shown, gl::StateCache& state, const math::HeadPose& physical, double time,
                                const math::View& eyes);

// The layout's start as a physical head pose.
math::HeadPose start_pose(const layout::Layout& layout);

// Frame times for the HUD, without the time spent saving files.
struct FrameClock {
    Clock::time_point last{}, last_poll{};
    Clock::time_point start{};    // the preview's time 0 for moving props (without --path)
    std::deque<double> frame_ms;  // the last kTimedFrames frames
    double io_seconds = 0.0;      // spent writing files last frame
};

// Seconds since the last tick; from frame 1 on, also records the frame time.
double tick(FrameClock& clock, long frame, Clock::time_point now);

struct PreviewSession {
    PreviewOptions options;
    std::string title;
    std::vector<layout::PathFrame> path;  // --path: one physical pose (and hands) a frame
    FrameFiles files;
    std::unique_ptr<PreviewWindow> window;  // declared before the GL objects: outlives them
    // The window context's one state cache, for the renderer, the present
    // and the overlays alike; declared before everything that draws with it.
    std::unique_ptr<gl::StateCache> state;
    Shown shown;
    OverlayProgram overlay;
    Presenter presenter;
    std::optional<LayoutWatcher> watcher;    // with a layout file
    std::vector<std::string> reload_errors;  // of the last failed reload
    math::HeadPose physical;
    walk::HandPoses physical_hands;  // this frame's: the path's line's, or G's (held_hands)
    FrameClock clock;
    render::FrameStats stats;
};

// Checks what can be checked without a window (the layout, the path file, the
// screenshot directory), then opens the window and builds what draws.
// Throws InputError.
void open_session(PreviewSession& session, PreviewOptions options);

// Every kReloadPollSeconds: a good edit of the layout replaces what is shown
// (the walk goes on in the same room with the same mapping), a bad one
// leaves its errors in session.reload_errors.
void poll_reload(PreviewSession& session, Clock::time_point now);

// R: a new walk from the layout's start.
void reset_walk(PreviewSession& session);

}  // namespace impossible::preview
