// A head walked with the changes, session-free; see change_walker.hpp.
#include "design/change_walker.hpp"

#include <algorithm>

#include "changes/seen.hpp"
#include "walk/replay.hpp"

namespace impossible::design {

ChangeWalker::ChangeWalker(const layout::Layout& layout, const math::View& view, double fps)
    : base_(&layout), view_(view), fps_(fps), changes_(layout) {
    current_ = std::make_unique<changes::PairedLayout>(changes::paired_layout(layout, changes_.pairing()));
    links_ = std::make_shared<const links::PortalLinks>(links::link_portals(current_->layout));
    walker_ = std::make_unique<walk::Walker>(current_->layout, layout.start.room, links_);
}

std::vector<char> ChangeWalker::seen_doors() const {
    math::View view = view_;
    walk::set_walked_view(view, *walker_, std::nullopt);
    const changes::SeenPortals seen = changes::seen_portals(current_->layout, *links_, view);
    std::vector<char> base(base_->portals.size(), 0);
    for (std::size_t k = 0; k < seen.seen.size(); ++k)
        if (seen.seen[k]) base[static_cast<std::size_t>(current_->base_index[k])] = 1;
    return base;
}

ChangeStep ChangeWalker::step(const math::HeadPose& physical) {
    ChangeStep out;
    out.teleports = walker_->step(physical);
    for (int& t : out.teleports) t = current_->base_index[static_cast<std::size_t>(t)];
    if (changes_.pending())
        out.changes = changes_.consider(frame_, walker_->room(), static_cast<double>(frame_) / fps_,
                                        [this] { return seen_doors(); });
    ++frame_;
    if (out.changes.empty()) return out;
    // The new pairing: a new layout, its links and a walker that goes on
    // with the same W from the same physical pose.
    auto next = std::make_unique<changes::PairedLayout>(changes::paired_layout(*base_, changes_.pairing()));
    auto links = std::make_shared<const links::PortalLinks>(links::link_portals(next->layout));
    auto walker = std::make_unique<walk::Walker>(next->layout, walker_->room(), links);
    walker->resume(walker_->physical_to_virtual(), walker_->physical_pose());
    walker_ = std::move(walker);
    links_ = std::move(links);
    current_ = std::move(next);
    return out;
}

ChangeWalkResult walk_with_changes(const layout::Layout& layout, const std::vector<math::HeadPose>& poses,
                                   const math::View& view) {
    ChangeWalkResult r;
    ChangeWalker walker(layout, view);
    for (const math::HeadPose& pose : poses) {
        const ChangeStep s = walker.step(pose);
        r.teleports += static_cast<int>(s.teleports.size());
        for (const int c : s.changes) {
            r.changes.push_back(c);
            r.change_frames.push_back(walker.frame() - 1);
        }
        if (std::find(r.rooms.begin(), r.rooms.end(), walker.room()) == r.rooms.end()) r.rooms.push_back(walker.room());
    }
    return r;
}

}  // namespace impossible::design
