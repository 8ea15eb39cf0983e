#include "assets/asset_cache.hpp"

#include <filesystem>
#include <vector>

#include "assets/limits.hpp"
#include "base/file_io.hpp"
#include "image/decode.hpp"

namespace impossible::assets {

std::string AssetCache::resolve(const std::string& path) const {
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

const Result<GltfModel>& AssetCache::load(const std::string& resolved) {
    auto it = entries_.find(resolved);
    if (it != entries_.end()) return it->second;
    Result<GltfModel> model = load_gltf_model(resolved, limits::kMaxModelTriangles);
    if (model && model->texels > limits::kMaxLayoutTexels - total_texels_) {
        model = Error{"has images of " + std::to_string(model->texels) + " texels, which bring the layout " +
                      over_texel_budget()};
    } else if (model) {
        total_texels_ += model->texels;
    }
    if (model) {
        files_.push_back({"the glTF model", resolved});
        for (std::size_t i = 1; i < model->files.size(); ++i)
            files_.push_back({"a file of the glTF model " + resolved + ":", model->files[i]});
    }
    return entries_.emplace(resolved, std::move(model)).first->second;
}

const Result<std::shared_ptr<const image::Pixels>>& AssetCache::load_image(const std::string& resolved) {
    auto it = images_.find(resolved);
    if (it != images_.end()) return it->second;
    const auto decode = [&]() -> Result<std::shared_ptr<const image::Pixels>> {
        const Result<std::vector<unsigned char>> bytes = read_file_bytes(resolved, limits::kMaxImageFileBytes, true);
        if (!bytes) return bytes;
        files_.push_back({"the texture", resolved});
        if (bytes->empty()) return Error{"is empty (expected a PNG or JPEG image)"};
        const Result<image::ImageSize> size = image::image_size(bytes->data(), bytes->size(), limits::kMaxImageSide);
        if (!size) return size;
        if (size->texels() > limits::kMaxLayoutTexels - total_texels_) {
            return Error{"is " + std::to_string(size->width) + " x " + std::to_string(size->height) +
                         " pixels, which brings the layout " + over_texel_budget()};
        }
        Result<image::Pixels> image = image::decode_image(bytes->data(), bytes->size(), limits::kMaxImageSide);
        if (!image) return image;
        total_texels_ += size->texels();
        return std::make_shared<const image::Pixels>(std::move(*image));
    };
    return images_.emplace(resolved, decode()).first->second;
}

Result<void> AssetCache::add_instance(std::size_t triangles) {
    total_triangles_ += triangles;
    if (total_triangles_ > limits::kMaxLayoutTriangles)
        return Error{"the glTF props of the layout have more than " + std::to_string(limits::kMaxLayoutTriangles) +
                     " triangles together"};
    return {};
}

}  // namespace impossible::assets
