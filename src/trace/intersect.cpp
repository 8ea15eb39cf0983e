#include "trace/intersect.hpp"

#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "math/crossing.hpp"
#include "shading/shading.hpp"
#include "trace/texture_sample.hpp"

namespace impossible::trace {

namespace {

// Keeps the hit (t, normal) in `best` when it is nearer.
void keep_nearest(std::optional<SurfaceHit>& best, double t, const dvec3& normal) {
    if (!best || t < best->t) best = SurfaceHit{t, normal};
}

}  // namespace

std::optional<double> hit_axis_rect(const AxisRect& rect, const dvec3& origin, const dvec3& dir) {
    const double along = dir[rect.axis];
    if (!(along * rect.sign < 0.0)) return std::nullopt;  // seen from behind, or edge-on
    const double t = (rect.coord - origin[rect.axis]) / along;
    if (!(t > 0.0)) return std::nullopt;
    if (!in_axis_rect(rect, origin + t * dir)) return std::nullopt;
    return t;
}

std::optional<SurfaceHit> hit_prop_box(const PropBox& box, const dvec3& origin, const dvec3& dir,
                                       const ClipPlane& clip) {
    // The six faces with outward normals; of a convex box only the face where
    // the ray enters faces the ray.
    std::optional<SurfaceHit> best;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {-1.0, 1.0}) {
            const AxisRect face{axis, sign < 0.0 ? box.min[axis] : box.max[axis], sign, box.min, box.max};
            const std::optional<double> t = hit_axis_rect(face, origin, dir);
            if (t && clip.keeps(origin + *t * dir)) keep_nearest(best, *t, axis_normal(axis, sign));
        }
    }
    return best;
}

std::optional<SurfaceHit> hit_triangle(const PropTriangle& tri, std::span<const PropMaterial> materials,
                                       const dvec3& origin, const dvec3& dir, const ClipPlane& clip) {
    // The material is read only where it matters (a back face, a hit), so
    // that a ray missing a front face touches nothing but the positions.
    const dvec3 e1 = tri.position[1] - tri.position[0];
    const dvec3 e2 = tri.position[2] - tri.position[0];
    const dvec3 geometric = glm::cross(e1, e2);  // towards the counter-clockwise side
    const double facing = glm::dot(dir, geometric);
    const bool back = !(facing < 0.0);
    // A back face counts only for a double-sided material; edge-on or degenerate never.
    if (back && !(facing > 0.0 && tri.material >= 0 && materials[tri.material].double_sided)) return std::nullopt;
    // Möller–Trumbore: barycentrics (u, v) of vertices 1 and 2, and t.
    const dvec3 pvec = glm::cross(dir, e2);
    const double inv_det = 1.0 / glm::dot(e1, pvec);  // det = -dot(dir, geometric): > 0 front, < 0 back
    const dvec3 tvec = origin - tri.position[0];
    const double u = glm::dot(tvec, pvec) * inv_det;
    if (!(u >= 0.0 && u <= 1.0)) return std::nullopt;
    const dvec3 qvec = glm::cross(tvec, e1);
    const double v = glm::dot(dir, qvec) * inv_det;
    if (!(v >= 0.0 && u + v <= 1.0)) return std::nullopt;
    const double t = glm::dot(e2, qvec) * inv_det;
    if (!(t > 0.0) || !clip.keeps(origin + t * dir)) return std::nullopt;
    const glm::dvec2 barycentric(u, v);
    if (tri.material >= 0) {
        const PropMaterial& material = materials[tri.material];
        if (material.mask && triangle_color(tri, materials, barycentric).a < material.alpha_cutoff)
            return std::nullopt;  // a hole: the ray goes on
    }
    const dvec3 blend = (1.0 - u - v) * tri.normal[0] + u * tri.normal[1] + v * tri.normal[2];
    const double length = glm::length(blend);
    const dvec3 normal = length > 0.0 ? blend / length : glm::normalize(geometric);
    return SurfaceHit{t, back ? -normal : normal, -1, barycentric};
}

namespace {

// The barycentric blend of three corner values; three equal corners give
// their value exactly (an untextured, uncoloured model keeps its colour to
// the bit).
template <typename V>
V blend_corners(const std::array<V, 3>& c, glm::dvec2 b) {
    if (c[0] == c[1] && c[1] == c[2]) return c[0];
    return (1.0 - b.x - b.y) * c[0] + b.x * c[1] + b.y * c[2];
}

}  // namespace

