#include "scene/portal_box.hpp"

#include <array>
#include <cstdint>

#include "shading/shading.hpp"

namespace impossible::scene {

FrontGrid corner_front(const MeshWriter& out, const math::PortalRect& rect) {
    math::dvec3 c[8];
    math::box_corners(rect, c);
    // Grid order (0,0), (1,0), (0,1), (1,1) = corners 0, 1, 3, 2.
    return FrontGrid{2, 2, {out.local(c[0]), out.local(c[1]), out.local(c[3]), out.local(c[2])}};
}

namespace {

// The front grid's points along side s, from front corner s to corner s+1
// (box_corners order: bottom (-u), right (+r), top (+u), left (-r)).
std::vector<glm::vec3> side_path(const FrontGrid& f, int side) {
    std::vector<glm::vec3> path;
    const int last_i = f.cols - 1, last_j = f.rows - 1;
    switch (side) {
        case 0:
            for (int i = 0; i <= last_i; ++i) path.push_back(f.at(i, 0));
            break;
        case 1:
            for (int j = 0; j <= last_j; ++j) path.push_back(f.at(last_i, j));
            break;
        case 2:
            for (int i = last_i; i >= 0; --i) path.push_back(f.at(i, last_j));
            break;
        default:
            for (int j = last_j; j >= 0; --j) path.push_back(f.at(0, j));
            break;
    }
    return path;
}

}  // namespace

PortalMesh append_portal_front(MeshWriter& out, const math::PortalRect& rect, const FrontGrid& front) {
    const glm::dvec3 n = rect.normal;
    PortalMesh mesh;
    // The grid's cells, counter-clockwise seen from +n (r × u = n).
    const std::uint32_t first = out.index_count();
    std::vector<std::uint32_t> ids;
    for (const glm::vec3& p : front.points) ids.push_back(out.vertex(p, n, shading::kPortalFillColor, 0.0));
    const auto id = [&](int i, int j) { return ids[static_cast<std::size_t>(j * front.cols + i)]; };
    for (int j = 0; j + 1 < front.rows; ++j) {
        for (int i = 0; i + 1 < front.cols; ++i) {
            out.triangle(id(i, j), id(i + 1, j), id(i + 1, j + 1));
            out.triangle(id(i, j), id(i + 1, j + 1), id(i, j + 1));
        }
    }
    mesh.front = out.range_since(first);
    return mesh;
}

PortalMesh append_portal_box(MeshWriter& out, const math::PortalRect& rect, const FrontGrid& front) {
    math::dvec3 c[8];
    math::box_corners(rect, c);
    const glm::dvec3 n = rect.normal;
    const glm::dvec3 u = rect.up;
    const glm::dvec3 r = math::portal_right(rect);
    PortalMesh mesh = append_portal_front(out, rect, front);

    // Inner: each side face is the polygon (front path, back corner s+1, back
    // corner s), fanned from back corner s so the front path keeps every point
    // the wall has there. Normals point into the box.
    const std::uint32_t first = out.index_count();
    const std::array<glm::dvec3, 4> side_normal = {u, -r, -u, r};
    for (int s = 0; s < 4; ++s) {
        const glm::dvec3& normal = side_normal[static_cast<std::size_t>(s)];
        const std::uint32_t back_s = out.vertex(out.local(c[4 + s]), normal, shading::kPortalFillColor, 0.0);
        const std::uint32_t back_next =
            out.vertex(out.local(c[4 + (s + 1) % 4]), normal, shading::kPortalFillColor, 0.0);
        const std::vector<glm::vec3> path = side_path(front, s);
        std::uint32_t previous = out.vertex(path.front(), normal, shading::kPortalFillColor, 0.0);
        for (std::size_t k = 1; k < path.size(); ++k) {
            const std::uint32_t next = out.vertex(path[k], normal, shading::kPortalFillColor, 0.0);
            out.triangle(back_s, previous, next);
            previous = next;
        }
        out.triangle(back_s, previous, back_next);
    }
    std::array<std::uint32_t, 4> back{};
    for (int k = 0; k < 4; ++k) {
        back[static_cast<std::size_t>(k)] = out.vertex(out.local(c[4 + k]), n, shading::kPortalFillColor, 0.0);
    }
    out.triangle(back[0], back[1], back[2]);
    out.triangle(back[0], back[2], back[3]);
    mesh.inner = out.range_since(first);
    return mesh;
}

}  // namespace impossible::scene
