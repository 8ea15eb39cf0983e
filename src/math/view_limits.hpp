// The ranges of a view's and a frame's settings, named once. The command
// line's option rows, the session's checks of a library or Python view, the
// preview and bench's sweeps all read them here; docs/cli.md lists them for
// users (keep the two in step).
#pragma once

#include <string>

#include "base/format.hpp"

namespace impossible::math::limits {

// A closed range [min, max].
template <class T>
struct Range {
    T min, max;
    constexpr bool contains(T v) const { return v >= min && v <= max; }
};

// Each eye's image, pixels a side (GL guarantees textures of 8192).
inline constexpr Range<int> kEyeSide{1, 8192};
// The preview's window: each eye at most 4096 a side.
inline constexpr Range<int> kWindowEyeSide{1, 4096};
inline constexpr Range<double> kIpd{0.0, 10.0};  // metres
// Each eye's pose relative to the head (--eye-poses, a profile's per-eye
// poses): at most kMaxEyeDistance metres from the head centre, and as
// angles, a pitch within ±kMaxEyePitchDeg (as a headset's fov angles).
inline constexpr double kMaxEyeDistance = 1.0;
inline constexpr double kMaxEyePitchDeg = 89.5;
// The vertical field of view, degrees: at least kMinFovDeg, less than
// kMaxFovDeg. Below 1 degree a pixel's angle nears single precision's
// resolution at 8192 pixels (the rasteriser drew 1e-6 degrees as background
// while the tracer showed a room), so narrower views are refused.
inline constexpr double kMinFovDeg = 1.0;
inline constexpr double kMaxFovDeg = 179.0;
// Portals one line of sight may pass; the stencil's 8 bits hold 250 levels
// and the hidden-area mask (render/hidden_mask.hpp).
inline constexpr Range<int> kMaxDepth{0, 250};
// Portal passes of one frame or one pixel's ray tree (docs/bounded-work.md).
inline constexpr Range<int> kPortalPasses{0, 10'000'000};
// Each number of a head or hand pose (metres and degrees).
inline constexpr double kMaxPoseComponent = 1e7;
// Samples per pixel: one of these (the driver offers a subset).
inline constexpr int kSampleCounts[] = {1, 2, 4, 8, 16};
// Frames a second of a replayed path (--fps).
inline constexpr Range<double> kFps{1e-3, 1e6};
// The line of a path file (--frame).
inline constexpr Range<int> kPathFrame{0, 100'000'000};
// Portals light may pass (layout-format.md, "Lights").
inline constexpr int kMaxLightDepth = 16;
inline constexpr Range<int> kLightDepth{0, kMaxLightDepth};
// Exposure, EV (--exposure, a layout's "exposure"): each surface's colour
// times 2^EV before its clamp (docs/lighting.md, "Exposure").
inline constexpr Range<double> kExposure{-20.0, 20.0};
// Cube shadow maps' texels per face side (0: no shadows).
inline constexpr Range<int> kShadowMapSize{0, 4096};
// Render-to-texture portals: the scale of their textures, in (0, 4].
inline constexpr double kMaxPortalTextureScale = 4.0;

// The rasteriser's samples of one frame, 2 W × H × samples: at most those of
// the largest single-sample frame, 2 × 8192². Its buffers (colour, ids,
// depth-stencil: 13 bytes a sample, and llvmpipe's own copies) then stay
// within about 2 GB; past it, 8192 × 4096 at 4 samples peaked at 4.95 GB and
// 8192² at 4 samples failed after 4.4 GB (docs/bounded-work.md).
inline constexpr long long kMaxFrameSamples = 2LL * 8192 * 8192;

// "MIN..MAX", as messages give a range.
template <class T>
std::string range_text(const Range<T>& r) {
    return format_number(r.min) + ".." + format_number(r.max);
}

constexpr bool is_sample_count(int n) {
    for (int c : kSampleCounts)
        if (n == c) return true;
    return false;
}

}  // namespace impossible::math::limits
