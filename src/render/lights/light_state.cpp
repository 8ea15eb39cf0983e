// A lit layout's light images for the frame's light depth (light_state.hpp).
#include "render/lights/light_state.hpp"

#include <algorithm>
#include <vector>

#include "render/scene_data.hpp"

namespace impossible::render {

void ensure_lights(LightBuffers& buffers, const SceneData& scene, const FrameDesc& frame) {
    const SceneLights& l = scene.lighting;
    if (!l.lit) return;
    const int depth = std::min(frame.light_depth.value_or(l.scene_light_depth), l.max_light_depth);
    if (buffers.depth == depth) return;
    if (depth == l.scene_light_depth) {
        buffers = upload_light_images(l.scene_room_lights, *l.lit_layout, scene.cell_origins, depth);
        return;
    }
    const std::vector<lights::RoomLights> rooms = lights::light_images(*l.lit_layout, scene.links, depth);
    buffers = upload_light_images(rooms, *l.lit_layout, scene.cell_origins, depth);
}

}  // namespace impossible::render
