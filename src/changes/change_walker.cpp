#include "changes/change_walker.hpp"

#include <algorithm>
#include <chrono>

#include "changes/seen.hpp"
#include "layout/path_file.hpp"
#include "walk/replay.hpp"

namespace impossible::changes {

ChangeWalker::ChangeWalker(const layout::Layout& layout, const math::View& view,
                           std::shared_ptr<const links::PortalLinks> links)
    : base_(&layout),
      view_(view),
      changes_(layout),
      current_(std::shared_ptr<const layout::Layout>(), &layout),
      links_(links ? std::move(links) : std::make_shared<const links::PortalLinks>(links::link_portals(layout))) {
    for (std::size_t k = 0; k < layout.portals.size(); ++k) base_index_.push_back(static_cast<int>(k));
    walker_ = std::make_unique<walk::Walker>(*current_, layout.start.room, links_);
}

void ChangeWalker::start_in(int room) {
    walker_ = std::make_unique<walk::Walker>(*current_, room >= 0 ? room : base_->start.room, links_);
}

void ChangeWalker::resume(int room, const math::dmat4& physical_to_virtual, const math::HeadPose& physical) {
    start_in(room);
    walker_->resume(physical_to_virtual, physical);
}

std::vector<char> ChangeWalker::seen_doors() {
    const auto start = std::chrono::steady_clock::now();
    math::View view = view_;
    walk::set_walked_view(view, *walker_, std::nullopt);
    const SeenPortals seen = seen_portals(*current_, *links_, view);
    std::vector<char> base(base_->portals.size(), 0);
    for (std::size_t k = 0; k < seen.seen.size(); ++k)
        if (seen.seen[k]) base[static_cast<std::size_t>(base_index_[k])] = 1;
    seen_asked_ = true;
    seen_passes_ = seen.passes;
    seen_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return base;
}

ChangeStep ChangeWalker::step(const math::HeadPose& physical, std::optional<double> time) {
    ChangeStep out;
    out.teleports = walker_->step(physical);
    for (int& t : out.teleports) t = base_index_[static_cast<std::size_t>(t)];
    seen_asked_ = false;
    seen_passes_ = 0;
    seen_seconds_ = 0.0;
    if (changes_.pending())
        out.changes = changes_.consider(frame_, walker_->room(),
                                        time.value_or(static_cast<double>(frame_) / layout::kDefaultPathFps),
                                        [this] { return seen_doors(); });
    ++frame_;
    if (out.changes.empty()) return out;
    // The new pairing: a new layout, its links and a walker that goes on
    // with the same W from the same physical pose.
    PairedLayout next = paired_layout(*base_, changes_.pairing());
    const math::dmat4 w = walker_->physical_to_virtual();
    const math::HeadPose pose = walker_->physical_pose();
    const int room = walker_->room();
    base_index_ = std::move(next.base_index);
    current_ = std::make_shared<const layout::Layout>(std::move(next.layout));
    links_ = std::make_shared<const links::PortalLinks>(links::link_portals(*current_));
    resume(room, w, pose);
    ++generation_;
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

}  // namespace impossible::changes
