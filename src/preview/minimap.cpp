#include "preview/minimap.hpp"

#include <algorithm>
#include <vector>

#include "layout/room_shape.hpp"
#include "math/rigid.hpp"
#include "preview/hud.hpp"

namespace impossible::preview {
namespace {

using Outline = std::vector<glm::dvec2>;

// A room's floor, its corners mapped by `m` and seen from above: a box
// room's rectangle, a prism room's polygon (layout::floor_outline).
Outline floor_of(const layout::Room& room, const math::dmat4& m) {
    const double y = room.min.y;
    std::vector<math::dvec3> corners;
    if (layout::is_prism(room)) {
        for (const glm::dvec2& c : layout::floor_outline(room)) corners.push_back({c.x, y, c.y});
    } else {
        corners = {math::dvec3{room.min.x, y, room.min.z},
                   {room.max.x, y, room.min.z},
                   {room.max.x, y, room.max.z},
                   {room.min.x, y, room.max.z}};
    }
    Outline q;
    for (const math::dvec3& c : corners) {
        const math::dvec4 p = m * math::dvec4(c, 1.0);
        q.push_back({p.x, p.z});
    }
    return q;
}

// Clips the segment to the rectangle (Liang–Barsky); false if nothing is left.
bool clip_segment(glm::vec2& a, glm::vec2& b, glm::vec2 lo, glm::vec2 hi) {
    float t0 = 0.0f, t1 = 1.0f;
    const glm::vec2 d = b - a;
    const float p[4] = {-d.x, d.x, -d.y, d.y};
    const float q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0f) {
            if (q[i] < 0.0f) return false;
            continue;
        }
        const float t = q[i] / p[i];
        if (p[i] < 0.0f)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    const glm::vec2 a0 = a;
    a = a0 + d * t0;
    b = a0 + d * t1;
    return true;
}

struct MapView {
    MapBounds bounds;
    glm::vec2 corner;
    float size, scale;
    glm::vec2 lo, hi;  // the panel's inner rectangle in pixels

    glm::vec2 to_pixel(glm::dvec2 xz) const {
        const glm::dvec2 centre = 0.5 * (bounds.min + bounds.max);
        return {corner.x + 0.5f * size + float(xz.x - centre.x) * scale,
                corner.y + 0.5f * size + float(xz.y - centre.y) * scale};
    }
    void segment(OverlayBatch& batch, glm::dvec2 a, glm::dvec2 b, glm::vec4 color) const {
        glm::vec2 pa = to_pixel(a), pb = to_pixel(b);
        if (clip_segment(pa, pb, lo, hi)) batch.line(pa, pb, color);
    }
    void loop(OverlayBatch& batch, const Outline& q, glm::vec4 color) const {
        for (std::size_t i = 0; i < q.size(); ++i) segment(batch, q[i], q[(i + 1) % q.size()], color);
    }
};

}  // namespace

glm::vec4 minimap_portal_colour(layout::PortalKind kind) {
    switch (kind) {
        case layout::PortalKind::Door: return {1.0f, 0.55f, 0.1f, 1.0f};    // orange
        case layout::PortalKind::Mirror: return {0.8f, 0.85f, 0.9f, 1.0f};  // silver
        case layout::PortalKind::Window: return {0.35f, 0.7f, 1.0f, 1.0f};  // sky blue
    }
    return {1.0f, 0.55f, 0.1f, 1.0f};
}

