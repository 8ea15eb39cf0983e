// The seen test's brute force on the tracer's side (portal_rays.hpp).
#include "trace/portal_rays.hpp"

#include <array>
#include <cstdint>

#include <glm/geometric.hpp>

#include "math/crossing.hpp"
#include "math/eyes.hpp"
#include "math/hidden_area.hpp"
#include "math/projection.hpp"
#include "trace/intersect.hpp"

namespace impossible::trace {

namespace {

// One line of sight: the (possibly virtual) eye, its head centre, direction,
// cell, clip plane and the portals passed since the real eye.
struct Sight {
    dvec3 origin{0.0};
    dvec3 head{0.0};
    dvec3 dir{0.0};
    int room = -1;
    ClipPlane clip;
    int passed = 0;
};

// The portal's front rectangle from its front side, in its own plane.
std::optional<double> hit_front(const ScenePortal& portal, const Sight& s) {
    const math::PortalRect& r = portal.rect;
    const dvec3 lo = dvec3(portal.to_local * dvec4(s.origin, 1.0));
    const dvec3 ld = dmat3(portal.to_local) * s.dir;
    const double hw = 0.5 * r.width, hh = 0.5 * r.height;
    const std::optional<double> t =
        hit_axis_rect(AxisRect{2, 0.0, 1.0, dvec3(-hw, -hh, -r.depth), dvec3(hw, hh, 0.0)}, lo, ld);
    if (!t || !s.clip.keeps(s.origin + *t * s.dir)) return std::nullopt;
    return t;
}

struct Walk {
    const Scene& scene;
    int max_depth = 0;
    int max_passes = 0;
    std::vector<char>& reached;
    long passes = 0;
    int tree_passes = 0;  // the current ray tree's

    // The nearest portal of the sight's cell it hits; -1 for none.
    int nearest(const Sight& s) const {
        int best = -1;
        double best_t = 0.0;
        for (const int q : scene.rooms[static_cast<std::size_t>(s.room)].portals) {
            const ScenePortal& p = scene.portals[static_cast<std::size_t>(q)];
            std::optional<double> t = hit_front(p, s);
            if (p.kind == layout::PortalKind::Door && math::has_inner_faces(p.rect, s.origin, s.head)) {
                bool inner = false;
                if (const std::optional<SurfaceHit> box = hit_portal_box(p, s.origin, s.dir, s.head, s.clip, inner))
                    if (!t || box->t < *t) t = box->t;
            }
            if (t && (best < 0 || *t < best_t)) {
                best = q;
                best_t = *t;
            }
        }
        return best;
    }

    void follow(const Sight& s) {
        const int q = nearest(s);
        if (q < 0) return;
        reached[static_cast<std::size_t>(q)] = 1;
        if (s.passed >= max_depth) return;
        const ScenePortal& p = scene.portals[static_cast<std::size_t>(q)];
        if (p.kind != layout::PortalKind::Door) {  // a mirror, or a window's reflected branch first
            if (!spend()) return;
            Sight r = s;
            r.origin = dvec3(p.reflection * dvec4(s.origin, 1.0));
            r.head = dvec3(p.reflection * dvec4(s.head, 1.0));
            r.dir = dmat3(p.reflection) * s.dir;
            r.clip = ClipPlane{true, p.plane, p.clip_tolerance, nullptr};
            r.passed = s.passed + 1;
            follow(r);
        }
        if (p.kind != layout::PortalKind::Mirror && p.target >= 0) {
            if (!spend()) return;
            const ScenePortal& b = scene.portals[static_cast<std::size_t>(p.target)];
            Sight t;
            t.origin = dvec3(p.transfer * dvec4(s.origin, 1.0));
            t.head = dvec3(p.transfer * dvec4(s.head, 1.0));
            t.dir = dmat3(p.transfer) * s.dir;
            t.room = b.room;
            t.clip =
                ClipPlane{glm::dot(t.origin - b.rect.center, b.rect.normal) < 0.0, b.plane, b.clip_tolerance, nullptr};
            t.passed = s.passed + 1;
            follow(t);
        }
    }

    // One pass of the ray tree's budget; false once it is spent.
    bool spend() {
        if (tree_passes >= max_passes) return false;
        ++tree_passes;
        ++passes;
        return true;
    }
};

}  // namespace

PortalRays portal_rays(const Scene& scene, const math::View& view, int step) {
    PortalRays out;
    out.reached.assign(scene.portals.size(), 0);
    Walk walk{scene, view.max_depth, view.max_portal_passes, out.reached};
    const std::array<math::Eye, 2> eyes = math::eyes_of(view);
    for (int e = 0; e < 2; ++e) {
        const math::Frustum frustum = math::eye_frustum(view, e);
        std::vector<std::uint8_t> hidden;
        if (view.eye_optics) {
            const math::Polygon2& visible = (*view.eye_optics)[static_cast<std::size_t>(e)].visible_area;
            if (!visible.empty()) hidden = math::hidden_pixels(visible, view.eye_width, view.eye_height);
        }
        const math::Eye& eye = eyes[static_cast<std::size_t>(e)];
        for (int j = 0; j < view.eye_height; j += step)
            for (int i = 0; i < view.eye_width; i += step) {
                if (!hidden.empty() && hidden[static_cast<std::size_t>(j) * view.eye_width + i]) continue;
                Sight s;
                s.origin = eye.position;
                s.head = eye.head;
                s.dir =
                    glm::normalize(eye.rotation * math::pixel_ray_eye(frustum, view.eye_width, view.eye_height, i, j));
                s.room = view.room;
                walk.tree_passes = 0;
                walk.follow(s);
                ++out.rays;
            }
    }
    out.passes = walk.passes;
    return out;
}

}  // namespace impossible::trace
