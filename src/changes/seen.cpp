#include "changes/seen.hpp"

#include <cmath>
#include <optional>

#include "math/crossing.hpp"
#include "math/eyes.hpp"
#include "math/portal.hpp"

namespace impossible::changes {

namespace {

using math::dmat3;
using math::dmat4;
using math::dvec3;
using Poly3 = std::vector<dvec3>;

// The half-space n · p + c ≥ 0.
struct HalfSpace {
    dvec3 n{0.0};
    double c = 0.0;
    double at(const dvec3& p) const { return glm::dot(n, p) + c; }
};

// Sutherland and Hodgman: the part of the convex polygon in the half-space.
Poly3 clip(const Poly3& poly, const HalfSpace& h) {
    Poly3 out;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3& a = poly[i];
        const dvec3& b = poly[(i + 1) % n];
        const double da = h.at(a), db = h.at(b);
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

dvec3 transform_point(const dmat4& m, const dvec3& p) { return dvec3(m * math::dvec4(p, 1.0)); }

// "Strictly in front of" a plane, as the renderers clip (layout-format.md,
// "What a pixel shows", Precision).
HalfSpace strictly_in_front(const math::PortalRect& r) {
    const double tolerance = 1e-9 * (1.0 + glm::length(r.center));
    return {r.normal, -glm::dot(r.normal, r.center) - tolerance};
}

// The planes through `apex` and each edge of the convex polygon, facing in.
std::vector<HalfSpace> cone_over(const dvec3& apex, const Poly3& poly) {
    dvec3 centroid(0.0);
    for (const dvec3& p : poly) centroid += p;
    centroid /= static_cast<double>(poly.size());
    std::vector<HalfSpace> cone;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        dvec3 n = glm::cross(poly[i] - apex, poly[(i + 1) % poly.size()] - apex);
        if (glm::dot(n, n) == 0.0) continue;
        if (glm::dot(n, centroid - apex) < 0.0) n = -n;
        cone.push_back({n, -glm::dot(n, apex)});
    }
    return cone;
}

double polygon_area(const Poly3& poly) {
    dvec3 sum(0.0);
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) sum += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    return 0.5 * glm::length(sum);
}

// One eye's view as it is searched: the eye where it stands after the
// portals passed, and the way back to the real eye.
struct Level {
    dvec3 eye{0.0};
    dvec3 head{0.0};
    dmat4 to_real{1.0};  // virtual → real coordinates
    std::vector<HalfSpace> cone;
    std::optional<HalfSpace> clip_plane;
    int cell = -1;
    int passed = 0;
};

class Search {
public:
    Search(const layout::Layout& layout, const links::PortalLinks& links, const math::View& view, SeenPortals& out)
        : layout_(layout), links_(links), max_depth_(view.max_depth), out_(out) {}

    void eye(const math::Eye& eye, const math::Frustum& frustum, const math::Polygon2* visible_area, int cell);

private:
    void search(const Level& level);
    void pass(const Level& level, const Poly3& through, const dmat4& m, int cell, const math::PortalRect& exit);
    bool shows(const Level& level, const Poly3& poly) const;

