#include <algorithm>
#include <filesystem>

#include "assets/gltf_model.hpp"
#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "image/decode.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"

namespace impossible::layout::detail {

namespace {

std::optional<BoxProp> read_box_prop(Checker& check, const Path& at, const json& value, const glm::dvec3& room_colour) {
    check.check_fields(at, value, {"box", "color", "id", "motion"}, {"box"});
    BoxProp prop;
    prop.color = room_colour;
    bool ok = true;
    if (const json* v = field(value, "color")) {
        if (const auto c = check.read_colour(at / "color", *v)) {
            prop.color = *c;
        } else {
            ok = false;
        }
    }
    const json* box = field(value, "box");
    if (box == nullptr) return std::nullopt;
    const Path box_at = at / "box";
    if (!check.expect_object(box_at, *box)) return std::nullopt;
    check.check_fields(box_at, *box, {"min", "max"}, {"min", "max"});
    std::optional<glm::dvec3> min, max;
    if (const json* v = field(*box, "min")) min = check.read_vec3(box_at / "min", *v, NumberKind::Coordinate);
    if (const json* v = field(*box, "max")) max = check.read_vec3(box_at / "max", *v, NumberKind::Coordinate);
    if (!min || !max) return std::nullopt;
    static const char* const axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        if (!((*max)[a] > (*min)[a])) {
            check.error(box_at / "max", std::string("must be greater than min on every axis (") + axes[a] + ": " +
                                            format_number((*max)[a]) + " <= " + format_number((*min)[a]) + ")");
            return std::nullopt;
        }
        if ((*max)[a] - (*min)[a] < limits::kMinLength) {
            check.error(box_at / "max", std::string("the box is too thin (") + axes[a] + ": " +
                                            format_number((*max)[a] - (*min)[a]) + " m; the minimum is " +
                                            format_number(limits::kMinLength) + " m)");
            return std::nullopt;
        }
    }
    prop.min = *min;
    prop.max = *max;
    if (!ok) return std::nullopt;
    return prop;
}

// A model prop's "blend" ("mask" or "opaque"; nothing when absent or bad,
// `ok` false when bad) and "lights" (true or false; `ok` false when bad).
std::optional<std::string> read_model_options(Checker& check, const Path& at, const json& value, bool& lights,
                                              bool& ok) {
    if (const json* v = field(value, "lights")) {
        if (v->is_boolean()) {
            lights = v->get<bool>();
        } else {
            check.error(at / "lights", "must be true or false (got " + json_type_name(*v) + ")");
            ok = false;
        }
    }
    const json* v = field(value, "blend");
    if (v == nullptr) return std::nullopt;
    const auto mode = check.read_string(at / "blend", *v);
    if (mode && (*mode == "mask" || *mode == "opaque")) return mode;
    if (mode) check.error(at / "blend", "must be \"mask\" or \"opaque\" (got " + quote(*mode) + ")");
    ok = false;
    return std::nullopt;
}

// What the model's alphaMode BLEND materials become (layout-format.md, "glTF
// props"): alpha-tested at 0.5, with a warning naming each, unless "blend"
// chose; opaque under "blend": "opaque".
void apply_blend(Checker& check, const Path& at, const std::optional<std::string>& blend, GltfProp& prop) {
    for (assets::Material& m : prop.materials) {
        if (!m.blend) continue;
        if (blend == "opaque") {
            m.alpha_mode = assets::AlphaMode::Opaque;
        } else if (!blend) {
            check.model_warning(at, "the model " + quote(prop.path, kQuotedPathCharacters) + " has " + m.name +
                                        " with alphaMode \"BLEND\", drawn alpha-tested at 0.5 (set the prop's "
                                        "\"blend\" to \"mask\" or \"opaque\" to choose)");
        }
    }
}

std::optional<GltfProp> read_gltf_prop(Checker& check, const Path& at, const json& value, assets::AssetCache& models) {
    check.check_fields(at, value, {"gltf", "position", "yaw_deg", "scale", "id", "motion", "blend", "lights"},
                       {"gltf"});
    GltfProp prop;
    bool ok = true;
    bool lights = true;
    const std::optional<std::string> blend = read_model_options(check, at, value, lights, ok);
    if (const json* v = field(value, "position")) {
        if (const auto p = check.read_vec3(at / "position", *v, NumberKind::Coordinate)) {
            prop.position = *p;
        } else {
            ok = false;
        }
    }
    if (const json* v = field(value, "yaw_deg")) {
        if (const auto yaw = check.read_number(at / "yaw_deg", *v, NumberKind::Angle)) {
            prop.yaw_deg = *yaw;
        } else {
            ok = false;
        }
    }
    if (const json* v = field(value, "scale")) {
        if (const auto scale = check.read_number(at / "scale", *v, NumberKind::Scale)) {
            prop.scale = *scale;
        } else {
            ok = false;
        }
    }
    const json* gltf = field(value, "gltf");
    if (gltf == nullptr || !load_gltf_model(check, at / "gltf", *gltf, models, 1, prop)) return std::nullopt;
    if (!ok) return std::nullopt;
    apply_blend(check, at, blend, prop);
    if (!lights) {
        prop.lights.clear();
        prop.directional_lights.clear();
    }
    return prop;
}

// One key [t, dx, dy, dz] of a motion path: a time in 0..kMaxMotionTime and
// an offset within the coordinate limits.
std::optional<MotionKey> read_motion_key(Checker& check, const Path& at, const json& value) {
    if (!value.is_array() || value.size() != 4) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        check.error(at, "must be an array of 4 numbers [t, dx, dy, dz] (got " + got + ")");
        return std::nullopt;
    }
    const auto t = check.read_number(at / 0, value[0], NumberKind::Time);
    const auto dx = check.read_number(at / 1, value[1], NumberKind::Coordinate);
    const auto dy = check.read_number(at / 2, value[2], NumberKind::Coordinate);
    const auto dz = check.read_number(at / 3, value[3], NumberKind::Coordinate);
    if (!t || !dx || !dy || !dz) return std::nullopt;
    return MotionKey{*t, {*dx, *dy, *dz}};
}

