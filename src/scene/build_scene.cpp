// build_scene: the portal links and the dynamic objects first, then rooms
// (each room's faces then its static props, one contiguous index range per
// cell), then every portal's box (front range, inner range), then the
// dynamic objects' meshes (scene/object_meshes.hpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <type_traits>
#include <variant>

#include "lights/light_bound.hpp"
#include "scene/box_mesh.hpp"
#include "scene/cell_objects.hpp"
#include "scene/mesh_writer.hpp"
#include "scene/object_meshes.hpp"
#include "scene/portal_box.hpp"
#include "scene/room_mesh.hpp"
#include "scene/scene.hpp"
#include "scene/volume_pieces.hpp"

namespace impossible::scene {

CellOrigin origin_of_cell(const layout::Room& room) {
    CellOrigin f;
    for (int axis = 0; axis < 3; ++axis) {
        const double centre = 0.5 * (room.min[axis] + room.max[axis]);
        f.origin[axis] = kCellOriginGrid * std::round(centre / kCellOriginGrid);
        // The checker's parity at origin + p is its parity at offset + p.
        const double period = 2.0 * room.checker;
        if (period > 0.0)
            f.checker_offset[axis] = static_cast<float>(f.origin[axis] - period * std::floor(f.origin[axis] / period));
    }
    return f;
}

namespace {

// Each room's portals, in file order: one pass over the portals, so that
// building n rooms does not look at every portal n times.
std::vector<std::vector<int>> portals_by_room(const layout::Layout& layout) {
    std::vector<std::vector<int>> room_portals(layout.rooms.size());
    for (std::size_t p = 0; p < layout.portals.size(); ++p) {
        const int room = layout.portals[p].room;
        if (room >= 0 && static_cast<std::size_t>(room) < layout.rooms.size())
            room_portals[static_cast<std::size_t>(room)].push_back(static_cast<int>(p));
    }
    return room_portals;
}

// One prop's triangles, appended as its own batches; the object bounds them.
void append_prop(Scene& scene, MeshWriter& out, const layout::Prop& prop, CellObjects& objects) {
    const auto first_vertex = static_cast<std::uint32_t>(scene.vertices.size());
    std::vector<DrawBatch> own;
    std::visit(
        [&](const auto& p) {
            if constexpr (std::is_same_v<std::decay_t<decltype(p)>, layout::BoxProp>) {
                const std::uint32_t box_first = out.index_count();
                append_box_prop(out, p);
                add_batch(own, DrawBatch{out.range_since(box_first)});
            } else {
                append_gltf_prop(out, p, own);
            }
        },
        prop);
    CellObject object;
    if (const auto* box = std::get_if<layout::BoxProp>(&prop)) {
        object.box_vertex = first_vertex;
        object.box_min = box->min;
        object.box_max = box->max;
    }
    bound_object(scene, first_vertex, out.origin, object);
    object.first_batch = static_cast<std::uint32_t>(objects.batches.size());
    object.batch_count = static_cast<std::uint32_t>(own.size());
    objects.objects.push_back(object);
    objects.batches.insert(objects.batches.end(), own.begin(), own.end());
}

// Room r's cell: its faces (holes for its portals, the fronts of portals in
// them kept in `fronts`), then its props, one contiguous index range.
void append_cell(Scene& scene, MeshWriter& out, const layout::Layout& layout, std::size_t r,
                 const std::vector<int>& room_portals, std::vector<std::optional<FrontGrid>>& fronts) {
    const layout::Room& room = layout.rooms[r];
    scene.origins.push_back(origin_of_cell(room));
    out.origin = scene.origins.back().origin;
    const std::uint32_t first = out.index_count();
    CellObjects objects;
    const auto faces = append_room_faces(out, layout, static_cast<int>(r), room_portals, fronts);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        DrawBatch b;
        b.range = faces[f];
        if (room.face_texture[f]) b.texture = out.texture(room.face_texture[f], assets::Sampler{});
        add_batch(objects.surfaces, b);
    }
    // Dynamic props (walk/objects.hpp) are drawn per frame, not with the cell.
    const std::vector<bool>& dynamic = scene.object_set.dynamic[r];
    for (std::size_t i = 0; i < room.props.size(); ++i)
        if (i >= dynamic.size() || !dynamic[i]) append_prop(scene, out, room.props[i], objects);
    scene.cells.push_back(out.range_since(first));
    scene.batches.push_back(finish_cell(scene, objects));
    // A prop inside a volume is hidden there: a room with volumes has no
    // occluders.
    if (scene.volumes[r].empty()) objects.occluders = occluders_of(room, dynamic);
    scene.objects.push_back(std::move(objects));
}

}  // namespace

