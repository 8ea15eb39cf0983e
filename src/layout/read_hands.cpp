// Top-level `hands` (layout-format.md, "Moving props, hands and crossing
// objects"): how tracked hands are drawn, a box or a glTF model.
#include <string>

#include "base/user_text.hpp"
#include "layout/readers.hpp"

namespace impossible::layout::detail {

namespace {

// `box`: [W, H, D], three lengths (width along the hand's right, height
// along its up, depth along its forward).
std::optional<glm::dvec3> read_hand_box(Checker& check, const Path& at, const json& value) {
    if (!value.is_array() || value.size() != 3) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        check.error(at, "must be an array of 3 numbers [W, H, D] (got " + got + ")");
        return std::nullopt;
    }
    const auto w = check.read_number(at / 0, value[0], NumberKind::Length);
    const auto h = check.read_number(at / 1, value[1], NumberKind::Length);
    const auto d = check.read_number(at / 2, value[2], NumberKind::Length);
    if (!w || !h || !d) return std::nullopt;
    return glm::dvec3(*w, *h, *d);
}

bool read_box_hand(Checker& check, const Path& at, const json& value, HandShape& hands) {
    bool ok = true;
    if (field(value, "scale") != nullptr) {
        check.error_at_key(at / "scale",
                           "a box hand has no scale (only a \"gltf\" hand is scaled); give the box its size in "
                           "\"box\" instead");
        ok = false;
    }
    if (const auto box = read_hand_box(check, at / "box", *field(value, "box"))) {
        hands.box = *box;
    } else {
        ok = false;
    }
    if (const json* v = field(value, "color")) {
        if (const auto colour = check.read_colour(at / "color", *v)) {
            hands.color = *colour;
        } else {
            ok = false;
        }
    }
    return ok;
}

// A glTF hand is read as a glTF prop at position 0, yaw 0, with its `scale`.
// Both hands draw it, so its triangles count twice towards the layout's
// budget.
bool read_gltf_hand(Checker& check, const Path& at, const json& value, assets::AssetCache& models, HandShape& hands) {
    bool ok = true;
    if (field(value, "color") != nullptr) {
        check.error_at_key(at / "color",
                           "a glTF hand has no color (its model's materials colour it); remove it, or draw the "
                           "hands as a \"box\"");
        ok = false;
    }
    GltfProp model;
    if (const json* v = field(value, "scale")) {
        if (const auto scale = check.read_number(at / "scale", *v, NumberKind::Scale)) {
            model.scale = *scale;
        } else {
            ok = false;
        }
    }
    if (!load_gltf_model(check, at / "gltf", *field(value, "gltf"), models, 2, model)) return false;
    hands.model = std::move(model);
    return ok;
}

}  // namespace

std::optional<HandShape> read_hands(Checker& check, const Path& at, const json& value, assets::AssetCache& models) {
    if (!check.expect_object(at, value)) return std::nullopt;
    check.check_fields(at, value, {"box", "color", "gltf", "scale"}, {});
    const bool is_box = field(value, "box") != nullptr;
    const bool is_gltf = field(value, "gltf") != nullptr;
    if (is_box && is_gltf) {
        check.error(at, "hands are either a \"box\" or a \"gltf\" model, not both");
        return std::nullopt;
    }
    if (!is_box && !is_gltf) {
        check.error(at, "missing field \"box\" or \"gltf\" (hands are drawn as a box [W, H, D] or a glTF model)");
        return std::nullopt;
    }
    HandShape hands;
    const bool ok = is_box ? read_box_hand(check, at, value, hands) : read_gltf_hand(check, at, value, models, hands);
    if (!ok) return std::nullopt;
    return hands;
}

}  // namespace impossible::layout::detail
