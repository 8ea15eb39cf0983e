// layout-format.md, "Lights": the top-level `lighting` and `light_depth`,
// each room's `ambient` and `lights`, and the lights of the rooms' glTF props.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout::detail {

namespace {

std::string light_point_text(const glm::dvec3& p) {
    return "[" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + "]";
}

// A number in low..high (`low` itself allowed unless `open_low`), or
// nothing (reported). `unit` follows the bounds in messages.
std::optional<double> light_number(Checker& check, const Path& at, const json& value, double low, bool open_low,
                                   double high, const char* unit) {
    if (!value.is_number()) {
        check.error(at, "must be a number (got " + json_type_name(value) + ")");
        return std::nullopt;
    }
    const double v = value.get<double>();
    const std::string shown = format_number(v);
    if (!std::isfinite(v)) {
        check.error(at, "must be a finite number (got " + shown + ")");
        return std::nullopt;
    }
    if (open_low ? !(v > low) : !(v >= low)) {
        check.error(at, std::string(open_low ? "must be greater than " : "must be at least ") + format_number(low) +
                            unit + " (got " + shown + ")");
        return std::nullopt;
    }
    if (v > high) {
        check.error(at, shown + " is too large (the maximum is " + format_number(high) + unit + ")");
        return std::nullopt;
    }
    return v;
}

// `ambient`: [r, g, b], each in 0..kMaxAmbient.
std::optional<glm::dvec3> read_ambient(Checker& check, const Path& at, const json& value) {
    if (!value.is_array() || value.size() != 3) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        check.error(at, "must be an array of 3 numbers [r, g, b] (got " + got + ")");
        return std::nullopt;
    }
    glm::dvec3 out(0.0);
    bool ok = true;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto v = light_number(check, at / i, value[i], 0.0, false, limits::kMaxAmbient, "");
        if (v) {
            out[static_cast<int>(i)] = *v;
        } else {
            ok = false;
        }
    }
    if (!ok) return std::nullopt;
    return out;
}

std::optional<Spot> read_spot(Checker& check, const Path& at, const json& value) {
    if (!check.expect_object(at, value)) return std::nullopt;
    bool ok = check.check_fields(at, value, {"direction", "inner_deg", "outer_deg"}, {"direction"});
    Spot spot;
    if (const json* v = field(value, "direction")) {
        const auto d = read_normal(check, at / "direction", *v);
        ok = ok && d.has_value();
        if (d) spot.direction = *d;
    }
    std::optional<double> inner = 0.0, outer = 45.0;
    if (const json* v = field(value, "inner_deg")) inner = light_number(check, at / "inner_deg", *v, 0, false, 90, "°");
    if (const json* v = field(value, "outer_deg")) outer = light_number(check, at / "outer_deg", *v, 0, true, 90, "°");
    if (!inner || !outer) return std::nullopt;
    if (!(*outer > *inner)) {
        const json* outer_value = field(value, "outer_deg");
        check.error(outer_value != nullptr ? at / "outer_deg" : at / "inner_deg",
                    "the cone's outer_deg " + format_number(*outer) + " must be greater than its inner_deg " +
                        format_number(*inner));
        return std::nullopt;
    }
    spot.inner_deg = *inner;
    spot.outer_deg = *outer;
    if (!ok) return std::nullopt;
    return spot;
}

std::optional<Light> read_light(Checker& check, const Path& at, const json& value) {
    if (!check.expect_object(at, value)) return std::nullopt;
    bool ok = check.check_fields(at, value, {"position", "color", "intensity", "range", "spot"}, {"position"});
    Light light;
    const auto take = [&ok](auto&& optional, auto& out) {
        if (optional) {
            out = *optional;
        } else {
            ok = false;
        }
    };
    if (const json* v = field(value, "position")) {
        take(check.read_vec3(at / "position", *v, NumberKind::Coordinate), light.position);
    }
    if (const json* v = field(value, "color")) take(check.read_colour(at / "color", *v), light.color);
    if (const json* v = field(value, "intensity")) {
        take(light_number(check, at / "intensity", *v, 0, true, limits::kMaxLightIntensity, ""), light.intensity);
    }
    if (const json* v = field(value, "range"))
        take(check.read_number(at / "range", *v, NumberKind::Length), light.range);
    if (const json* v = field(value, "spot")) {
        const std::optional<Spot> spot = read_spot(check, at / "spot", *v);
        ok = ok && spot.has_value();
        light.spot = spot;
    }
    if (!ok) return std::nullopt;
    return light;
}

// "only with lighting: lights" for a field of a "fixed" layout.
void only_with_lights(Checker& check, const Path& at) {
    check.error_at_key(at, "only with \"lighting\": \"lights\" (this layout's lighting is \"fixed\")");
}

