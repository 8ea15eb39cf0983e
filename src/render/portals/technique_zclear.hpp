// Internal to src/render: z-clear portals (--technique z-clear), the PowerVR
// scheme, for comparison with the stencil recursion (technique_zclear.cpp).
#pragma once

#include "base/result.hpp"
#include "render/draw/draw_state.hpp"

namespace impossible::render {

// Whether the frame's z-clear portals can be drawn (FrameDesc::z_clear):
// depth <= 1, doors only, no volumes, with culling, no portal textures; the
// error names the option and what breaks the rule.
Result<void> check_zclear(const SceneData& r, const FrameDesc& frame);

// The head's view (level 0) by the z-clear scheme: each visible door's target
// room first, within its rectangle, then depth cleared, the doors into depth
// and the head's room over them.
void draw_zclear(const DrawContext& ctx, const LevelView& view);

}  // namespace impossible::render
