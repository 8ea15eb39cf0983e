// The walker (see walk.hpp).
#include "walk/walker.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "math/crossing.hpp"
#include "math/eyes.hpp"
#include "math/portal.hpp"
#include "math/rigid.hpp"

namespace impossible::walk {

namespace {

math::dvec3 apply(const math::dmat4& m, const math::dvec3& p) { return math::dvec3(m * math::dvec4(p, 1.0)); }

}  // namespace

Walker::Walker(const layout::Layout& layout) : Walker(layout, layout.start.room) {}

Walker::Walker(const layout::Layout& layout, int room)
    : Walker(layout, room, std::make_shared<const links::PortalLinks>(links::link_portals(layout))) {}

Walker::Walker(const layout::Layout& layout, int room, std::shared_ptr<const links::PortalLinks> links)
    : layout_(&layout), links_(std::move(links)), room_(room) {
    head_ = layout.start.position;
    physical_pose_.position = layout.start.position;
    physical_pose_.yaw_deg = layout.start.yaw_deg;
    physical_rotation_ = math::head_rotation(physical_pose_);
}

void Walker::resume(const math::dmat4& physical_to_virtual, const math::HeadPose& physical) {
    w_ = physical_to_virtual;
    physical_pose_ = physical;
    physical_rotation_ = math::head_rotation(physical);
    head_ = apply(w_, physical.position);
    started_ = true;
    history_.clear();
}

std::vector<int> Walker::step(const math::HeadPose& physical) {
    std::vector<int> passed;
    physical_pose_ = physical;
    physical_rotation_ = math::head_rotation(physical);
    math::dvec3 end = apply(w_, physical.position);
    if (!started_) {
        started_ = true;
        head_ = end;
        return passed;
    }

    math::dvec3 begin = head_;
    int exclude = -1;  // the portal just come out of
    while (static_cast<int>(passed.size()) < kMaxCrossingsPerFrame &&
           links::valid_index(room_, links_->room_portals.size())) {
        int best = -1;
        math::SegmentCrossing best_crossing;
        for (int i : links_->room_portals[room_]) {
            // Only doors teleport: the head passes a mirror's or a window's
            // plane as it passes any wall, and stays where it is.
            if (i == exclude || layout_->portals[i].kind != layout::PortalKind::Door) continue;
            const auto c = math::segment_crossing(layout_->portals[i].rect, begin, end);
            // Strict '<': on an exact tie the portal listed first keeps it.
            if (c && (best < 0 || c->t < best_crossing.t)) {
                best = i;
                best_crossing = *c;
            }
        }
        if (best < 0) break;

        const int target = layout_->portals[best].target;
        const math::PortalRect& out = layout_->portals[target].rect;
        teleport(best);
        room_ = layout_->portals[target].room;
        begin = apply(links_->transfer[best], best_crossing.point);
        end = apply(w_, physical.position);
        // Strictly in front of B, whatever rounding did (a couple of rounds
        // at most: the first lands within a few ulps of the target distance).
        const double margin = 1e-9 * (1.0 + glm::length(out.center));
        for (int k = 0; k < 4; ++k) {
            const double d = math::signed_distance(out, end);
            if (d > 0.0) break;
            w_[3] += math::dvec4((margin - d) * out.normal, 0.0);
            end = apply(w_, physical.position);
        }
        passed.push_back(best);
        exclude = target;
    }
    head_ = end;
    return passed;
}

void Walker::teleport(int portal) {
    if (!history_.empty() && layout_->portals[history_.back().portal].target == portal) {
        w_ = history_.back().w_before;  // back through the pair just passed
        history_.pop_back();
        return;
    }
    history_.push_back(Passed{portal, w_});
    if (history_.size() > kHistoryLength) history_.pop_front();
    w_ = math::orthonormalize_rigid(links_->transfer[portal] * w_);
}

math::dmat3 Walker::rotation() const { return math::dmat3(w_) * physical_rotation_; }

math::dvec3 Walker::forward() const { return math::forward_of(rotation()); }

std::array<math::Eye, 2> Walker::eyes(double ipd) const {
    const auto e = math::eyes_of(physical_pose_, ipd);
    return {math::transform_eye(w_, e[0]), math::transform_eye(w_, e[1])};
}

std::array<math::Eye, 2> Walker::eyes(const std::array<math::EyeOffset, 2>& offsets) const {
    const auto e = math::eyes_of(physical_pose_, offsets);
    return {math::transform_eye(w_, e[0]), math::transform_eye(w_, e[1])};
}

}  // namespace impossible::walk
