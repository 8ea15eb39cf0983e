#include "links/portal_links.hpp"

namespace impossible::links {
PortalLinks link_portals(const layout::Layout& layout) {
    PortalLinks links;
    links.transfer.assign(layout.portals.size(), math::dmat4(1.0));
    links.reflection.assign(layout.portals.size(), math::dmat4(1.0));
    links.room_portals.resize(layout.rooms.size());
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const layout::Portal& p = layout.portals[i];
        if (p.kind != layout::PortalKind::Door) links.reflection[i] = math::reflection_matrix(p.rect);
        if (p.kind == layout::PortalKind::Mirror) {
            if (valid_index(p.room, layout.rooms.size())) links.room_portals[p.room].push_back(static_cast<int>(i));
            continue;
        }
        if (!valid_index(p.room, layout.rooms.size()) || !valid_index(p.target, layout.portals.size()) ||
            !valid_index(layout.portals[p.target].room, layout.rooms.size()))
            continue;
        links.transfer[i] = math::transfer_matrix(p.rect, layout.portals[p.target].rect);
        links.room_portals[p.room].push_back(static_cast<int>(i));
    }
    return links;
}

}  // namespace impossible::links