    const layout::Layout& layout_;
    const links::PortalLinks& links_;
    int max_depth_;
    SeenPortals& out_;
    // The real eye of the search under way: its image, for the visible area.
    math::Eye real_{};
    math::FovTangents tangents_{};
    const math::Polygon2* visible_area_ = nullptr;
};

void Search::eye(const math::Eye& eye, const math::Frustum& frustum, const math::Polygon2* visible_area, int cell) {
    real_ = eye;
    visible_area_ = visible_area && !visible_area->empty() ? visible_area : nullptr;
    if (frustum.tangents) {
        tangents_ = *frustum.tangents;
    } else {
        const double t = std::tan(math::radians(frustum.fov_y_deg) * 0.5);
        tangents_ = {-t * frustum.aspect, t * frustum.aspect, t, -t};
    }
    const math::FovTangents& t = tangents_;
    Poly3 corners = {dvec3(t.left, t.up, -1.0), dvec3(t.right, t.up, -1.0), dvec3(t.right, t.down, -1.0),
                     dvec3(t.left, t.down, -1.0)};
    for (dvec3& c : corners) c = eye.position + eye.rotation * c;
    Level level;
    level.eye = eye.position;
    level.head = eye.head;
    level.cone = cone_over(eye.position, corners);
    level.cell = cell;
    search(level);
    // An eye inside a door's box, reached through the door, sees through it
    // whatever its direction (the box's inner faces surround it).
    for (const int q : links_.room_portals[static_cast<std::size_t>(cell)]) {
        const layout::Portal& p = layout_.portals[static_cast<std::size_t>(q)];
        if (p.kind != layout::PortalKind::Door || p.target < 0) continue;
        if (math::signed_distance(p.rect, eye.position) >= 0.0 ||
            !math::has_inner_faces(p.rect, eye.position, eye.head))
            continue;
        out_.seen[static_cast<std::size_t>(q)] = 1;
        if (max_depth_ < 1) continue;
        const dmat4& m = links_.transfer[static_cast<std::size_t>(q)];
        Level through;
        through.eye = transform_point(m, eye.position);
        through.head = transform_point(m, eye.head);
        through.to_real = glm::inverse(m);
        for (const HalfSpace& h : level.cone) {
            const dvec3 n = dmat3(m) * h.n;
            through.cone.push_back({n, -glm::dot(n, through.eye)});
        }
        through.cell = layout_.portals[static_cast<std::size_t>(p.target)].room;
        through.passed = 1;
        ++out_.passes;
        search(through);
    }
}

// Whether the polygon (in the level's coordinates, inside its cone) shows
// in the real eye's visible area.
bool Search::shows(const Level& level, const Poly3& poly) const {
    if (!visible_area_) return true;
    math::Polygon2 image;
    const dmat3 to_eye = glm::transpose(real_.rotation);
    for (const dvec3& p : poly) {
        const dvec3 q = to_eye * (transform_point(level.to_real, p) - real_.position);
        if (q.z > -1e-12) return true;  // at the eye: no image point (conservative)
        const double x = q.x / -q.z, y = q.y / -q.z;
        image.push_back({(x - tangents_.left) / (tangents_.right - tangents_.left),
                         (tangents_.up - y) / (tangents_.up - tangents_.down)});
    }
    if (math::area(image) == 0.0) return math::contains(*visible_area_, image.front());
    return math::intersection_area(*visible_area_, image) > 0.0;
}

void Search::search(const Level& level) {
    if (out_.saturated || !links::valid_index(level.cell, links_.room_portals.size())) return;
    for (const int q : links_.room_portals[static_cast<std::size_t>(level.cell)]) {
        const layout::Portal& p = layout_.portals[static_cast<std::size_t>(q)];
        if (math::signed_distance(p.rect, level.eye) <= 0.0) continue;  // its back, or edge on
        dvec3 corners[8];
        math::box_corners(p.rect, corners);
        Poly3 poly(corners, corners + 4);
        if (level.clip_plane) poly = clip(poly, *level.clip_plane);
        for (const HalfSpace& h : level.cone) {
            if (poly.empty()) break;
            poly = clip(poly, h);
        }
        if (poly.empty() || !shows(level, poly)) continue;
        out_.seen[static_cast<std::size_t>(q)] = 1;
        if (level.passed >= max_depth_ || poly.size() < 3 || polygon_area(poly) == 0.0) continue;
        const std::size_t qi = static_cast<std::size_t>(q);
        if (p.kind != layout::PortalKind::Door || p.target >= 0) {
            if (p.kind == layout::PortalKind::Mirror || p.kind == layout::PortalKind::Window)
                pass(level, poly, links_.reflection[qi], level.cell, p.rect);
            if (p.target >= 0) {
                const layout::Portal& target = layout_.portals[static_cast<std::size_t>(p.target)];
                pass(level, poly, links_.transfer[qi], target.room, target.rect);
            }
        }
        if (out_.saturated) return;
    }
}

// Continues through the part `through` of a portal, mapped by m into `cell`,
// clipped by `exit`'s plane (the target's, or the mirror's own).
void Search::pass(const Level& level, const Poly3& through, const dmat4& m, int cell, const math::PortalRect& exit) {
    if (++out_.passes >= kMaxSeenPasses) {
        out_.saturated = true;
        return;
    }
    Level next;
    next.eye = transform_point(m, level.eye);
    next.head = transform_point(m, level.head);
    next.to_real = level.to_real * glm::inverse(m);
    Poly3 mapped;
    for (const dvec3& p : through) mapped.push_back(transform_point(m, p));
    next.cone = cone_over(next.eye, mapped);
    next.clip_plane = strictly_in_front(exit);
    next.cell = cell;
    next.passed = level.passed + 1;
    search(next);
}

}  // namespace

SeenPortals seen_portals(const layout::Layout& layout, const links::PortalLinks& links, const math::View& view) {
    SeenPortals out;
    out.seen.assign(layout.portals.size(), 0);
    Search search(layout, links, view, out);
    const std::array<math::Eye, 2> eyes = math::eyes_of(view);
    for (int k = 0; k < 2; ++k) {
        const math::Polygon2* area =
            view.eye_optics ? &(*view.eye_optics)[static_cast<std::size_t>(k)].visible_area : nullptr;
        search.eye(eyes[static_cast<std::size_t>(k)], math::eye_frustum(view, k), area, view.room);
        if (out.saturated) break;
    }
    if (out.saturated) out.seen.assign(layout.portals.size(), 1);
    return out;
}

}  // namespace impossible::changes
