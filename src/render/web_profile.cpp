#include "render/web_profile.hpp"

#if defined(__EMSCRIPTEN__)
#include "gl/webgl.hpp"
#endif

namespace impossible::render {

Result<void> web_profile_check([[maybe_unused]] const FrameDesc& frame) {
#if defined(__EMSCRIPTEN__)
    const gl::webgl::Extensions& e = gl::webgl::extensions();
    if (!e.clip_distance)
        return Error{"this browser's WebGL 2 lacks WEBGL_clip_cull_distance, which the portals' clipping needs"};
    if (frame.samples > 1)
        return Error{"{samples} " + std::to_string(frame.samples) +
                     ": the web build draws without multisampling (WebGL 2 has no multisampled textures to "
                     "resolve the id map from); use --samples 1"};
    if (frame.stereo == StereoMode::ViewportIndex)
        return Error{"{stereo} viewport-index: WebGL 2 has no viewport arrays; use clip-shift or two-pass"};
    if (frame.occlusion_test) return Error{"{occlusion-test}: WebGL 2 has no conditional rendering"};
    if (frame.profile) return Error{"the per-portal profile needs GL_SAMPLES_PASSED queries, which WebGL 2 lacks"};
    if (frame.depth == DepthMode::ReversedZ && !e.clip_control)
        return Error{
            "{depth} reversed-z needs EXT_clip_control, which this browser's WebGL 2 lacks; use --depth standard"};
    if (!e.draw_buffers_indexed)
        return Error{"this browser's WebGL 2 lacks OES_draw_buffers_indexed, which the id map's passes need"};
#endif
    return {};
}

const FrameDesc& web_profile_fallbacks(const FrameDesc& frame, [[maybe_unused]] FrameDesc& adjusted) {
#if defined(__EMSCRIPTEN__)
    if (frame.depth == DepthMode::ReversedZ && !gl::webgl::extensions().clip_control) {
        adjusted = frame;
        adjusted.depth = DepthMode::Standard;
        return adjusted;
    }
#endif
    return frame;
}

}  // namespace impossible::render
