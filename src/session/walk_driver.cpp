#include "session/walk_driver.hpp"

#include <chrono>

#include "changes/seen.hpp"
#include "layout/path_file.hpp"

namespace impossible::session {

bool any_motion(const layout::Layout& layout) {
    for (const layout::Room& room : layout.rooms)
        for (const layout::Prop& prop : room.props)
            if (!layout::prop_motion(prop).keys.empty()) return true;
    return false;
}

namespace {

// A session that is not owned: the one the driver was given.
std::shared_ptr<const Session> borrowed(const Session& session) {
    return std::shared_ptr<const Session>(std::shared_ptr<const Session>(), &session);
}

}  // namespace

WalkDriver::WalkDriver(const Session& session, const math::View& view)
    : session_(&session),
      current_(borrowed(session)),
      view_(view),
      moves_(any_motion(session.layout())),
      walker_(session.make_walker()) {
    for (std::size_t k = 0; k < session.layout().portals.size(); ++k) base_index_.push_back(static_cast<int>(k));
    if (!session.layout().changes.empty()) changes_.emplace(session.layout());
}

void WalkDriver::start_in(int room) { walker_ = current_->make_walker(room); }

void WalkDriver::resume(int room, const math::dmat4& physical_to_virtual, const math::HeadPose& physical) {
    walker_ = current_->make_walker(room);
    walker_.resume(physical_to_virtual, physical);
}

std::vector<char> WalkDriver::seen_doors() {
    const auto start = std::chrono::steady_clock::now();
    math::View view = view_;
    walk::set_walked_view(view, walker_, std::nullopt);
    const changes::SeenPortals seen = changes::seen_portals(current_->layout(), current_->links(), view);
    seen_passes_ = seen.passes;
    std::vector<char> base(session_->layout().portals.size(), 0);
    for (std::size_t k = 0; k < seen.seen.size(); ++k)
        if (seen.seen[k]) base[static_cast<std::size_t>(base_index_[k])] = 1;
    seen_asked_ = true;
    seen_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return base;
}

std::vector<int> WalkDriver::consider_changes(double time) {
    seen_asked_ = false;
    seen_passes_ = 0;
    seen_seconds_ = 0.0;
    if (!changes_ || !changes_->pending()) return {};
    const std::vector<int> made = changes_->consider(frame_, walker_.room(), time, [this] { return seen_doors(); });
    if (made.empty()) return made;
    changes::PairedLayout paired = changes::paired_layout(session_->layout(), changes_->pairing());
    base_index_ = std::move(paired.base_index);
    current_ = std::make_shared<const Session>(std::move(paired.layout));
    const math::dmat4 w = walker_.physical_to_virtual();
    const math::HeadPose physical = walker_.physical_pose();
    resume(walker_.room(), w, physical);
    // Hands and props walk with the new pairing from the next frame on.
    objects_.reset();
    moving_.clear();
    prop_walks_.reset();
    return made;
}

const walk::ObjectSet& WalkDriver::objects() {
    if (!objects_) {
        objects_ = walk::build_object_set(current_->layout(), current_->links());
        for (std::size_t k = 0; k < objects_->props.size(); ++k)
            if (!objects_->props[k].motion.keys.empty()) moving_.push_back(static_cast<int>(k));
        // The walks are kept from frame to frame: each walks only the keys
        // passed since (the frames' times only grow).
        prop_walks_.emplace(*objects_);
    }
    return *objects_;
}

WalkedFrame WalkDriver::step(const math::HeadPose& physical, const walk::HandPoses& hands, std::optional<double> time) {
    WalkedFrame f;
    f.teleports = walker_.step(physical);
    for (int& t : f.teleports) t = base_index_[static_cast<std::size_t>(t)];
    f.room = walker_.room();
    f.position = walker_.position();
    f.forward = walker_.forward();
    f.virtual_pose = math::head_pose_from(f.position, walker_.rotation());
    if (hands) {
        const walk::ObjectSet& set = objects();
        std::array<WalkedHand, 2> placed;
        for (std::size_t h = 0; h < 2; ++h) {
            placed[h].virtual_pose = walk::virtual_pose(walker_.physical_to_virtual(), (*hands)[h]);
            placed[h].room = walk::place_hand(set, f.room, f.position, placed[h].virtual_pose).room;
        }
        f.hands = placed;
    }
    if (time && moves_) {
        const walk::ObjectSet& set = objects();
        const layout::Layout& layout = session_->layout();  // the same rooms and props as current_'s
        for (const int m : moving_) {
            const walk::DynamicProp& p = set.props[static_cast<std::size_t>(m)];
            const layout::Prop& prop =
                layout.rooms[static_cast<std::size_t>(p.room)].props[static_cast<std::size_t>(p.index)];
            f.props.push_back({&layout::prop_id(prop), prop_walks_->at(m, *time).room});
        }
    }
    f.changes = consider_changes(time.value_or(static_cast<double>(frame_) / layout::kDefaultPathFps));
    ++frame_;
    return f;
}

Session replay_to(const Session& session, math::View& view, const std::vector<layout::PathFrame>& frames,
                  std::size_t line, double fps) {
    WalkDriver driver(session, view);
    const bool moves = any_motion(session.layout());
    for (std::size_t k = 0; k <= line && k < frames.size(); ++k)
        driver.step(frames[k].head, std::nullopt,
                    moves || driver.changes() ? std::optional(walk::line_time(k, fps)) : std::nullopt);
    walk::set_walked_view(view, driver.walker(), frames[line].hands);
    view.time = walk::line_time(line, fps);
    return driver.session();
}

}  // namespace impossible::session
