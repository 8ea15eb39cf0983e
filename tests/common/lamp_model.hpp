// A small lamp made the way real glTF lamps are (issue 38, the Khronos
// sample assets): a shade and a pane of alphaMode BLEND, a bulb, a point
// light named "Point.002" below the model's floor and a directional light.
//
// In model coordinates (metres, +z towards the viewer):
// - the shade, material 0 "Glass" (BLEND, factor [0.9, 0.8, 0.5, 1]): a
//   quad x -0.3..0.3, y 0.9..1.5 at z 0 facing +z, whose COLOR_0 alpha is 0
//   along its bottom and 1 along its top: alpha-tested at 0.5 its lower half
//   is cut away along y = 1.2;
// - the pane, material 1 "Frosted" (BLEND, factor alpha 0.3): a quad
//   x 0.4..0.8, y 0.5..1.1 at z 0 facing +z, wholly cut away at 0.5 and
//   drawn under "blend": "opaque";
// - light 0 "Bulb" (point, 3 cd, warm) on node "BulbNode" at (0, 1.2, 0.4);
//   light 1 "Point.002" (point, 15 cd) on node "Fill" at (0, -1, 0), below
//   any floor the model stands on; light 2 "Sun" (directional) on node
//   "SunNode".
#pragma once

#include <string>
#include <vector>

#include "layout/gltf_writer.hpp"

namespace impossible::test {

static inline void write_lamp_model(const std::string& path) {
    layout_test::GltfWriter w;
    using layout_test::json;
    const auto quad = [&](float x0, float x1, float y0, float y1, int material, const std::vector<float>& alpha) {
        const int positions = w.vec3({x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0});
        json attributes = {{"POSITION", positions}};
        if (!alpha.empty()) {
            std::vector<float> rgba;
            for (float a : alpha) rgba.insert(rgba.end(), {1, 1, 1, a});
            const int view = w.view(rgba.data(), rgba.size() * sizeof(float));
            w.doc["accessors"].push_back(
                {{"bufferView", view}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}});
            attributes["COLOR_0"] = int(w.doc["accessors"].size()) - 1;
        }
        const int indices = w.indices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
        return w.mesh({{"attributes", attributes}, {"indices", indices}, {"material", material}});
    };
    w.node({{"name", "Shade"}, {"mesh", quad(-0.3f, 0.3f, 0.9f, 1.5f, 0, {0, 0, 1, 1})}});
    w.node({{"name", "Pane"}, {"mesh", quad(0.4f, 0.8f, 0.5f, 1.1f, 1, {})}});
    const auto light_node = [&](const char* name, int light, std::vector<double> at) {
        w.node({{"name", name}, {"translation", at}, {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    };
    light_node("BulbNode", 0, {0, 1.2, 0.4});
    light_node("Fill", 1, {0, -1, 0});
    light_node("SunNode", 2, {0, 3, 0});
    w.doc["materials"] = json::array({{{"name", "Glass"},
                                       {"alphaMode", "BLEND"},
                                       {"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.5, 1}}}}},
                                      {{"name", "Frosted"},
                                       {"alphaMode", "BLEND"},
                                       {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.8, 1.0, 0.3}}}}}});
    w.doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    w.doc["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights", json::array({{{"name", "Bulb"}, {"type", "point"}, {"intensity", 3}, {"color", {1, 0.9, 0.7}}},
                                  {{"name", "Point.002"}, {"type", "point"}, {"intensity", 15}},
                                  {{"name", "Sun"}, {"type", "directional"}, {"intensity", 2}}})}}}};
    w.write(path);
}

}  // namespace impossible::test