void read_room_lighting(Checker& check, const Path& at, const json& value, RoomDraft& draft, bool lit) {
    if (const json* v = field(value, "ambient")) {
        if (!lit) {
            only_with_lights(check, at / "ambient");
        } else if (const auto ambient = read_ambient(check, at / "ambient", *v)) {
            draft.room.ambient = *ambient;
        }
    }
    const json* lights = field(value, "lights");
    if (lights == nullptr) return;
    if (!lit) {
        only_with_lights(check, at / "lights");
        return;
    }
    if (!check.expect_array(at / "lights", *lights, limits::kMaxLightsPerRoom)) return;
    for (std::size_t i = 0; i < lights->size(); ++i) {
        const Path light_at = at / "lights" / i;
        std::optional<Light> light = read_light(check, light_at, (*lights)[i]);
        if (!light) continue;
        if (draft.shape_ok && !strictly_inside(draft.room, light->position)) {
            check.error(light_at / "position", "the light at " + light_point_text(light->position) +
                                                   " is not strictly inside its room " + quote(draft.room.id));
            continue;
        }
        draft.room.lights.push_back(*light);
    }
}

}  // namespace

bool strictly_inside(const Room& room, const glm::dvec3& p) {
    const double tolerance = 1e-9 * (1.0 + glm::length(p));
    if (is_prism(room)) {
        if (!(p.y - room.min.y > tolerance && room.max.y - p.y > tolerance)) return false;
        const glm::dvec2 q{p.x, p.z};
        return math::contains(room.floor, q, 0.0) && math::distance_to_boundary(room.floor, q) > tolerance;
    }
    for (int a = 0; a < 3; ++a) {
        if (!(p[a] - room.min[a] > tolerance && room.max[a] - p[a] > tolerance)) return false;
    }
    return true;
}

// The top-level "exposure" (docs/lighting.md, "Exposure"): a number of EV
// in math::limits::kExposure, for either lighting.
static void read_exposure(Checker& check, const json& root, Layout& layout) {
    const json* v = field(root, "exposure");
    if (v == nullptr) return;
    const Path at = Path() / "exposure";
    constexpr auto range = math::limits::kExposure;
    if (!v->is_number() || !std::isfinite(v->get<double>()) || !range.contains(v->get<double>())) {
        const std::string got = v->is_number() ? format_number(v->get<double>()) : json_type_name(*v);
        check.error(at, "must be a number of EV from " + format_number(range.min) + " to " + format_number(range.max) +
                            " (got " + got + ")");
        return;
    }
    layout.exposure = v->get<double>();
}

void read_lighting(Checker& check, const json& root, std::vector<RoomDraft>& rooms, Layout& layout) {
    const Path top;
    read_exposure(check, root, layout);
    if (const json* v = field(root, "lighting")) {
        // A bad value leaves the light fields unchecked (they would only
        // repeat it as "only with lights" or as their own problems).
        const auto name = check.read_string(top / "lighting", *v);
        if (!name) return;
        if (*name == "lights") {
            layout.lighting = Lighting::Lights;
        } else if (*name != "fixed") {
            check.error(top / "lighting", "must be \"fixed\" or \"lights\" (got " + quote(*name) + ")");
            return;
        }
    }
    const bool lit = layout.lighting == Lighting::Lights;
    if (const json* v = field(root, "light_depth")) {
        if (!lit) {
            only_with_lights(check, top / "light_depth");
        } else if (!v->is_number_integer() || v->get<std::int64_t>() < 0 || v->get<std::int64_t>() > kMaxLightDepth) {
            std::string got = v->is_number() ? format_number(v->get<double>()) : json_type_name(*v);
            // 2.0 or 1e1: a JSON decimal, which "(got 2)" would hide.
            const double d = v->is_number_float() ? v->get<double>() : 0.5;
            if (d == std::floor(d))
                got = "a decimal number equal to " + got + (d >= 0 && d <= kMaxLightDepth ? "; write " + got : "");
            check.error(top / "light_depth",
                        "must be an integer from 0 to " + std::to_string(kMaxLightDepth) + " (got " + got + ")");
        } else {
            layout.light_depth = static_cast<int>(v->get<std::int64_t>());
        }
    }
    const json* list = field(root, "rooms");
    if (list == nullptr || !list->is_array() || list->size() != rooms.size()) return;
    for (std::size_t i = 0; i < rooms.size(); ++i) {
        if ((*list)[i].is_object()) read_room_lighting(check, top / "rooms" / i, (*list)[i], rooms[i], lit);
    }
}

}  // namespace impossible::layout::detail
