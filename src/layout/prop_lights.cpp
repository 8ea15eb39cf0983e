// layout-format.md, "Lights": the KHR_lights_punctual lights of the rooms'
// glTF props, posed with their props and added to their rooms, and the
// warning for a light inside a prop.
#include <algorithm>
#include <cmath>

#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"

namespace impossible::layout::detail {

namespace {

constexpr double kDegreesPerRadian = 57.29577951308232;

// A model's light posed with its prop at rest (no motion offset).
Light pose_model_light(const GltfProp& prop, const assets::ModelLight& in, int prop_index) {
    Light light;
    light.position = place_model_point(prop, in.position);
    light.color = in.color;
    light.intensity = in.intensity;
    light.range = in.range;
    light.prop = prop_index;
    if (in.spot) {
        Spot spot;
        spot.direction = place_model_normal(prop, in.direction);
        // The assets reader checked 0 <= inner < outer <= pi/2; degrees
        // may round past 90.
        spot.outer_deg = std::min(90.0, in.outer_cone_rad * kDegreesPerRadian);
        spot.inner_deg = std::min(in.inner_cone_rad * kDegreesPerRadian, spot.outer_deg);
        if (!(spot.outer_deg > spot.inner_deg)) spot.inner_deg = std::nextafter(spot.outer_deg, 0.0);
        light.spot = spot;
    }
    return light;
}

std::string prop_light_point(const glm::dvec3& p) {
    return "[" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + "]";
}

// Each prop's solid as a box: a box prop's closed volume, a model's bounds
// (computed once per room, not once per light).
std::vector<std::pair<glm::dvec3, glm::dvec3>> prop_bounds(const Room& room) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> out;
    for (const Prop& prop : room.props) {
        glm::dvec3 lo(0.0), hi(-1.0);
        if (const auto* box = std::get_if<BoxProp>(&prop)) {
            lo = box->min, hi = box->max;
        } else if (const auto* model = std::get_if<GltfProp>(&prop); model && !model->triangles.empty()) {
            lo = hi = place_model_point(*model, model->triangles[0].position[0]);
            for (const assets::ModelTriangle& t : model->triangles) {
                for (const glm::dvec3& corner : t.position) {
                    const glm::dvec3 q = place_model_point(*model, corner);
                    lo = glm::min(lo, q);
                    hi = glm::max(hi, q);
                }
            }
        }
        out.emplace_back(lo, hi);
    }
    return out;
}

// The prop whose bounds hold `p`, other than `own`; -1: none.
int prop_holding(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& bounds, const glm::dvec3& p, int own) {
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        if (static_cast<int>(i) == own) continue;
        const auto& [lo, hi] = bounds[i];
        if (glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi))) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace

void add_prop_lights(Checker& check, std::vector<RoomDraft>& rooms, bool lit, std::optional<HandShape>& hands) {
    if (hands && hands->model) hands->model->lights.clear();  // a hand carries no light
    for (RoomDraft& draft : rooms) {
        Room& room = draft.room;
        for (std::size_t i = 0; i < room.props.size(); ++i) {
            auto* prop = std::get_if<GltfProp>(&room.props[i]);
            if (prop == nullptr) continue;
            if (!lit) {
                prop->lights.clear();
                continue;
            }
            const Path prop_at = draft.path / "props" / i;
            const std::string model = "the model " + quote(prop->path, kQuotedPathCharacters) + "'s ";
            for (const std::string& name : prop->directional_lights) {
                check.model_warning(prop_at, model + "directional " + name +
                                                 " is dropped (a layout's lights are point and spot lights; the "
                                                 "prop's \"lights\": false drops all of its lights)");
            }
            for (std::size_t k = 0; k < prop->lights.size(); ++k) {
                const Light light = pose_model_light(*prop, prop->lights[k], static_cast<int>(i));
                if (!strictly_inside(room, light.position)) {
                    check.model_warning(
                        prop_at, model + prop->lights[k].name + " stands at " + prop_light_point(light.position) +
                                     ", not strictly inside the room " + quote(room.id) + ": it is dropped");
                    continue;
                }
                if (room.lights.size() >= limits::kMaxLightsPerRoom) {
                    check.error(prop_at, "the room " + quote(room.id) + " has more than " +
                                             std::to_string(limits::kMaxLightsPerRoom) +
                                             " lights, its props' lights included");
                    return;
                }
                room.lights.push_back(light);
            }
        }
    }
}

void warn_lights_in_props(Checker& check, const std::vector<RoomDraft>& rooms) {
    for (const RoomDraft& draft : rooms) {
        const Room& room = draft.room;
        if (room.lights.empty()) continue;
        const auto bounds = prop_bounds(room);
        for (std::size_t k = 0; k < room.lights.size(); ++k) {
            const Light& light = room.lights[k];
            const int holder = prop_holding(bounds, light.position, light.prop);
            if (holder < 0) continue;
            const Path at = light.prop < 0 ? draft.path / "lights" / k / "position"
                                           : draft.path / "props" / static_cast<std::size_t>(light.prop);
            const std::string what = light.prop < 0 ? "the light" : "the model's light";
            check.warning(at, what + " at " + prop_light_point(light.position) + " is inside " +
                                  (draft.path / "props" / static_cast<std::size_t>(holder)).display +
                                  " (a box, or a model's bounds), which may hide it");
        }
    }
}

}  // namespace impossible::layout::detail
