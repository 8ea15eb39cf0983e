// The seen test's brute force: dense pixel rays of both eyes followed as a
// view ray is (layout-format.md, "What a pixel shows"), with room faces and
// props ignored: each ray's nearest portal rectangle hit from its front side
// (strictly in front of the clipping plane) is seen, then passed (a door or
// window to its target, a mirror or window reflecting) while fewer than
// max_depth portals were passed.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/crossing.hpp"
#include "math/eyes.hpp"
#include "math/portal.hpp"
#include "math/projection.hpp"
#include "math/view.hpp"

namespace impossible::changes::testing {

struct BruteRays {
    const layout::Layout& layout;
    const links::PortalLinks& links;
    int max_depth = 8;
    std::vector<char> seen = std::vector<char>(layout.portals.size(), 0);

    void follow(int cell, math::dvec3 o, math::dvec3 d, const std::optional<math::dvec4>& clip, int passed) {
        int best = -1;
        double best_t = INFINITY;
        for (const int q : links.room_portals[static_cast<std::size_t>(cell)]) {
            const math::PortalRect& r = layout.portals[static_cast<std::size_t>(q)].rect;
            const double dn = glm::dot(d, r.normal);
            const double d0 = math::signed_distance(r, o);
            if (dn >= 0.0 || d0 <= 0.0) continue;
            const double t = -d0 / dn;
            const math::dvec3 p = o + t * d;
            if (!(t > 0.0) || t >= best_t || !math::within_rectangle(r, p)) continue;
            if (clip && glm::dot(math::dvec3(*clip), p) + (*clip).w <= 1e-9 * (1.0 + glm::length(p))) continue;
            best = q;
            best_t = t;
        }
        if (best < 0) return;
        seen[static_cast<std::size_t>(best)] = 1;
        if (passed >= max_depth) return;
        const layout::Portal& p = layout.portals[static_cast<std::size_t>(best)];
        const std::size_t b = static_cast<std::size_t>(best);
        if (p.kind != layout::PortalKind::Door) {
            const math::dmat4& m = links.reflection[b];
            follow(cell, math::dvec3(m * math::dvec4(o, 1.0)), math::dmat3(m) * d, math::portal_plane(p.rect),
                   passed + 1);
        }
        if (p.target >= 0) {
            const math::dmat4& m = links.transfer[b];
            const layout::Portal& t = layout.portals[static_cast<std::size_t>(p.target)];
            follow(t.room, math::dvec3(m * math::dvec4(o, 1.0)), math::dmat3(m) * d, math::portal_plane(t.rect),
                   passed + 1);
        }
    }

    // Every `step`-th pixel of both eyes' images (with hidden pixels of a
    // visible area left out).
    void view(const math::View& v, int step) {
        max_depth = v.max_depth;
        const std::array<math::Eye, 2> eyes = math::eyes_of(v);
        for (int k = 0; k < 2; ++k) {
            const math::Frustum f = math::eye_frustum(v, k);
            for (int j = 0; j < v.eye_height; j += step)
                for (int i = 0; i < v.eye_width; i += step) {
                    if (v.eye_optics) {
                        const math::Polygon2& a = (*v.eye_optics)[static_cast<std::size_t>(k)].visible_area;
                        if (!a.empty() && !math::contains(a, {(i + 0.5) / v.eye_width, (j + 0.5) / v.eye_height}, 0))
                            continue;
                    }
                    const math::dvec3 d = eyes[static_cast<std::size_t>(k)].rotation *
                                          math::pixel_ray_eye(f, v.eye_width, v.eye_height, i, j);
                    follow(v.room, eyes[static_cast<std::size_t>(k)].position, d, std::nullopt, 0);
                }
        }
    }
};

}  // namespace impossible::changes::testing
