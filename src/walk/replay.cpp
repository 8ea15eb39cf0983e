#include "walk/replay.hpp"

namespace impossible::walk {

math::HeadPose virtual_pose(const math::dmat4& w, const math::HeadPose& physical) {
    const math::dvec3 position(w * math::dvec4(physical.position, 1.0));
    return math::head_pose_from(position, math::dmat3(w) * math::head_rotation(physical));
}

HandPoses virtual_hands(const math::dmat4& w, const HandPoses& physical) {
    if (!physical) return std::nullopt;
    return std::array<math::HeadPose, 2>{virtual_pose(w, (*physical)[0]), virtual_pose(w, (*physical)[1])};
}

void set_walked_view(math::View& view, const Walker& walker, const HandPoses& physical_hands) {
    view.head = math::head_pose_from(walker.position(), walker.rotation());
    view.room = walker.room();
    view.hands = virtual_hands(walker.physical_to_virtual(), physical_hands);
}

void replay_view(math::View& view, Walker& walker, const std::vector<layout::PathFrame>& frames, std::size_t line,
                 double fps) {
    for (std::size_t k = 0; k <= line && k < frames.size(); ++k) walker.step(frames[k].head);
    set_walked_view(view, walker, frames[line].hands);
    view.time = line_time(line, fps);
}

void set_replayed_view(math::View& view, const layout::Layout& layout, const std::vector<layout::PathFrame>& frames,
                       std::size_t line, double fps) {
    Walker walker(layout);
    replay_view(view, walker, frames, line, fps);
}

}  // namespace impossible::walk
