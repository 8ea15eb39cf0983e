// Analytic ray–surface intersections for the reference tracer. A ray is
// origin + t · dir for t > 0 (dir need not be unit length; t is in units of
// |dir|). Every test returns only front-facing hits: the surface's normal
// points against the ray (dot(dir, normal) < 0). Rectangle and triangle
// edges count as inside.
#pragma once

#include <optional>
#include <span>

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

// "Only the part of the ray strictly in front of the plane counts"
// (layout-format.md, "What a pixel shows"): a point counts when its signed
// distance exceeds the tolerance. Inactive: every point counts.
struct ClipPlane {
    bool active = false;
    dvec4 plane{0.0};  // (n, -dot(n, centre)): dot(plane, (p, 1)) = signed distance
    double tolerance = 0.0;

    bool keeps(const dvec3& p) const {
        return !active || plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w > tolerance;
    }
};

// The rectangle, seen from the side its normal points to.
std::optional<double> hit_axis_rect(const AxisRect& rect, const dvec3& origin, const dvec3& dir);

// A room face with its holes (each hole tested in its portal's own frame:
// |x| ≤ width/2 and |y| ≤ height/2 is inside the hole). A hit inside a hole
// is a hit on that portal's front face (SurfaceHit::portal), in the face's
// plane: wall and door then share one test, so no ray slips between the
// hole's edge and the door's edge, even where the door lies up to the hole
// tolerance off the face's plane. The rasteriser draws the front face in the
// face's plane too (scene/room_mesh.cpp). Mirrors and windows fill their
// holes the same way: the face is seen only from inside the room, so they
// are seen only from their front.
std::optional<SurfaceHit> hit_room_face(const RoomFace& face, const Scene& scene, const dvec3& origin, const dvec3& dir,
                                        const ClipPlane& clip);

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
// texel of its texture (if any) at shading::room_texture_uv(face, p, size),
// read at mip level 0 with the default sampler (repeat, linear).
dvec3 room_face_color(const RoomFace& face, const dvec3& p);

// A portal's box for a ray from `origin`, which is the (possibly virtual)
// eye: the front rectangle (facing +n) always, unless the portal fills a
// room face's hole (then hit_room_face meets it); for a door, the four side
// faces and the back face (facing inwards) only when the eye is in the box's
// column. A mirror or a window has no box: only its front rectangle, which
// lies in a hole in any valid layout, so this finds nothing for it there.
// The nearest such face that the clip plane keeps.
std::optional<SurfaceHit> hit_portal_box(const ScenePortal& portal, const dvec3& origin, const dvec3& dir,
                                         const ClipPlane& clip);

}  // namespace impossible::trace
