#include "trace/tracer.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include <glm/geometric.hpp>

#include "math/projection.hpp"
#include "scene/shading.hpp"
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

    void offer(const std::optional<SurfaceHit>& hit, int portal_index, const dvec3& color, double side) {
        if (!hit || (found && hit->t >= t)) return;
        found = true;
        t = hit->t;
        normal = hit->normal;
        portal = portal_index;
        base = color;
        checker = side;
    }
};

Nearest nearest_in_room(const Scene& scene, int room_index, const dvec3& origin, const dvec3& dir,
                        const ClipPlane& clip) {
    const SceneRoom& room = scene.rooms[room_index];
    Nearest nearest;
    for (const RoomFace& face : room.faces) {
        const std::optional<SurfaceHit> hit = hit_room_face(face, scene, origin, dir, clip);
        nearest.offer(hit, hit ? hit->portal : -1, face.color, room.checker);
    }
    for (const PropBox& box : room.boxes)
        nearest.offer(hit_prop_box(box, origin, dir, clip), -1, box.color, 0.0);
    for (const PropTriangle& tri : room.triangles)
        nearest.offer(hit_triangle(tri, origin, dir, clip), -1, tri.color, 0.0);
    for (int p : room.portals)
        nearest.offer(hit_portal_box(scene.portals[p], origin, dir, clip), p, dvec3(0.0), 0.0);
    return nearest;
}

}  // namespace

TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, int max_depth) {
    TraceHit hit;
    hit.origin = origin;
    hit.dir = dir;
    ClipPlane clip;  // none for the real eye
    for (;;) {
        const Nearest n = nearest_in_room(scene, room, hit.origin, hit.dir, clip);
        if (!n.found) {
            hit.color = scene::kBackgroundColor;
            return hit;  // id 0, room -1
        }
        hit.room = room;
        hit.point = hit.origin + n.t * hit.dir;
        hit.normal = n.normal;
        if (n.portal < 0) {
            hit.id = 1 + room;
            hit.color = scene::shade(n.base, n.normal, hit.point, n.checker);
            return hit;
        }
        if (hit.portals_passed >= max_depth) {
            hit.id = kIdDepthLimit;
            hit.color = scene::kPortalFillColor;
            return hit;
        }
        // Step 2: continue from the virtual eye in the target room.
        const ScenePortal& a = scene.portals[n.portal];
        const ScenePortal& b = scene.portals[a.target];
        hit.origin = dvec3(a.transfer * dvec4(hit.origin, 1.0));
        hit.dir = dmat3(a.transfer) * hit.dir;
        room = b.room;
        ++hit.portals_passed;
        clip.active = math::signed_distance(b.rect, hit.origin) < 0.0;
        clip.plane = math::portal_plane(b.rect);
        clip.tolerance = b.clip_tolerance;
    }
}

std::uint8_t to_byte(double c) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

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
PixelRay eye_point_ray(const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye, double x,
                       double y) {
    const dvec3 dir_eye = math::image_point_ray_eye(frustum, desc.eye_width, desc.eye_height, x, y);
    return {eye.position, glm::normalize(eye.rotation * dir_eye)};
}

// One pixel's id and bytes: the centre ray's id; with several samples, the
// mean of the samples' bytes rounded to nearest (half up), like a resolve.
void trace_pixel(const Scene& scene, const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye,
                 int i, int j, std::uint8_t* id, std::uint8_t* rgb) {
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

image::Image trace_frame(const Scene& scene, const TraceDesc& desc) {
    if (desc.room < 0 || desc.room >= static_cast<int>(scene.rooms.size()))
        throw std::invalid_argument("trace: room index " + std::to_string(desc.room) + " is out of range");
    if (desc.eye_width <= 0 || desc.eye_height <= 0 || desc.eye_width > 1 << 15 || desc.eye_height > 1 << 15)
        throw std::invalid_argument("trace: bad eye image size");
    if (desc.max_depth < 0) throw std::invalid_argument("trace: max_depth is negative");
    if (sample_pattern(desc.samples).empty())
        throw std::invalid_argument("trace: no sample pattern for " + std::to_string(desc.samples) + " samples");

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

image::Image trace_frame(const layout::Layout& layout, const TraceDesc& desc) {
    return trace_frame(prepare_scene(layout), desc);
}

}  // namespace impossible::trace
