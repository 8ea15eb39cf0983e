// Mirrors and windows (layout-format.md, "Mirrors and windows"; steps 4 and 5
// of "What a pixel shows") inside the stencil recursion, as doors are.
//
// A mirror at level L: mark its pixels (L → L + 1) and clear their depth,
// draw its room from the mirrored eyes (the winding flips; the mirror's plane
// clips), multiply the pixels by the tint, unmark (as PortalSteps says). The
// full-target passes cover level L + 1 and deeper: a door in the view may
// have left its pixels marked.
//
// A window's pixels show two views blended by their final colours,
// (1 - r) · tint · C_through + r · C_reflect. Blending while drawing would
// blend every overdrawn fragment again (a wall, then a prop in front of it),
// so each view is drawn whole first: the reflected view, whose colours are
// copied aside; the pixels back to the background; the view through the
// window, which writes the ids (the spec's id is the through view's); then
// one full-target triangle, limited by the stencil to the window's pixels,
// whose blend adds r · the copy to (1 - r) · tint · the colour. Each final
// pixel of each view is blended exactly once.
//
// A window branch whose weight falls below shading::kMinBranchWeight is not
// drawn and shows the fill colour, as the tracer does.
#include <algorithm>
#include <cassert>

#include "render/portals/portal_draw.hpp"
#include "render/portals/portal_glass.hpp"
#include "render/portals/portal_recursion.hpp"
#include "shading/shading.hpp"

