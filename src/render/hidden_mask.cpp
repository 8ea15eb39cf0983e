// A headset's hidden-area mask in the stencil (hidden_mask.hpp).
#include "render/hidden_mask.hpp"

#include <algorithm>
#include <cmath>

#include "math/hidden_area.hpp"
#include "render/scene_program.hpp"

namespace impossible::render {

namespace {

Result<gl::Program> build_mask_program() {
    const std::vector<gl::ShaderSource> stages = {embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
                                                  embedded_shader(GL_FRAGMENT_SHADER, "shaders/hidden_mask.frag.glsl")};
    Result<gl::Program> built = gl::build_program(stages, "");
    if (!built) return built;
    gl::UniformLocations u(built->get(), gl::program_name(stages));
    glProgramUniform1i(built->get(), u.required("u_mask"), 0);
    if (Result<void> all = u.check(); !all) return all;
    return built;
}

// The mask texture's texels (both eyes side by side, rows from the bottom)
// and each row's visible span.
std::vector<std::uint8_t> build_texels(HiddenMask& mask, const std::array<math::EyeOptics, 2>& optics, int w, int h) {
    const size_t row = 2 * static_cast<size_t>(w);
    std::vector<std::uint8_t> texels(row * static_cast<size_t>(h), 0);
    for (int e = 0; e < 2; ++e) {
        const std::vector<std::uint8_t> hidden = math::hidden_pixels(optics[static_cast<size_t>(e)].visible_area, w, h);
        std::vector<std::array<int, 2>>& spans = mask.rows[static_cast<size_t>(e)];
        spans.assign(static_cast<size_t>(h), {w, -1});
        for (int j = 0; j < h; ++j) {
            const std::uint8_t* src = &hidden[static_cast<size_t>(j) * w];
            std::copy(src, src + w, &texels[static_cast<size_t>(h - 1 - j) * row + static_cast<size_t>(e * w)]);
            for (int i = 0; i < w; ++i) {
                if (src[i]) {
                    mask.active = true;
                    continue;
                }
                spans[static_cast<size_t>(j)][0] = std::min(spans[static_cast<size_t>(j)][0], i);
                spans[static_cast<size_t>(j)][1] = i;
            }
        }
    }
    return texels;
}

}  // namespace

Result<void> prepare_hidden_mask(HiddenMask& mask, const math::View& frame) {
    if (mask.optics == frame.eye_optics && mask.eye_width == frame.eye_width && mask.eye_height == frame.eye_height)
        return {};
    mask.optics = frame.eye_optics;
    mask.eye_width = frame.eye_width;
    mask.eye_height = frame.eye_height;
    mask.active = false;
    mask.rows = {};
    mask.texture = {};
    if (!math::has_hidden_area(frame)) return {};
    const std::vector<std::uint8_t> texels = build_texels(mask, *frame.eye_optics, frame.eye_width, frame.eye_height);
    if (!mask.active) return {};
    if (!mask.program.get()) {
        Result<gl::Program> built = build_mask_program();
        if (!built) return built;
        mask.program = std::move(*built);
    }
    mask.texture = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(mask.texture.get(), 1, GL_R8UI, 2 * frame.eye_width, frame.eye_height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(mask.texture.get(), 0, 0, 0, 2 * frame.eye_width, frame.eye_height, GL_RED_INTEGER,
                        GL_UNSIGNED_BYTE, texels.data());
    glTextureParameteri(mask.texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(mask.texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return {};
}

void draw_hidden_mask(gl::StateCache& state, const Target& target, const HiddenMask& mask, GLuint empty_vao,
                      FrameStats& stats) {
    if (!mask.active) return;
    gl::PassState s;
    s.depth_test = false;
    s.depth_write = false;
    s.color_mask = gl::kColorNone;
    s.write_ids = false;
    s.cull_back_faces = false;
    s.stencil.enabled = true;
    s.stencil.func = GL_ALWAYS;
    s.stencil.pass = GL_REPLACE;
    state.apply(s, kHiddenStencil);
    state.no_scissor();
    state.draw_framebuffer(target.framebuffer.get());
    state.viewport({0, 0, target.width, target.height});
    state.program(mask.program.get());
    state.vertex_array(empty_vao);
    state.texture(0, mask.texture.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    stats.draw_calls += 1;
}

bool meets_visible_area(const HiddenMask& mask, int eye, const NdcRect& rect, int samples) {
    if (!mask.active) return true;
    if (rect.empty()) return false;
    const int w = mask.eye_width, h = mask.eye_height;
    // Pixel centres (i + 0.5, j + 0.5) within the rectangle, with the margin
    // of covers_pixel_centre; a multisampled pixel counts if any of it does.
    const double grow = samples > 1 ? 1.0 : 1.0 / 256.0;
    const double x0 = (rect.x0 + 1.0) * 0.5 * w - grow, x1 = (rect.x1 + 1.0) * 0.5 * w + grow;
    const double top = (1.0 - rect.y1) * 0.5 * h - grow, bottom = (1.0 - rect.y0) * 0.5 * h + grow;
    const int i0 = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
    const int i1 = std::min(w - 1, static_cast<int>(std::floor(x1 - 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::ceil(top - 0.5)));
    const int j1 = std::min(h - 1, static_cast<int>(std::floor(bottom - 0.5)));
    const std::vector<std::array<int, 2>>& spans = mask.rows[static_cast<size_t>(eye)];
    for (int j = j0; j <= j1; ++j) {
        const std::array<int, 2>& s = spans[static_cast<size_t>(j)];
        if (s[0] <= s[1] && s[0] <= i1 && s[1] >= i0) return true;
    }
    return false;
}

}  // namespace impossible::render