Scene build_scene(const layout::Layout& layout) { return build_scene(layout, links::link_portals(layout)); }

Scene build_scene(const layout::Layout& layout, const links::PortalLinks& links) {
    Scene scene;
    MeshWriter out{scene};
    // Fronts of portals that are holes in their room's faces, set while the
    // room is built so that they share the wall's vertices.
    std::vector<std::optional<FrontGrid>> fronts(layout.portals.size());
    const std::vector<std::vector<int>> room_portals = portals_by_room(layout);
    scene.links = links;
    scene.object_set = walk::build_object_set(layout, scene.links);
    scene.object_set.dynamic.resize(layout.rooms.size());
    scene.volumes.resize(layout.rooms.size());
    for (const layout::Volume& v : layout.volumes) scene.volumes[static_cast<std::size_t>(v.room)].push_back(v);
    scene.cells.reserve(layout.rooms.size());
    scene.batches.reserve(layout.rooms.size());
    scene.origins.reserve(layout.rooms.size());
    for (std::size_t r = 0; r < layout.rooms.size(); ++r) append_cell(scene, out, layout, r, room_portals[r], fronts);
    scene.volume_pieces.resize(layout.rooms.size());
    std::size_t volume_budget = kVolumeTriangleBudget;
    for (std::size_t r = 0; r < layout.rooms.size(); ++r)
        for (const layout::Volume& v : scene.volumes[r]) {
            const auto t = static_cast<std::size_t>(v.target_room);
            scene.volume_pieces[r].push_back(
                volume_pieces(scene, scene.batches[t], scene.origins[t].origin, v, volume_budget));
        }

    scene.portals.reserve(layout.portals.size());
    scene.portal_info.reserve(layout.portals.size());
    for (std::size_t p = 0; p < layout.portals.size(); ++p) {
        const layout::Portal& lp = layout.portals[p];
        out.origin = scene.origins[static_cast<std::size_t>(lp.room)].origin;
        const FrontGrid front = fronts[p] ? *fronts[p] : corner_front(out, lp.rect);
        const bool box = lp.kind == layout::PortalKind::Door;
        scene.portals.push_back(box ? append_portal_box(out, lp.rect, front)
                                    : append_portal_front(out, lp.rect, front));
        scene.portal_info.push_back({lp.rect, lp.room, lp.target, lp.kind, lp.tint, lp.reflectance});
    }
    append_object_meshes(scene, out, layout);
    scene.exposure = layout.exposure;
    if (layout.lighting == layout::Lighting::Lights) {
        // The light images at the layout's depth, of the lights that light
        // frames, within the light paths' and rectangles' bound as the
        // tracer cuts them (lights::light_bound); the layout, with those
        // lights, is kept for a renderer asked for another depth
        // (View::light_depth).
        scene.lighting = layout::Lighting::Lights;
        const lights::LightBound bound = lights::light_bound(layout, scene.links);
        scene.max_light_depth = bound.depth;
        scene.light_depth = std::min(layout.light_depth, scene.max_light_depth);
        scene.lit_layout = std::make_shared<const layout::Layout>(lights::with_lit_lights(layout, bound));
        scene.room_lights = lights::light_images(*scene.lit_layout, scene.links, scene.light_depth);
    }
    return scene;
}

}  // namespace impossible::scene
