// The walker: physical head poses → virtual head in the layout, teleporting
// through portals (layout-format.md, "Head, eyes and walking").
//
// W maps physical to virtual coordinates (rigid, starts as identity); the
// current room starts as the layout's start room. The first pose places the
// head with no crossing test. Each later pose moves the virtual head from the
// previous virtual centre p0 to p1 = W · physical; the segment is tested
// against the doors of the current room (math/crossing.hpp): the nearest
// crossing along it wins, an exact tie goes to the portal listed first.
// Mirrors and windows are never walked through: the head passes their
// planes as it passes any wall, and stays in its room. A
// crossing of A teleports: W ← M_AB · W, the room becomes B's, and the rest
// of the segment, from the crossing point mapped by M_AB to the new head, is
// tested again in the new room without B. At most kMaxCrossingsPerFrame
// portals are passed in one frame; the rest of the segment is then not
// tested (only a degenerate layout of stacked coincident portals gets there).
//
// After each teleport W is re-orthonormalised, and if rounding leaves the
// head at d ≤ 0 for B, W is moved along B's normal until the head is
// 1e-9 · (1 + |B.center|) in front, so rounding never sends it straight back.
//
// Going back through the pair just passed (B after A, with nothing passed
// in between) restores W exactly as it was before A instead of multiplying
// by M_BA: the value M_BA · M_AB · W has in exact arithmetic, so walking back
// and forth through a portal accumulates no rounding at all (the last
// kHistoryLength teleports are remembered for this). Only the ~1e-9 nudge of
// a rounding fix, if one was made, is forgotten with it.
//
// Units metres, angles degrees, double precision throughout.
#pragma once

#include <array>
#include <deque>
#include <memory>
#include <vector>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/pose.hpp"

namespace impossible::walk {

inline constexpr int kMaxCrossingsPerFrame = 64;
inline constexpr std::size_t kHistoryLength = 256;

class Walker {
public:
    // Starts in layout.start.room, head at the start position and yaw. The
    // layout must outlive the walker.
    explicit Walker(const layout::Layout& layout);
    // Starts in the given room instead.
    Walker(const layout::Layout& layout, int room);
    // The same with the layout's links made once beforehand (link_portals of
    // this layout), for walkers made often (walk/objects.hpp).
    Walker(const layout::Layout& layout, int room, std::shared_ptr<const links::PortalLinks> links);
    // A temporary layout would dangle.
    explicit Walker(const layout::Layout&&) = delete;
    Walker(const layout::Layout&&, int) = delete;

    // Feeds one physical head pose; returns the indices of the portals passed
    // during this frame, in order (empty for the first pose).
    std::vector<int> step(const math::HeadPose& physical);

    // Continues a walk begun by another walker (e.g. before the layout was
    // reloaded): its W and last physical pose, in this walker's room. The
    // next step tests the segment from W · physical on, as the other walker
    // would have. The teleport history starts empty.
    void resume(const math::dmat4& physical_to_virtual, const math::HeadPose& physical);

    int room() const { return room_; }
    bool started() const { return started_; }
    const math::dmat4& physical_to_virtual() const { return w_; }
    const math::HeadPose& physical_pose() const { return physical_pose_; }
    const links::PortalLinks& links() const { return *links_; }

    // The virtual head centre and orientation (columns right, up, back) after
    // the last step (before any, the layout's start).
    math::dvec3 position() const { return head_; }
    math::dmat3 rotation() const;
    math::dvec3 forward() const;
    // Both eyes in virtual coordinates, left first (math::eyes_of of the
    // physical head mapped by W): at ±ipd/2 along the head's x axis, or
    // placed by each eye's pose relative to the head (View::eye_offsets).
    // Eye::head is the virtual head centre: an eye past a door plane the
    // head has not crossed stays in the head's room and, reached through
    // the door, has its box's inner faces (math::has_inner_faces).
    std::array<math::Eye, 2> eyes(double ipd) const;
    std::array<math::Eye, 2> eyes(const std::array<math::EyeOffset, 2>& offsets) const;

private:
    struct Passed {
        int portal = -1;
        math::dmat4 w_before{1.0};
    };
    void teleport(int portal);

    const layout::Layout* layout_;
    std::shared_ptr<const links::PortalLinks> links_;
    math::dmat4 w_{1.0};
    int room_ = -1;
    math::dvec3 head_{0.0};               // virtual head centre
    math::dmat3 physical_rotation_{1.0};  // of the last physical pose
    math::HeadPose physical_pose_{};      // the last physical pose
    bool started_ = false;
    std::deque<Passed> history_;  // the latest teleports, newest last
};

}  // namespace impossible::walk
