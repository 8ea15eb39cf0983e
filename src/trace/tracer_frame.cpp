// The tracer's frames (tracer.hpp, trace_frame): a ray per pixel (or per
// sample) through trace_ray, rows shared out between threads.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>
#include <thread>

#include <glm/geometric.hpp>

#include "base/format.hpp"
#include "math/eyes.hpp"
#include "math/hidden_area.hpp"
#include "math/projection.hpp"
#include "math/view_limits.hpp"
#include "shading/shading.hpp"
#include "trace/sample_pattern.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {

std::uint8_t to_byte(double c) { return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

namespace {

// Eye `eye`'s frustum: symmetric, or the eye's optics (math/view.hpp).
math::Frustum frustum_of(const TraceDesc& desc, int eye) { return math::eye_frustum(desc, eye); }

// Each eye's hidden pixels (math/hidden_area.hpp), rows from the top; empty
// for an eye with no hidden area.
std::array<std::vector<std::uint8_t>, 2> hidden_masks(const TraceDesc& desc) {
    std::array<std::vector<std::uint8_t>, 2> masks;
    if (!desc.eye_optics) return masks;
    for (int e = 0; e < 2; ++e) {
        const math::Polygon2& visible = (*desc.eye_optics)[static_cast<size_t>(e)].visible_area;
        if (!visible.empty()) masks[e] = math::hidden_pixels(visible, desc.eye_width, desc.eye_height);
    }
    return masks;
}

PixelRay eye_pixel_ray(const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye, int i, int j) {
    const dvec3 dir_eye = math::pixel_ray_eye(frustum, desc.eye_width, desc.eye_height, i, j);
    return {eye.position, glm::normalize(eye.rotation * dir_eye), eye.head};
}

// The ray through a point of an eye's image (pixel units, rows from the top).
PixelRay eye_point_ray(const TraceDesc& desc, const math::Frustum& frustum, const math::Eye& eye, double x, double y) {
    const dvec3 dir_eye = math::image_point_ray_eye(frustum, desc.eye_width, desc.eye_height, x, y);
    return {eye.position, glm::normalize(eye.rotation * dir_eye), eye.head};
}

// What every ray of a frame shares: the scene, the view, and the view's
// dynamic objects, placed once (place_frame_objects).
struct FrameRays {
    const Scene& scene;
    const TraceDesc& desc;
    FrameObjects objects;
};

// One ray tree of a frame, its budget's cuts added to `stats`.
TraceHit trace_counted(const FrameRays& frame, const PixelRay& ray, TraceStats& stats) {
    const TraceDesc& desc = frame.desc;
    const RayLimits limits{desc.max_depth, desc.max_portal_passes, desc.light_depth.value_or(-1), desc.exposure};
    const TraceHit hit = trace_ray(frame.scene, ray, desc.room, limits, frame.objects);
    stats.budget_rays += hit.budget_fills > 0 ? 1 : 0;
    stats.budget_fills += hit.budget_fills;
    return hit;
}

// One pixel's id and bytes: the centre ray's id; with several samples, the
// mean of the samples' bytes rounded to nearest (half up), like a resolve.
void trace_pixel(const FrameRays& frame, const math::Frustum& frustum, const math::Eye& eye, int i, int j,
                 std::uint8_t* id, std::uint8_t* rgb, TraceStats& stats) {
    const TraceDesc& desc = frame.desc;
    const TraceHit hit = trace_counted(frame, eye_pixel_ray(desc, frustum, eye, i, j), stats);
    *id = static_cast<std::uint8_t>(hit.id);
    if (desc.samples <= 1) {
        for (int c = 0; c < 3; ++c) rgb[c] = to_byte(hit.color[c]);
        return;
    }
    int sum[3] = {0, 0, 0};
    for (const SamplePosition& s : sample_pattern(desc.samples)) {
        const PixelRay ray = eye_point_ray(desc, frustum, eye, i + s.x, j + 1.0 - s.y);
        const TraceHit sample = trace_counted(frame, ray, stats);
        for (int c = 0; c < 3; ++c) sum[c] += to_byte(sample.color[c]);
    }
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<std::uint8_t>((2 * sum[c] + desc.samples) / (2 * desc.samples));
}

std::optional<Error> check_desc(const Scene& scene, const TraceDesc& desc) {
    if (desc.room < 0 || desc.room >= static_cast<int>(scene.rooms.size()))
        return Error{"trace: room index " + std::to_string(desc.room) + " is out of range"};
    if (desc.eye_width <= 0 || desc.eye_height <= 0 || desc.eye_width > 1 << 15 || desc.eye_height > 1 << 15)
        return Error{"trace: bad eye image size"};
    if (desc.max_depth < 0) return Error{"trace: max_depth is negative"};
    if (desc.max_portal_passes < 0) return Error{"trace: max_portal_passes is negative"};
    if (desc.light_depth && (*desc.light_depth < 0 || *desc.light_depth > layout::kMaxLightDepth))
        return Error{"trace: light_depth " + std::to_string(*desc.light_depth) + " is not in 0.." +
                     std::to_string(layout::kMaxLightDepth)};
    if (desc.exposure && !math::limits::kExposure.contains(*desc.exposure))
        return Error{"trace: exposure " + format_number(*desc.exposure) + " is not in " +
                     math::limits::range_text(math::limits::kExposure)};
    if (sample_pattern(desc.samples).empty())
        return Error{"trace: no sample pattern for " + std::to_string(desc.samples) + " samples"};
    return std::nullopt;
}

}  // namespace

PixelRay pixel_ray(const TraceDesc& desc, int eye, int i, int j) {
    return eye_pixel_ray(desc, frustum_of(desc, eye), math::eyes_of(desc)[eye], i, j);
}

Result<image::Image> trace_frame(const Scene& scene, const TraceDesc& desc, TraceStats* stats) {
    if (const std::optional<Error> error = check_desc(scene, desc)) return *error;

    image::Image image;
    image.width = 2 * desc.eye_width;
    image.height = desc.eye_height;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    image.rgb.assign(3 * pixels, 0);
    image.ids.assign(pixels, 0);

    const std::array<math::Eye, 2> eyes = math::eyes_of(desc);
    const std::array<math::Frustum, 2> frusta = {frustum_of(desc, 0), frustum_of(desc, 1)};
    // A hidden pixel keeps the background: black, id 0 (docs/headsets.md).
    const std::array<std::vector<std::uint8_t>, 2> hidden = hidden_masks(desc);
    const FrameRays frame{scene, desc, place_frame_objects(scene, desc)};
    auto trace_row = [&](int j, TraceStats& counted) {
        for (int eye = 0; eye < 2; ++eye) {
            const std::vector<std::uint8_t>& mask = hidden[static_cast<size_t>(eye)];
            for (int i = 0; i < desc.eye_width; ++i) {
                const size_t at = static_cast<size_t>(j) * image.width + eye * desc.eye_width + i;
                if (!mask.empty() && mask[static_cast<size_t>(j) * desc.eye_width + i]) continue;
                trace_pixel(frame, frusta[eye], eyes[eye], i, j, &image.ids[at], &image.rgb[3 * at], counted);
            }
        }
    };
    // Threads take rows from a shared counter. Each pixel depends only on its
    // own ray and is written by one thread, so the image is the same for any
    // thread count (and if a thread cannot be started, the others do its rows).
    // Each thread counts the budget's cuts apart; the sums do not depend on
    // which thread traced which row.
    std::atomic<int> next_row{0};
    std::atomic<long> budget_rays{0}, budget_fills{0};
    auto worker = [&] {
        TraceStats counted;
        for (int j = next_row++; j < desc.eye_height; j = next_row++) trace_row(j, counted);
        budget_rays += counted.budget_rays;
        budget_fills += counted.budget_fills;
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
    if (stats) *stats = {budget_rays.load(), budget_fills.load()};
    return image;
}

Result<image::Image> trace_frame(const layout::Layout& layout, const TraceDesc& desc) {
    const Result<Scene> scene = prepare_scene(layout);
    if (!scene) return scene;
    return trace_frame(*scene, desc);
}

}  // namespace impossible::trace
