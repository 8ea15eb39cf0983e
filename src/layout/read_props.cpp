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
    check.check_fields(at, value, {"box", "color"}, {"box"});
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

std::optional<GltfProp> read_gltf_prop(Checker& check, const Path& at, const json& value, assets::AssetCache& models) {
    check.check_fields(at, value, {"gltf", "position", "yaw_deg", "scale"}, {"gltf"});
    GltfProp prop;
    bool ok = true;
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
    if (gltf == nullptr) return std::nullopt;
    const Path gltf_at = at / "gltf";
    const auto path = check.read_string(gltf_at, *gltf);
    if (!path) return std::nullopt;
    if (path->empty()) {
        check.error(gltf_at, "must name a .glb or .gltf file (got an empty path)");
        return std::nullopt;
    }
    if (has_control_character(*path)) {
        check.error(gltf_at, "the path " + quote(*path, kQuotedPathCharacters) + " contains a control character");
        return std::nullopt;
    }
    prop.path = *path;
    prop.resolved_path = models.resolve(*path);
    const Result<assets::GltfModel>& model = models.load(prop.resolved_path);
    if (!model) {
        check.error(gltf_at, "the model " + quote(prop.resolved_path, kQuotedPathCharacters) + " " + model.error());
        return std::nullopt;
    }
    if (Result<void> counted = models.add_instance(model->triangles.size()); !counted) {
        check.error(gltf_at, counted.error());
        return std::nullopt;
    }
    prop.triangles = model->triangles;
    prop.materials = model->materials;
    prop.textures = model->textures;  // the images are shared, not copied
    if (!ok) return std::nullopt;
    return prop;
}

}  // namespace

void read_props(Checker& check, const Path& at, const json& props, const glm::dvec3& room_colour,
                assets::AssetCache& models, std::vector<Prop>& out) {
    for (std::size_t i = 0; i < props.size(); ++i) {
        const Path prop_at = at / i;
        const json& value = props[i];
        if (!check.expect_object(prop_at, value)) continue;
        const bool is_box = value.contains("box");
        const bool is_gltf = value.contains("gltf");
        if (is_box && is_gltf) {
            check.error(prop_at, "a prop is either a \"box\" or a \"gltf\" model, not both");
        } else if (is_box) {
            if (auto prop = read_box_prop(check, prop_at, value, room_colour)) out.emplace_back(*prop);
        } else if (is_gltf) {
            if (auto prop = read_gltf_prop(check, prop_at, value, models)) out.emplace_back(std::move(*prop));
        } else {
            check.error(prop_at, "a prop needs a \"box\" or a \"gltf\" field");
        }
    }
}

}  // namespace impossible::layout::detail
