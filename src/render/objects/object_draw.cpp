// Dynamic objects and volume portals in the stencil recursion
// (layout-format.md, "Moving props, hands and crossing objects" and "Volume
// portals"; docs/crossing.md).
//
// The frame's objects are placed once (frame_objects.hpp): instances, each
// a mesh, a cell, a rigid matrix from the mesh's own coordinates and up to
// two door planes that cut it. Every level that draws a cell draws the
// cell's instances after its own batches (instance_draw.cpp): all their
// plain batches in one multi-draw for both eyes, each instance's matrix and
// cuts read from its per-instance record (instance_stream.hpp), the cuts as
// two more clip distances (the OBJECT_CUTS variant). A cell with volumes is
// drawn, all of it, by the VOLUMES variant, which drops its fragments inside
// the volumes; each volume's target room is then drawn in the same level,
// shown only inside the volume and tinted.
#include "render/objects/object_draw.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/lights/light_draw.hpp"
#include "render/objects/object_culling.hpp"

namespace impossible::render {
namespace {

// Room `t`'s own batches in a level of another cell (a volume's target, in
// the same coordinates), shown inside volume `inside` only.
void draw_volume_room(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, int t, int inside) {
    const SceneData& r = ctx.scene;
    const scene::CellOrigin& origin = r.cell_origins[static_cast<size_t>(t)];
    const math::dmat4 model = glm::translate(math::dmat4(1.0), origin.origin);
    // Lit by its own room's ambient and lights (layout-format.md, "Lights").
    if (r.lighting.lit) ctx.scratch.stats.light_images += ctx.lights.count[static_cast<size_t>(t)];
    for (const scene::DrawBatch& b : r.cells[static_cast<size_t>(t)]) {
        const SceneProgram& program =
            cell_program(ctx, view.cell, light_flags(ctx) | (has_material(b) ? kMaterials : 0u));
        set_model_uniforms(ctx, view, program, {view.eyes[0].rect, view.eyes[1].rect}, model, origin.checker_offset);
        set_cell_id(program, static_cast<unsigned>(t + 1), false);
        set_room_lights(ctx, program, t, false);
        set_volume_uniforms(ctx, view, program, model, inside);
        if (has_material(b)) set_material(ctx, program, b);
        draw_range(ctx, view, {Pass::Scene, view.level, &program, scissor}, b.range);
    }
}

}  // namespace

// A batch's material uniforms and texture (portal_draw.cpp's draw_cell does
// the same for a cell's batches).
void set_material(const DrawContext& ctx, const SceneProgram& m, const scene::DrawBatch& b) {
    glProgramUniform1i(m.program.get(), m.mip_level0, ctx.frame.textures_mip_level0 ? 1 : 0);
    glProgramUniform1i(m.program.get(), m.textured, b.texture >= 0 ? 1 : 0);
    glProgramUniform1f(m.program.get(), m.alpha_cutoff, b.alpha_cutoff);
    const GLuint texture = b.texture >= 0 ? ctx.scene.gpu.textures[static_cast<std::size_t>(b.texture)].get() : 0;
    ctx.state.texture(kSceneTextureUnit, texture);
}

bool has_material(const scene::DrawBatch& b) { return b.texture >= 0 || b.alpha_cutoff >= 0.0f; }

const SceneProgram& cell_program(const DrawContext& ctx, int cell, unsigned flags) {
    const SceneData& r = ctx.scene;
    if (!r.volumes[static_cast<size_t>(cell)].empty()) flags |= kVolumes;
    if (flags == 0u) return ctx.scene_program;
    if (flags == kMaterials) {
        assert(ctx.material_program != nullptr);
        return *ctx.material_program;
    }
    const std::optional<SceneProgram>& variant = ctx.programs.variants[static_cast<int>(ctx.frame.stereo)][flags];
    assert(variant);  // prepare_frame built it
    return *variant;
}

namespace {

// The level's view narrowed, per eye, to where volume `v` may be seen (two
// pixels of margin, as props'): its target room is drawn only there.
LevelView narrowed_to(const DrawContext& ctx, const LevelView& view, const VolumeBox& v) {
    math::dvec3 corners[8];
    for (int k = 0; k < 8; ++k) {
        const double sr = k == 0 || k == 3 || k == 4 || k == 7 ? -1.0 : 1.0;
        const double su = k % 4 < 2 ? -1.0 : 1.0;
        const double sn = k < 4 ? 1.0 : -1.0;
        corners[k] = v.center + sr * v.half.x * v.axes[0] + su * v.half.y * v.axes[1] + sn * v.half.z * v.axes[2];
    }
    LevelView narrowed = view;
    for (EyeView& ev : narrowed.eyes) {
        const NdcRect rect = box_rect(corners, ev);
        ev.rect = rect.empty() ? NdcRect::none()
                               : intersect(widened(rect, 2.0, ctx.frame.eye_width, ctx.frame.eye_height), ev.rect);
    }
    return narrowed;
}

}  // namespace

void draw_volume_rooms(const DrawContext& ctx, const LevelView& view, const Scissor& scissor) {
    const std::vector<VolumeBox>& volumes = ctx.scene.volumes[static_cast<size_t>(view.cell)];
    for (size_t k = 0; k < volumes.size(); ++k) {
        // With culling, the target room is drawn only where the volume may
        // be seen (the rest of it would be discarded fragment by fragment).
        const LevelView narrowed = ctx.frame.cull_portals ? narrowed_to(ctx, view, volumes[k]) : view;
        if (narrowed.eyes[0].rect.empty() && narrowed.eyes[1].rect.empty()) continue;
        const Scissor within = ctx.frame.cull_portals
                                   ? portal_scissor(ctx, narrowed, {narrowed.eyes[0].rect, narrowed.eyes[1].rect})
                                   : scissor;
        draw_volume_room(ctx, narrowed, within, volumes[k].target, static_cast<int>(k));
        draw_cell_instances(ctx, narrowed, within, volumes[k].target, static_cast<int>(k));
    }
}

}  // namespace impossible::render
