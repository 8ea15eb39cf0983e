#include "assets/gltf_material.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <tiny_gltf.h>
#include <glm/common.hpp>

#include "assets/gltf_preflight.hpp"
#include "assets/limits.hpp"
#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "image/decode.hpp"

namespace impossible::assets {

namespace {

// "material 2" or "material 2 ("Glass")": names are shown, cut to 60 bytes.
std::string named(const char* kind, int index, const std::string& name) {
    std::string out = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) out += " (" + quote(name.substr(0, 60)) + ")";
    return out;
}

bool valid_mag_filter(int f) { return f == sampler_code::kNearest || f == sampler_code::kLinear; }
bool valid_min_filter(int f) {
    return valid_mag_filter(f) || (f >= sampler_code::kNearestMipmapNearest && f <= sampler_code::kLinearMipmapLinear);
}
bool valid_wrap(int w) {
    return w == sampler_code::kClampToEdge || w == sampler_code::kMirroredRepeat || w == sampler_code::kRepeat;
}

// The sampler of texture `t` (checked by check_material), glTF's defaults
// filling what it leaves out.
Sampler sampler_of(const tinygltf::Model& model, const tinygltf::Texture& texture) {
    Sampler out;
    if (texture.sampler < 0) return out;
    const tinygltf::Sampler& s = model.samplers[static_cast<std::size_t>(texture.sampler)];
    if (s.magFilter != -1) out.mag_filter = s.magFilter;
    if (s.minFilter != -1) out.min_filter = s.minFilter;
    out.wrap_s = s.wrapS;
    out.wrap_t = s.wrapT;
    return out;
}

Result<void> check_sampler(const tinygltf::Model& model, int index) {
    const tinygltf::Sampler& s = model.samplers[static_cast<std::size_t>(index)];
    const std::string who = "has " + named("sampler", index, s.name);
    if (s.magFilter != -1 && !valid_mag_filter(s.magFilter)) {
        return Error{who + " whose magFilter " + std::to_string(s.magFilter) + " is not a glTF filter (9728 or 9729)"};
    }
    if (s.minFilter != -1 && !valid_min_filter(s.minFilter)) {
        return Error{who + " whose minFilter " + std::to_string(s.minFilter) +
                     " is not a glTF filter (9728, 9729 or 9984 to 9987)"};
    }
    if (!valid_wrap(s.wrapS) || !valid_wrap(s.wrapT)) {
        return Error{who + " whose wrapS or wrapT (" + std::to_string(s.wrapS) + ", " + std::to_string(s.wrapT) +
                     ") is not a glTF wrap mode (33071, 33648 or 10497)"};
    }
    return {};
}

// The encoded bytes of image `index`, or why there are none.
Result<std::pair<const unsigned char*, std::size_t>> image_bytes(const tinygltf::Model& model, const KeptImages& kept,
                                                                 int index, const std::string& folder) {
    const tinygltf::Image& image = model.images[static_cast<std::size_t>(index)];
    const std::string who = "has " + named("image", index, image.name);
    if (!image.mimeType.empty() && image.mimeType != "image/png" && image.mimeType != "image/jpeg") {
        return Error{who + " of the unsupported mimeType " + quote(image.mimeType.substr(0, 60)) +
                     " (only image/png and image/jpeg are supported)"};
    }
    if (image.bufferView >= 0) {
        // Checked before parsing (check_gltf_document); checked again here.
        const auto view_index = static_cast<std::size_t>(image.bufferView);
        if (view_index < model.bufferViews.size()) {
            const tinygltf::BufferView& view = model.bufferViews[view_index];
            if (view.buffer >= 0 && static_cast<std::size_t>(view.buffer) < model.buffers.size()) {
                const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
                if (view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset) {
                    return std::make_pair(data.data() + view.byteOffset, view.byteLength);
                }
            }
        }
        return Error{who + " whose bufferView " + std::to_string(image.bufferView) + " does not lie inside its buffer"};
    }
    const std::string file = quote(image.uri.substr(0, 200));
    if (image.uri.rfind("data:", 0) != 0 && absolute_uri(image.uri)) {
        return Error{who + " whose file " + file + " lies outside the model's folder"};
    }
    const auto at = static_cast<std::size_t>(index);
    if (at < kept.delivered.size() && kept.delivered[at]) {
        return std::make_pair(kept.bytes[at].data(), kept.bytes[at].size());
    }
    if (image.uri.empty()) return Error{who + " whose data: URI could not be read"};
    if (image.uri.rfind("data:", 0) == 0) {
        return Error{who + " whose data: URI is not base64 data of type image/png or image/jpeg"};
    }
    // An external file tinygltf could not read: say why.
    const std::string path = (folder.empty() ? "/" : folder + "/") + decode_uri(image.uri);
    if (!inside_folder(path, folder)) return Error{who + " whose file " + file + " lies outside the model's folder"};
    if (Result<void> readable = check_readable_file(path, limits::kMaxModelBytes, true); !readable) {
        return Error{who + " whose file " + file + " " + readable.error()};
    }
    return Error{who + " whose file " + file + " could not be read"};
}

// Material `index` (checked by check_material) without its texture.
Material read_material(const tinygltf::Material& m, int index) {
    Material material;
    const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;  // checked: 4 finite numbers
    material.base_color = glm::clamp(glm::dvec4(f[0], f[1], f[2], f[3]), 0.0, 1.0);
    material.double_sided = m.doubleSided;
    // BLEND is drawn alpha-tested at 0.5 (layout-format.md, "glTF props";
    // the prop's "blend" may make it opaque).
    material.blend = m.alphaMode == "BLEND";
    material.alpha_mode = m.alphaMode == "OPAQUE" ? AlphaMode::Opaque : AlphaMode::Mask;
    material.alpha_cutoff = material.blend ? 0.5 : m.alphaCutoff;
    material.name = named("material", index, m.name);
    return material;
}

}  // namespace