MapBounds minimap_bounds(const MinimapInput& in) {
    const math::dmat4 to_physical = math::rigid_inverse(in.physical_to_virtual);
    glm::dvec2 lo{in.physical_head.position.x, in.physical_head.position.z}, hi = lo;
    auto grow = [&](glm::dvec2 p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    if (in.layout->play_area) {
        grow(in.layout->play_area->min);
        grow(in.layout->play_area->max);
    }
    if (in.room >= 0 && static_cast<std::size_t>(in.room) < in.layout->rooms.size())
        for (const glm::dvec2& p : floor_of(in.layout->rooms[in.room], to_physical)) grow(p);
    const double margin = 0.08 * std::max({hi.x - lo.x, hi.y - lo.y, 1.0});
    return {lo - margin, hi + margin};
}

namespace {

// The play area: filled, and its outline.
void add_play_area(OverlayBatch& batch, const MapView& view, const layout::PlayArea& a) {
    glm::vec2 p0 = glm::clamp(view.to_pixel(a.min), view.lo, view.hi);
    glm::vec2 p1 = glm::clamp(view.to_pixel(a.max), view.lo, view.hi);
    batch.rect(p0, p1, {0.2f, 0.8f, 0.3f, 0.15f});
    const std::vector<glm::dvec2> poly = layout::outline(a);  // the rectangle, or the polygon
    for (std::size_t i = 0; i < poly.size(); ++i)
        view.segment(batch, poly[i], poly[(i + 1) % poly.size()], {0.3f, 0.9f, 0.4f, 1.0f});
}

// Rooms one door away, where they lie on the same physical floor (a mirror
// or window leads nowhere one can walk).
void add_neighbours(OverlayBatch& batch, const MapView& view, const MinimapInput& in, const math::dmat4& to_physical) {
    const layout::Layout& layout = *in.layout;
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const layout::Portal& p = layout.portals[i];
        if (p.room != in.room || p.kind != layout::PortalKind::Door) continue;
        const layout::Portal& target = layout.portals[p.target];
        const math::dmat4 m = to_physical * (*in.transfer)[p.target];  // B's room → A's → physical
        view.loop(batch, floor_of(layout.rooms[target.room], m), {0.35f, 0.55f, 1.0f, 0.7f});
    }
}

// The head's room and its portals, each with a short line along its normal.
void add_room(OverlayBatch& batch, const MapView& view, const layout::Layout& layout, int room,
              const math::dmat4& to_physical) {
    view.loop(batch, floor_of(layout.rooms[room], to_physical), {1.0f, 0.95f, 0.5f, 1.0f});
    for (const layout::Portal& p : layout.portals) {
        if (p.room != room) continue;
        const math::PortalRect& r = p.rect;
        const math::dvec3 right = math::portal_right(r);
        const math::dvec3 hw = right * (0.5 * r.width), hh = r.up * (0.5 * r.height);
        Outline q;
        for (const math::dvec3& corner :
             {r.center - hw - hh, r.center + hw - hh, r.center + hw + hh, r.center - hw + hh}) {
            const math::dvec4 c = to_physical * math::dvec4(corner, 1.0);
            q.push_back({c.x, c.z});
        }
        const glm::vec4 colour = minimap_portal_colour(p.kind);
        view.loop(batch, q, colour);
        const math::dvec4 c0 = to_physical * math::dvec4(r.center, 1.0);
        const math::dvec4 c1 = to_physical * math::dvec4(r.center + r.normal * 0.25, 1.0);
        view.segment(batch, {c0.x, c0.z}, {c1.x, c1.z}, colour);
    }
}

// The head: a dot and its (physical) view direction.
void add_head(OverlayBatch& batch, const MapView& view, const math::HeadPose& head) {
    const math::dvec3 h = head.position;
    const math::dvec3 f = math::forward_of(math::head_rotation(head));
    const glm::vec2 hp = view.to_pixel({h.x, h.z});
    if (hp.x >= view.lo.x && hp.x <= view.hi.x && hp.y >= view.lo.y && hp.y <= view.hi.y)
        batch.rect(hp - 3.0f, hp + 3.0f, {1.0f, 0.2f, 0.2f, 1.0f});
    glm::dvec2 dir{f.x, f.z};
    if (glm::length(dir) > 1e-6) dir = glm::normalize(dir);
    view.segment(batch, {h.x, h.z}, glm::dvec2{h.x, h.z} + dir * (18.0 / view.scale), {1.0f, 0.2f, 0.2f, 1.0f});
}

}  // namespace

void add_minimap(OverlayBatch& batch, const MinimapInput& in, glm::vec2 corner, float size) {
    const layout::Layout& layout = *in.layout;
    MapView view;
    view.bounds = minimap_bounds(in);
    view.corner = corner;
    view.size = size;
    const glm::dvec2 extent = view.bounds.max - view.bounds.min;
    view.scale = size / float(std::max(extent.x, extent.y));
    view.lo = corner + 1.0f;
    view.hi = corner + size - 1.0f;

    batch.rect(corner, corner + size, {0.0f, 0.0f, 0.0f, 0.65f});
    const math::dmat4 to_physical = math::rigid_inverse(in.physical_to_virtual);
    if (layout.play_area) add_play_area(batch, view, *layout.play_area);
    const bool room_ok = in.room >= 0 && static_cast<std::size_t>(in.room) < layout.rooms.size();
    if (room_ok && in.transfer) add_neighbours(batch, view, in, to_physical);
    if (room_ok) add_room(batch, view, layout, in.room, to_physical);
    add_head(batch, view, in.physical_head);
    add_text(batch, corner.x + 4.0f, corner.y + 4.0f, "physical floor", {0.8f, 0.8f, 0.8f, 0.9f}, 1.0f);
}

}  // namespace impossible::preview
