// The CPU reference ray tracer (cli.md `trace`): double precision, analytic
// intersections, rays followed through portals exactly as layout-format.md,
// "What a pixel shows", describes. It is the accuracy oracle for the OpenGL
// rasteriser and shares with it only the layout, src/math and the shading
// model (scene/shading.hpp). See docs/tracer.md.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/result.hpp"
#include "image/image.hpp"
#include "layout/layout.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"
#include "shading/shading.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::trace {

// Cell ids (layout-format.md, "Cell-id maps"); the fill's is shading::kFillId.
inline constexpr std::uint8_t kIdNothing = 0;

// What one ray shows. `color` is the whole pixel's, with every window's
// blend of its branches in it. The other fields describe the main path, the
// one the id comes from: through doors, mirrors (reflected) and windows
// (their through branch). That path ends on a surface, on nothing, at the
// recursion limit or the tree's budget of portal passes, or at a window
// whose through branch is cut by the weight rule (scene/shading.hpp,
// kMinBranchWeight: id 255, as at the limit).
struct TraceHit {
    int id = kIdNothing;     // 1 + room index, kIdNothing, or shading::kFillId
    int room = -1;           // the room the path ended in (-1 when nothing was hit)
    dvec3 color{0.0};        // linear colour, 0..1
    int portals_passed = 0;  // portals (doors, mirrors, windows) the path went through
    dvec3 point{0.0};        // the final hit, in the layout's coordinates (for the fill:
                             // the point on the portal the path could not pass)
    dvec3 normal{0.0};       // front-facing normal at `point`
    dvec3 origin{0.0};       // the final (possibly virtual) eye and direction
    dvec3 dir{0.0};
    int passes = 0;        // portal passes of the whole ray tree (RayLimits::max_passes)
    int budget_fills = 0;  // portals the tree shows as the fill because its passes were spent
};

// The bounds of one ray tree: portals on any one line of sight (a window's
// two branches each count it once), and portal passes in the whole tree
// (docs/bounded-work.md): every door, mirror and window branch followed
// counts one, and once max_passes are made every further portal shows the
// fill colour (id 255 on the id's path), as at the depth limit. The tree is
// followed depth first, a window's reflected branch before its through
// branch, so where the budget falls does not depend on threads or pixel order.
struct RayLimits {
    int max_depth = 8;
    int max_passes = math::kDefaultMaxPortalPasses;
    // Under "lighting": "lights": portals a light path may pass
    // (View::light_depth, --light-depth); -1: the layout's light_depth.
    int light_depth = -1;
    // View::exposure, EV: each surface's colour times 2^EV before its clamp
    // (docs/lighting.md, "Exposure"); none: the scene's (the layout's).
    std::optional<double> exposure{};
};

// A ray from an eye: where it starts, its direction (any length but not
// zero) and the head centre the eye belongs to, which decides whether the
// eye has a door box's inner faces (layout-format.md, "The portal box").
struct PixelRay {
    dvec3 origin{0.0};
    dvec3 dir{0.0};
    dvec3 head{0.0};
};

// Follows the ray from `start.origin` (an eye in room `room`) within
// `limits`, among the frame's dynamic objects (place_frame_objects: moving
// props at the frame's time, hands, props crossing doors). `room` must be a
// valid room index.
TraceHit trace_ray(const Scene& scene, const PixelRay& start, int room, const RayLimits& limits,
                   const FrameObjects& objects);
// The same from an eye at the head centre (origin), for tests and tools:
// such an eye has the inner faces of a door box only in front of its plane.
TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, const RayLimits& limits,
                   const FrameObjects& objects);
// The same among the objects at time 0 without hands (Scene::rest).
TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, const RayLimits& limits);
// The same with the default budget of passes.
TraceHit trace_ray(const Scene& scene, const dvec3& origin, const dvec3& dir, int room, int max_depth);

// The view (scene/view.hpp) and how the tracer computes it. The view's
// max_portal_passes is each ray tree's budget (RayLimits::max_passes).
struct TraceDesc : math::View {
    int threads = 0;  // 0: std::thread::hardware_concurrency()
    // Supersampling: 1 traces the pixel centre (exactly as before); 2, 4, 8
    // or 16 trace one ray per position of trace/sample_pattern.hpp and give
    // the pixel the mean of their colours taken as bytes, round(Σ byte / N),
    // as a multisample resolve averages 8-bit samples. The id is always the
    // centre ray's, so id maps do not depend on the count.
    int samples = 1;
};

// 0..1 → 0..255 as round(clamp(c, 0, 1) · 255).
std::uint8_t to_byte(double c);

// The ray of pixel (i, j) of an eye image (direction in the layout's
// coordinates, unit length): eye 0 is the left eye.
PixelRay pixel_ray(const TraceDesc& desc, int eye, int i, int j);

// What the budget of portal passes cut in a frame, summed over its ray trees
// (one per pixel sample); the same whatever the thread count.
struct TraceStats {
    long budget_rays = 0;   // ray trees that met a portal after their passes were spent
    long budget_fills = 0;  // portals those trees show as the fill because of it
};

// Traces every pixel of both eyes. Rows are split across threads; the image
// (and `stats`, where given) does not depend on the thread count. A bad room
// index, size, negative depth or budget, or a sample count with no pattern
// is an error (docs/choices.md, "Errors and results in the code"), as is a
// layout prepare_scene refuses.
Result<image::Image> trace_frame(const Scene& scene, const TraceDesc& desc, TraceStats* stats = nullptr);
Result<image::Image> trace_frame(const layout::Layout& layout, const TraceDesc& desc);

}  // namespace impossible::trace
