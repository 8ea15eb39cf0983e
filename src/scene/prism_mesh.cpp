#include "scene/prism_mesh.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "layout/room_shape.hpp"
#include "scene/grid_front.hpp"
#include "scene/polygon_tess.hpp"
#include "scene/prism_plan.hpp"

namespace impossible::scene {

namespace {

// How a wall's vertices look: its exact normal, colour, checker, and its
// texture coordinates along the wall (layout::wall_uv: (s, -y) / size, less
// `shift`, whole tiles that keep them small far from the origin).
struct WallStyle {
    glm::dvec3 normal{0.0};
    glm::dvec3 color{0.0};
    double checker = 0.0;
    bool textured = false;
    double size = 1.0;
    glm::dvec2 shift{0.0};
};

std::uint32_t wall_vertex(MeshWriter& out, const WallStyle& style, const glm::vec3& position, double s, double t) {
    const glm::dvec2 uv = style.textured ? glm::dvec2(s, -t) / style.size - style.shift : glm::dvec2(0.0);
    return out.vertex(position, style.normal, style.color, style.checker, uv, 1.0);
}

std::size_t line_at(const std::vector<double>& lines, double value) {
    const auto it = std::lower_bound(lines.begin(), lines.end(), value);
    assert(it != lines.end() && *it == value);
    return static_cast<std::size_t>(it - lines.begin());
}

// A wall on its grid (s_lines × rows); fills the fronts of its holes.
void append_grid_wall(MeshWriter& out, const PrismWall& w, const WallStyle& style,
                      std::vector<std::optional<FrontGrid>>& fronts) {
    const std::vector<double>& ss = w.s_lines;
    const std::vector<double>& ts = w.rows;
    const std::size_t na = ss.size(), nb = ts.size();
    std::vector<glm::vec3> points(na * nb);
    for (std::size_t j = 0; j < nb; ++j)
        for (std::size_t i = 0; i < na; ++i) points[j * na + i] = out.local(w.point(ss[i], ts[j]));
    std::vector<char> open((na - 1) * (nb - 1), 1);  // cell (i, j) at [j * (na - 1) + i]
    for (const PrismHole& h : w.holes) {
        const std::size_t i0 = line_at(ss, h.lo.x), i1 = line_at(ss, h.hi.x);
        const std::size_t j0 = line_at(ts, h.lo.y), j1 = line_at(ts, h.hi.y);
        for (std::size_t j = j0; j < j1; ++j)
            for (std::size_t i = i0; i < i1; ++i) open[j * (na - 1) + i] = 0;
        fronts[static_cast<std::size_t>(h.portal)] = grid_front(
            h.corners, [&](std::size_t i, std::size_t j) { return points[j * na + i]; }, i0, i1, j0, j1);
    }
    emit_open_cells(out, na, nb, open, [&](std::size_t i, std::size_t j) {
        return wall_vertex(out, style, points[j * na + i], ss[i], ts[j]);
    });
}

// A hole's front from its corners, given as the face's vertices there.
FrontGrid corners_front(const std::array<glm::vec3, 4>& c) { return FrontGrid{2, 2, {c[0], c[1], c[3], c[2]}}; }

// Emits the tessellation's triangles, a vertex per point made when first used.
template <class MakeVertex>
void append_tessellation(MeshWriter& out, const Tessellation& tess, MakeVertex make_vertex) {
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> ids(tess.points.size(), kNone);
    const auto id = [&](int k) {
        std::uint32_t& v = ids[static_cast<std::size_t>(k)];
        if (v == kNone) v = make_vertex(static_cast<std::size_t>(k));
        return v;
    };
    for (const std::array<int, 3>& t : tess.triangles) out.triangle(id(t[0]), id(t[1]), id(t[2]));
}

// A wall that is not a grid (no holes, or one not upright in it): its
// rectangle, through every cut along its bottom and top and every height on
// its sides, less its holes, by the tessellator.
void append_tessellated_wall(MeshWriter& out, const PrismWall& w, const WallStyle& style,
                             std::vector<std::optional<FrontGrid>>& fronts) {
    // The outline counter-clockwise: bottom, high side, top, low side.
    const std::vector<double>& ss = w.s_lines;
    const std::vector<double>& high = w.high_side;
    const std::vector<double>& low = w.low_side;
    std::vector<std::vector<glm::dvec2>> contours(1);
    for (std::size_t k = 0; k + 1 < ss.size(); ++k) contours[0].push_back({ss[k], low.front()});
    for (std::size_t k = 0; k + 1 < high.size(); ++k) contours[0].push_back({ss.back(), high[k]});
    for (std::size_t k = ss.size() - 1; k > 0; --k) contours[0].push_back({ss[k], high.back()});
    for (std::size_t k = low.size() - 1; k > 0; --k) contours[0].push_back({ss.front(), low[k]});
    for (const PrismHole& h : w.holes) {
        contours.emplace_back(h.corners.begin(), h.corners.end());
        std::array<glm::vec3, 4> c;
        for (std::size_t k = 0; k < 4; ++k) c[k] = out.local(w.point(h.corners[k].x, h.corners[k].y));
        fronts[static_cast<std::size_t>(h.portal)] = corners_front(c);
    }
    const Tessellation tess = tessellate(contours);
    append_tessellation(out, tess, [&](std::size_t k) {
        const glm::dvec2 st = tess.points[k];
        return wall_vertex(out, style, out.local(w.point(st.x, st.y)), st.x, st.y);
    });
}

// The floor (face 0) or ceiling (1): the polygon through every wall's grid
// points along its edges, less the trapdoors' holes, by the tessellator.
void append_cap(MeshWriter& out, const layout::Room& room, const PrismPlan& plan, int face,
                std::vector<std::optional<FrontGrid>>& fronts) {
    const auto f = static_cast<std::size_t>(face);
    const layout::FaceFrame& frame = plan.caps[f];
    const double y = face == 0 ? room.min.y : room.max.y;
    std::vector<std::vector<glm::dvec2>> contours(1);
    std::vector<glm::vec3> positions;
    for (const PrismWall& w : plan.walls) {
        const std::vector<double> s = w.from_a();
        for (std::size_t k = 0; k + 1 < s.size(); ++k) {  // corner b is the next wall's a
            const glm::dvec3 p = w.point(s[k], y);
            contours[0].push_back(layout::to_face(frame, p));
            positions.push_back(out.local(p));
        }
    }
    for (const PrismHole& h : plan.cap_holes[f]) {
        contours.emplace_back(h.corners.begin(), h.corners.end());
        std::array<glm::vec3, 4> c;
        for (std::size_t k = 0; k < 4; ++k) c[k] = out.local(layout::from_face(frame, h.corners[k]));
        positions.insert(positions.end(), c.begin(), c.end());
        fronts[static_cast<std::size_t>(h.portal)] = corners_front(c);
    }
    const Tessellation tess = tessellate(contours);
    for (std::size_t k = positions.size(); k < tess.points.size(); ++k)
        positions.push_back(out.local(layout::from_face(frame, tess.points[k])));
    const glm::dvec3& color = room.face_color[f];
    append_tessellation(out, tess,
                        [&](std::size_t k) { return out.vertex(positions[k], frame.normal, color, room.checker); });
}

WallStyle wall_style(const MeshWriter& out, const layout::Room& room, const PrismWall& w, std::size_t face) {
    WallStyle style;
    style.normal = w.frame.normal;
    style.color = room.face_color[face];
    style.checker = room.checker;
    style.textured = room.face_texture[face] != nullptr;
    style.size = room.texture_size;
    style.shift = glm::dvec2(0.0, std::floor(-out.origin.y / room.texture_size));
    return style;
}

}  // namespace

std::vector<IndexRange> append_prism_faces(MeshWriter& out, const layout::Layout& layout, int room_index,
                                           const std::vector<int>& room_portals,
                                           std::vector<std::optional<FrontGrid>>& fronts) {
    const layout::Room& room = layout.rooms[static_cast<std::size_t>(room_index)];
    const PrismPlan plan = plan_prism(layout, room_index, room_portals);
    std::vector<IndexRange> ranges(static_cast<std::size_t>(layout::face_count(room)));
    for (std::size_t face = 0; face < ranges.size(); ++face) {
        const std::uint32_t first = out.index_count();
        out.face_uv.reset();
        if (face < 2) {
            if (room.face_texture[face]) {
                const auto f = static_cast<layout::Face>(face);
                out.face_uv = FaceUv{f, room.texture_size,
                                     glm::floor(shading::room_texture_uv(f, out.origin, room.texture_size))};
            }
            append_cap(out, room, plan, static_cast<int>(face), fronts);
        } else {
            const PrismWall& w = plan.walls[face - 2];
            const WallStyle style = wall_style(out, room, w, face);
            if (w.grid)
                append_grid_wall(out, w, style, fronts);
            else
                append_tessellated_wall(out, w, style, fronts);
        }
        ranges[face] = out.range_since(first);
    }
    out.face_uv.reset();
    return ranges;
}

}  // namespace impossible::scene
