// Analytic ray–surface intersections for the reference tracer. A ray is
// origin + t · dir for t > 0 (dir need not be unit length; t is in units of
// |dir|). Every test returns only front-facing hits: the surface's normal
// points against the ray (dot(dir, normal) < 0). Rectangle and triangle
// edges count as inside.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <span>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "trace/trace_scene.hpp"

namespace impossible::trace {

// Where the ray meets a surface, and the surface's front-facing normal there.
struct SurfaceHit {
    double t = 0.0;
    dvec3 normal{0.0};
    int portal = -1;              // ≥ 0: the front face of this portal, met in its hole
    glm::dvec2 barycentric{0.0};  // a triangle's: the weights (u, v) of its vertices 1 and 2
};

// The signed distance dot(plane, (p, 1)), always summed in this order.
inline double plane_distance(const dvec4& plane, const dvec3& p) {
    return plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w;
}

// What else decides whether a hit point counts, besides the clip plane
// (docs/tracer.md, "Crossing objects" and "Volume portals"). Points are
// tested in the cell's coordinates: a placed object's hit point is moved
// there by its to_cell first.
struct RayFilter {
    std::span<const SceneVolume> outside;  // hidden inside any of these volumes
    const SceneVolume* inside = nullptr;   // counts only inside this volume
    const PlacedObject* placed = nullptr;  // points are in its own coordinates; its cuts apply
};

struct ClipPlane;
// ClipPlane::keeps with a filter: the clip plane, the placed object's cuts
// and the volumes, all on the point in the cell's coordinates.
bool filtered_keeps(const ClipPlane& clip, const dvec3& point);

// "Only the part of the ray strictly in front of the plane counts"
// (layout-format.md, "What a pixel shows"): a point counts when its signed
// distance exceeds the tolerance. Inactive: every point counts. A filter,
// where set, decides further (filtered_keeps); without one nothing else is
// read, so rays in cells without volumes or dynamic objects cost what they
// did before.
struct ClipPlane {
    bool active = false;
    dvec4 plane{0.0};  // (n, -dot(n, centre)): dot(plane, (p, 1)) = signed distance
    double tolerance = 0.0;
    const RayFilter* filter = nullptr;

