// A head walked with a layout's changes (layout-format.md, "Changes while
// walking"): the walker on the layout of the pairing in force, the changes
// considered after each step with the seen test on the eyes the view
// options place, and, when a change is made, the layout of the new pairing
// with a walker that goes on with the same W from the same physical pose.
// The one head walk with changes: session::WalkDriver (walk, render --path,
// the preview, the library, the headset page) adds hands, moving props and
// sessions around it; the designer's tour walks with it alone.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "changes/change_walk.hpp"
#include "changes/pairing.hpp"
#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/view.hpp"
#include "walk/walker.hpp"

namespace impossible::changes {

struct ChangeStep {
    std::vector<int> teleports;  // portals passed, indices in the loaded layout
    std::vector<int> changes;    // changes made at this frame, file order
};

class ChangeWalker {
public:
    // From the layout's start, with the seen test's view options `view`
    // (its head, room and time are the walk's; render's defaults unless
    // told). The layout must outlive this. `links`, when given, are the
    // layout's own (linked once elsewhere).
    explicit ChangeWalker(const layout::Layout& layout, const math::View& view = {},
                          std::shared_ptr<const links::PortalLinks> links = nullptr);
    ChangeWalker(const ChangeWalker&) = delete;
    ChangeWalker& operator=(const ChangeWalker&) = delete;

    // One frame: the head's step, then the changes at `time` (the changes'
    // `time` conditions; none: frame / layout::kDefaultPathFps).
    ChangeStep step(const math::HeadPose& physical, std::optional<double> time = std::nullopt);

    // The seen test's view options from the next frame on.
    void set_view(const math::View& view) { view_ = view; }
    // Before the first step: start in `room` (the start room when -1).
    void start_in(int room);
    // Goes on with a walk begun by another walker: its W and last physical
    // pose, in `room` (walk::Walker::resume), with the pairing in force.
    void resume(int room, const math::dmat4& physical_to_virtual, const math::HeadPose& physical);

    const walk::Walker& walker() const { return *walker_; }
    int room() const { return walker_->room(); }
    int frame() const { return frame_; }  // frames walked
    // The layout with the pairing in force and its links (shared: a
    // session may be made of them); base_index maps its portals to the
    // loaded layout's. Each change made gives new ones; generation() counts
    // them.
    const layout::Layout& current() const { return *current_; }
    const std::shared_ptr<const layout::Layout>& shared_current() const { return current_; }
    const links::PortalLinks& links() const { return *links_; }
    const std::shared_ptr<const links::PortalLinks>& shared_links() const { return links_; }
    const std::vector<int>& base_index() const { return base_index_; }
    int generation() const { return generation_; }
    const ChangeWalk& changes() const { return changes_; }
    const Pairing& pairing() const { return changes_.pairing(); }
    // The last frame's seen test: whether it ran (some armed change
    // waited), its portal passes and its time in seconds (a monotonic clock).
    bool seen_asked() const { return seen_asked_; }
    int seen_passes() const { return seen_passes_; }
    double seen_seconds() const { return seen_seconds_; }

private:
    std::vector<char> seen_doors();

    const layout::Layout* base_;
    math::View view_;
    ChangeWalk changes_;
    std::shared_ptr<const layout::Layout> current_;  // base_ itself (not owned) until a change is made
    std::shared_ptr<const links::PortalLinks> links_;
    std::vector<int> base_index_;
    std::unique_ptr<walk::Walker> walker_;
    int frame_ = 0;
    int generation_ = 0;
    bool seen_asked_ = false;
    int seen_passes_ = 0;
    double seen_seconds_ = 0.0;
};

// The rooms a walk of `poses` is in, in order of first visit, and the
// changes made (indices, in the order made), walked with ChangeWalker.
struct ChangeWalkResult {
    std::vector<int> rooms;
    std::vector<int> changes;
    std::vector<int> change_frames;  // the frame each of `changes` was made at
    int teleports = 0;
};
ChangeWalkResult walk_with_changes(const layout::Layout& layout, const std::vector<math::HeadPose>& poses,
                                   const math::View& view = {});

}  // namespace impossible::changes
