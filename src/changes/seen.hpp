// The seen test of layout-format.md, "Changes while walking": which portals
// either eye of a view can see, through portal chains only. Room faces and
// props hide nothing here, so the answer is conservative: a door called
// unseen lies in no pixel of either eye, whatever the room holds.
//
// Each eye's view is a convex cone (the four planes through the eye and the
// image corners, FovTangents or fov_y_deg × aspect). A portal Q of the cell
// is reached when the eye is strictly in front of Q's plane and the part of
// Q's rectangle inside the cone (and, below the first level, strictly in
// front of the clipping plane of the portal the view came out of) is not
// empty; with a visible area (a headset's lens mask), that part's image must
// also overlap the visible area. A reached door or window is passed (to its
// target, M_QT), a mirror or window reflects (M_Q), while fewer than
// max_depth portals were passed: the cone then narrows to the planes through
// the virtual eye and the clipped polygon's edges. Closed doors are not in
// the layout this runs on (changes/pairing.hpp), so they pass nothing.
//
// One reading beyond the spec's words (docs/changes.md): an eye behind a
// door's plane that has the door's inner faces (math::has_inner_faces: the
// head reached it through the door) sees through that door, so that door is
// seen and the cell behind it is searched with the eye's whole cone, as is
// its own cell. The spec's rays "from P's front side" would miss what that
// eye shows through the box.
//
// Work is bounded: past kMaxSeenPasses portal passes in one frame the test
// gives up and calls every portal seen (no change is made that frame).
// Double precision throughout.
#pragma once

#include <vector>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/view.hpp"

namespace impossible::changes {

inline constexpr int kMaxSeenPasses = 20'000;

struct SeenPortals {
    std::vector<char> seen;  // per portal of the layout: 1 seen by either eye
    int passes = 0;          // portal passes made (both eyes)
    bool saturated = false;  // kMaxSeenPasses was reached: every portal is marked seen
};

// The portals of `layout` either eye of `view` sees: its head, room,
// eyes (math::eyes_of), frusta (math::eye_frustum), visible areas and
// max_depth. `links` are the layout's.
SeenPortals seen_portals(const layout::Layout& layout, const links::PortalLinks& links, const math::View& view);

}  // namespace impossible::changes
