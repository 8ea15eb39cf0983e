// Multisampled targets and their resolve (see multisample.hpp).
#include "render/targets/multisample.hpp"

#include <algorithm>
#include <cassert>
#include <string>

#include "render/programs/programs.hpp"
#include "render/programs/scene_program.hpp"
#include "render/targets/frame_targets.hpp"

namespace impossible::render {
namespace {

std::vector<int> counts_for(GLenum target, GLenum format) {
    GLint n = 0;
    glGetInternalformativ(target, format, GL_NUM_SAMPLE_COUNTS, 1, &n);
    std::vector<GLint> counts(static_cast<size_t>(std::max(n, 0)));
    if (n > 0) glGetInternalformativ(target, format, GL_SAMPLES, n, counts.data());
    return {counts.begin(), counts.end()};
}

// Kept at most per renderer: enough for a sweep of 2, 4, 8 and 16 samples.
constexpr size_t kMaxMultisampledTargets = 4;

const Target* find_target(const Multisampling& m, const FrameDesc& frame) {
    for (const Target& t : m.targets)
        if (t.samples == frame.samples && t.width == 2 * frame.eye_width && t.height == frame.eye_height &&
            t.depth == frame.depth)
            return &t;
    return nullptr;
}

Result<gl::Framebuffer> framebuffer_around(GLuint renderbuffer, const char* what) {
    gl::Framebuffer fb = gl::create_framebuffer();
    glNamedFramebufferRenderbuffer(fb.get(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
    glNamedFramebufferDrawBuffer(fb.get(), GL_COLOR_ATTACHMENT0);
    if (glCheckNamedFramebufferStatus(fb.get(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return Error{std::string("the multisample resolve's ") + what + " framebuffer is incomplete"};
    return fb;
}

Result<void> build_id_resolve(std::vector<gl::Program>& id_resolve, int samples) {
    if (id_resolve.size() <= static_cast<size_t>(samples)) id_resolve.resize(samples + 1);
    if (id_resolve[samples]) return {};
    Result<gl::Program> built = build_id_resolve_program(samples);
    if (!built) return built;
    id_resolve[samples] = std::move(*built);
    return {};
}

}  // namespace

std::vector<int> offered_sample_counts(DepthMode depth) {
    const GLenum depth_format = depth == DepthMode::ReversedZ ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
    std::vector<int> out = counts_for(GL_RENDERBUFFER, GL_RGBA8);
    for (const std::vector<int>& other :
         {counts_for(GL_RENDERBUFFER, depth_format), counts_for(GL_TEXTURE_2D_MULTISAMPLE, GL_R8UI)})
        std::erase_if(out, [&](int n) { return std::find(other.begin(), other.end(), n) == other.end(); });
    out.push_back(1);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Result<void> check_sample_count(int samples, DepthMode depth) {
    const std::vector<int> offered = offered_sample_counts(depth);
    if (std::find(offered.begin(), offered.end(), samples) != offered.end()) return {};
    std::string list;
    for (int n : offered) list += (list.empty() ? "" : ", ") + std::to_string(n);
    GLint max_samples = 0, max_integer = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    glGetIntegerv(GL_MAX_INTEGER_SAMPLES, &max_integer);
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return Error{"{samples} " + std::to_string(samples) + ": the OpenGL driver (" + (renderer ? renderer : "unknown") +
                 ") offers " + list + " samples for these buffers (GL_MAX_SAMPLES " + std::to_string(max_samples) +
                 ", GL_MAX_INTEGER_SAMPLES " + std::to_string(max_integer) + ")"};
}

Result<void> ensure_multisampled(Programs& programs, FrameTargets& targets, const FrameDesc& frame) {
    if (frame.samples <= 1) return {};
    Multisampling& m = targets.multisampling;
    if (!find_target(m, frame)) {
        if (Result<void> offered = check_sample_count(frame.samples, frame.depth); !offered) return offered;
        Result<Target> made =
            create_multisampled_target(2 * frame.eye_width, frame.eye_height, frame.depth, frame.samples);
        if (!made) return Error{"multisampled " + made.error()};
        if (m.targets.size() == kMaxMultisampledTargets) m.targets.erase(m.targets.begin());
        m.targets.push_back(std::move(*made));
    }
    if (!m.colour_out) {
        Result<gl::Framebuffer> colour = framebuffer_around(targets.target.color.get(), "colour");
        if (!colour) return colour;
        Result<gl::Framebuffer> ids = framebuffer_around(targets.target.ids.get(), "id");
        if (!ids) return ids;
        m.colour_out = std::move(*colour);
        m.ids_out = std::move(*ids);
    }
    return build_id_resolve(programs.id_resolve, frame.samples);
}

const Target& drawing_target(const FrameTargets& targets, const FrameDesc& frame) {
    if (frame.samples <= 1) return targets.target;
    const Target* t = find_target(targets.multisampling, frame);
    assert(t);  // ensure_multisampled made it
    return *t;
}

void resolve_multisampled(gl::StateCache& state, const Programs& programs, const FrameTargets& targets,
                          const FrameDesc& frame) {
    if (frame.samples <= 1) return;
    const Multisampling& m = targets.multisampling;
    const Target& from = drawing_target(targets, frame);
    // Blits obey the scissor; the id pass writes its one attachment everywhere.
    state.apply(gl::plain_2d_state(false), 0);
    state.no_scissor();
    const int w = from.width, h = from.height;
    glNamedFramebufferReadBuffer(from.framebuffer.get(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(from.framebuffer.get(), m.colour_out.get(), 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);

    state.draw_framebuffer(m.ids_out.get());
    state.viewport({0, 0, w, h});
    state.program(programs.id_resolve[static_cast<size_t>(from.samples)].get());
    state.texture(0, from.ids_texture.get());
    state.vertex_array(programs.empty_vao.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace impossible::render
