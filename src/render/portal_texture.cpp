// Render-to-texture portals (the classic technique, for comparison): the view
// through each portal of the head's cell is drawn into a texture of scale ×
// the eye size, both eyes side by side (recursion inside it by stencil), and
// the box then shows that texture where it is the visible surface.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "render/portal_recursion.hpp"

namespace impossible::render {
namespace {

// The frame drawn into a portal texture: the eye size scaled, no textures inside.
FrameDesc inner_frame(const FrameDesc& f) {
    assert(f.portal_texture_scale > 0.0);
    FrameDesc inner = f;
    inner.eye_width = std::max(1, static_cast<int>(std::lround(f.eye_width * f.portal_texture_scale)));
    inner.eye_height = std::max(1, static_cast<int>(std::lround(f.eye_height * f.portal_texture_scale)));
    inner.portal_texture_scale = 0.0;
    return inner;
}

}  // namespace

Result<void> ensure_portal_textures(RendererData& r, const FrameDesc& frame) {
    assert(frame.room >= 0 && static_cast<size_t>(frame.room) < r.links.room_portals.size());
    const FrameDesc inner = inner_frame(frame);
    const size_t count = r.links.room_portals[frame.room].size();
    if (r.portal_textures.size() < count) r.portal_textures.resize(count);
    for (size_t slot = 0; slot < count; ++slot) {
        Target& texture = r.portal_textures[slot];
        if (texture.width == 2 * inner.eye_width && texture.height == inner.eye_height &&
            texture.depth == frame.depth && texture.framebuffer)
            continue;
        Result<Target> made = create_sampled_target(2 * inner.eye_width, inner.eye_height, frame.depth);
        if (!made) return Error{"portal texture: " + made.error()};
        texture = std::move(*made);
    }
    return {};
}

void draw_portal_via_texture(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                             size_t slot) {
    RendererData& r = ctx.renderer;
    gl::StateCache& state = *r.state;
    const FrameDesc& f = ctx.frame;
    const FrameDesc inner = inner_frame(f);
    assert(slot < r.portal_textures.size());  // ensure_portal_textures made them
    const Target& texture = r.portal_textures[slot];

    // The view through the portal, at level + 1 everywhere in the texture.
    state.draw_framebuffer(texture.framebuffer.get());
    state.viewport({0, 0, texture.width, texture.height});
    clear_target(r, texture, view.level + 1);
    DrawContext inside{r, ctx.program, inner, ctx.stats, ctx.projection, ctx.profiler};
    inside.material_program = ctx.material_program;
    inside.target = &texture;
    ctx.stats.portal_passes_drawn += 1;
    draw_level(inside, child_view(ctx, view, p, rects));

    // The box shows the texture where it is the visible surface.
    state.draw_framebuffer(drawing_target(r, f).framebuffer.get());
    state.viewport({0, 0, 2 * f.eye_width, f.eye_height});
    if (f.cull_portals) state.scissor(scissor_of(ctx, rects, view));
    else state.no_scissor();
    const SceneProgram& shows = *r.portal_texture_program;
    state.program(shows.program.get());
    glProgramUniform2f(shows.program.get(), shows.target_size, float(2 * f.eye_width), float(f.eye_height));
    glBindTextureUnit(0, texture.color_texture.get());
    glBindTextureUnit(1, texture.ids_texture.get());
    DrawContext outside{r, shows, f, ctx.stats, ctx.projection, nullptr};
    use_pass(outside, view, Pass::PortalTexture, view.level);
    {
        const ColourQueryScope colour(ctx.profiler);
        draw_portal_box(outside, view, p, rects);
    }
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
    state.program(ctx.program.program.get());
}

}  // namespace impossible::render
