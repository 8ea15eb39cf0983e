// What the web build's renderer (WebGL 2, gl/webgl.hpp) cannot draw, refused
// in one line before a frame is drawn (docs/web.md, "What the web build
// refuses"). The native build refuses nothing here.
#pragma once

#include "base/result.hpp"
#include "render/frame.hpp"

namespace impossible::render {

Result<void> web_profile_check(const FrameDesc& frame);

}  // namespace impossible::render
