// A head walked with a layout's changes (layout-format.md, "Changes while
// walking"), for the designer's tools, which sit below session/: the head
// only (no hands, no moving props), the changes considered after each step
// at time frame / fps with the seen test on the eyes `view`'s options place
// (render's defaults unless told), as session::WalkDriver does for `walk`.
// `tour` plans with it, and its tests replay a tour's poses with it.
#pragma once

#include <memory>
#include <vector>

#include "changes/change_walk.hpp"
#include "changes/pairing.hpp"
#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "links/portal_links.hpp"
#include "math/view.hpp"
#include "walk/walker.hpp"

namespace impossible::design {

struct ChangeStep {
    std::vector<int> teleports;  // portals passed, indices in the loaded layout
    std::vector<int> changes;    // changes made at this frame, file order
};

class ChangeWalker {
public:
    // From the layout's start; the layout must outlive this.
    explicit ChangeWalker(const layout::Layout& layout, const math::View& view = {},
                          double fps = layout::kDefaultPathFps);
    ChangeWalker(const ChangeWalker&) = delete;
    ChangeWalker& operator=(const ChangeWalker&) = delete;

    ChangeStep step(const math::HeadPose& physical);

    const walk::Walker& walker() const { return *walker_; }
    int room() const { return walker_->room(); }
    int frame() const { return frame_; }  // frames walked
    // The layout with the pairing in force and its links; base_index maps
    // its portals to the loaded layout's.
    const layout::Layout& current() const { return current_->layout; }
    const links::PortalLinks& links() const { return *links_; }
    const std::vector<int>& base_index() const { return current_->base_index; }
    const changes::ChangeWalk& changes() const { return changes_; }
    const changes::Pairing& pairing() const { return changes_.pairing(); }

private:
    std::vector<char> seen_doors() const;

    const layout::Layout* base_;
    math::View view_;
    double fps_;
    changes::ChangeWalk changes_;
    std::unique_ptr<changes::PairedLayout> current_;
    std::shared_ptr<const links::PortalLinks> links_;
    std::unique_ptr<walk::Walker> walker_;
    int frame_ = 0;
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

}  // namespace impossible::design
