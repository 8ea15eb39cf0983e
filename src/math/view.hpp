// What one stereo frame looks at, whoever draws it: the head, the room it is
// in, the eyes and the image size. Declared once; the rasteriser's
// render::FrameDesc and the tracer's trace::TraceDesc extend it with their own
// settings (a FrameDesc hands the tracer its View as it is).
#pragma once

#include <array>
#include <optional>

#include "math/polygon.hpp"
#include "math/pose.hpp"
#include "math/projection.hpp"

namespace impossible::math {

// The default budget of portal passes (--max-portal-passes): per frame for
// the rasteriser, per ray tree for the tracer (docs/bounded-work.md).
inline constexpr int kDefaultMaxPortalPasses = 10'000;

// One eye of a headset (--fov-angles, --hmd; docs/headsets.md): its
// asymmetric field of view and the part of its image the lenses show.
struct EyeOptics {
    FovAngles fov;
    // The visible area in normalised image coordinates (math/hidden_area.hpp);
    // empty: every pixel is visible. Pixels outside are masked: black, id 0.
    Polygon2 visible_area;
    bool operator==(const EyeOptics&) const = default;
};

struct View {
    math::HeadPose head;
    int room = 0;             // index of the room the head is in
    double ipd = 0.064;       // metres between the eyes (not read with eye_offsets)
    double fov_y_deg = 90.0;  // vertical field of view of each eye
    int eye_width = 1280;     // each eye's image; the side-by-side image is 2 × width
    int eye_height = 720;
    int max_depth = 8;  // portals one line of sight may pass
    // Portal passes one frame (rasteriser) or one pixel sample's ray tree
    // (tracer) may make; past it, portals show the fill colour. Only a view
    // that needs more changes (docs/bounded-work.md).
    int max_portal_passes = kDefaultMaxPortalPasses;
    // Seconds: moving props stand where their motion puts them at this time
    // (layout-format.md, "Moving props"; a negative time reads as 0).
    double time = 0.0;
    // The tracked hands, left then right, as virtual poses in the head's
    // coordinates (with --pose the physical and virtual frames coincide);
    // none: no hands are drawn. Each hand's room is found by walking from
    // the head centre to it (walk/objects.hpp).
    std::optional<std::array<math::HeadPose, 2>> hands;
    // --light-depth: replaces the layout's light_depth under "lighting":
    // "lights" (cli.md); none: the layout's. No effect on "fixed" layouts.
    std::optional<int> light_depth;
    // --exposure, EV: each surface's colour times 2^exposure before its clamp
    // to 0..1 (docs/lighting.md, "Exposure"), in both renderers; none: the
    // layout's "exposure" (0 unless it says).
    std::optional<double> exposure;
    // Per-eye optics, left then right: the eyes' frusta are then these
    // angles (fov_y_deg is not read) and the hidden areas are masked.
    std::optional<std::array<EyeOptics, 2>> eye_optics;
    // Each eye's pose relative to the head, left then right (--eye-poses, a
    // profile's per-eye poses; docs/headsets.md): the eyes stand and look as
    // these say (ipd is not read); none: at ±ipd/2 along the head's x axis,
    // looking the head's way. math/eyes.hpp places the eyes either way.
    std::optional<std::array<EyeOffset, 2>> eye_offsets;
};

// The frustum of eye `eye` (0 left, 1 right) of `view` for an image of its
// eye size: symmetric from fov_y_deg, or the eye's optics' angles.
inline Frustum eye_frustum(const View& view, int eye) {
    Frustum f;
    f.fov_y_deg = view.fov_y_deg;
    f.aspect = static_cast<double>(view.eye_width) / view.eye_height;
    if (view.eye_optics) f.tangents = fov_tangents((*view.eye_optics)[static_cast<std::size_t>(eye)].fov);
    return f;
}

// Whether any eye of `view` has a hidden area to mask.
inline bool has_hidden_area(const View& view) {
    return view.eye_optics &&
           (!(*view.eye_optics)[0].visible_area.empty() || !(*view.eye_optics)[1].visible_area.empty());
}

}  // namespace impossible::math
