// Internal to src/render: a headset's hidden-area mask (docs/headsets.md).
// With per-eye optics that have a visible area, every pixel whose centre
// math::pixel_hidden finds outside it gets the stencil value
// kHiddenStencil right after the target is cleared, before anything is
// drawn. Every pass of the portal renderer tests stencil == its level, and
// no level reaches kHiddenStencil (max_depth <= 250), so nothing is drawn
// there: the pixel keeps the clear's background colour and id 0, as the
// tracer leaves it. Portals whose rectangle holds no visible pixel centre
// are culled (FrameStats::portal_passes_masked).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "math/view.hpp"
#include "render/frame.hpp"
#include "render/portals/view.hpp"
#include "render/target.hpp"

namespace impossible::render {

inline constexpr int kHiddenStencil = 255;

struct HiddenMask {
    // What it was made for: the optics and eye size of the last frame with
    // a hidden area (kept across frames without one, which do not use it).
    std::optional<std::array<math::EyeOptics, 2>> optics;
    int eye_width = 0, eye_height = 0;
    bool multisample = false;  // made for a multisampled target (hidden_mask.cpp)
    bool active = false;       // this frame masks: it has a hidden area, and some pixel is hidden
    // The hidden pixels as trapezoids (hidden_mask.cpp), two triangles each,
    // in the target's NDC.
    gl::Buffer vertices;
    gl::VertexArray vertex_array;
    int vertex_count = 0;
    gl::Program program;  // built on first use
    // Per eye and image row (from the top): the first and last visible
    // column (first > last: none), for culling.
    std::array<std::vector<std::array<int, 2>>, 2> rows;
};

// Makes `mask` the one for the frame's optics and size (made again only
// when they change); inactive for a frame without a hidden area.
Result<void> prepare_hidden_mask(HiddenMask& mask, const math::View& frame, int samples);

// Sets the stencil of the hidden pixels of `target` (just cleared) to
// kHiddenStencil. Nothing when the mask is inactive.
void draw_hidden_mask(gl::StateCache& state, const Target& target, const HiddenMask& mask, FrameStats& stats);

// Whether `rect` (eye `eye`'s NDC) may hold a visible pixel centre (with
// samples > 1, any part of a visible pixel): true for an inactive mask.
// Conservative: a row's visible columns are taken as one span.
bool meets_visible_area(const HiddenMask& mask, int eye, const NdcRect& rect, int samples);

}  // namespace impossible::render
