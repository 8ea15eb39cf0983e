// The shadow maps' reach per lit room (shadow_regions.hpp).
#include "render/lights/shadow_regions.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "lights/lit_region.hpp"
#include "render/objects/frame_objects.hpp"
#include "render/scene_data.hpp"

namespace impossible::render {
namespace {

// One occluder's hull into `out`; false where it may shadow anywhere. `to_c`
// maps its box's own coordinates into C's.
bool add_occluder(const glm::dvec3& light, const glm::dmat4& to_c, const glm::dvec3& lo, const glm::dvec3& hi,
                  double reach, int map_size, std::vector<std::array<glm::dvec3, 16>>& out) {
    std::array<glm::dvec3, 16> hull;
    if (!lights::shadow_region(light, to_c, lo, hi, reach, shadow_grow_angle(map_size), hull)) return false;
    out.push_back(hull);
    return true;
}

// One image's occluders (its legs' static props and the instances placed in
// their rooms, as the map draws them); false where one may shadow anywhere.
bool add_image(const ShadowSources& s, const std::vector<std::vector<int>>& by_room, const lights::LightImage& image,
               double reach, int map_size, std::vector<std::array<glm::dvec3, 16>>& out) {
    for (size_t i = 0; i < image.rooms.size(); ++i) {
        const auto room = static_cast<size_t>(image.rooms[i]);
        const glm::dmat4 to_c = glm::inverse(image.to_room[i]);  // the leg's room -> C
        for (const scene::CellObject& object : (*s.objects)[room].objects)
            if (!add_occluder(image.position, to_c, object.lo, object.hi, reach, map_size, out)) return false;
        for (const int k : by_room[room]) {
            const walk::ObjectInstance& inst = (*s.instances)[static_cast<size_t>(k)];
            const scene::ObjectMesh& mesh =
                (*s.object_meshes)[static_cast<size_t>((*s.instance_mesh)[static_cast<size_t>(k)])];
            if (!add_occluder(image.position, to_c * inst.to_cell, mesh.lo, mesh.hi, reach, map_size, out))
                return false;
        }
    }
    return true;
}

}  // namespace

std::vector<RoomShadowRegions> shadow_regions(const ShadowSources& s, const std::vector<lights::RoomLights>& rooms,
                                              const std::vector<int>& layer,
                                              const std::vector<std::pair<glm::dvec3, glm::dvec3>>& bounds,
                                              int map_size) {
    std::vector<std::vector<int>> by_room(s.objects->size());
    for (size_t i = 0; i < s.instances->size(); ++i) {
        const int cell = (*s.instances)[i].cell;
        if (cell >= 0 && static_cast<size_t>(cell) < by_room.size())
            by_room[static_cast<size_t>(cell)].push_back(static_cast<int>(i));
    }
    std::vector<RoomShadowRegions> out(rooms.size());
    size_t g = 0;
    for (size_t c = 0; c < rooms.size(); ++c) {
        std::vector<std::array<glm::dvec3, 16>> hulls;
        bool bounded = true;
        for (const lights::LightImage& image : rooms[c].images) {
            const bool mapped = g < layer.size() && layer[g] >= 0;
            ++g;
            if (!mapped || !bounded) continue;
            bounded =
                add_image(s, by_room, image, lights::light_reach(image.position, bounds[c].first, bounds[c].second),
                          map_size, hulls);
        }
        if (bounded) out[c] = std::move(hulls);
    }
    return out;
}

ShadowSources shadow_sources(const SceneData& r, const FrameObjects& objects) {
    return ShadowSources{.gpu = &r.gpu,
                         .objects = &r.objects,
                         .origins = &r.cell_origins,
                         .object_meshes = &r.object_meshes,
                         .instances = &objects.instances,
                         .instance_mesh = &objects.mesh};
}

std::vector<RoomShadowRegions> frame_shadow_regions(const ShadowMaps& maps, const SceneData& r,
                                                    const FrameObjects& objects,
                                                    const std::vector<lights::RoomLights>& rooms,
                                                    const FrameDesc& frame) {
    if (!frame.split_light_draws || !frame.cull_portals || !r.lighting.lit_layout) return {};
    std::vector<std::pair<glm::dvec3, glm::dvec3>> bounds;
    for (const layout::Room& room : r.lighting.lit_layout->rooms) bounds.emplace_back(room.min, room.max);
    if (bounds.size() != rooms.size()) return {};
    return shadow_regions(shadow_sources(r, objects), rooms, maps.layer, bounds, maps.size);
}

}  // namespace impossible::render
