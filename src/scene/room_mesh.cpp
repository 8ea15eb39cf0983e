#include "scene/room_mesh.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "layout/room_shape.hpp"
#include "scene/face_slabs.hpp"
#include "scene/grid_front.hpp"
#include "scene/prism_mesh.hpp"

namespace impossible::scene {

namespace {

// A rectangle whose corners all lie within this of its bounding rectangle's
// corners counts as axis-aligned (below float resolution at room scale).
constexpr double kAlignTolerance = 1e-6;

struct FaceAxes {
    int axis = 0;          // the normal's axis
    double plane = 0.0;    // the face's coordinate on that axis
    bool positive = true;  // the normal into the room is +e_axis
    PlaneAxes in;          // e_a × e_b = normal into the room
};

FaceAxes face_axes(const layout::Room& room, int face) {
    static constexpr std::array<int, layout::kFaceCount> kAxis = {1, 1, 0, 0, 2, 2};
    FaceAxes f;
    f.axis = kAxis[static_cast<std::size_t>(face)];
    f.positive = face % 2 == 0;  // floor, -x and -z lie at the minimum and face +axis
    f.plane = f.positive ? room.min[f.axis] : room.max[f.axis];
    f.in = plane_axes(f.axis, f.positive);
    return f;
}

glm::dvec3 inward_normal(const FaceAxes& f) {
    glm::dvec3 n(0.0);
    n[f.axis] = f.positive ? 1.0 : -1.0;
    return n;
}

// A portal that is a hole in a face, in the face's (a, b) coordinates.
struct FaceHole {
    int portal = -1;
    std::array<glm::dvec2, 4> corners;  // box_corners' front corners
    glm::dvec2 lo{0.0}, hi{0.0};        // bounding rectangle, clamped to the face
    bool aligned = true;
};

FaceHole make_hole(const layout::Room& room, const FaceAxes& f, int portal, const math::PortalRect& rect) {
    math::dvec3 c[8];
    math::box_corners(rect, c);
    FaceHole h;
    h.portal = portal;
    const glm::dvec2 face_lo(room.min[f.in.a], room.min[f.in.b]);
    const glm::dvec2 face_hi(room.max[f.in.a], room.max[f.in.b]);
    h.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    h.hi = -h.lo;
    for (std::size_t k = 0; k < 4; ++k) {
        h.corners[k] = glm::clamp(glm::dvec2(c[k][f.in.a], c[k][f.in.b]), face_lo, face_hi);
        h.lo = glm::min(h.lo, h.corners[k]);
        h.hi = glm::max(h.hi, h.corners[k]);
    }
    const auto near = [](double x, double a, double b) {
        return std::abs(x - a) <= kAlignTolerance || std::abs(x - b) <= kAlignTolerance;
    };
    for (const glm::dvec2& p : h.corners) {
        h.aligned = h.aligned && near(p.x, h.lo.x, h.hi.x) && near(p.y, h.lo.y, h.hi.y);
    }
    return h;
}

std::size_t line_index(const std::vector<float>& lines, float value) {
    const auto it = std::lower_bound(lines.begin(), lines.end(), value);
    assert(it != lines.end() && *it == value);
    return static_cast<std::size_t>(it - lines.begin());
}

using Lines = std::array<std::vector<float>, 3>;

// A face's grid: its lines along the face's axes a and b, in the mesh's
// local coordinates, and their crossings.
struct FaceGrid {
    const FaceAxes& f;
    const std::vector<float>& as;
    const std::vector<float>& bs;
    float plane = 0.0f;

