#include "session/walk_driver.hpp"

namespace impossible::session {

bool any_motion(const layout::Layout& layout) {
    for (const layout::Room& room : layout.rooms)
        for (const layout::Prop& prop : room.props)
            if (!layout::prop_motion(prop).keys.empty()) return true;
    return false;
}

WalkDriver::WalkDriver(const Session& session)
    : session_(&session), moves_(any_motion(session.layout())), walker_(session.make_walker()) {}

const walk::ObjectSet& WalkDriver::objects() {
    if (!objects_) {
        objects_ = walk::build_object_set(session_->layout(), session_->links());
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
        const layout::Layout& layout = session_->layout();
        for (const int m : moving_) {
            const walk::DynamicProp& p = set.props[static_cast<std::size_t>(m)];
            const layout::Prop& prop =
                layout.rooms[static_cast<std::size_t>(p.room)].props[static_cast<std::size_t>(p.index)];
            f.props.push_back({&layout::prop_id(prop), prop_walks_->at(m, *time).room});
        }
    }
    return f;
}

}  // namespace impossible::session
