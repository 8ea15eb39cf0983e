// Step 1 of "What a pixel shows" (layout-format.md) for the tracer: the
// nearest front-facing surface along a ray in one cell, among the room's own
// surfaces, the dynamic objects placed in it this frame (props that move or
// meet a door, hands; walk/objects.hpp) and, through its volume portals, the
// surfaces of their target rooms inside them. Internal to src/trace
// (tracer.cpp); see docs/tracer.md, "Crossing objects" and "Volume portals".
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "trace/bvh.hpp"
#include "trace/coplanar.hpp"
#include "trace/intersect.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::trace {

// Whose surface a hit is: a room's own, or a dynamic object's (its surfaces
// in its own coordinates, its rotation into the cell's), seen in the ray's
// room or, through a volume, in the volume's target room.
struct SurfaceSource {
    int room = -1;                        // the room whose surface it is (the id's); -1: the ray's
    const SceneObject* object = nullptr;  // a placed object's surfaces; none: the room's
    const dmat3* rotation = nullptr;      // the object's own normals → the cell's; none: identity
    const dvec3* tint = nullptr;          // a volume's tint; none: 1
};

// The nearest front-facing surface of one cell along a ray: what it is and
// how to shade it.
struct Nearest {
    bool found = false;
    double t = 0.0;
    dvec3 normal{0.0};  // in the surface's own coordinates (see world_normal)
    int portal = -1;    // ≥ 0: a face of this portal's box
    dvec3 base{0.0};    // otherwise: the surface's base colour and checker side
    double checker = 0.0;
    // Where the base colour is read at the hit point instead (base_color):
    const RoomFace* textured_face = nullptr;  // a room face with a texture
    int triangle = -1;                        // a glTF triangle (its index in its list)
    glm::dvec2 barycentric{0.0};              // … and where it was hit
    // Whose surface; room -1: the ray's own room's (every hit in a cell
    // without volumes and dynamic objects). Set after a search, not by offer.
    SurfaceSource source;
    Tie tie;        // the kept hit's part in a coplanar tie
    long kept = 0;  // hits kept so far (a tie may keep a hit at the same t)

    // Whether the hit replaces the one kept (nearer, or winning a coplanar
    // tie), and so is now kept.
    bool offer(const std::optional<SurfaceHit>& hit, int portal_index, const dvec3& color, double side,
               const Tie& hit_tie = Tie{}) {
        if (!hit || (found && !replaces(hit->t, hit_tie, t, tie))) return false;
        found = true;
        ++kept;
        tie = hit_tie;
        t = hit->t;
        normal = hit->normal;
        portal = portal_index;
        base = color;
        checker = side;
        textured_face = nullptr;
        triangle = -1;
        return true;
    }
};

// Inline, so that the search of a room without volumes or objects, every
// ray's in most layouts, is compiled into the tracer's loop as it was
// before they existed.
inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

inline double limit_of(const Nearest& n) { return n.found ? search_limit(n.t, n.tie) : kNoLimit; }

// Boxes and triangles (a room's props or an object's), after whatever was
// offered before, which wins a tie: the first box of those at the smallest t,
// then the first triangle (bvh.hpp).
inline void nearest_prop(const PropSurfaces& s, const dvec3& origin, const dvec3& dir, const ClipPlane& clip,
                         Nearest& nearest) {
    if (!s.boxes.empty()) {
        const double limit = limit_of(nearest);
        const BoxHit box = s.box_bvh.nodes.empty() ? nearest_box_scan(s.boxes, origin, dir, clip, limit)
                                                   : nearest_box(s.box_bvh, s.boxes, origin, dir, clip, limit);
        if (box.hit) nearest.offer(box.hit, -1, s.boxes[box.index].color, 0.0);
    }
    if (!s.triangles.empty()) {
        const double limit = limit_of(nearest);
        const TriangleHit tri = s.bvh.nodes.empty()
                                    ? nearest_triangle_scan(s.triangles, s.materials, origin, dir, clip, limit)
                                    : nearest_triangle(s.bvh, s.triangles, s.materials, origin, dir, clip, limit);
        if (tri.hit && nearest.offer(tri.hit, -1, s.triangles[tri.index].color, 0.0)) {
            nearest.triangle = tri.index;
            nearest.barycentric = tri.hit->barycentric;
        }
    }
}

// nearest_static in a prism room (nearest.cpp): its faces (prism_faces.hpp),
// then as in a box room.
void nearest_prism_static(const Scene& scene, const SceneRoom& room, const dvec3& origin, const dvec3& dir,
                          const dvec3& head, const ClipPlane& clip, Nearest& nearest);

