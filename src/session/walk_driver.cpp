#include "session/walk_driver.hpp"

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
      head_(session.layout(), view, session.shared_links()),
      has_changes_(!session.layout().changes.empty()),
      moves_(any_motion(session.layout())) {}

void WalkDriver::start_in(int room) { head_.start_in(room); }

void WalkDriver::resume(int room, const math::dmat4& physical_to_virtual, const math::HeadPose& physical) {
    head_.resume(room, physical_to_virtual, physical);
}

void WalkDriver::follow_pairing() {
    if (head_.generation() == generation_) return;
    generation_ = head_.generation();
    current_ = std::make_shared<const Session>(head_.shared_current(), head_.shared_links());
    objects_.reset();
    moving_.clear();
    prop_walks_.reset();
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
    // The head's step, then the changes. A change made leaves the head's W,
    // room and place as they were, so the hands and props below are walked
    // as before it, with the pairing the frame started with (objects_ is
    // still that pairing's), as the spec orders them.
    changes::ChangeStep step = head_.step(physical, time);
    f.teleports = std::move(step.teleports);
    f.changes = std::move(step.changes);
    const walk::Walker& walker = head_.walker();
    f.room = walker.room();
    f.position = walker.position();
    f.forward = walker.forward();
    f.virtual_pose = math::head_pose_from(f.position, walker.rotation());
    if (hands) {
        const walk::ObjectSet& set = objects();
        std::array<WalkedHand, 2> placed;
        for (std::size_t h = 0; h < 2; ++h) {
            placed[h].virtual_pose = walk::virtual_pose(walker.physical_to_virtual(), (*hands)[h]);
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
    follow_pairing();
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