bool keep_image_bytes(tinygltf::Image* image, int index, std::string* err, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user_data) {
    KeptImages& kept = *static_cast<KeptImages*>(user_data);
    if (index < 0) return false;
    const auto at = static_cast<std::size_t>(index);
    if (kept.bytes.size() <= at) {
        kept.bytes.resize(at + 1);
        kept.delivered.resize(at + 1, false);
    }
    if (image->bufferView >= 0) return true;  // read from the buffer when needed
    const std::size_t n = size > 0 ? static_cast<std::size_t>(size) : 0;
    if (n > limits::kMaxModelBytes - kept.total) {
        kept.error =
            "has images of more than " + format_bytes(limits::kMaxModelBytes) + " together in data: URIs and files";
        if (err != nullptr) *err += kept.error + "\n";
        return false;
    }
    kept.total += n;
    kept.bytes[at].assign(bytes, bytes + n);
    kept.delivered[at] = true;
    return true;
}

Result<int> check_material(const tinygltf::Model& model, int material) {
    const tinygltf::Material& m = model.materials[static_cast<std::size_t>(material)];
    const std::string who = "has " + named("material", material, m.name);
    const std::vector<double>& factor = m.pbrMetallicRoughness.baseColorFactor;
    if (factor.size() != 4 || !std::all_of(factor.begin(), factor.end(), [](double v) { return std::isfinite(v); })) {
        return Error{who + " whose baseColorFactor is not 4 finite numbers"};
    }
    if (m.alphaMode != "OPAQUE" && m.alphaMode != "MASK" && m.alphaMode != "BLEND") {
        return Error{who + " with alphaMode " + quote(m.alphaMode.substr(0, 60)) +
                     "; glTF allows \"OPAQUE\", \"MASK\" and \"BLEND\""};
    }
    if (!std::isfinite(m.alphaCutoff) || m.alphaCutoff < 0.0) {
        return Error{who + " whose alphaCutoff is not a finite number of 0 or more"};
    }
    const tinygltf::TextureInfo& info = m.pbrMetallicRoughness.baseColorTexture;
    if (info.index == -1) return -1;
    if (info.index < 0 || static_cast<std::size_t>(info.index) >= model.textures.size()) {
        return Error{who + " whose baseColorTexture names texture " + std::to_string(info.index) +
                     ", which does not exist (the model has " + count_of(model.textures.size(), "texture", "textures") +
                     ")"};
    }
    if (info.texCoord < 0) {
        return Error{who + " whose baseColorTexture has the texCoord " + std::to_string(info.texCoord) +
                     " (it must be 0 or more)"};
    }
    const tinygltf::Texture& texture = model.textures[static_cast<std::size_t>(info.index)];
    const std::string texture_who = "has " + named("texture", info.index, texture.name);
    if (texture.source == -1) {
        return Error{texture_who +
                     " without a source image (images only in extensions, such as "
                     "KHR_texture_basisu or EXT_texture_webp, are not supported)"};
    }
    if (texture.source < 0 || static_cast<std::size_t>(texture.source) >= model.images.size()) {
        return Error{texture_who + " whose source names image " + std::to_string(texture.source) +
                     ", which does not exist (the model has " + count_of(model.images.size(), "image", "images") + ")"};
    }
    if (texture.sampler < -1 ||
        (texture.sampler >= 0 && static_cast<std::size_t>(texture.sampler) >= model.samplers.size())) {
        return Error{texture_who + " whose sampler names sampler " + std::to_string(texture.sampler) +
                     ", which does not exist (the model has " + count_of(model.samplers.size(), "sampler", "samplers") +
                     ")"};
    }
    if (texture.sampler >= 0) {
        if (Result<void> ok = check_sampler(model, texture.sampler); !ok) return ok;
    }
    return info.texCoord;
}

