#include "preview/present.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/programs/scene_program.hpp"

namespace impossible::preview {

WindowLayout window_layout(int fb_width, int fb_height, double aspect, PreviewView view) {
    const int panels = view == PreviewView::Anaglyph ? 1 : 2;
    // The largest eye of the given aspect such that `panels` of them fit side by side.
    int w = static_cast<int>(std::floor(std::min(double(fb_width) / panels, double(fb_height) * aspect)));
    w = std::max(w, 1);
    const int h = std::clamp(static_cast<int>(std::lround(w / aspect)), 1, std::max(fb_height, 1));
    const int x0 = (fb_width - panels * w) / 2, y0 = (fb_height - h) / 2;
    WindowLayout out;
    const PixelRect first{x0, y0, w, h};
    const PixelRect second{x0 + (panels - 1) * w, y0, w, h};
    out.eye_rects =
        view == PreviewView::Cross ? std::array<PixelRect, 2>{second, first} : std::array<PixelRect, 2>{first, second};
    return out;
}

Result<Presenter> build_presenter() {
    Presenter p;
    Result<gl::Program> built =
        gl::build_program({render::embedded_shader(GL_VERTEX_SHADER, "shaders/preview_present.vert.glsl"),
                           render::embedded_shader(GL_FRAGMENT_SHADER, "shaders/preview_present.frag.glsl")},
                          "");
    if (!built) return built;
    p.program = std::move(*built);
    p.u_eye = glGetUniformLocation(p.program.get(), "u_eye");
    glProgramUniform1i(p.program.get(), glGetUniformLocation(p.program.get(), "u_view"), 0);
    p.empty_vao = gl::create_vertex_array();
    return p;
}

void present(Presenter& p, gl::StateCache& state, const render::Target& target, const WindowLayout& layout,
             PreviewView view, int fb_width, int fb_height) {
    if (p.width != target.width || p.height != target.height || !p.texture) {
        // The old texture and framebuffer go: the cache forgets them first.
        if (p.texture) state.deleting_texture(p.texture.get());
        if (p.framebuffer) state.deleting_framebuffer(p.framebuffer.get());
        p.texture = gl::create_texture(GL_TEXTURE_2D);
        glTextureStorage2D(p.texture.get(), 1, GL_RGBA8, target.width, target.height);
        glTextureParameteri(p.texture.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(p.texture.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(p.texture.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(p.texture.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        p.framebuffer = gl::create_framebuffer();
        glNamedFramebufferTexture(p.framebuffer.get(), GL_COLOR_ATTACHMENT0, p.texture.get(), 0);
        p.width = target.width;
        p.height = target.height;
    }
    // The blit obeys the scissor too, which the renderer's last pass may
    // have left on a door's rectangle (the window was then mostly black).
    state.no_scissor();
    glNamedFramebufferReadBuffer(target.framebuffer.get(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(target.framebuffer.get(), p.framebuffer.get(), 0, 0, target.width, target.height, 0, 0,
                           target.width, target.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);

    state.draw_framebuffer(0);
    // The clear obeys the colour mask and the scissor.
    state.apply(gl::plain_2d_state(false), 0);
    state.no_scissor();
    const GLfloat grey[4] = {0.12f, 0.12f, 0.13f, 1.0f};
    glClearNamedFramebufferfv(0, GL_COLOR, 0, grey);
    state.program(p.program.get());
    state.texture(0, p.texture.get());
    state.vertex_array(p.empty_vao.get());
    const int draws = view == PreviewView::Anaglyph ? 1 : 2;
    for (int e = 0; e < draws; ++e) {
        const PixelRect& r = layout.eye_rects[e];
        state.viewport({r.x, r.y, r.width, r.height});
        glProgramUniform1i(p.program.get(), p.u_eye, view == PreviewView::Anaglyph ? -1 : e);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    // The overlay draws over the whole window next.
    state.viewport({0, 0, fb_width, fb_height});
}

std::vector<std::uint8_t> read_window(gl::StateCache& state, int w, int h) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3), row(static_cast<std::size_t>(w) * 3);
    state.read_framebuffer(0);
    glNamedFramebufferReadBuffer(0, GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    for (int y = 0; y < h / 2; ++y) {  // GL rows start at the bottom
        std::uint8_t* a = &rgb[static_cast<std::size_t>(y) * w * 3];
        std::uint8_t* b = &rgb[static_cast<std::size_t>(h - 1 - y) * w * 3];
        std::memcpy(row.data(), a, row.size());
        std::memcpy(a, b, row.size());
        std::memcpy(b, row.data(), row.size());
    }
    return rgb;
}

}  // namespace impossible::preview
