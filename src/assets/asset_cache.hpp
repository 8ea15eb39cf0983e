// The files a layout names, each read and decoded once: glTF models and
// PNG or JPEG images, resolved against the layout's folder, with the
// layout-wide budgets of triangles and decoded texels (assets/limits.hpp).
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assets/file_read.hpp"
#include "assets/gltf_model.hpp"
#include "base/result.hpp"
#include "image/pixels.hpp"

namespace impossible::assets {

// glTF models and room texture images, read once per file per layout, with
// caps on all triangles and on all decoded texels.
class AssetCache {
public:
    explicit AssetCache(std::string base_dir) : base_dir_(std::move(base_dir)) {}

    // The path resolved against the layout's directory.
    std::string resolve(const std::string& path) const;

    // Reads the model at `resolved` (or returns it from the cache); the
    // error is a reason, without the path. Its texels count toward the
    // layout's cap once.
    const Result<GltfModel>& load(const std::string& resolved);

    // Reads and decodes the PNG or JPEG image at `resolved` (or returns it
    // from the cache: one Image per file); the error is a reason, without
    // the path ("does not exist", "is neither PNG nor JPEG data").
    const Result<std::shared_ptr<const image::Pixels>>& load_image(const std::string& resolved);

    // Counts one more instance of `triangles` toward the layout's cap.
    Result<void> add_instance(std::size_t triangles);

    // Every file read so far, in order: images, models and the buffers and
    // images of each model.
    const std::vector<FileRead>& files_read() const { return files_; }

private:
    std::string base_dir_;
    std::map<std::string, Result<GltfModel>> entries_;
    std::map<std::string, Result<std::shared_ptr<const image::Pixels>>> images_;
    std::size_t total_triangles_ = 0;
    std::size_t total_texels_ = 0;  // decoded, models and room textures, each once
    std::vector<FileRead> files_;
};

}  // namespace impossible::assets
