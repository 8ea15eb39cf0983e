// The portal pairs of a layout, linked once: the transfer matrix M_AB of
// every portal and the portals of every room. build_scene keeps them in the
// Scene for the renderer; the walker links with the same function.
#pragma once

#include <cstddef>
#include <vector>

#include "layout/layout.hpp"
#include "math/portal.hpp"

namespace impossible::links {

// transfer[i] is M from portal i to its target (doors and windows);
// reflection[i] is M_P of a mirror or window (identity for a door);
// room_portals[r] lists the portals of room r in file order. A portal whose
// room or target index is out of range is left out of room_portals (the
// loader never produces one); a mirror has no target.
struct PortalLinks {
    std::vector<math::dmat4> transfer;
    std::vector<math::dmat4> reflection;
    std::vector<std::vector<int>> room_portals;
};

PortalLinks link_portals(const layout::Layout& layout);

// Whether i indexes an array of n things.
inline bool valid_index(int i, std::size_t n) { return i >= 0 && static_cast<std::size_t>(i) < n; }

}  // namespace impossible::links