    glm::vec3 point(std::size_t i, std::size_t j) const { return plane_point(f.axis, plane, f.in, as[i], bs[j]); }
};

// One face on the room's grid; fills the fronts of its holes.
void append_grid_face(MeshWriter& out, const layout::Room& room, int face, const Lines& lines,
                      const std::vector<FaceHole>& holes, std::vector<std::optional<FrontGrid>>& fronts) {
    const FaceAxes f = face_axes(room, face);
    const FaceGrid grid{f, lines[static_cast<std::size_t>(f.in.a)], lines[static_cast<std::size_t>(f.in.b)],
                        out.local(f.plane, f.axis)};
    const std::vector<float>& as = grid.as;
    const std::vector<float>& bs = grid.bs;
    const std::size_t na = as.size(), nb = bs.size();
    std::vector<char> open((na - 1) * (nb - 1), 1);  // cell (i, j) at [j * (na - 1) + i]

    for (const FaceHole& h : holes) {
        const std::size_t i0 = line_index(as, out.local(h.lo.x, f.in.a));
        const std::size_t i1 = line_index(as, out.local(h.hi.x, f.in.a));
        const std::size_t j0 = line_index(bs, out.local(h.lo.y, f.in.b));
        const std::size_t j1 = line_index(bs, out.local(h.hi.y, f.in.b));
        for (std::size_t j = j0; j < j1; ++j) {
            for (std::size_t i = i0; i < i1; ++i) open[j * (na - 1) + i] = 0;
        }
        fronts[static_cast<std::size_t>(h.portal)] = grid_front(
            h.corners, [&](std::size_t i, std::size_t j) { return grid.point(i, j); }, i0, i1, j0, j1);
    }

    const glm::dvec3 normal = inward_normal(f);
    const glm::dvec3& color = room.face_color[static_cast<std::size_t>(face)];
    emit_open_cells(out, na, nb, open, [&](std::size_t i, std::size_t j) {
        return out.vertex(grid.point(i, j), normal, color, room.checker);
    });
}

void append_face(MeshWriter& out, const layout::Room& room, int face, const Lines& lines,
                 const std::vector<FaceHole>& holes, bool slabs, const layout::Layout& layout,
                 std::vector<std::optional<FrontGrid>>& fronts) {
    const auto fi = static_cast<std::size_t>(face);
    if (!slabs) {
        append_grid_face(out, room, face, lines, holes, fronts);
        return;
    }
    const FaceAxes f = face_axes(room, face);
    SlabFace s;
    s.axis = f.axis;
    s.plane = f.plane;
    s.in = f.in;
    s.lo = {room.min[f.in.a], room.min[f.in.b]};
    s.hi = {room.max[f.in.a], room.max[f.in.b]};
    s.normal = inward_normal(f);
    s.color = room.face_color[fi];
    s.checker = room.checker;
    for (const float v : lines[static_cast<std::size_t>(f.in.a)]) s.cuts.push_back(out.world(v, f.in.a));
    for (const FaceHole& h : holes) {
        s.holes.push_back(h.corners);
        fronts[static_cast<std::size_t>(h.portal)] =
            corner_front(out, layout.portals[static_cast<std::size_t>(h.portal)].rect);
    }
    append_face_slabs(out, s);
}

}  // namespace

std::vector<IndexRange> append_room_faces(MeshWriter& out, const layout::Layout& layout, int room_index,
                                          const std::vector<int>& room_portals,
                                          std::vector<std::optional<FrontGrid>>& fronts) {
    const layout::Room& room = layout.rooms[static_cast<std::size_t>(room_index)];
    if (layout::is_prism(room)) return append_prism_faces(out, layout, room_index, room_portals, fronts);
    std::array<std::vector<FaceHole>, layout::kFaceCount> holes;
    std::array<bool, layout::kFaceCount> slabs{};  // faces with a hole that is not axis-aligned
    for (const int p : room_portals) {
        const layout::Portal& portal = layout.portals[static_cast<std::size_t>(p)];
        if (portal.room != room_index || portal.hole_face < 0) continue;
        const int fi = portal.hole_face;
        assert(fi < layout::kFaceCount);
        const FaceHole h = make_hole(room, face_axes(room, fi), p, portal.rect);
        slabs[static_cast<std::size_t>(fi)] = slabs[static_cast<std::size_t>(fi)] || !h.aligned;
        holes[static_cast<std::size_t>(fi)].push_back(h);
    }

    // The grid lines every face shares: the room's bounds and the hole edges.
    Lines lines;
    for (int axis = 0; axis < 3; ++axis) {
        lines[static_cast<std::size_t>(axis)] = {out.local(room.min[axis], axis), out.local(room.max[axis], axis)};
    }
    for (int face = 0; face < layout::kFaceCount; ++face) {
        if (slabs[static_cast<std::size_t>(face)]) continue;
        const PlaneAxes in = face_axes(room, face).in;
        for (const FaceHole& h : holes[static_cast<std::size_t>(face)]) {
            for (const double v : {h.lo.x, h.hi.x}) lines[static_cast<std::size_t>(in.a)].push_back(out.local(v, in.a));
            for (const double v : {h.lo.y, h.hi.y}) lines[static_cast<std::size_t>(in.b)].push_back(out.local(v, in.b));
        }
    }
    for (std::vector<float>& l : lines) {
        std::sort(l.begin(), l.end());
        l.erase(std::unique(l.begin(), l.end()), l.end());
    }

    std::vector<IndexRange> ranges(layout::kFaceCount);
    for (int face = 0; face < layout::kFaceCount; ++face) {
        const auto fi = static_cast<std::size_t>(face);
        const std::uint32_t first = out.index_count();
        out.face_uv.reset();
        if (room.face_texture[fi]) {
            const auto f = static_cast<layout::Face>(face);
            out.face_uv =
                FaceUv{f, room.texture_size, glm::floor(shading::room_texture_uv(f, out.origin, room.texture_size))};
        }
        append_face(out, room, face, lines, holes[fi], slabs[fi], layout, fronts);
        ranges[fi] = out.range_since(first);
    }
    out.face_uv.reset();
    return ranges;
}

}  // namespace impossible::scene