    bool keeps(const dvec3& p) const {
        if (filter) [[unlikely]]
            return filtered_keeps(*this, p);
        return !active || plane_distance(plane, p) > tolerance;
    }
};

// Whether a point of the rectangle's plane lies in it (edges count).
inline bool in_axis_rect(const AxisRect& rect, const dvec3& p) {
    for (int a = 0; a < 3; ++a) {
        if (a == rect.axis) continue;
        if (!(p[a] >= rect.lo[a] && p[a] <= rect.hi[a])) return false;
    }
    return true;
}

// The rectangle, seen from the side its normal points to.
std::optional<double> hit_axis_rect(const AxisRect& rect, const dvec3& origin, const dvec3& dir);

// The unit vector along `axis`, times sign (built without an indexed store,
// which would keep it in memory on the tracer's hot path).
inline dvec3 axis_normal(int axis, double sign) {
    return dvec3(axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0);
}

// The portal (an index into Scene::portals) whose hole in `face` holds the
// point p of the face's plane, tested in the portal's own frame; -1 for none.
inline int hole_at(const RoomFace& face, const Scene& scene, const dvec3& p) {
    for (int index : face.holes) {
        const ScenePortal& portal = scene.portals[index];
        const dvec3 v = p - portal.rect.center;
        if (std::abs(glm::dot(v, portal.right)) <= 0.5 * portal.rect.width &&
            std::abs(glm::dot(v, portal.rect.up)) <= 0.5 * portal.rect.height)
            return index;
    }
    return -1;
}

// A room face with its holes (each hole tested in its portal's own frame:
// |x| ≤ width/2 and |y| ≤ height/2 is inside the hole). A hit inside a hole
// is a hit on that portal's front face (SurfaceHit::portal), in the face's
// plane: wall and door then share one test, so no ray slips between the
// hole's edge and the door's edge, even where the door lies up to the hole
// tolerance off the face's plane. The rasteriser draws the front face in the
// face's plane too (scene/room_mesh.cpp). Mirrors and windows fill their
// holes the same way: the face is seen only from inside the room, so they
// are seen only from their front. The hit's normal is the face's,
// axis_normal(face.rect.axis, face.rect.sign). A hit at t_limit or beyond is
// not reported (the tracer passes the nearest face so far). Defined here so
// that it inlines: every ray tests its room's faces again at every portal.
struct FaceHit {
    double t = 0.0;
    int portal = -1;  // ≥ 0: the front face of this portal, met in its hole
};
inline std::optional<FaceHit> hit_room_face(const RoomFace& face, const Scene& scene, const dvec3& origin,
                                            const dvec3& dir, const ClipPlane& clip,
                                            double t_limit = std::numeric_limits<double>::infinity()) {
    const AxisRect& rect = face.rect;
    const double along = dir[rect.axis];
    if (!(along * rect.sign < 0.0)) return std::nullopt;  // seen from behind, or edge-on
    const double t = (rect.coord - origin[rect.axis]) / along;
    if (!(t > 0.0 && t < t_limit)) return std::nullopt;
    const dvec3 p = origin + t * dir;
    if (!in_axis_rect(rect, p) || !clip.keeps(p)) return std::nullopt;
    return FaceHit{t, hole_at(face, scene, p)};
}

// A prop box from outside: the face where the ray enters it.
std::optional<SurfaceHit> hit_prop_box(const PropBox& box, const dvec3& origin, const dvec3& dir,
                                       const ClipPlane& clip);

// A triangle from its counter-clockwise side (Möller–Trumbore); the normal is
// the barycentric blend of the vertex normals, normalised (the geometric
// normal if that blend vanishes). Its material (an index into `materials`)
// may change that (docs/tracer.md, "Materials and textures"): a
// double-sided triangle is hit from its back too, where the normal is
// reversed; a masked one is not hit where its alpha (triangle_color) is
// below the cutoff, and the ray goes on to whatever lies behind.
std::optional<SurfaceHit> hit_triangle(const PropTriangle& tri, std::span<const PropMaterial> materials,
                                       const dvec3& origin, const dvec3& dir, const ClipPlane& clip);

// A triangle's colour at barycentrics (u, v) (those of vertices 1 and 2):
// rgb its base colour, color · COLOR_0 · texel, and alpha the material's
// alpha · COLOR_0's · the texel's. COLOR_0 and uv are blended with weights
// (1 - u - v, u, v), except that three equal corners give their value
// exactly. The texel is read at mip level 0 with the sampler's mag filter
// (texture_sample.hpp); without a texture it is white.
dvec4 triangle_color(const PropTriangle& tri, std::span<const PropMaterial> materials, glm::dvec2 barycentric);

// A room face's base colour at a point p of it: its colour, times the
// texel of its texture (if any) at shading::room_texture_uv(face, p, size)
// (on a prism's wall at layout::wall_uv's coordinates), read at mip level 0
// with the default sampler (repeat, linear).
dvec3 room_face_color(const RoomFace& face, const dvec3& p);

// A portal's box for a ray from `origin`, which is the (possibly virtual)
// eye of the (possibly virtual) head centre `head`: the front rectangle
// (facing +n) always, unless the portal fills a room face's hole (then
// hit_room_face meets it); for a door, the four side faces and the back face
// (facing inwards) only when the eye has them (math::has_inner_faces: in the
// box's column, reached by the head through the door). A mirror or a window
// has no box: only its front rectangle, which lies in a hole in any valid
// layout, so this finds nothing for it there. The nearest such face that the
// clip plane keeps; `inner` says whether it is an inner face.
std::optional<SurfaceHit> hit_portal_box(const ScenePortal& portal, const dvec3& origin, const dvec3& dir,
                                         const dvec3& head, const ClipPlane& clip, bool& inner);

// The front rectangle of a portal that fills no hole (facing +n), as
// hit_portal_box meets it, and never the box's inner faces: what a shadow
// ray meets of a free-standing portal (layout-format.md, "Lights": a door
// box counts as its front rectangle only). Nothing for a portal in a hole.
std::optional<SurfaceHit> hit_portal_front(const ScenePortal& portal, const dvec3& origin, const dvec3& dir,
                                           const ClipPlane& clip);

}  // namespace impossible::trace
