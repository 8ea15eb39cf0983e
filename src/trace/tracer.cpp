#include "trace/tracer.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <system_error>
#include <thread>

#include <glm/geometric.hpp>

#include "math/projection.hpp"
#include "shading/shading.hpp"
#include "trace/bvh.hpp"
#include "trace/intersect.hpp"
#include "trace/sample_pattern.hpp"

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

Nearest nearest_in_room(const Scene& scene, int room_index, const dvec3& origin, const dvec3& dir,
                        const ClipPlane& clip) {
    const SceneRoom& room = scene.rooms[room_index];
    Nearest nearest;
    for (const RoomFace& face : room.faces) {
        const std::optional<SurfaceHit> hit = hit_room_face(face, scene, origin, dir, clip);
        if (nearest.offer(hit, hit ? hit->portal : -1, face.color, room.checker) && face.texture)
            nearest.textured_face = &face;
    }
    // The boxes after the faces, losing a tie to them; the first box of those
    // at the smallest t (bvh.hpp).
    const double box_limit = nearest.found ? nearest.t : std::numeric_limits<double>::infinity();
    const BoxHit box = room.box_bvh.nodes.empty() ? nearest_box_scan(room.boxes, origin, dir, clip, box_limit)
                                                  : nearest_box(room.box_bvh, room.boxes, origin, dir, clip, box_limit);
    if (box.hit) nearest.offer(box.hit, -1, room.boxes[box.index].color, 0.0);
    // The triangles come after the faces and boxes and lose a tie to them;
    // among themselves the first in the list wins one (bvh.hpp).
    const double t_limit = nearest.found ? nearest.t : std::numeric_limits<double>::infinity();
    const TriangleHit tri =
        room.bvh.nodes.empty() ? nearest_triangle_scan(room.triangles, room.materials, origin, dir, clip, t_limit)
                               : nearest_triangle(room.bvh, room.triangles, room.materials, origin, dir, clip, t_limit);
    if (tri.hit && nearest.offer(tri.hit, -1, room.triangles[tri.index].color, 0.0)) {
        nearest.triangle = tri.index;
        nearest.barycentric = tri.hit->barycentric;
    }
    for (int p : room.portals) nearest.offer(hit_portal_box(scene.portals[p], origin, dir, clip), p, dvec3(0.0), 0.0);
    return nearest;
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
    ray.clip.active = math::signed_distance(b.rect, ray.origin) < 0.0;
    ray.clip.plane = math::portal_plane(b.rect);
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
    r.clip.plane = math::portal_plane(p.rect);
    r.clip.tolerance = p.clip_tolerance;
    return r;
}

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

dvec3 follow(const Scene& scene, Ray ray, int max_depth, TraceHit* main);

// Step 5 at window P, hit at `point`: the reflected branch is followed by a
// recursive call where the through branch goes on too; where the through
// branch is cut by weight, the main path ends (id 255) and the loop follows
// the reflected branch. False where both are cut: the path's colour is then
// path.done.
bool window_step(const Scene& scene, const ScenePortal& p, const dvec3& point, const dvec3& normal, int max_depth,
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
        if (back_on) path.done += back_factor * follow(scene, back, max_depth, nullptr);
        pass_through(scene, p, ray);
        ray.weight = through_weight;
        path.factor = through_factor;
        return true;
    }
    // The through branch is cut: the main path ends here, as at the limit.
    path.end_main(shading::kFillId, ray.room, point, normal);
    path.done += through_factor * shading::kPortalFillColor;
    if (!back_on) return false;
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
dvec3 follow(const Scene& scene, Ray ray, int max_depth, TraceHit* main) {
    PathState path{ray, dvec3(0.0), dvec3(1.0), main};
    for (;;) {
        const Ray& now = path.ray;
        const Nearest n = nearest_in_room(scene, now.room, now.origin, now.dir, now.clip);
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
        if (now.portals_passed >= max_depth) {  // step 3, for every kind
            path.end_main(shading::kFillId, now.room, point, n.normal);
            return path.done + path.factor * shading::kPortalFillColor;
        }
        const ScenePortal& p = scene.portals[n.portal];
        switch (p.kind) {
            case layout::PortalKind::Door: pass_through(scene, p, path.ray); break;
            case layout::PortalKind::Mirror: {  // step 4; never cut by weight
                const double weight = now.weight * shading::max_channel(p.tint);
                path.ray = reflected(p, now);
                path.ray.weight = weight;
                path.factor *= p.tint;
                break;
            }
            case layout::PortalKind::Window:
                if (!window_step(scene, p, point, n.normal, max_depth, path)) return path.done;
                break;
        }
    }
}

}  // namespace

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, int max_depth) {
    TraceHit hit;
    Ray ray;
    ray.origin = origin;
    ray.dir = dir;
    ray.room = room;
    hit.color = follow(scene, ray, max_depth, &hit);
    return hit;
}