// The keys of `path`: at least one, the first at t = 0, times increasing
// strictly. A key that cannot be read is reported once; the next readable
// key is compared with the last readable one.
bool read_motion_path(Checker& check, const Path& at, const json& path, Motion& motion) {
    if (!check.expect_array(at, path, limits::kMaxMotionKeys)) return false;
    if (path.empty()) {
        check.error(at, "a motion needs at least one key [t, dx, dy, dz] (the first at t = 0)");
        return false;
    }
    bool ok = true;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const auto key = read_motion_key(check, at / i, path[i]);
        if (!key) {
            ok = false;
            continue;
        }
        if (i == 0 && key->t != 0.0) {
            check.error(at / 0 / 0, "the first key's time must be 0 (got " + format_number(key->t) + ")");
            ok = false;
        } else if (!motion.keys.empty() && !(key->t > motion.keys.back().t)) {
            check.error(at / i / 0, "must be greater than the time " + format_number(motion.keys.back().t) +
                                        " of the key before it (times increase strictly)");
            ok = false;
        }
        motion.keys.push_back(*key);
    }
    return ok;
}

// `motion` (layout-format.md, "Moving props"): {"path": [[t, dx, dy, dz],
// ...], "loop": false}. A loop repeats with the period of the last key's
// time, so it needs at least two keys (the project's choice: with one its
// period would be 0).
std::optional<Motion> read_motion(Checker& check, const Path& at, const json& value) {
    if (!check.expect_object(at, value)) return std::nullopt;
    bool ok = check.check_fields(at, value, {"path", "loop"}, {"path"});
    Motion motion;
    if (const json* v = field(value, "loop")) {
        if (v->is_boolean()) {
            motion.loop = v->get<bool>();
        } else {
            check.error(at / "loop", "must be true or false (got " + json_type_name(*v) + ")");
            ok = false;
        }
    }
    const json* path = field(value, "path");
    if (path == nullptr || !read_motion_path(check, at / "path", *path, motion)) return std::nullopt;
    if (motion.loop && motion.keys.size() < 2) {
        check.error(at / "loop",
                    "a looping motion needs at least two keys (it repeats with the period of the last key's "
                    "time, which is 0 with one key); add a key or remove \"loop\"");
        return std::nullopt;
    }
    if (!ok) return std::nullopt;
    return motion;
}

