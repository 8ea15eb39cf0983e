// Analytic ray–surface intersections for the reference tracer. A ray is
// origin + t · dir for t > 0 (dir need not be unit length; t is in units of
// |dir|). Every test returns only front-facing hits: the surface's normal
// points against the ray (dot(dir, normal) < 0). Rectangle and triangle
// edges count as inside.
#pragma once

#include <optional>

#include "trace/trace_scene.hpp"

namespace impossible::trace {

// Where the ray meets a surface, and the surface's front-facing normal there.
struct SurfaceHit {
    double t = 0.0;
    dvec3 normal{0.0};
    int portal = -1;  // ≥ 0: the front face of this portal, met in its hole
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
std::optional<SurfaceHit> hit_room_face(const RoomFace& face, const Scene& scene, const dvec3& origin,
                                        const dvec3& dir, const ClipPlane& clip);

// A prop box from outside: the face where the ray enters it.
std::optional<SurfaceHit> hit_prop_box(const PropBox& box, const dvec3& origin, const dvec3& dir,
                                       const ClipPlane& clip);

// A triangle from its counter-clockwise side (Möller–Trumbore); the normal is
// the barycentric blend of the vertex normals, normalised (the geometric
// normal if that blend vanishes).
std::optional<SurfaceHit> hit_triangle(const PropTriangle& tri, const dvec3& origin, const dvec3& dir,
                                       const ClipPlane& clip);

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
