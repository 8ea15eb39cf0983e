#include <algorithm>
#include <filesystem>

#include "layout/file_io.hpp"
#include "layout/gltf_model.hpp"
#include "layout/image_decode.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/text_util.hpp"

namespace impossible::layout::detail {

std::string ModelCache::resolve(const std::string& path) const {
    const std::filesystem::path p(path);
    if (p.is_absolute() || base_dir_.empty()) return p.lexically_normal().string();
    return (std::filesystem::path(base_dir_) / p).lexically_normal().string();
}

namespace {

std::string over_texel_budget() {
    return "over the limit of " + std::to_string(limits::kMaxLayoutTexels) +
           " decoded texels for all the images of a layout (glTF textures and room textures together)";
}

}  // namespace

const Result<GltfModel>& ModelCache::load(const std::string& resolved) {
    auto it = entries_.find(resolved);
    if (it != entries_.end()) return it->second;
    Result<GltfModel> model = load_gltf_model(resolved, limits::kMaxModelTriangles);
    if (model && model->texels > limits::kMaxLayoutTexels - total_texels_) {
        model = Error{"has images of " + std::to_string(model->texels) + " texels, which bring the layout " +
                      over_texel_budget()};
    } else if (model) {
        total_texels_ += model->texels;
    }
    return entries_.emplace(resolved, std::move(model)).first->second;
}

const Result<std::shared_ptr<const Image>>& ModelCache::load_image(const std::string& resolved) {
    auto it = images_.find(resolved);
    if (it != images_.end()) return it->second;
    const auto decode = [&]() -> Result<std::shared_ptr<const Image>> {
        const Result<std::vector<unsigned char>> bytes =
            read_file_bytes(resolved, limits::kMaxImageFileBytes, true);
        if (!bytes) return Error{bytes.error()};
        if (bytes->empty()) return Error{"is empty (expected a PNG or JPEG image)"};
        const Result<ImageSize> size = image_size(bytes->data(), bytes->size());
        if (!size) return Error{size.error()};
        if (size->texels() > limits::kMaxLayoutTexels - total_texels_) {
            return Error{"is " + std::to_string(size->width) + " x " + std::to_string(size->height) +
                         " pixels, which brings the layout " + over_texel_budget()};
        }
        Result<Image> image = decode_image(bytes->data(), bytes->size());
        if (!image) return Error{image.error()};
        total_texels_ += size->texels();
        return std::make_shared<const Image>(std::move(*image));
    };
    return images_.emplace(resolved, decode()).first->second;
}

Result<void> ModelCache::add_instance(std::size_t triangles) {
    total_triangles_ += triangles;
    if (total_triangles_ > limits::kMaxLayoutTriangles)
        return Error{"the glTF props of the layout have more than " + std::to_string(limits::kMaxLayoutTriangles) +
                     " triangles together"};
    return {};
}

namespace {

std::optional<BoxProp> read_box_prop(Checker& check, const Path& at, const json& value,
                                     const glm::dvec3& room_colour) {
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
            check.error(box_at / "max", std::string("must be greater than min on every axis (") +
                                            axes[a] + ": " + format_number((*max)[a]) + " <= " +
                                            format_number((*min)[a]) + ")");
            return std::nullopt;
        }
        if ((*max)[a] - (*min)[a] < limits::kMinLength) {
            check.error(box_at / "max", std::string("the box is too thin (") + axes[a] + ": " +
                                            format_number((*max)[a] - (*min)[a]) +
                                            " m; the minimum is " +
                                            format_number(limits::kMinLength) + " m)");
            return std::nullopt;
        }
    }
    prop.min = *min;
    prop.max = *max;
    if (!ok) return std::nullopt;
    return prop;
}

std::optional<GltfProp> read_gltf_prop(Checker& check, const Path& at, const json& value,
                                       ModelCache& models) {
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
        check.error(gltf_at, "the path " + quote(*path) + " contains a control character");
        return std::nullopt;
    }
    prop.path = *path;
    prop.resolved_path = models.resolve(*path);
    const Result<GltfModel>& model = models.load(prop.resolved_path);
    if (!model) {
        check.error(gltf_at, "the model " + quote(prop.resolved_path) + " " + model.error());
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
                ModelCache& models, std::vector<Prop>& out) {
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