namespace impossible::render {
namespace {

bool is_white(const glm::dvec3& c) { return c.x == 1.0 && c.y == 1.0 && c.z == 1.0; }

// A full-target triangle through the clear program, in a region pass over
// the portal's marked pixels, with a blend colour (Tint's: the tint).
void draw_region(const DrawContext& ctx, const LevelView& view, Pass pass, const std::array<NdcRect, 2>& rects,
                 const glm::dvec3& blend_color = glm::dvec3(1.0)) {
    const ClearDepthProgram& clear = ctx.programs.clear_depth;
    const GLuint program = clear.program.get();
    glProgramUniform1f(program, clear.far_depth, far_depth(ctx.frame));
    const glm::dvec3 bg = shading::kBackgroundColor;
    glProgramUniform4f(program, clear.color, float(bg.r), float(bg.g), float(bg.b), 1.0f);
    glProgramUniform1i(program, clear.eye_quads, 0);
    const Scissor scissor = portal_scissor(ctx, view, rects);
    draw_full_target(ctx, view, {pass, view.level + 1, program, scissor, glm::vec3(blend_color)});
}

// The pixels of the drawing target in the portal's scissor (all of them
// without culling).
gl::ScissorRect region_of(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects) {
    const Target& t = ctx.target;
    if (!ctx.frame.cull_portals) return {0, 0, t.width, t.height};
    gl::ScissorRect s = scissor_of(ctx, rects, view);
    s.width = std::max(0, std::min(s.width, t.width - s.x));
    s.height = std::max(0, std::min(s.height, t.height - s.y));
    return s;
}

// Copies the region's colour into the next free saved colour (made, or
// remade for another size, on first use); returns its texture.
GLuint save_colour(const DrawContext& ctx, const gl::ScissorRect& region) {
    const Target& t = ctx.target;
    std::vector<SavedColour>& saves = ctx.scratch.saved_colours;
    const size_t slot = ctx.scratch.saved_colours_used++;
    if (saves.size() <= slot) saves.resize(slot + 1);
    SavedColour& s = saves[slot];
    const GLenum kind = t.samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    if (s.texture.get() == 0 || s.width != t.width || s.height != t.height || s.samples != t.samples) {
        // A render-to-texture portal's windows are of its texture's size:
        // the old copy may be bound still.
        if (s.texture) ctx.state.deleting_texture(s.texture.get());
        s.texture = gl::create_texture(kind);
        if (t.samples > 1)
            glTextureStorage2DMultisample(s.texture.get(), t.samples, GL_RGBA8, t.width, t.height, GL_TRUE);
        else
            glTextureStorage2D(s.texture.get(), 1, GL_RGBA8, t.width, t.height);
        s.width = t.width;
        s.height = t.height;
        s.samples = t.samples;
    }
    if (region.width > 0 && region.height > 0) {
        const bool from_texture = t.color_texture.get() != 0;
        glCopyImageSubData(from_texture ? t.color_texture.get() : t.color.get(),
                           from_texture ? GL_TEXTURE_2D : GL_RENDERBUFFER, 0, region.x, region.y, 0, s.texture.get(),
                           kind, 0, region.x, region.y, 0, region.width, region.height, 1);
    }
    return s.texture.get();
}

// colour ← r · (the copy, or the fill colour without one) + colour · (1 - r) · tint.
void blend_window(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects,
                  const scene::PortalInfo& w, GLuint saved) {
    const std::optional<WindowBlendProgram>& slot = ctx.programs.window_blend[ctx.target.samples > 1 ? 1 : 0];
    assert(slot);  // prepare_window_blend made it with the frame
    const WindowBlendProgram& blend = *slot;
    const double r = w.reflectance;
    const glm::dvec3 through = (1.0 - r) * w.tint;
    const GLuint program = blend.program.get();
    glProgramUniform1i(program, blend.use_saved, saved != 0 ? 1 : 0);
    glProgramUniform3f(program, blend.scale, float(r), float(r), float(r));
    const glm::dvec3 fill = r * shading::kPortalFillColor;
    glProgramUniform3f(program, blend.constant, float(fill.r), float(fill.g), float(fill.b));
    ctx.state.texture(0, saved);  // the copy, or none
    const Scissor scissor = portal_scissor(ctx, view, rects);
    draw_full_target(ctx, view, {Pass::WindowBlend, view.level + 1, program, scissor, glm::vec3(through)});
}

}  // namespace

Result<void> prepare_window_blend(Programs& programs, bool multisample) {
    std::optional<WindowBlendProgram>& slot = programs.window_blend[multisample ? 1 : 0];
    if (slot) return {};
    Result<WindowBlendProgram> built = build_window_blend_program(multisample);
    if (!built) return built;
    slot = std::move(*built);
    return {};
}

void draw_mirror_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                        const PortalSteps& steps) {
    const scene::PortalInfo& m = ctx.scene.portals[p];
    mark_portal(ctx, view, p, rects, steps);
    ctx.scratch.stats.portal_passes_drawn += 1;
    draw_level(ctx, reflected_view(ctx, view, p, rects, shading::max_channel(m.tint)));
    if (!is_white(m.tint)) draw_region(ctx, view, Pass::Tint, rects, m.tint);
    unmark_portal(ctx, view, p, rects, steps);
}

void draw_window_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                        const PortalSteps& steps) {
    const scene::PortalInfo& w = ctx.scene.portals[p];
    const double r = w.reflectance;
    const double through_factor = (1.0 - r) * shading::max_channel(w.tint);
    const bool reflect = view.weight * r >= shading::kMinBranchWeight;
    const bool through = view.weight * through_factor >= shading::kMinBranchWeight;
    FrameScratch& s = ctx.scratch;
    mark_portal(ctx, view, p, rects, steps);

    GLuint saved = 0;
    if (reflect) {
        s.stats.portal_passes_drawn += 1;
        draw_level(ctx, reflected_view(ctx, view, p, rects, r));
        saved = save_colour(ctx, region_of(ctx, view, rects));
        draw_region(ctx, view, Pass::ClearRegion, rects);
    }
    if (through) {
        s.stats.portal_passes_drawn += 1;
        draw_level(ctx, child_view(ctx, view, p, rects, through_factor));
    } else {
        draw_fill(ctx, view, p, rects, view.level + 1);
    }
    blend_window(ctx, view, rects, w, saved);
    if (reflect) s.saved_colours_used -= 1;
    unmark_portal(ctx, view, p, rects, steps);
}

}  // namespace impossible::render
