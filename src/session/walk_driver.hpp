// The one walk driver: physical head (and hand) poses in, a walked frame out,
// as `walk` prints it and the library's and Python's Walker return it. The
// head is the walker's; the hands are mapped by its W and placed by walking
// from the head centre; moving props are walked to the frame's time
// (layout-format.md, "Head, eyes and walking"; cli.md, "Time, hands and
// lights"). A layout with `changes` is walked with the pairing in force
// (layout-format.md, "Changes while walking"): after each step the changes
// are considered (changes/change_walk.hpp) with the seen test on the frame's
// eyes, placed by the view options given (ipd, fov, size, headset, depth),
// and a change made swaps in the session of the new pairing.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "changes/change_walker.hpp"
#include "layout/path_file.hpp"
#include "session/session.hpp"
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"
#include "walk/replay.hpp"

namespace impossible::session {

struct WalkedHand {
    math::HeadPose virtual_pose;  // the physical hand mapped by W
    int room = -1;                // walked from the head centre; -1: none
};

struct WalkedProp {
    const std::string* id = nullptr;  // the prop's id (layout::prop_id), in the session's layout
    int room = -1;                    // its room at the frame's time
};

struct WalkedFrame {
    int room = -1;               // the head's room after the frame
    std::vector<int> teleports;  // the portals passed during it, in order (indices in the loaded layout)
    std::vector<int> changes;    // the changes made at this frame, in file order
    math::dvec3 position{0.0};   // the virtual head centre
    math::dvec3 forward{0.0};    // the virtual view direction
    math::HeadPose virtual_pose;
    std::optional<std::array<WalkedHand, 2>> hands;  // only for a frame walked with hands
    std::vector<WalkedProp> props;                   // each moving prop, in layout order, with a time
};

class WalkDriver {
public:
    // From the layout's start; the session must outlive the driver.
    // `view` holds the view options the seen test places the eyes by (its
    // head, room and time are the walk's); only read with changes.
    explicit WalkDriver(const Session& session, const math::View& view = {});
    // It keeps walks that point into its own object set.
    WalkDriver(const WalkDriver&) = delete;
    WalkDriver& operator=(const WalkDriver&) = delete;

    // One frame: the head, the hands if any, and with `time` the moving
    // props at that time (none when no prop moves). The changes' `time`
    // conditions read `time`, or frame / kDefaultPathFps without one.
    WalkedFrame step(const math::HeadPose& physical, const walk::HandPoses& hands = std::nullopt,
                     std::optional<double> time = std::nullopt);

    // The view options of the seen test from the next frame on (the
    // preview's keys change the IPD and the depth while it walks).
    void set_view(const math::View& view) { head_.set_view(view); }
    // Before the first step: the walk starts in `room` (the start room when
    // -1) instead of the start room.
    void start_in(int room);
    // Goes on with a walk begun by another walker (e.g. before the layout
    // was reloaded): its W and last physical pose, in `room` (as
    // walk::Walker::resume), with the pairing in force now.
    void resume(int room, const math::dmat4& physical_to_virtual, const math::HeadPose& physical);

    const walk::Walker& walker() const { return head_.walker(); }
    // The session with the pairing in force (the one given until a change
    // is made): what a frame of the walk is drawn with.
    const Session& session() const { return *current_; }
    // The changes' state; none without changes.
    const changes::ChangeWalk* changes() const { return has_changes_ ? &head_.changes() : nullptr; }
    // The last frame's seen test: whether it was asked, its portal passes
    // and its cost in seconds (a monotonic clock).
    bool seen_asked() const { return head_.seen_asked(); }
    int seen_passes() const { return head_.seen_passes(); }
    double seen_seconds() const { return head_.seen_seconds(); }

private:
    const walk::ObjectSet& objects();  // built at the first frame that needs it
    // After a change: the session of the new pairing, hands and props
    // walked with it from the next frame on.
    void follow_pairing();

    const Session* session_;
    std::shared_ptr<const Session> current_;  // session_ itself until a change is made
    changes::ChangeWalker head_;
    int generation_ = 0;  // head_'s pairing that current_ holds
    bool has_changes_ = false;
    bool moves_ = false;  // any_motion(layout)
    std::optional<walk::ObjectSet> objects_;
    std::vector<int> moving_;  // indices of objects_->props that move
    std::optional<walk::PropWalks> prop_walks_;
};

// Walks lines 0..line of a path (head, hands, time line / fps) from the
// layout's start as `walk` does, with the changes and the seen test on the
// eyes `view`'s options place, and sets view's head, room, hands and time
// to line `line`'s. Returns the session with the pairing in force at that
// line's picture: `session` itself without changes made. `line` must be
// below frames.size().
Session replay_to(const Session& session, math::View& view, const std::vector<layout::PathFrame>& frames,
                  std::size_t line, double fps);

// Whether any prop of the layout moves.
bool any_motion(const layout::Layout& layout);

}  // namespace impossible::session
