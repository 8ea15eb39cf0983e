#include "changes/pairing.hpp"

#include <algorithm>

namespace impossible::changes {

Pairing loaded_pairing(const layout::Layout& layout) {
    Pairing pairing;
    for (const layout::Portal& p : layout.portals) pairing.target.push_back(p.target);
    return pairing;
}

std::vector<int> affected_doors(const layout::Change& change, const Pairing& pairing) {
    std::vector<int> doors;
    for (const std::array<int, 2>& pair : change.pairs) {
        for (const int d : pair) {
            doors.push_back(d);
            const int partner = pairing.target[static_cast<std::size_t>(d)];
            if (partner >= 0) doors.push_back(partner);
        }
    }
    std::sort(doors.begin(), doors.end());
    doors.erase(std::unique(doors.begin(), doors.end()), doors.end());
    return doors;
}

void make_change(const layout::Change& change, Pairing& pairing) {
    std::vector<int> former;
    for (const std::array<int, 2>& pair : change.pairs)
        for (const int d : pair)
            if (pairing.target[static_cast<std::size_t>(d)] >= 0)
                former.push_back(pairing.target[static_cast<std::size_t>(d)]);
    for (const int f : former) pairing.target[static_cast<std::size_t>(f)] = -1;
    for (const std::array<int, 2>& pair : change.pairs) {
        pairing.target[static_cast<std::size_t>(pair[0])] = pair[1];
        pairing.target[static_cast<std::size_t>(pair[1])] = pair[0];
    }
}

PairedLayout paired_layout(const layout::Layout& base, const Pairing& pairing) {
    PairedLayout out;
    out.layout = base;
    std::vector<int> index(base.portals.size(), -1);
    std::vector<layout::Portal> kept;
    for (std::size_t i = 0; i < base.portals.size(); ++i) {
        const bool closed = base.portals[i].kind == layout::PortalKind::Door && pairing.target[i] < 0;
        if (closed) continue;
        index[i] = static_cast<int>(kept.size());
        kept.push_back(base.portals[i]);
        out.base_index.push_back(static_cast<int>(i));
    }
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const int target = pairing.target[static_cast<std::size_t>(out.base_index[k])];
        kept[k].target = target >= 0 ? index[static_cast<std::size_t>(target)] : -1;
    }
    out.layout.portals = std::move(kept);
    out.layout.changes.clear();  // they index base's portals; the walk keeps them
    return out;
}

}  // namespace impossible::changes