// A prop's `id` and `motion`, common to boxes and models. Ids are unique
// among all the props of the layout (`ids` holds the ones seen so far); a
// moving prop needs one. False if either is wrong (reported).
bool read_prop_identity(Checker& check, const Path& at, const json& value, PropIds& ids, std::string& id,
                        Motion& motion) {
    bool ok = true;
    const json* id_value = field(value, "id");
    if (id_value != nullptr) {
        if (auto read = check.read_id(at / "id", *id_value)) {
            const auto [it, inserted] = ids.emplace(*read, at.display);
            if (!inserted) {
                check.error(at / "id", "duplicate prop id " + quote(*read) + " (also used by " + it->second +
                                           "; prop ids are unique in the whole layout)");
                ok = false;
            }
            id = std::move(*read);
        } else {
            ok = false;
        }
    }
    if (const json* v = field(value, "motion")) {
        if (auto read = read_motion(check, at / "motion", *v)) {
            motion = std::move(*read);
        } else {
            ok = false;
        }
        if (id_value == nullptr) {
            check.error(at,
                        "missing field \"id\": a prop with a \"motion\" needs an id (unique among the "
                        "layout's props), by which walk and the renderers name it");
            ok = false;
        }
    }
    return ok;
}

}  // namespace

bool load_gltf_model(Checker& check, const Path& gltf_at, const json& gltf, assets::AssetCache& models,
                     std::size_t instances, GltfProp& prop) {
    const auto path = check.read_string(gltf_at, gltf);
    if (!path) return false;
    if (path->empty()) {
        check.error(gltf_at, "must name a .glb or .gltf file (got an empty path)");
        return false;
    }
    if (has_control_character(*path)) {
        check.error(gltf_at, "the path " + quote(*path, kQuotedPathCharacters) + " contains a control character");
        return false;
    }
    prop.path = *path;
    prop.resolved_path = models.resolve(*path);
    const Result<assets::GltfModel>& model = models.load(prop.resolved_path);
    if (!model) {
        check.error(gltf_at, "the model " + quote(prop.resolved_path, kQuotedPathCharacters) + " " + model.error());
        return false;
    }
    if (Result<void> counted = models.add_instance(model->triangles.size() * instances); !counted) {
        check.error(gltf_at, counted.error());
        return false;
    }
    prop.triangles = model->triangles;
    prop.materials = model->materials;
    prop.textures = model->textures;  // the images are shared, not copied
    prop.lights = model->lights;      // kept under "lighting": "lights" only (add_prop_lights)
    prop.directional_lights = model->directional_lights;
    return true;
}

void read_props(Checker& check, const Path& at, const json& props, const glm::dvec3& room_colour,
                assets::AssetCache& models, PropIds& ids, std::vector<Prop>& out) {
    for (std::size_t i = 0; i < props.size(); ++i) {
        const Path prop_at = at / i;
        const json& value = props[i];
        if (!check.expect_object(prop_at, value)) continue;
        std::string id;
        Motion motion;
        const bool identity_ok = read_prop_identity(check, prop_at, value, ids, id, motion);
        const bool is_box = value.contains("box");
        const bool is_gltf = value.contains("gltf");
        if (is_box && is_gltf) {
            check.error(prop_at, "a prop is either a \"box\" or a \"gltf\" model, not both");
        } else if (is_box) {
            auto prop = read_box_prop(check, prop_at, value, room_colour);
            if (prop && identity_ok) out.emplace_back(BoxProp{prop->min, prop->max, prop->color, id, motion});
        } else if (is_gltf) {
            auto prop = read_gltf_prop(check, prop_at, value, models);
            if (prop && identity_ok) {
                prop->id = std::move(id);
                prop->motion = std::move(motion);
                out.emplace_back(std::move(*prop));
            }
        } else {
            check.error(prop_at, "a prop needs a \"box\" or a \"gltf\" field");
        }
    }
}

}  // namespace impossible::layout::detail
