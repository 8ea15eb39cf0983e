// What the web build's renderer (WebGL 2, gl/webgl.hpp) cannot draw, refused
// in one line before a frame is drawn (docs/web.md, "What the web build
// refuses"). The native build refuses nothing here.
#pragma once

#include "base/result.hpp"
#include "render/frame.hpp"

namespace impossible::render {

Result<void> web_profile_check(const FrameDesc& frame);

// What the web build falls back on (docs/web.md): reversed-Z depth becomes
// standard depth where the browser lacks EXT_clip_control. Returns `frame`,
// or `adjusted` holding its changed copy.
const FrameDesc& web_profile_fallbacks(const FrameDesc& frame, FrameDesc& adjusted);

}  // namespace impossible::render