std::uint8_t to_byte(double c) { return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

namespace {

math::Frustum frustum_of(const TraceDesc& desc) {
    math::Frustum f;
    f.fov_y_deg = desc.fov_y_deg;
    f.aspect = static_cast<double>(desc.eye_width) / desc.eye_height;
    return f;
}

PixelRay eye_pixel_ray(const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye, int i, int j) {
    const dvec3 dir_eye = math::pixel_ray_eye(frustum, desc.eye_width, desc.eye_height, i, j);
    return {eye.position, glm::normalize(eye.rotation * dir_eye)};
}

// The ray through a point of an eye's image (pixel units, rows from the top).
PixelRay eye_point_ray(const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye, double x, double y) {
    const dvec3 dir_eye = math::image_point_ray_eye(frustum, desc.eye_width, desc.eye_height, x, y);
    return {eye.position, glm::normalize(eye.rotation * dir_eye)};
}

// One pixel's id and bytes: the centre ray's id; with several samples, the
// mean of the samples' bytes rounded to nearest (half up), like a resolve.
void trace_pixel(const Scene& scene, const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye, int i,
                 int j, std::uint8_t* id, std::uint8_t* rgb) {
    const PixelRay centre = eye_pixel_ray(desc, frustum, eye, i, j);
    const TraceHit hit = trace_ray(scene, centre.origin, centre.dir, desc.room, desc.max_depth);
    *id = static_cast<std::uint8_t>(hit.id);
    if (desc.samples <= 1) {
        for (int c = 0; c < 3; ++c) rgb[c] = to_byte(hit.color[c]);
        return;
    }
    int sum[3] = {0, 0, 0};
    for (const SamplePosition& s : sample_pattern(desc.samples)) {
        const PixelRay ray = eye_point_ray(desc, frustum, eye, i + s.x, j + 1.0 - s.y);
        const TraceHit sample = trace_ray(scene, ray.origin, ray.dir, desc.room, desc.max_depth);
        for (int c = 0; c < 3; ++c) sum[c] += to_byte(sample.color[c]);
    }
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<std::uint8_t>((2 * sum[c] + desc.samples) / (2 * desc.samples));
}

}  // namespace

PixelRay pixel_ray(const TraceDesc& desc, int eye, int i, int j) {
    return eye_pixel_ray(desc, frustum_of(desc), math::eyes_of(desc.head, desc.ipd)[eye], i, j);
}

Result<image::Image> trace_frame(const Scene& scene, const TraceDesc& desc) {
    if (desc.room < 0 || desc.room >= static_cast<int>(scene.rooms.size()))
        return Error{"trace: room index " + std::to_string(desc.room) + " is out of range"};
    if (desc.eye_width <= 0 || desc.eye_height <= 0 || desc.eye_width > 1 << 15 || desc.eye_height > 1 << 15)
        return Error{"trace: bad eye image size"};
    if (desc.max_depth < 0) return Error{"trace: max_depth is negative"};
    if (sample_pattern(desc.samples).empty())
        return Error{"trace: no sample pattern for " + std::to_string(desc.samples) + " samples"};

    image::Image image;
    image.width = 2 * desc.eye_width;
    image.height = desc.eye_height;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    image.rgb.assign(3 * pixels, 0);
    image.ids.assign(pixels, 0);

    const std::array<math::Eye, 2> eyes = math::eyes_of(desc.head, desc.ipd);
    const math::Frustum frustum = frustum_of(desc);
    auto trace_row = [&](int j) {
        for (int eye = 0; eye < 2; ++eye) {
            for (int i = 0; i < desc.eye_width; ++i) {
                const size_t at = static_cast<size_t>(j) * image.width + eye * desc.eye_width + i;
                trace_pixel(scene, desc, frustum, eyes[eye], i, j, &image.ids[at], &image.rgb[3 * at]);
            }
        }
    };
    // Threads take rows from a shared counter. Each pixel depends only on its
    // own ray and is written by one thread, so the image is the same for any
    // thread count (and if a thread cannot be started, the others do its rows).
    std::atomic<int> next_row{0};
    auto worker = [&] {
        for (int j = next_row++; j < desc.eye_height; j = next_row++) trace_row(j);
    };
    int threads = desc.threads > 0 ? desc.threads : static_cast<int>(std::thread::hardware_concurrency());
    threads = std::clamp(threads, 1, desc.eye_height);
    std::vector<std::thread> helpers;
    for (int k = 1; k < threads; ++k) {
        try {
            helpers.emplace_back(worker);
        } catch (const std::system_error&) {
            break;
        }
    }
    worker();
    for (std::thread& h : helpers) h.join();
    return image;
}

Result<image::Image> trace_frame(const layout::Layout& layout, const TraceDesc& desc) {
    const Result<Scene> scene = prepare_scene(layout);
    if (!scene) return scene;
    return trace_frame(*scene, desc);
}

}  // namespace impossible::trace
