// Internal to src/render: render-to-texture portals, the classic technique,
// for comparison (portal_texture.cpp).
#pragma once

#include <array>
#include <cstddef>

#include "base/result.hpp"
#include "render/draw/draw_state.hpp"

namespace impossible::render {

// Makes sure there is one sampled target per portal of the frame's room, of
// FrameDesc::portal_texture_scale × the eye size; an incomplete one is an
// error.
Result<void> ensure_portal_textures(const SceneData& r, FrameTargets& targets, const FrameDesc& frame);

// The view through portal `p` of the head's cell drawn into portal texture
// `slot`, which the box then shows where it is the visible surface.
void draw_portal_via_texture(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                             size_t slot);

}  // namespace impossible::render
