// impossible::api::Walker and walk: physical head poses through the doors.
#include <cmath>
#include <optional>

#include "api/api_data.hpp"
#include "layout/path_file.hpp"
#include "session/walk_driver.hpp"

namespace impossible::api {

namespace {

// The view options of the seen test: `view` without its pose, room and
// hands (the walk's head places the eyes), checked as Renderer's.
Result<math::View> seen_view(const Layout& layout, View view) {
    view.pose.reset();
    view.room.clear();
    view.hands.reset();
    return resolve_view(layout.data().layout, view);
}

}  // namespace

struct WalkerData {
    WalkerData(const Layout& l, const math::View& view) : layout(l), driver(layout.data().session, view) {}
    Layout layout;  // the driver reads its session; declared first, so it outlives the driver
    session::WalkDriver driver;
    std::optional<Layout> paired;  // layout of driver.session(), made when asked; reset by a change
};

Walker::Walker(const Layout& layout)
    : data_(std::make_unique<WalkerData>(layout, *seen_view(layout, View{}))) {}  // the defaults are valid
Walker::Walker(std::unique_ptr<WalkerData> data) : data_(std::move(data)) {}
Walker::Walker(Walker&&) noexcept = default;
Walker& Walker::operator=(Walker&&) noexcept = default;
Walker::~Walker() = default;

Expected<Walker> Walker::make(const Layout& layout, const View& view) {
    return no_throw([&]() -> Expected<Walker> {
        const Result<math::View> v = seen_view(layout, view);
        if (!v) return Error{v.error()};
        return Walker(std::make_unique<WalkerData>(layout, *v));
    });
}

Layout Walker::layout() const {
    if (!data_->paired) data_->paired = paired_layout_of(data_->layout, data_->driver.session());
    return *data_->paired;
}

std::vector<ChangeState> Walker::changes() const {
    std::vector<ChangeState> states;
    const changes::ChangeWalk* walk = data_->driver.changes();
    if (walk == nullptr) return states;
    const layout::Layout& l = data_->layout.data().layout;
    for (std::size_t c = 0; c < l.changes.size(); ++c)
        states.push_back({l.changes[c].id, walk->status()[c].armed, walk->status()[c].made_frame});
    return states;
}

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
    for (const int c : f.changes) s.changes.push_back(l.changes[static_cast<std::size_t>(c)].id);
    return s;
}

}  // namespace

namespace {

WalkStep walker_step(WalkerData& data, const Pose& physical, const walk::HandPoses& hands) {
    const session::WalkedFrame f = data.driver.step(to_head_pose(physical), hands);
    if (!f.changes.empty()) data.paired.reset();
    return step_of(data.layout.data().layout, f);
}

}  // namespace

WalkStep Walker::step(const Pose& physical) { return walker_step(*data_, physical, std::nullopt); }

WalkStep Walker::step(const Pose& physical, const std::array<Pose, 2>& hands) {
    return walker_step(*data_, physical, std::array<math::HeadPose, 2>{to_head_pose(hands[0]), to_head_pose(hands[1])});
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

namespace {

walk::HandPoses hands_of(const PathLine& line) {
    if (!line.hands) return std::nullopt;
    return std::array<math::HeadPose, 2>{to_head_pose((*line.hands)[0]), to_head_pose((*line.hands)[1])};
}

std::vector<WalkStep> timed_walk(const Layout& layout, const std::vector<PathLine>& physical, double fps,
                                 const math::View& view) {
    // Moving props at line k / fps (a non-positive or infinite fps: time 0).
    const bool timed = fps > 0.0 && std::isfinite(fps);
    session::WalkDriver driver(layout.data().session, view);
    std::vector<WalkStep> steps;
    steps.reserve(physical.size());
    for (std::size_t k = 0; k < physical.size(); ++k) {
        const double time = timed ? static_cast<double>(k) / fps : 0.0;
        steps.push_back(
            step_of(layout.data().layout, driver.step(to_head_pose(physical[k].head), hands_of(physical[k]), time)));
    }
    return steps;
}

}  // namespace

std::vector<WalkStep> walk(const Layout& layout, const std::vector<PathLine>& physical, double fps) {
    return timed_walk(layout, physical, fps, *seen_view(layout, View{}));
}

Expected<std::vector<WalkStep>> walk(const Layout& layout, const std::vector<PathLine>& physical, double fps,
                                     const View& view) {
    return no_throw([&]() -> Expected<std::vector<WalkStep>> {
        const Result<math::View> v = seen_view(layout, view);
        if (!v) return Error{v.error()};
        return timed_walk(layout, physical, fps, *v);
    });
}

Expected<Layout> paired_at(const Layout& layout, const std::vector<PathLine>& physical, std::size_t frame, double fps,
                           const View& view) {
    return no_throw([&]() -> Expected<Layout> {
        if (frame >= physical.size())
            return Error{"frame " + std::to_string(frame) + " is past the path's end (" +
                         std::to_string(physical.size()) + " lines)"};
        if (!(fps > 0.0 && std::isfinite(fps))) return Error{"fps must be above 0 and finite"};
        Result<math::View> v = seen_view(layout, view);
        if (!v) return Error{v.error()};
        std::vector<layout::PathFrame> frames;
        frames.reserve(frame + 1);
        for (std::size_t k = 0; k <= frame; ++k)
            frames.push_back({to_head_pose(physical[k].head), hands_of(physical[k])});
        return paired_layout_of(layout, session::replay_to(layout.data().session, *v, frames, frame, fps));
    });
}

}  // namespace impossible::api
