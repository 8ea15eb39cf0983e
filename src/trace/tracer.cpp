// The tracer's rays (tracer.hpp, trace_ray): "What a pixel shows"
// (layout-format.md) step by step, through portals, mirrors and windows.
#include "trace/tracer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/lighting.hpp"
#include "shading/shading.hpp"
#include "trace/intersect.hpp"
#include "trace/light_paths.hpp"
#include "trace/nearest.hpp"

namespace impossible::trace {

namespace {

// One line of sight being followed (the eye's, or a window's branch): the
// (possibly virtual) eye, its head centre (carried with it: it decides
// which door boxes have inner faces) and direction, the room, the clipping plane, the
// portals passed since the real eye and the view's weight (the product of
// the largest channel of every factor multiplied into its colour since the
// eye; scene/shading.hpp, kMinBranchWeight).
struct Ray {
    dvec3 origin{0.0};
    dvec3 head{0.0};
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
    ray.head = dvec3(a.transfer * dvec4(ray.head, 1.0));
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
    r.head = dvec3(p.reflection * dvec4(ray.head, 1.0));
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
    int budget_fills = 0;                   // portals shown as the fill because the passes were spent
    const FrameObjects* objects = nullptr;  // the frame's dynamic objects
    int light_depth = 0;                    // under Scene::lit: portals a light path may pass
    double exposure = 1.0;                  // 2^EV: each surface's colour times it before its clamp
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

// The surface `n` (not a portal) hit at `point` ends the path: its shaded
// colour, times a volume's tint where it is a volume's target room's
// (docs/tracer.md, "Volume portals"), with its room's id. Under
// "lighting": "lights" the colour is lit by its room's ambient and the light
// paths to the point (layout-format.md, "Lights"; light_paths.hpp).
dvec3 surface_color(const Scene& scene, const Nearest& n, const dvec3& point, const Tree& tree, PathState& path) {
    const int now = path.ray.room;
    const int room = hit_room(n, now);
    const dvec3 normal = world_normal(n);
    path.end_main(1 + room, room, point, normal);
    const dvec3 base = base_color(scene, now, n, point);
    dvec3 color;
    if (scene.lit) {
        const double dark = shading::checker_dark(point, normal, n.checker) ? shading::kCheckerDark : 1.0;
        const dvec3 sum = light_sum(scene, tree.objects, LitPoint{room, point, normal}, tree.light_depth);
        color = shading::lit_color(base, dark, scene.rooms[room].ambient, sum, tree.exposure);
    } else {
        color = shading::exposed(shading::shade(base, normal, point, n.checker), tree.exposure);
    }
    return n.source.tint ? color * *n.source.tint : color;
}

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
        nearest_in_room(scene, tree.objects, now.room, now.origin, now.dir, now.head, now.clip, n);
        if (!n.found) {
            path.end_main(kIdNothing, -1, dvec3(0.0), dvec3(0.0));
            return path.done + path.factor * shading::kBackgroundColor;
        }
        const dvec3 point = now.origin + n.t * now.dir;
        if (n.portal < 0) return path.done + path.factor * surface_color(scene, n, point, tree, path);
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

TraceHit trace_ray(const Scene& scene, const PixelRay& start, int room, const RayLimits& limits,
                   const FrameObjects& objects) {
    TraceHit hit;
    Ray ray;
    ray.origin = start.origin;
    ray.head = start.head;
    ray.dir = start.dir;
    ray.room = room;
    Tree tree{limits.max_depth, limits.max_passes};
    tree.objects = objects.placed.empty() ? nullptr : &objects;
    tree.light_depth =
        limits.light_depth >= 0 ? std::min(limits.light_depth, scene.max_light_depth) : scene.light_depth;
    tree.exposure = std::exp2(limits.exposure.value_or(scene.exposure));
    hit.color = follow(scene, ray, tree, &hit);
    hit.passes = tree.passes;
    hit.budget_fills = tree.budget_fills;
    return hit;
}

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, const RayLimits& limits,
                   const FrameObjects& objects) {
    return trace_ray(scene, PixelRay{origin, dir, origin}, room, limits, objects);
}

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, const RayLimits& limits) {
    return trace_ray(scene, origin, dir, room, limits, scene.rest);
}

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, int max_depth) {
    RayLimits limits;
    limits.max_depth = max_depth;
    return trace_ray(scene, origin, dir, room, limits);
}

}  // namespace impossible::trace
