// The one walk driver: physical head (and hand) poses in, a walked frame out,
// as `walk` prints it and the library's and Python's Walker return it. The
// head is the walker's; the hands are mapped by its W and placed by walking
// from the head centre; moving props are walked to the frame's time
// (layout-format.md, "Head, eyes and walking"; cli.md, "Time, hands and
// lights").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "session/session.hpp"
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"
#include "walk/replay.hpp"

namespace impossible::session {

struct WalkedHand {
    math::HeadPose virtual_pose;  // the physical hand mapped by W
    int room = -1;                // walked from the head centre; -1: none
};

struct WalkedProp {
    const std::string* id = nullptr;  // the prop's id (layout::prop_id), in the session's layout
    int room = -1;                    // its room at the frame's time
};

struct WalkedFrame {
    int room = -1;               // the head's room after the frame
    std::vector<int> teleports;  // the portals passed during it, in order
    math::dvec3 position{0.0};   // the virtual head centre
    math::dvec3 forward{0.0};    // the virtual view direction
    math::HeadPose virtual_pose;
    std::optional<std::array<WalkedHand, 2>> hands;  // only for a frame walked with hands
    std::vector<WalkedProp> props;                   // each moving prop, in layout order, with a time
};

class WalkDriver {
public:
    // From the layout's start; the session must outlive the driver.
    explicit WalkDriver(const Session& session);
    // It keeps walks that point into its own object set.
    WalkDriver(const WalkDriver&) = delete;
    WalkDriver& operator=(const WalkDriver&) = delete;

    // One frame: the head, the hands if any, and with `time` the moving
    // props at that time (none when no prop moves).
    WalkedFrame step(const math::HeadPose& physical, const walk::HandPoses& hands = std::nullopt,
                     std::optional<double> time = std::nullopt);

    const walk::Walker& walker() const { return walker_; }

private:
    const walk::ObjectSet& objects();  // built at the first frame that needs it

    const Session* session_;
    bool moves_ = false;  // any_motion(layout)
    walk::Walker walker_;
    std::optional<walk::ObjectSet> objects_;
    std::vector<int> moving_;  // indices of objects_->props that move
    std::optional<walk::PropWalks> prop_walks_;
};

// Whether any prop of the layout moves.
bool any_motion(const layout::Layout& layout);

}  // namespace impossible::session
