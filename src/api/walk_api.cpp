// impossible::api::Walker and walk: physical head poses through the doors.
#include <cmath>
#include <optional>

#include "api/api_data.hpp"
#include "layout/path_file.hpp"
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"
#include "walk/replay.hpp"
#include "walk/walker.hpp"

namespace impossible::api {

struct WalkerData {
    explicit WalkerData(const Layout& l) : layout(l), walker(layout.data().session.make_walker()) {}
    Layout layout;  // the walker reads it; declared first, so it outlives the walker
    walk::Walker walker;
    std::optional<walk::ObjectSet> objects;  // made at the first step with hands (walk::place_hand)
};

Walker::Walker(const Layout& layout) : data_(std::make_unique<WalkerData>(layout)) {}
Walker::Walker(Walker&&) noexcept = default;
Walker& Walker::operator=(Walker&&) noexcept = default;
Walker::~Walker() = default;

namespace {

std::string room_id(const layout::Layout& l, int room) {
    return room >= 0 && static_cast<std::size_t>(room) < l.rooms.size() ? l.rooms[room].id : "";
}

}  // namespace

WalkStep Walker::step(const Pose& physical) {
    const layout::Layout& l = data_->layout.data().layout;
    walk::Walker& w = data_->walker;
    const std::vector<int> passed = w.step(to_head_pose(physical));
    WalkStep s;
    s.room = room_id(l, w.room());
    for (const int p : passed) s.teleports.push_back(l.portals[p].id);
    const math::dvec3 position = w.position(), forward = w.forward();
    for (int k = 0; k < 3; ++k) {
        s.position[k] = position[k];
        s.forward[k] = forward[k];
    }
    s.virtual_pose = to_pose(math::head_pose_from(position, w.rotation()));
    return s;
}

WalkStep Walker::step(const Pose& physical, const std::array<Pose, 2>& hands) {
    WalkStep s = step(physical);
    const layout::Layout& l = data_->layout.data().layout;
    const walk::Walker& w = data_->walker;
    if (!data_->objects) data_->objects = walk::build_object_set(l, w.links());
    std::array<WalkHand, 2> out;
    for (std::size_t h = 0; h < 2; ++h) {
        const math::HeadPose hand = walk::virtual_pose(w.physical_to_virtual(), to_head_pose(hands[h]));
        out[h].virtual_pose = to_pose(hand);
        out[h].room = room_id(l, walk::place_hand(*data_->objects, w.room(), w.position(), hand).room);
    }
    s.hands = out;
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
    std::vector<WalkStep> steps = walk(layout, physical);
    const layout::Layout& l = layout.data().layout;
    const walk::ObjectSet set = walk::build_object_set(l, layout.data().session.links());
    std::vector<int> moving;  // indices of set.props
    for (std::size_t k = 0; k < set.props.size(); ++k)
        if (!set.props[k].motion.keys.empty()) moving.push_back(static_cast<int>(k));
    if (moving.empty()) return steps;
    walk::PropWalks walks(set);
    const bool timed = fps > 0.0 && std::isfinite(fps);
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const double time = timed ? static_cast<double>(k) / fps : 0.0;
        for (const int m : moving) {
            const walk::DynamicProp& p = set.props[static_cast<std::size_t>(m)];
            const std::string& id =
                layout::prop_id(l.rooms[static_cast<std::size_t>(p.room)].props[static_cast<std::size_t>(p.index)]);
            steps[k].props.emplace_back(id, room_id(l, walks.at(m, time).room));
        }
    }
    return steps;
}

}  // namespace impossible::api