Result<void> build_materials(const tinygltf::Model& model, const KeptImages& kept, const std::string& folder,
                             std::vector<ModelTriangle>& triangles, std::vector<Material>& materials,
                             std::vector<Texture>& textures, std::size_t& texels) {
    std::map<int, int> material_of;  // glTF material → index into materials
    std::map<int, int> texture_of;   // glTF texture → index into textures
    std::map<int, std::shared_ptr<const image::Pixels>> image_of;
    texels = 0;
    for (ModelTriangle& triangle : triangles) {
        if (triangle.material < 0) continue;
        const auto found = material_of.find(triangle.material);
        if (found != material_of.end()) {
            triangle.material = found->second;
            continue;
        }
        const int gltf_index = triangle.material;
        const tinygltf::Material& m = model.materials[static_cast<std::size_t>(gltf_index)];
        Material material = read_material(m, gltf_index);
        const int t = m.pbrMetallicRoughness.baseColorTexture.index;
        if (t >= 0) {
            const auto known = texture_of.find(t);
            if (known != texture_of.end()) {
                material.texture = known->second;
            } else {
                const tinygltf::Texture& texture = model.textures[static_cast<std::size_t>(t)];
                std::shared_ptr<const image::Pixels>& image = image_of[texture.source];
                if (image == nullptr) {
                    const auto bytes = image_bytes(model, kept, texture.source, folder);
                    if (!bytes) return bytes;
                    const std::string who = "has " + named("image", texture.source,
                                                           model.images[static_cast<std::size_t>(texture.source)].name);
                    const Result<image::ImageSize> size =
                        image::image_size(bytes->first, bytes->second, limits::kMaxImageSide);
                    if (!size) return Error{who + " that " + size.error()};
                    if (size->texels() > limits::kMaxModelTexels - texels) {
                        return Error{"has images of more than " + std::to_string(limits::kMaxModelTexels) +
                                     " texels together (the limit for one model; " + who.substr(4) + " is " +
                                     std::to_string(size->width) + " x " + std::to_string(size->height) + ")"};
                    }
                    Result<image::Pixels> decoded =
                        image::decode_image(bytes->first, bytes->second, limits::kMaxImageSide);
                    if (!decoded) return Error{who + " that " + decoded.error()};
                    texels += size->texels();
                    image = std::make_shared<const image::Pixels>(std::move(*decoded));
                }
                textures.push_back({image, sampler_of(model, texture)});
                material.texture = static_cast<int>(textures.size()) - 1;
                texture_of.emplace(t, material.texture);
            }
        }
        materials.push_back(material);
        triangle.material = static_cast<int>(materials.size()) - 1;
        material_of.emplace(gltf_index, triangle.material);
    }
    return {};
}

}  // namespace impossible::assets
