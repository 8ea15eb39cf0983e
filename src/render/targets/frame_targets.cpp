// The targets a renderer's frames are drawn into (frame_targets.hpp).
#include "render/targets/frame_targets.hpp"

#include "render/portals/passes.hpp"
#include "shading/shading.hpp"

namespace impossible::render {

Result<void> ensure_frame_target(FrameTargets& targets, int width, int height, DepthMode depth) {
    Target& t = targets.target;
    if (t.width == width && t.height == height && t.depth == depth && t.framebuffer) return {};
    Result<Target> made = create_target(width, height, depth);
    if (!made) return made;
    t = std::move(*made);
    // The resolve's framebuffers hold the old target's buffers.
    targets.multisampling.colour_out = {};
    targets.multisampling.ids_out = {};
    return {};
}

void clear_target(gl::StateCache& state, const Target& target, int stencil) {
    state.apply(kClearState, 0);
    state.no_scissor();
    const glm::dvec3 bg = shading::kBackgroundColor;
    const GLfloat color[4] = {static_cast<GLfloat>(bg.r), static_cast<GLfloat>(bg.g), static_cast<GLfloat>(bg.b), 1.0f};
    const GLuint id[4] = {0, 0, 0, 0};
    const GLuint fb = target.framebuffer.get();
    glClearNamedFramebufferfv(fb, GL_COLOR, 0, color);
    glClearNamedFramebufferuiv(fb, GL_COLOR, 1, id);
    glClearNamedFramebufferfi(fb, GL_DEPTH_STENCIL, 0, target.depth == DepthMode::ReversedZ ? 0.0f : 1.0f, stencil);
}

}  // namespace impossible::render
