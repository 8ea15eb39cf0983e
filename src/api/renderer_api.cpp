// impossible::api::Renderer: the OpenGL rasteriser behind the public API, in
// the headless context its thread's renderers share or in the caller's.
#include <algorithm>
#include <optional>

#include "api/api_data.hpp"
#include "api/headless_share.hpp"
#include "gl/context.hpp"
#include "gl/gl.hpp"
#include "gl/state.hpp"
#include "render/renderer.hpp"
#include "session/field_error.hpp"

namespace impossible::api {

struct RendererParts {
    explicit RendererParts(const Layout& l) : layout(l) {}
    // The renderer frees its GL objects in its context, made current again
    // (another renderer's may be), and leaves the thread's share first.
    ~RendererParts() {
        if (share) {
            (void)gl::make_current(share->context());
            if (renderer) share->leave(*renderer);
        }
        renderer.reset();
        if (!share) return;
        share.reset();  // the context too, with the thread's last renderer
        return_free_memory();
    }
    RendererParts(const RendererParts&) = delete;
    RendererParts& operator=(const RendererParts&) = delete;
    Layout layout;                                 // for resolving each view's room
    std::shared_ptr<HeadlessShare> share;          // headless: the thread's context and renderers
    std::unique_ptr<gl::StateCache> caller_state;  // in the caller's context
    std::optional<render::Renderer> renderer;
    GetProcAddress callers_loader = nullptr;  // in the caller's context: its loader

    gl::StateCache& state() { return share ? share->context().state() : *caller_state; }

    // Before each frame: the shared context current on this thread (another
    // may be), or the caller's state forgotten (the caller may have changed
    // any of it since the last frame).
    Result<void> prepare() {
        if (share) return gl::make_current(share->context());
        state().invalidate();
        return gl::load_functions(callers_loader);
    }
};

// Around a frame of a headless renderer: the bound on what the thread's
// renderers keep together (headless_share.hpp).
class FrameInShare {
public:
    FrameInShare(RendererParts& parts, const render::FrameDesc& frame) : parts_(parts) {
        if (parts_.share)
            parts_.share->before_frame(*parts_.renderer,
                                       2LL * frame.eye_width * frame.eye_height * std::max(1, frame.samples));
    }
    ~FrameInShare() {
        if (parts_.share) parts_.share->after_frame(*parts_.renderer);
    }
    FrameInShare(const FrameInShare&) = delete;
    FrameInShare& operator=(const FrameInShare&) = delete;

private:
    RendererParts& parts_;
};

namespace {

FrameStats stats_of(const render::FrameStats& s) {
    return {s.draw_calls,   s.triangles,    s.portal_passes_drawn, s.portal_passes_culled,
            s.portal_fills, s.budget_fills, s.max_level_reached};
}

Expected<void> build(RendererParts& parts, const Layout& layout) {
    Result<render::Renderer> made = layout.data().session.make_renderer(
        parts.state(), parts.share ? parts.share->programs() : render::SharedPrograms{});
    if (!made) return Error{made.error()};
    parts.renderer.emplace(std::move(*made));
    return {};
}

// The renderer's messages name settings as {field}: the library's names.
Error library_error(const std::string& message) {
    return Error{session::spell_fields(message, session::library_field)};
}

}  // namespace

Renderer::Renderer(std::unique_ptr<RendererParts> parts) : parts_(std::move(parts)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

Expected<Renderer> Renderer::headless(const Layout& layout, Backend backend) {
    return no_throw([&]() -> Expected<Renderer> {
        auto parts = std::make_unique<RendererParts>(layout);
        const std::optional<gl::Backend> requested =
            backend == Backend::Any ? std::nullopt
                                    : std::optional(backend == Backend::Egl ? gl::Backend::Egl : gl::Backend::OSMesa);
        Result<std::shared_ptr<HeadlessShare>> share = HeadlessShare::of_this_thread(requested);
        if (!share) return Error{"no OpenGL 4.5 context: " + share.error()};
        parts->share = std::move(*share);
        if (Result<void> current = gl::make_current(parts->share->context()); !current) return Error{current.error()};
        if (Expected<void> built = build(*parts, layout); !built) return built.error();
        parts->share->join(*parts->renderer);
        return Renderer(std::move(parts));
    });
}

Expected<Renderer> Renderer::in_current_context(const Layout& layout, GetProcAddress load) {
    return no_throw([&]() -> Expected<Renderer> {
        if (Result<void> loaded = gl::load_functions(load); !loaded) return Error{loaded.error()};
        auto parts = std::make_unique<RendererParts>(layout);
        parts->caller_state = std::make_unique<gl::StateCache>();
        parts->callers_loader = load;
        if (Expected<void> built = build(*parts, layout); !built) return built.error();
        return Renderer(std::move(parts));
    });
}

Expected<Frame> Renderer::render(const View& view, const RenderOptions& options) {
    return no_throw([&]() -> Expected<Frame> {
        Result<render::FrameDesc> frame = frame_desc(parts_->layout.data().layout, view, options);
        if (!frame) return Error{frame.error()};
        if (Result<void> ready = parts_->prepare(); !ready) return Error{ready.error()};
        const FrameInShare in_share(*parts_, *frame);
        Result<render::RenderedFrame> drawn = parts_->renderer->render(*frame);
        if (!drawn) return library_error(drawn.error());
        Frame out;
        out.width = drawn->image.width;
        out.height = drawn->image.height;
        out.rgb = std::move(drawn->image.rgb);
        out.ids = std::move(drawn->image.ids);
        out.stats = stats_of(drawn->stats);
        return out;
    });
}

Expected<FrameStats> Renderer::draw_to(const View& view, unsigned framebuffer, const RenderOptions& options) {
    return no_throw([&]() -> Expected<FrameStats> {
        Result<render::FrameDesc> frame = frame_desc(parts_->layout.data().layout, view, options);
        if (!frame) return Error{frame.error()};
        if (Result<void> ready = parts_->prepare(); !ready) return Error{ready.error()};
        const FrameInShare in_share(*parts_, *frame);
        render::FrameStats stats;
        if (Result<void> drawn = parts_->renderer->draw(*frame, &stats); !drawn) return library_error(drawn.error());
        const render::Target& target = parts_->renderer->target();
        const GLuint from = target.framebuffer.get();
        parts_->state().no_scissor();  // the scissor test applies to blits too
        glNamedFramebufferReadBuffer(from, GL_COLOR_ATTACHMENT0);
        glBlitNamedFramebuffer(from, framebuffer, 0, 0, target.width, target.height, 0, 0, target.width, target.height,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
        return stats_of(stats);
    });
}

std::string Renderer::gl_renderer() const {
    if (parts_->share) return parts_->share->context().renderer;
    const GLubyte* name = glGetString(GL_RENDERER);
    return name != nullptr ? reinterpret_cast<const char*>(name) : "";
}

}  // namespace impossible::api
