// Internal to src/render: mirrors and windows inside the stencil recursion
// (portal_glass.cpp).
#pragma once

#include <array>

#include "base/result.hpp"
#include "render/draw/draw_state.hpp"
#include "render/portals/portal_steps.hpp"

namespace impossible::render {

// A visible mirror or window of `view` below the recursion limit: the view(s)
// in it, tinted and blended, drawn where it is the visible surface.
void draw_mirror_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                        const PortalSteps& steps);
void draw_window_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                        const PortalSteps& steps);

// The window blend's program for single-sample or multisampled targets,
// built on first use; prepare_frame makes the ones a frame may need.
Result<void> prepare_window_blend(Programs& programs, bool multisample);

}  // namespace impossible::render
