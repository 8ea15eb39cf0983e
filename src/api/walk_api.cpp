// impossible::api::Walker and walk: physical head poses through the doors.
#include <cmath>
#include <optional>

#include "api/api_data.hpp"
#include "layout/path_file.hpp"
#include "session/walk_driver.hpp"

namespace impossible::api {

struct WalkerData {
    explicit WalkerData(const Layout& l) : layout(l), driver(layout.data().session) {}
    Layout layout;  // the driver reads its session; declared first, so it outlives the driver
    session::WalkDriver driver;
};

Walker::Walker(const Layout& layout) : data_(std::make_unique<WalkerData>(layout)) {}
Walker::Walker(Walker&&) noexcept = default;
Walker& Walker::operator=(Walker&&) noexcept = default;
Walker::~Walker() = default;

namespace {

std::string room_id(const layout::Layout& l, int room) {
    return room >= 0 && static_cast<std::size_t>(room) < l.rooms.size() ? l.rooms[room].id : "";
}

WalkStep step_of(const layout::Layout& l, const session::WalkedFrame& f) {
    WalkStep s;
    s.room = room_id(l, f.room);
    for (const int p : f.teleports) s.teleports.push_back(l.portals[p].id);
    for (int k = 0; k < 3; ++k) {
        s.position[k] = f.position[k];
        s.forward[k] = f.forward[k];
    }
    s.virtual_pose = to_pose(f.virtual_pose);
    if (f.hands) {
        std::array<WalkHand, 2> hands;
        for (std::size_t h = 0; h < 2; ++h)
            hands[h] = {to_pose((*f.hands)[h].virtual_pose), room_id(l, (*f.hands)[h].room)};
        s.hands = hands;
    }
    for (const session::WalkedProp& p : f.props) s.props.emplace_back(*p.id, room_id(l, p.room));
    return s;
}

}  // namespace

WalkStep Walker::step(const Pose& physical) {
    return step_of(data_->layout.data().layout, data_->driver.step(to_head_pose(physical)));
}

WalkStep Walker::step(const Pose& physical, const std::array<Pose, 2>& hands) {
    const walk::HandPoses h = std::array<math::HeadPose, 2>{to_head_pose(hands[0]), to_head_pose(hands[1])};
    return step_of(data_->layout.data().layout, data_->driver.step(to_head_pose(physical), h));
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

Expected<std::vector<PathLine>> read_path_lines(const std::string& path) {
    return no_throw([&]() -> Expected<std::vector<PathLine>> {
        const layout::PathFrames file = layout::read_path_frames_file(path);
        if (!file) return Error{file.error()};
        std::vector<PathLine> lines;
        lines.reserve(file->size());
        for (const layout::PathFrame& f : *file) {
            PathLine line{to_pose(f.head), std::nullopt};
            if (f.hands) line.hands = std::array<Pose, 2>{to_pose((*f.hands)[0]), to_pose((*f.hands)[1])};
            lines.push_back(line);
        }
        return lines;
    });
}

std::vector<WalkStep> walk(const Layout& layout, const std::vector<Pose>& physical) {
    Walker walker(layout);
    std::vector<WalkStep> steps;
    steps.reserve(physical.size());
    for (const Pose& p : physical) steps.push_back(walker.step(p));
    return steps;
}

std::vector<WalkStep> walk(const Layout& layout, const std::vector<PathLine>& physical) {
    Walker walker(layout);
    std::vector<WalkStep> steps;
    steps.reserve(physical.size());
    for (const PathLine& p : physical) steps.push_back(p.hands ? walker.step(p.head, *p.hands) : walker.step(p.head));
    return steps;
}

std::vector<WalkStep> walk(const Layout& layout, const std::vector<PathLine>& physical, double fps) {
    // Moving props at line k / fps (a non-positive or infinite fps: time 0).
    const bool timed = fps > 0.0 && std::isfinite(fps);
    session::WalkDriver driver(layout.data().session);
    std::vector<WalkStep> steps;
    steps.reserve(physical.size());
    for (std::size_t k = 0; k < physical.size(); ++k) {
        walk::HandPoses hands;
        if (physical[k].hands)
            hands = std::array<math::HeadPose, 2>{to_head_pose((*physical[k].hands)[0]),
                                                  to_head_pose((*physical[k].hands)[1])};
        const double time = timed ? static_cast<double>(k) / fps : 0.0;
        steps.push_back(step_of(layout.data().layout, driver.step(to_head_pose(physical[k].head), hands, time)));
    }
    return steps;
}

}  // namespace impossible::api