// The portals' boxes of a room (hit_portal_box), each offered with its tie.
inline void nearest_boxes(const Scene& scene, const SceneRoom& room, const dvec3& origin, const dvec3& dir,
                          const dvec3& head, const ClipPlane& clip, Nearest& nearest) {
    for (int p : room.box_portals) {
        const ScenePortal& portal = scene.portals[p];
        bool inner = false;
        const std::optional<SurfaceHit> hit = hit_portal_box(portal, origin, dir, head, clip, inner);
        if (hit) nearest.offer(hit, p, dvec3(0.0), 0.0, box_tie(portal, inner, hit->normal, dir));
    }
}

// A room's static surfaces: the faces first, the first in order at the
// smallest t (a face no nearer than the nearest so far would lose to it),
// then the props, then the portals' boxes, each losing a tie to those before
// except as the coplanar rules say (Tie). `head` is the (virtual) head
// centre of the eye at `origin`.
inline void nearest_static(const Scene& scene, const SceneRoom& room, const dvec3& origin, const dvec3& dir,
                           const dvec3& head, const ClipPlane& clip, Nearest& nearest) {
    if (!room.prism.faces.empty()) [[unlikely]] {
        nearest_prism_static(scene, room, origin, dir, head, clip, nearest);
        return;
    }
    int face = -1;
    FaceHit face_hit{limit_of(nearest), -1};
    Tie tie;
    for (int f = 0; f < layout::kFaceCount; ++f) {
        const double limit = face < 0 ? face_hit.t : search_limit(face_hit.t, tie);
        if (const std::optional<FaceHit> hit = hit_room_face(room.faces[f], scene, origin, dir, clip, limit)) {
            const Tie hit_tie = face_tie(scene, hit->portal, dir);
            if (face >= 0 && !replaces(hit->t, hit_tie, face_hit.t, tie)) continue;
            face = f;
            face_hit = *hit;
            tie = hit_tie;
        }
    }
    if (face >= 0) {
        const RoomFace& f = room.faces[face];
        if (nearest.offer(SurfaceHit{face_hit.t, axis_normal(f.rect.axis, f.rect.sign)}, face_hit.portal, f.color,
                          room.checker, tie) &&
            f.texture)
            nearest.textured_face = &f;
    }
    nearest_prop(room, origin, dir, clip, nearest);
    nearest_boxes(scene, room, origin, dir, head, clip, nearest);
}

// nearest_in_room in a room with volumes or placed objects (nearest.cpp).
void nearest_in_mixed_room(const Scene& scene, const FrameObjects* objects, int room_index, const dvec3& origin,
                           const dvec3& dir, const dvec3& head, const ClipPlane& clip, Nearest& nearest);

// The frame's dynamic objects (FrameObjects), or null for none.
// Finds the nearest surface into `nearest`, reused from ray to ray: each
// field a hit sets is read only where that hit was kept (offer), so only
// `found` is reset.
inline void nearest_in_room(const Scene& scene, const FrameObjects* objects, int room_index, const dvec3& origin,
                            const dvec3& dir, const dvec3& head, const ClipPlane& clip, Nearest& nearest) {
    const SceneRoom& room = scene.rooms[room_index];
    if (room.volumes.empty() && (!objects || objects->in_room(room_index).empty())) {
        nearest.found = false;
        nearest.source = SurfaceSource{};
        nearest_static(scene, room, origin, dir, head, clip, nearest);
        return;
    }
    nearest_in_mixed_room(scene, objects, room_index, origin, dir, head, clip, nearest);
}

// What a shadow ray meets in room `room_index` before `t_limit`
// (layout-format.md, "Lights", step 2): the room's faces minus holes (a hit
// in a hole is the portal's), its props, the front rectangles of its
// free-standing portals (never a door box's inner faces) and the objects
// placed in it this frame. Volumes play no part: the room's own surfaces
// count inside them too, and their target rooms' not at all. `nearest`
// holds the nearest hit with t < t_limit, or found false (nearest.cpp).
void nearest_for_light(const Scene& scene, const FrameObjects* objects, int room_index, const dvec3& origin,
                       const dvec3& dir, const ClipPlane& clip, double t_limit, Nearest& nearest);

// The room a kept hit belongs to (its id's room): `ray_room` for the ray's
// own room's surfaces.
inline int hit_room(const Nearest& n, int ray_room) { return n.source.room >= 0 ? n.source.room : ray_room; }

// The kept hit's normal in the cell's coordinates.
inline dvec3 world_normal(const Nearest& n) { return n.source.rotation ? *n.source.rotation * n.normal : n.normal; }

// base_color of a textured face or a triangle (nearest.cpp).
dvec3 read_base_color(const Scene& scene, int ray_room, const Nearest& n, const dvec3& point);

// The base colour of the surface `n` (not a portal) at its hit point, in the
// cell's coordinates: a textured face's or a triangle's read there
// (docs/tracer.md, "Materials and textures"), any other's as offered.
inline dvec3 base_color(const Scene& scene, int ray_room, const Nearest& n, const dvec3& point) {
    if (!n.textured_face && n.triangle < 0) return n.base;
    return read_base_color(scene, ray_room, n, point);
}

}  // namespace impossible::trace
