// KHR_lights_punctual (layout-format.md, "Lights"): the point and spot lights
// of the default scene's nodes, placed by each node's world transform.
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "assets/gltf_import.hpp"
#include "base/user_text.hpp"

namespace impossible::assets {

namespace {

// The light `light` of the extension, checked; nothing for a directional
// light (skipped).
Result<std::optional<ModelLight>> read_light(const tinygltf::Light& light, const std::string& who) {
    if (light.type == "directional") return std::optional<ModelLight>{};
    if (light.type != "point" && light.type != "spot") {
        return Error{who + " of unknown type \"" + printable(light.type, 20) +
                     "\" (KHR_lights_punctual's types are point, spot and directional)"};
    }
    ModelLight out;
    if (!light.color.empty()) {
        if (light.color.size() != 3) return Error{who + " whose color does not have 3 numbers"};
        for (int c = 0; c < 3; ++c) {
            const double v = light.color[static_cast<std::size_t>(c)];
            if (!(v >= 0.0 && v <= 1.0))
                return Error{who + " whose color holds " + format_number(v) + ", outside 0..1"};
            out.color[c] = v;
        }
    }
    if (!(light.intensity > 0.0) || light.intensity > limits::kMaxLightIntensity) {
        return Error{who + " whose intensity " + format_number(light.intensity) + " is not in (0, " +
                     format_number(limits::kMaxLightIntensity) + "] (a layout's light shines)"};
    }
    out.intensity = light.intensity;
    // tinygltf reads an absent range as 0 (no limit).
    if (!(light.range >= 0.0) || light.range > limits::kMaxCoordinate) {
        return Error{who + " whose range " + format_number(light.range) + " is not in (0, " +
                     format_number(limits::kMaxCoordinate) + "]"};
    }
    out.range = light.range;
    if (light.type == "spot") {
        const double inner = light.spot.innerConeAngle;
        const double outer = light.spot.outerConeAngle;
        if (!(inner >= 0.0 && inner < outer && outer <= 1.5707963267948966 + 1e-12)) {
            return Error{who + " whose cone (innerConeAngle " + format_number(inner) + ", outerConeAngle " +
                         format_number(outer) + ") is not 0 <= inner < outer <= pi/2"};
        }
        out.spot = true;
        out.inner_cone_rad = inner;
        out.outer_cone_rad = outer;
    }
    return std::optional<ModelLight>{out};
}

// "light \"Point.002\" (light 1, node 4 \"Bulb\")": the glTF names, cut to
// 60 bytes, where the file gives them.
std::string light_name(const tinygltf::Model& model, std::size_t light, int node) {
    const std::string& own = model.lights[light].name;
    std::string out = own.empty() ? "light " + std::to_string(light) : "light " + quote(own.substr(0, 60));
    out += " (";
    if (!own.empty()) out += "light " + std::to_string(light) + ", ";
    out += "node " + std::to_string(node);
    const std::string& node_name = model.nodes[static_cast<std::size_t>(node)].name;
    if (!node_name.empty()) out += " " + quote(node_name.substr(0, 60));
    return out + ")";
}

}  // namespace

Result<std::vector<ModelLight>> read_lights(const tinygltf::Model& model, const std::vector<LightInstance>& lights,
                                            std::vector<std::string>& directional) {
    std::vector<ModelLight> out;
    for (const LightInstance& instance : lights) {
        const std::string node = "has node " + std::to_string(instance.node);
        const tinygltf::Value& index = *instance.light;
        if (!index.IsInt() || index.GetNumberAsInt() < 0 ||
            static_cast<std::size_t>(index.GetNumberAsInt()) >= model.lights.size()) {
            return Error{node + " whose KHR_lights_punctual light does not exist"};
        }
        const auto n = static_cast<std::size_t>(index.GetNumberAsInt());
        Result<std::optional<ModelLight>> light = read_light(model.lights[n], "has light " + std::to_string(n));
        if (!light) return light;
        if (!light->has_value()) {
            directional.push_back(light_name(model, n, instance.node));
            continue;
        }
        ModelLight placed = **light;
        placed.name = light_name(model, n, instance.node);
        const glm::dvec4 origin = instance.world * glm::dvec4(0.0, 0.0, 0.0, 1.0);
        const glm::dvec3 axis = glm::dvec3(instance.world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
        const double length = glm::length(axis);
        if (!std::isfinite(origin.x + origin.y + origin.z) || !(length > 0.0) || !std::isfinite(length)) {
            return Error{node + " whose light cannot be placed (its transform is degenerate)"};
        }
        placed.position = glm::dvec3(origin);
        placed.direction = axis / length;
        if (out.size() >= limits::kMaxModelLights) {
            return Error{"has more than " + std::to_string(limits::kMaxModelLights) + " point and spot lights"};
        }
        out.push_back(placed);
    }
    return out;
}

}  // namespace impossible::assets
