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
// drawn by the VOLUMES variant, which drops its fragments inside the
// volumes, only within the volumes' screen bounds, and by the plain variants
// around them (draw_level_colour); each volume's target room is then drawn
// in the same level, shown only inside the volume and tinted.
#include "render/objects/object_draw.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/lights/light_draw.hpp"
#include "render/objects/object_culling.hpp"
#include "render/portals/portal_draw.hpp"

namespace impossible::render {
namespace {

gl::ScissorRect clipped(const gl::ScissorRect& r, const gl::ScissorRect& to) {
    const int x0 = std::max(r.x, to.x), y0 = std::max(r.y, to.y);
    const int x1 = std::min(r.x + r.width, to.x + to.width), y1 = std::min(r.y + r.height, to.y + to.height);
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

// Room `t`'s own batches in a level of another cell (a volume's target, in
// the same coordinates), shown inside volume `inside` only. With culling,
// only its triangles that may lie inside, piece by piece, each within the
// screen bounds of where it meets the volume: the same triangles in the same
// order, with the same clip rectangles, so the same pixels; fewer fragments
// to discard (scene/volume_pieces.hpp; FrameDesc::volume_pieces).
void draw_volume_room(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, const VolumeBox& volume,
                      int inside) {
    const SceneData& r = ctx.scene;
    const int t = volume.target;
    const scene::CellOrigin& origin = r.cell_origins[static_cast<size_t>(t)];
    const math::dmat4 model = glm::translate(math::dmat4(1.0), origin.origin);
    // Lit by its own room's ambient and lights (layout-format.md, "Lights").
    if (r.lighting.lit) ctx.scratch.stats.light_images += ctx.lights.count[static_cast<size_t>(t)];
    const SceneProgram* set_up = nullptr;  // the program whose per-draw uniforms are set
    const auto draw = [&](const scene::DrawBatch& b, const Scissor& within) {
        const SceneProgram& program =
            cell_program(ctx, view, light_flags(ctx, t) | (has_material(b) ? kMaterials : 0u));
        // The same for every piece of a program: set once, not per piece.
        if (&program != set_up) {
            set_model_uniforms(ctx, view, program, {view.eyes[0].rect, view.eyes[1].rect}, model,
                               origin.checker_offset);
            set_cell_id(program, static_cast<unsigned>(t + 1), false);
            set_room_lights(ctx, program, t, false);
            set_volume_uniforms(ctx, view, program, model, inside);
            set_up = &program;
        }
        if (has_material(b)) set_material(ctx, program, b);
        draw_range(ctx, view, {Pass::Scene, view.level, &program, within}, b.range);
    };
    if (!ctx.frame.cull_portals || !ctx.frame.split_volume_draws || !ctx.frame.volume_pieces) {
        for (const scene::DrawBatch& b : r.cells[static_cast<size_t>(t)]) draw(b, scissor);
        return;
    }
    for (const scene::VolumePiece& piece : volume.target_pieces) {
        std::array<NdcRect, 2> rects{NdcRect::none(), NdcRect::none()};
        for (size_t e = 0; e < 2; ++e)
            if (view.eyes[e].active && !view.eyes[e].rect.empty())
                rects[e] = box_rect(piece.corners.data(), view.eyes[e]);
        if (rects[0].empty() && rects[1].empty()) continue;
        const gl::ScissorRect within =
            scissor ? clipped(scissor_of(ctx, rects, view), *scissor) : scissor_of(ctx, rects, view);
        if (within.width > 0 && within.height > 0) draw(piece.batch, within);
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

const SceneProgram& cell_program(const DrawContext& ctx, const LevelView& view, unsigned flags) {
    const SceneData& r = ctx.scene;
    if (!view.outside_volumes && !r.volumes[static_cast<size_t>(view.cell)].empty()) flags |= kVolumes;
    if (flags == 0u) return ctx.scene_program;
    if (flags == kMaterials) {
        assert(ctx.material_program != nullptr);
        return *ctx.material_program;
    }
    const std::map<unsigned, SceneProgram>& variants = ctx.programs.variants[static_cast<int>(ctx.frame.stereo)];
    const auto variant = variants.find(flags);
    assert(variant != variants.end());  // prepare_frame built it
    return variant->second;
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

// Where the volumes of view.cell may be seen, per eye: the union of their
// rectangles (narrowed_to's), none where no volume is seen.
std::array<NdcRect, 2> volumes_rects(const DrawContext& ctx, const LevelView& view) {
    std::array<NdcRect, 2> all{NdcRect::none(), NdcRect::none()};
    for (const VolumeBox& v : ctx.scene.volumes[static_cast<size_t>(view.cell)]) {
        const LevelView narrowed = narrowed_to(ctx, view, v);
        for (size_t e = 0; e < 2; ++e) all[e] = united(all[e], narrowed.eyes[e].rect);
    }
    return all;
}

// The pixels of `level` outside the (disjoint) rectangles `holes`, as
// disjoint rectangles: the rows between consecutive edges of the holes, each
// less the holes spanning them.
std::vector<gl::ScissorRect> outside_of(const gl::ScissorRect& level, const std::vector<gl::ScissorRect>& holes) {
    std::vector<int> ys = {level.y, level.y + level.height};
    for (const gl::ScissorRect& h : holes) {
        ys.push_back(h.y);
        ys.push_back(h.y + h.height);
    }
    std::sort(ys.begin(), ys.end());
    std::vector<gl::ScissorRect> out;
    for (size_t k = 0; k + 1 < ys.size(); ++k) {
        const int y0 = ys[k], y1 = ys[k + 1];
        if (y1 <= y0) continue;
        std::vector<std::pair<int, int>> cut;  // the holes' columns over this strip
        for (const gl::ScissorRect& h : holes)
            if (h.y <= y0 && y1 <= h.y + h.height) cut.emplace_back(h.x, h.x + h.width);
        std::sort(cut.begin(), cut.end());
        int x = level.x;
        for (const auto& [c0, c1] : cut) {
            if (c0 > x) out.push_back({x, y0, c0 - x, y1 - y0});
            x = std::max(x, c1);
        }
        if (level.x + level.width > x) out.push_back({x, y0, level.x + level.width - x, y1 - y0});
    }
    return out;
}

// What a part of a level's draws leaves out: the volumes (the plain
// variants: no volume is seen there), or the cell's light paths.
struct PartKind {
    bool outside_volumes = false;
    bool outside_light_paths = false;
    bool outside_shadows = false;
};

// The cell's batches and instances of a level within `scissor`, by the
// variants `kind` picks.
void draw_part(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, PartKind kind,
               bool count_lights) {
    LevelView part = view;
    part.outside_volumes = kind.outside_volumes;
    part.outside_light_paths = kind.outside_light_paths;
    part.outside_shadows = kind.outside_shadows;
    const SceneProgram& shaded = cell_program(ctx, part, light_flags(ctx, part.cell, &part));
    if (shaded.volume_count >= 0)
        ctx.scratch.stats.volume_variant_pixels += scissor ? static_cast<long>(scissor->width) * scissor->height
                                                           : 2L * ctx.frame.eye_width * ctx.frame.eye_height;
    set_eye_uniforms(ctx, part, shaded, {part.eyes[0].rect, part.eyes[1].rect});
    set_cell_id(shaded, static_cast<unsigned>(part.cell + 1), false);
    set_room_lights(ctx, shaded, part.cell, count_lights);
    // The instances first, as a cell's still props come before the faces
    // they stand on: what they hide fails the early depth test.
    draw_cell_instances(ctx, part, scissor, part.cell, -1);
    draw_cell(ctx, part, {Pass::Scene, part.level, &shaded, scissor});
}

// Per eye, the union of the rectangles rect_of(region, eye) of `regions`,
// each with two pixels of margin, within the eye's rect; none where none is
// seen.
template <class Regions, class RectOf>
std::array<NdcRect, 2> united_rects(const DrawContext& ctx, const LevelView& view, const Regions& regions,
                                    RectOf rect_of) {
    std::array<NdcRect, 2> all{NdcRect::none(), NdcRect::none()};
    for (const auto& region : regions)
        for (size_t e = 0; e < 2; ++e) {
            const NdcRect r = rect_of(region, view.eyes[e]);
            if (r.empty()) continue;
            all[e] = united(all[e],
                            intersect(widened(r, 2.0, ctx.frame.eye_width, ctx.frame.eye_height), view.eyes[e].rect));
        }
    return all;
}

// Where the path images of view.cell's lights may light it, per eye: the
// union of their lit regions' rectangles. nullopt where some path image may
// light the whole cell.
std::optional<std::array<NdcRect, 2>> light_paths_rects(const DrawContext& ctx, const LevelView& view) {
    const std::optional<std::vector<std::array<math::dvec3, 8>>>& regions =
        ctx.lights.path_regions[static_cast<size_t>(view.cell)];
    if (!regions) return std::nullopt;
    return united_rects(ctx, view, *regions, [](const std::array<math::dvec3, 8>& region, const EyeView& eye) {
        return box_rect(region.data(), eye);
    });
}

// Each part draws all of the cell's triangles again (the scissor only drops
// their fragments): a cell of more than kMaxLightSplitIndices indices is not
// split for its lights, where the vertices would cost more than the
// fragments save (a large glTF model).
constexpr std::uint64_t kMaxLightSplitIndices = 300'000;

bool light_split_pays(const DrawContext& ctx, size_t cell) {
    std::uint64_t indices = 0;
    for (const scene::DrawBatch& b : ctx.scene.cells[cell]) indices += b.range.count;
    return indices <= kMaxLightSplitIndices;
}

// Where a prop's shadow may fall on view.cell, per eye: the union of its
// images' shadow hulls' rectangles (render/lights/shadow_regions.hpp).
// nullopt where the split does not apply: shadows anywhere, or none at all
// (then every draw of the room skips the lookups).
std::optional<std::array<NdcRect, 2>> shadow_rects(const DrawContext& ctx, const LevelView& view) {
    const auto c = static_cast<size_t>(view.cell);
    if (!ctx.scene.lighting.lit || !ctx.frame.cull_portals || !ctx.frame.split_light_draws ||
        c >= ctx.lights.shadow_regions.size() || !ctx.lights.shadow_regions[c] ||
        ctx.lights.shadow_regions[c]->empty() || ctx.lights.count[c] == 0 || !ctx.scene.volumes[c].empty() ||
        !light_split_pays(ctx, c))
        return std::nullopt;
    return united_rects(
        ctx, view, *ctx.lights.shadow_regions[c],
        [](const std::array<math::dvec3, 16>& hull, const EyeView& eye) { return hull_rect(hull.data(), 16, eye); });
}

using PartDraw = void (*)(const DrawContext&, const LevelView&, const Scissor&, PartKind, bool);

// The level in parts: within `inside` (per eye) as `in`, the rest as
// `out`, each part by `draw` (the first counting the room's light images
// when `count`). The parts are scissor rectangles of whole pixels,
// disjoint, and every draw keeps the level's own clip rectangles, so each
// pixel is drawn by one draw of the same triangles as before.
void draw_in_parts(const DrawContext& ctx, const LevelView& view, const Scissor& scissor,
                   const std::array<NdcRect, 2>& inside, PartKind in, PartKind out, bool count, PartDraw draw) {
    const gl::ScissorRect level =
        scissor.value_or(gl::ScissorRect{0, 0, 2 * ctx.frame.eye_width, ctx.frame.eye_height});
    std::vector<gl::ScissorRect> holes;
    for (size_t e = 0; e < 2; ++e) {
        if (inside[e].empty() || !view.eyes[e].active) continue;
        std::array<NdcRect, 2> one{NdcRect::none(), NdcRect::none()};
        one[e] = inside[e];
        const gl::ScissorRect hole = clipped(scissor_of(ctx, one, view), level);
        if (hole.width > 0 && hole.height > 0) holes.push_back(hole);
    }
    if (holes.size() == 2 && clipped(holes[0], holes[1]).width > 0) {  // never in practice: one hole
        const gl::ScissorRect& a = holes[0];
        const gl::ScissorRect& b = holes[1];
        const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
        holes = {{x0, y0, std::max(a.x + a.width, b.x + b.width) - x0, std::max(a.y + a.height, b.y + b.height) - y0}};
    }
    for (const gl::ScissorRect& r : outside_of(level, holes)) {
        draw(ctx, view, r, out, count);
        count = false;
    }
    for (const gl::ScissorRect& h : holes) {
        draw(ctx, view, h, in, count);
        count = false;
    }
}

// A part of a lit level, split again where the props' shadows may fall:
// outside, without the shadow-map lookups.
void draw_shadow_parts(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, PartKind kind,
                       bool count) {
    if (const std::optional<std::array<NdcRect, 2>> inside = shadow_rects(ctx, view)) {
        PartKind out = kind;
        out.outside_shadows = true;
        draw_in_parts(ctx, view, scissor, *inside, kind, out, count, draw_part);
        return;
    }
    draw_part(ctx, view, scissor, kind, count);
}

// A cell whose light is cached (render/lights/light_cache.hpp): one part,
// whose fragments read their cells' sums and add only the images their
// cells' bits name.
void draw_cached(const DrawContext& ctx, const LevelView& view, const Scissor& scissor) {
    const int c = view.cell;
    const SceneProgram& cached = cell_program(ctx, view, cached_light_flags(ctx, c));
    set_eye_uniforms(ctx, view, cached, {view.eyes[0].rect, view.eyes[1].rect});
    set_cell_id(cached, static_cast<unsigned>(c + 1), false);
    set_room_lights(ctx, cached, c, true);
    draw_cell(ctx, view, {Pass::Scene, view.level, &cached, scissor});
    ctx.scratch.stats.cached_levels += 1;
}

}  // namespace

void draw_level_colour(const DrawContext& ctx, const LevelView& view, const Scissor& scissor) {
    const auto c = static_cast<size_t>(view.cell);
    if (draws_cached(ctx, view.cell)) {
        draw_cached(ctx, view, scissor);
        return;
    }
    const bool volumes = !ctx.scene.volumes[c].empty();
    if (volumes && ctx.frame.cull_portals && ctx.frame.split_volume_draws) {
        // Outside the volumes' rectangles no fragment can lie in a volume:
        // the plain variants there, which test depth before shading; the
        // discarding one only inside.
        draw_in_parts(ctx, view, scissor, volumes_rects(ctx, view), {}, {.outside_volumes = true}, true, draw_part);
        return;
    }
    const bool paths = ctx.scene.lighting.lit && !ctx.frame.naive_lights && ctx.lights.count[c] > ctx.lights.direct[c];
    if (!volumes && paths && ctx.frame.cull_portals && ctx.frame.split_light_draws && light_split_pays(ctx, c)) {
        // Outside the rectangles where the cell's path images may light it,
        // their terms are 0 at every point: the variant without their loop
        // there (llvmpipe runs every fragment through all of a shader's code).
        if (const std::optional<std::array<NdcRect, 2>> inside = light_paths_rects(ctx, view)) {
            draw_in_parts(ctx, view, scissor, *inside, {}, {.outside_light_paths = true}, true, draw_shadow_parts);
            return;
        }
    }
    draw_shadow_parts(ctx, view, scissor, {}, true);
}

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
        draw_volume_room(ctx, narrowed, within, volumes[k], static_cast<int>(k));
        draw_cell_instances(ctx, narrowed, within, volumes[k].target, static_cast<int>(k));
    }
}

}  // namespace impossible::render
