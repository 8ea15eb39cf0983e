// The nearest surface of a cell along a ray (nearest.hpp): the room's own
// surfaces, the frame's dynamic objects placed in it, and the target rooms
// of its volume portals inside them.
#include "trace/nearest.hpp"

#include <span>

#include "trace/prism_faces.hpp"

namespace impossible::trace {

namespace {

// Runs `search`; where it kept a hit, marks the hit as `source`'s.
template <class Search>
void search_from(Nearest& nearest, const SurfaceSource& source, Search&& search) {
    const long kept = nearest.kept;
    search();
    if (nearest.kept != kept) nearest.source = source;
}

// The objects placed in a cell, each in its own coordinates (the ray moved
// there by from_cell; rigid, so t is the same) and filtered in the cell's:
// `region`'s volumes, the object's cuts and the clip plane. They come after
// the cell's static surfaces and lose a tie to them; `shown_in` is the room
// whose id they take, `tint` a volume's.
void nearest_placed(const Scene& scene, std::span<const PlacedObject> placed, const RayFilter& region, int shown_in,
                    const dvec3* tint, const dvec3& origin, const dvec3& dir, const ClipPlane& clip, Nearest& nearest) {
    for (const PlacedObject& p : placed) {
        const SceneObject& object = p.prop >= 0 ? scene.props[p.prop] : scene.hand;
        RayFilter filter = region;
        filter.placed = &p;
        ClipPlane own = clip;
        own.filter = &filter;
        const dvec3 o = dvec3(p.from_cell * dvec4(origin, 1.0));
        const dvec3 d = dmat3(p.from_cell) * dir;
        search_from(nearest, SurfaceSource{shown_in, &object, &p.rotation, tint},
                    [&] { nearest_prop(object, o, d, own, nearest); });
    }
}

// The target room of each volume of `room`, inside the volume only: its
// faces and props, and the objects placed in it, taking its id and the
// volume's tint. It has no portals (layout-format.md, "Volume portals").
void nearest_through_volumes(const Scene& scene, const FrameObjects* objects, const SceneRoom& room,
                             const dvec3& origin, const dvec3& dir, const dvec3& head, const ClipPlane& clip,
                             Nearest& nearest) {
    for (const SceneVolume& v : room.volumes) {
        RayFilter inside;
        inside.inside = &v;
        ClipPlane within = clip;
        within.filter = &inside;
        search_from(nearest, SurfaceSource{v.target, nullptr, nullptr, &v.tint},
                    [&] { nearest_static(scene, scene.rooms[v.target], origin, dir, head, within, nearest); });
        if (objects)
            nearest_placed(scene, objects->in_room(v.target), inside, v.target, &v.tint, origin, dir, clip, nearest);
    }
}

}  // namespace

void nearest_in_mixed_room(const Scene& scene, const FrameObjects* objects, int room_index, const dvec3& origin,
                           const dvec3& dir, const dvec3& head, const ClipPlane& clip, Nearest& nearest) {
    const SceneRoom& room = scene.rooms[room_index];
    nearest.found = false;
    nearest.source = SurfaceSource{};
    const std::span<const PlacedObject> placed =
        objects ? objects->in_room(room_index) : std::span<const PlacedObject>{};
    if (room.volumes.empty()) {
        // Exactly as in a room without objects, then the objects.
        nearest_static(scene, room, origin, dir, head, clip, nearest);
        nearest_placed(scene, placed, RayFilter{}, room_index, nullptr, origin, dir, clip, nearest);
        return;
    }
    // The room's own surfaces count only outside every volume.
    RayFilter outside;
    outside.outside = std::span<const SceneVolume>(room.volumes);
    ClipPlane hidden = clip;
    hidden.filter = &outside;
    nearest_static(scene, room, origin, dir, head, hidden, nearest);
    nearest_placed(scene, placed, outside, room_index, nullptr, origin, dir, clip, nearest);
    nearest_through_volumes(scene, objects, room, origin, dir, head, clip, nearest);
}

void nearest_prism_static(const Scene& scene, const SceneRoom& room, const dvec3& origin, const dvec3& dir,
                          const dvec3& head, const ClipPlane& clip, Nearest& nearest) {
    const PrismHit hit = hit_prism_faces(scene, room.prism, origin, dir, clip, limit_of(nearest));
    if (hit.face >= 0) {
        const PrismFace& f = room.prism.faces[static_cast<std::size_t>(hit.face)];
        if (nearest.offer(SurfaceHit{hit.t, f.normal}, hit.portal, f.surface.color, room.checker,
                          face_tie(scene, hit.portal, dir)) &&
            f.surface.texture)
            nearest.textured_face = &f.surface;
    }
    nearest_prop(room, origin, dir, clip, nearest);
    nearest_boxes(scene, room, origin, dir, head, clip, nearest);
}

void nearest_for_light(const Scene& scene, const FrameObjects* objects, int room_index, const dvec3& origin,
                       const dvec3& dir, const ClipPlane& clip, double t_limit, Nearest& nearest) {
    const SceneRoom& room = scene.rooms[room_index];
    // Seeded with the limit, so that every search below keeps only nearer hits.
    nearest.found = true;
    nearest.t = t_limit;
    nearest.portal = -1;
    nearest.source = SurfaceSource{};
    if (room.prism.faces.empty()) {
        for (const RoomFace& f : room.faces) {
            if (const std::optional<FaceHit> hit = hit_room_face(f, scene, origin, dir, clip, nearest.t))
                nearest.offer(SurfaceHit{hit->t, axis_normal(f.rect.axis, f.rect.sign)}, hit->portal, f.color, 0.0);
        }
    } else if (const PrismHit hit = hit_prism_faces(scene, room.prism, origin, dir, clip, nearest.t); hit.face >= 0) {
        const PrismFace& f = room.prism.faces[static_cast<std::size_t>(hit.face)];
        nearest.offer(SurfaceHit{hit.t, f.normal}, hit.portal, f.surface.color, 0.0);
    }
    nearest_prop(room, origin, dir, clip, nearest);
    for (int p : room.box_portals)
        nearest.offer(hit_portal_front(scene.portals[p], origin, dir, clip), p, dvec3(0.0), 0.0);
    if (objects)
        nearest_placed(scene, objects->in_room(room_index), RayFilter{}, room_index, nullptr, origin, dir, clip,
                       nearest);
    if (!(nearest.t < t_limit)) nearest.found = false;
}

dvec3 read_base_color(const Scene& scene, int ray_room, const Nearest& n, const dvec3& point) {
    if (n.textured_face) return room_face_color(*n.textured_face, point);
    {
        const SceneObject* object = n.source.object;
        const SceneRoom& room = scene.rooms[hit_room(n, ray_room)];
        const std::vector<PropTriangle>& triangles = object ? object->triangles : room.triangles;
        const std::vector<PropMaterial>& materials = object ? object->materials : room.materials;
        return dvec3(triangle_color(triangles[n.triangle], materials, n.barycentric));
    }
}

}  // namespace impossible::trace
