// Render-to-texture portals (the classic technique, for comparison): the view
// through each door of the head's cell (or, hybrid, of the cells at
// FrameDesc::portal_texture_level) is drawn into a texture of scale ×
// the eye size, both eyes side by side (recursion inside it by stencil), and
// the box then shows that texture where it is the visible surface.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "render/portals/portal_draw.hpp"
#include "render/portals/portal_recursion.hpp"
#include "render/portals/portal_texture.hpp"

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

Result<void> ensure_portal_textures(const SceneData& r, FrameTargets& targets, const FrameDesc& frame) {
    assert(frame.room >= 0 && static_cast<size_t>(frame.room) < r.links.room_portals.size());
    const FrameDesc inner = inner_frame(frame);
    // One slot per portal of a cell whose doors may take a texture (a slot
    // is drawn and shown before the next door's): the head's cell at level
    // 0, any cell deeper (hybrid portals).
    size_t count = r.links.room_portals[frame.room].size();
    if (frame.portal_texture_level > 0)
        for (const std::vector<int>& portals : r.links.room_portals) count = std::max(count, portals.size());
    if (targets.portal_textures.size() < count) targets.portal_textures.resize(count);
    for (size_t slot = 0; slot < count; ++slot) {
        Target& texture = targets.portal_textures[slot];
        if (texture.width == 2 * inner.eye_width && texture.height == inner.eye_height &&
            texture.depth == frame.depth && texture.framebuffer)
            continue;
        Result<Target> made = create_sampled_target(2 * inner.eye_width, inner.eye_height, frame.depth);
        if (!made) return Error{"portal texture: " + made.error()};
        texture = std::move(*made);
    }
    return {};
}

void draw_portal_via_texture(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                             size_t slot) {
    const SceneData& r = ctx.scene;
    const FrameDesc inner = inner_frame(ctx.frame);
    assert(slot < ctx.targets.portal_textures.size());  // ensure_portal_textures made them
    const Target& texture = ctx.targets.portal_textures[slot];

    // The view through the portal, at level + 1 everywhere in the texture,
    // which is its own target: the view is not limited to the portal's
    // pixels there.
    clear_target(ctx.state, texture, stencil_level(ctx.frame.max_depth, view.level + 1));
    const DrawContext inside{.state = ctx.state,
                             .scene = r,
                             .programs = ctx.programs,
                             .lights = ctx.lights,
                             .frame = inner,
                             .scene_program = ctx.scene_program,
                             .material_program = ctx.material_program,
                             .target = texture,
                             .targets = ctx.targets,
                             .projections = ctx.projections,
                             .eye = ctx.eye,
                             .profiler = ctx.profiler,
                             .scratch = ctx.scratch};
    LevelView through = child_view(ctx, view, p, rects);
    through.through_portal = false;
    ctx.scratch.stats.portal_passes_drawn += 1;
    draw_level(inside, through);

    // The box shows the texture where it is the visible surface.
    const bool volumes = !r.volumes[static_cast<size_t>(view.cell)].empty();
    const SceneProgram& shows = volumes ? *ctx.programs.portal_texture_volumes : *ctx.programs.portal_texture;
    glProgramUniform2f(shows.program.get(), shows.target_size, float(2 * ctx.frame.eye_width),
                       float(ctx.frame.eye_height));
    ctx.state.texture(0, texture.color_texture.get());
    ctx.state.texture(1, texture.ids_texture.get());
    const ColourQueryScope colour(ctx.profiler);
    draw_portal_box(ctx, view, {Pass::PortalTexture, view.level, &shows, portal_scissor(ctx, view, rects)}, p, rects);
}

}  // namespace impossible::render
