// impossible::api::Walker and walk: physical head poses through the doors.
#include "api/api_data.hpp"
#include "layout/path_file.hpp"
#include "walk/walker.hpp"

namespace impossible::api {

struct WalkerData {
    explicit WalkerData(const Layout& l) : layout(l), walker(layout.data().layout) {}
    Layout layout;  // the walker reads it; declared first, so it outlives the walker
    walk::Walker walker;
};

Walker::Walker(const Layout& layout) : data_(std::make_unique<WalkerData>(layout)) {}
Walker::Walker(Walker&&) noexcept = default;
Walker& Walker::operator=(Walker&&) noexcept = default;
Walker::~Walker() = default;

WalkStep Walker::step(const Pose& physical) {
    const layout::Layout& l = data_->layout.data().layout;
    walk::Walker& w = data_->walker;
    const std::vector<int> passed = w.step(to_head_pose(physical));
    WalkStep s;
    s.room = w.room() >= 0 && static_cast<std::size_t>(w.room()) < l.rooms.size() ? l.rooms[w.room()].id : "";
    for (const int p : passed) s.teleports.push_back(l.portals[p].id);
    const math::dvec3 position = w.position(), forward = w.forward();
    for (int k = 0; k < 3; ++k) {
        s.position[k] = position[k];
        s.forward[k] = forward[k];
    }
    s.virtual_pose = to_pose(math::head_pose_from(position, w.rotation()));
    return s;
}

Expected<std::vector<Pose>> read_path(const std::string& path) {
    return no_throw([&]() -> Expected<std::vector<Pose>> {
        const layout::PathFile file = layout::read_path_file(path);
        if (!file) return Error{file.error()};
        std::vector<Pose> poses;
        poses.reserve(file->size());
        for (const math::HeadPose& h : *file) poses.push_back(to_pose(h));
        return poses;
    });
}

std::vector<WalkStep> walk(const Layout& layout, const std::vector<Pose>& physical) {
    Walker walker(layout);
    std::vector<WalkStep> steps;
    steps.reserve(physical.size());
    for (const Pose& p : physical) steps.push_back(walker.step(p));
    return steps;
}

}  // namespace impossible::api