dvec4 triangle_color(const PropTriangle& tri, std::span<const PropMaterial> materials, glm::dvec2 barycentric) {
    const dvec4 vertex = blend_corners(tri.vertex_color, barycentric);
    dvec3 rgb = tri.color * dvec3(vertex);
    if (tri.material < 0) return dvec4(rgb, vertex.a);
    const PropMaterial& material = materials[tri.material];
    double alpha = material.alpha * vertex.a;
    if (material.texture.image) {
        const dvec4 texel = sample_mip0(material.texture, blend_corners(tri.uv, barycentric));
        rgb *= dvec3(texel);
        alpha *= texel.a;
    }
    return dvec4(rgb, alpha);
}

dvec3 room_face_color(const RoomFace& face, const dvec3& p) {
    if (!face.texture) return face.color;
    // A prism's wall: layout::wall_uv, from the wall's frame kept in the face.
    const glm::dvec2 uv = face.wall >= 0
                              ? glm::dvec2(glm::dot(p - face.wall_origin, face.wall_s_axis), -p.y) / face.texture_size
                              : shading::room_texture_uv(face.face, p, face.texture_size);
    const dvec4 texel = sample_mip0(*face.texture, assets::Sampler{}, uv);
    return face.color * dvec3(texel);
}

std::optional<SurfaceHit> hit_portal_box(const ScenePortal& portal, const dvec3& origin, const dvec3& dir,
                                         const dvec3& head, const ClipPlane& clip, bool& inner_hit) {
    // Work in the portal's frame, where the box is [-w/2, w/2] × [-h/2, h/2] × [-depth, 0]
    // and the frame's axes are (right, up, normal). t is the same in both frames.
    const math::PortalRect& r = portal.rect;
    // A portal in a hole leaves its front to hit_room_face, and only a door
    // has inner faces: such a portal has nothing more to show unless the eye
    // has them. Most rays stop here.
    inner_hit = false;
    const bool inner = portal.kind == layout::PortalKind::Door && math::has_inner_faces(r, origin, head);
    if (portal.in_hole && !inner) return std::nullopt;
    const dvec3 lo = dvec3(portal.to_local * dvec4(origin, 1.0));
    const dvec3 ld = dmat3(portal.to_local) * dir;
    const double hw = 0.5 * r.width, hh = 0.5 * r.height;
    const dvec3 frame[3] = {portal.right, r.up, r.normal};

    std::optional<SurfaceHit> best;
    auto try_face = [&](int axis, double coord, double sign, const dvec3& min, const dvec3& max, bool is_inner) {
        const std::optional<double> t = hit_axis_rect(AxisRect{axis, coord, sign, min, max}, lo, ld);
        if (t && clip.keeps(origin + *t * dir) && (!best || *t < best->t)) {
            best = SurfaceHit{*t, sign * frame[axis]};
            inner_hit = is_inner;
        }
    };
    const dvec3 box_min(-hw, -hh, -r.depth), box_max(hw, hh, 0.0);
    if (!portal.in_hole) try_face(2, 0.0, 1.0, box_min, box_max, false);  // the front rectangle, facing +n
    if (inner) {
        // Inner faces, facing into the box. From an eye in front of the
        // plane they lie behind the front face (a ray meets one only through
        // the front, or through its edge): they tie as the front does.
        const bool behind = math::signed_distance(r, origin) < 0.0;
        try_face(0, hw, -1.0, box_min, box_max, behind);
        try_face(0, -hw, 1.0, box_min, box_max, behind);
        try_face(1, hh, -1.0, box_min, box_max, behind);
        try_face(1, -hh, 1.0, box_min, box_max, behind);
        try_face(2, -r.depth, 1.0, box_min, box_max, behind);
    }
    return best;
}

std::optional<SurfaceHit> hit_portal_front(const ScenePortal& portal, const dvec3& origin, const dvec3& dir,
                                           const ClipPlane& clip) {
    if (portal.in_hole) return std::nullopt;
    const math::PortalRect& r = portal.rect;
    const dvec3 lo = dvec3(portal.to_local * dvec4(origin, 1.0));
    const dvec3 ld = dmat3(portal.to_local) * dir;
    const double hw = 0.5 * r.width, hh = 0.5 * r.height;
    const std::optional<double> t =
        hit_axis_rect(AxisRect{2, 0.0, 1.0, dvec3(-hw, -hh, -r.depth), dvec3(hw, hh, 0.0)}, lo, ld);
    if (!t || !clip.keeps(origin + *t * dir)) return std::nullopt;
    return SurfaceHit{*t, r.normal};
}

}  // namespace impossible::trace
