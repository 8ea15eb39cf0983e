// The tracer's rays (tracer.hpp, trace_ray): "What a pixel shows"
// (layout-format.md) step by step, through portals, mirrors and windows.
#include "trace/tracer.hpp"

#include <limits>

#include <glm/geometric.hpp>

#include "shading/shading.hpp"
#include "trace/bvh.hpp"
#include "trace/intersect.hpp"

namespace impossible::trace {

namespace {

// The nearest front-facing surface of one room along a ray (step 1 of "What a
// pixel shows"): what it is and how to shade it.
struct Nearest {
    bool found = false;
    double t = 0.0;
    dvec3 normal{0.0};
    int portal = -1;  // ≥ 0: a face of this portal's box
    dvec3 base{0.0};  // otherwise: the surface's base colour and checker side
    double checker = 0.0;
    // Where the base colour is read at the hit point instead (base_color):
    const RoomFace* textured_face = nullptr;  // a room face with a texture
    int triangle = -1;                        // a glTF triangle (its index in the room)
    glm::dvec2 barycentric{0.0};              // … and where it was hit

    // Whether the hit is nearer than the one kept, and so now kept.
    bool offer(const std::optional<SurfaceHit>& hit, int portal_index, const dvec3& color, double side) {
        if (!hit || (found && hit->t >= t)) return false;
        found = true;
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

// Finds it into `nearest`, reused from ray to ray: each field a hit sets is
// read only where that hit was kept (offer), so only `found` is reset, and
// the struct is not cleared at every portal a ray passes.
void nearest_in_room(const Scene& scene, int room_index, const dvec3& origin, const dvec3& dir, const ClipPlane& clip,
                     Nearest& nearest) {
    const SceneRoom& room = scene.rooms[room_index];
    nearest.found = false;
    // The faces first, the first in order at the smallest t: a face no
    // nearer than the nearest so far would lose to it.
    int face = -1;
    FaceHit face_hit{std::numeric_limits<double>::infinity(), -1};
    for (int f = 0; f < layout::kFaceCount; ++f) {
        if (const std::optional<FaceHit> hit = hit_room_face(room.faces[f], scene, origin, dir, clip, face_hit.t)) {
            face = f;
            face_hit = *hit;
        }
    }
    if (face >= 0) {
        const RoomFace& f = room.faces[face];
        nearest.offer(SurfaceHit{face_hit.t, axis_normal(f.rect.axis, f.rect.sign)}, face_hit.portal, f.color,
                      room.checker);
        if (f.texture) nearest.textured_face = &f;
    }
    // The boxes after the faces, losing a tie to them; the first box of those
    // at the smallest t (bvh.hpp).
    if (!room.boxes.empty()) {
        const double limit = nearest.found ? nearest.t : std::numeric_limits<double>::infinity();
        const BoxHit box = room.box_bvh.nodes.empty() ? nearest_box_scan(room.boxes, origin, dir, clip, limit)
                                                      : nearest_box(room.box_bvh, room.boxes, origin, dir, clip, limit);
        if (box.hit) nearest.offer(box.hit, -1, room.boxes[box.index].color, 0.0);
    }
    // The triangles come after the faces and boxes and lose a tie to them;
    // among themselves the first in the list wins one (bvh.hpp).
    if (!room.triangles.empty()) {
        const double limit = nearest.found ? nearest.t : std::numeric_limits<double>::infinity();
        const TriangleHit tri =
            room.bvh.nodes.empty()
                ? nearest_triangle_scan(room.triangles, room.materials, origin, dir, clip, limit)
                : nearest_triangle(room.bvh, room.triangles, room.materials, origin, dir, clip, limit);
        if (tri.hit && nearest.offer(tri.hit, -1, room.triangles[tri.index].color, 0.0)) {
            nearest.triangle = tri.index;
            nearest.barycentric = tri.hit->barycentric;
        }
    }
    for (int p : room.box_portals)
        nearest.offer(hit_portal_box(scene.portals[p], origin, dir, clip), p, dvec3(0.0), 0.0);
}

// The base colour of the surface `n` found in room `room_index` (not a
// portal), at its hit point: a textured face's or a triangle's read there
// (docs/tracer.md, "Materials and textures"), any other's as offered.
dvec3 base_color(const Scene& scene, int room_index, const Nearest& n, const dvec3& point) {
    if (n.textured_face) return room_face_color(*n.textured_face, point);
    if (n.triangle >= 0) {
        const SceneRoom& room = scene.rooms[room_index];
        return dvec3(triangle_color(room.triangles[n.triangle], room.materials, n.barycentric));
    }
    return n.base;
}

// One line of sight being followed (the eye's, or a window's branch): the
// (possibly virtual) eye and direction, the room, the clipping plane, the
// portals passed since the real eye and the view's weight (the product of
// the largest channel of every factor multiplied into its colour since the
// eye; scene/shading.hpp, kMinBranchWeight).
struct Ray {
    dvec3 origin{0.0};
    dvec3 dir{0.0};
    int room = -1;
    ClipPlane clip;  // none for the real eye
    int portals_passed = 0;
    double weight = 1.0;
};

// Step 2: through door (or window) A into its target B's room, from the
// virtual eye; B's plane clips when the virtual eye is behind it.
void pass_through(const Scene& scene, const ScenePortal& a, Ray& ray) {
    const ScenePortal& b = scene.portals[a.target];
    ray.origin = dvec3(a.transfer * dvec4(ray.origin, 1.0));
    ray.dir = dmat3(a.transfer) * ray.dir;
    ray.room = b.room;
    ++ray.portals_passed;
    // math::signed_distance(b.rect, ray.origin) < 0, written out to inline.
    ray.clip.active = glm::dot(ray.origin - b.rect.center, b.rect.normal) < 0.0;
    ray.clip.plane = b.plane;
    ray.clip.tolerance = b.clip_tolerance;
}

// Step 4: reflected in mirror (or window) P, in the same room, clipped by
// P's plane, which the virtual eye is always behind. The weight is the
// caller's to set.
Ray reflected(const ScenePortal& p, const Ray& ray) {
    Ray r = ray;
    r.origin = dvec3(p.reflection * dvec4(ray.origin, 1.0));
    r.dir = dmat3(p.reflection) * ray.dir;
    ++r.portals_passed;
    r.clip.active = true;
    r.clip.plane = p.plane;
    r.clip.tolerance = p.clip_tolerance;
    return r;
}

// One ray tree (a pixel sample's): its limits, and the portal passes it has
// made so far (docs/bounded-work.md). Every door, mirror and window branch
// followed counts one, in the order the tree is followed (a window's
// reflected branch first, as the rasteriser draws it); once `passes`
// reaches the budget, every further portal shows the fill colour, as at the
// depth limit.
struct Tree {
    int max_depth = 0;
    int max_passes = 0;
    int passes = 0;
    int budget_fills = 0;  // portals shown as the fill because the passes were spent
};

// The state of follow's loop along one path: the ray, the colour of the
// branches finished so far (each times its factor), the factor that
// multiplies what the ray shows from here on, and, while the path is the
// main one (the id's), where its end is written.
struct PathState {
    Ray ray;
    dvec3 done{0.0};
    dvec3 factor{1.0};
    TraceHit* main = nullptr;

    // Writes the main path's end (all of TraceHit but the colour), once.
    void end_main(int id, int room, const dvec3& point, const dvec3& normal) {
        if (!main) return;
        main->id = id;
        main->room = room;
        main->portals_passed = ray.portals_passed;
        main->point = point;
        main->normal = normal;
        main->origin = ray.origin;
        main->dir = ray.dir;
        main = nullptr;
    }
};

dvec3 follow(const Scene& scene, Ray ray, Tree& tree, TraceHit* main);

// Step 5 at window P, hit at `point`: the reflected branch is followed by a
// recursive call where the through branch goes on too; where the through
// branch is cut by weight, the main path ends (id 255) and the loop follows
// the reflected branch. False where both are cut: the path's colour is then
// path.done.
bool window_step(const Scene& scene, const ScenePortal& p, const dvec3& point, const dvec3& normal, Tree& tree,
                 PathState& path) {
    Ray& ray = path.ray;
    const double r = p.reflectance;
    Ray back = reflected(p, ray);
    back.weight = ray.weight * r;
    const dvec3 back_factor = path.factor * r;
    const double through_weight = ray.weight * ((1.0 - r) * shading::max_channel(p.tint));
    const dvec3 through_factor = path.factor * ((1.0 - r) * p.tint);
    const bool back_on = back.weight >= shading::kMinBranchWeight;
    const bool through_on = through_weight >= shading::kMinBranchWeight;
    if (!back_on) path.done += back_factor * shading::kPortalFillColor;
    if (through_on) {
        if (back_on) {
            ++tree.passes;
            path.done += back_factor * follow(scene, back, tree, nullptr);
        }
        ++tree.passes;
        pass_through(scene, p, ray);
        ray.weight = through_weight;
        path.factor = through_factor;
        return true;
    }
    // The through branch is cut: the main path ends here, as at the limit.
    path.end_main(shading::kFillId, ray.room, point, normal);
    path.done += through_factor * shading::kPortalFillColor;
    if (!back_on) return false;
    ++tree.passes;
    ray = back;
    path.factor = back_factor;
    return true;
}

// Follows `ray` ("What a pixel shows", steps 1-5) and returns the colour it
// shows. The loop follows one path: through doors, mirrors and windows'
// through branches. A window's reflected branch is followed by a recursive
// call where the through branch goes on too, and by this loop where the
// through branch is cut. Doors and mirrors never branch, so a ray that meets
// no window neither allocates nor recurses. The nesting is at most max_depth
// (each level passes a portal), and below 256 whatever max_depth is: a call
// is nested only where both weights, w · r and w · (1 - r) · max(tint), are
// at least kMinBranchWeight = 1/256, and its weight is at most
// w · r = w - w · (1 - r) ≤ w - 1/256.
//
// While `main` is set, the loop's path is the main one (the id's) and its end
// is written there (all of TraceHit but the colour); it ends where that path
// ends, or at a window whose through branch is cut by weight (id 255).
dvec3 follow(const Scene& scene, Ray ray, Tree& tree, TraceHit* main) {
    PathState path{ray, dvec3(0.0), dvec3(1.0), main};
    Nearest n;
    for (;;) {
        const Ray& now = path.ray;
        nearest_in_room(scene, now.room, now.origin, now.dir, now.clip, n);
        if (!n.found) {
            path.end_main(kIdNothing, -1, dvec3(0.0), dvec3(0.0));
            return path.done + path.factor * shading::kBackgroundColor;
        }
        const dvec3 point = now.origin + n.t * now.dir;
        if (n.portal < 0) {
            path.end_main(1 + now.room, now.room, point, n.normal);
            return path.done +
                   path.factor * shading::shade(base_color(scene, now.room, n, point), n.normal, point, n.checker);
        }
        // Step 3, for every kind; then the tree's budget, counted as a
        // budget fill only where the depth allows more.
        const bool deep = now.portals_passed >= tree.max_depth;
        if (deep || tree.passes >= tree.max_passes) {
            tree.budget_fills += deep ? 0 : 1;
            path.end_main(shading::kFillId, now.room, point, n.normal);
            return path.done + path.factor * shading::kPortalFillColor;
        }
        const ScenePortal& p = scene.portals[n.portal];
        switch (p.kind) {
            case layout::PortalKind::Door:
                ++tree.passes;
                pass_through(scene, p, path.ray);
                break;
            case layout::PortalKind::Mirror: {  // step 4; never cut by weight
                ++tree.passes;
                const double weight = now.weight * shading::max_channel(p.tint);
                path.ray = reflected(p, now);
                path.ray.weight = weight;
                path.factor *= p.tint;
                break;
            }
            case layout::PortalKind::Window:
                if (!window_step(scene, p, point, n.normal, tree, path)) return path.done;
                break;
        }
    }
}

}  // namespace

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, const RayLimits& limits) {
    TraceHit hit;
    Ray ray;
    ray.origin = origin;
    ray.dir = dir;
    ray.room = room;
    Tree tree{limits.max_depth, limits.max_passes};
    hit.color = follow(scene, ray, tree, &hit);
    hit.passes = tree.passes;
    hit.budget_fills = tree.budget_fills;
    return hit;
}

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, int max_depth) {
    return trace_ray(scene, origin, dir, room, RayLimits{max_depth});
}

}  // namespace impossible::trace
