// load_gltf_model: the file read and checked (gltf_preflight.cpp), parsed by
// tinygltf in its sandbox (gltf_sandbox.cpp), the node tree walked
// (gltf_nodes.cpp), every primitive checked and counted before any is turned
// into triangles (gltf_primitives.cpp), and the materials built
// (gltf_material.cpp).
#include "assets/gltf_model.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <new>
#include <string_view>
#include <utility>

#include "assets/gltf_import.hpp"
#include "assets/gltf_preflight.hpp"
#include "base/file_io.hpp"
#include "base/user_text.hpp"

namespace impossible::assets {

namespace {

// A model file read and checked before tinygltf sees it.
struct ModelFile {
    std::vector<unsigned char> bytes;
    std::string_view json_text;  // into `bytes`
    bool binary = false;         // .glb
    long long bin_size = -1;     // the .glb binary chunk's size, or -1
    std::string folder;          // the model's folder, canonical ("" for the root)
};

// Reads the file, bounded, and splits a .glb into its chunks.
Result<void> read_model_bytes(const std::string& path, ModelFile& file) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    file.binary = extension == ".glb";
    if (!file.binary && extension != ".gltf") {
        return Error{"is not a glTF model (expected a .glb or .gltf file)"};
    }
    Result<std::vector<unsigned char>> bytes = read_file_bytes(path, limits::kMaxModelBytes, true);
    if (!bytes) return bytes;
    if (bytes->empty()) {
        return Error{"is not a valid glTF 2.0 file: the file is empty"};
    }
    file.bytes = std::move(*bytes);
    file.json_text = std::string_view(reinterpret_cast<const char*>(file.bytes.data()), file.bytes.size());
    if (file.binary) {
        Result<GlbChunks> chunks = split_glb(file.bytes);
        if (!chunks) return chunks;
        file.json_text = chunks->json;
        if (chunks->has_bin) file.bin_size = static_cast<long long>(chunks->bin_size);
    }
    return {};
}

// The file read and checked (gltf_preflight.hpp) before tinygltf sees it.
Result<void> read_model_file(const std::string& path, ModelFile& file) {
    if (Result<void> read = read_model_bytes(path, file); !read) return read;
    if (Result<void> shape = check_json_shape(file.json_text); !shape) return shape;

    std::error_code ec;
    file.folder = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec).parent_path(), ec).string();
    if (ec) return Error{"cannot be opened: " + ec.message()};
    while (file.folder.size() > 1 && file.folder.back() == '/') file.folder.pop_back();
    if (file.folder == "/") file.folder.clear();  // a model at the root: everything is below it
    return check_gltf_document(file.json_text, file.binary, file.bin_size, file.folder);
}

// What tinygltf accepts but we do not.
Result<void> check_parsed(const tinygltf::Model& model) {
    if (model.asset.version.rfind("2.", 0) != 0) {
        return Error{"is glTF version " + quote(model.asset.version) + "; only 2.0 is supported"};
    }
    for (const std::string& name : model.extensionsRequired) {  // check_gltf_document refused them already
        if (name != "KHR_lights_punctual") return Error{"requires the unsupported glTF extension " + quote(name)};
    }
    return {};
}

using PrimitiveWork = std::vector<std::pair<PrimitiveData, MeshInstance>>;

// Checks every primitive of every instance and counts triangles before any
// is read; `triangles` returns the count.
Result<PrimitiveWork> read_primitives(const tinygltf::Model& model, const std::vector<MeshInstance>& instances,
                                      std::size_t max_triangles, std::size_t& triangles) {
    PrimitiveWork work;
    triangles = 0;
    for (const MeshInstance& instance : instances) {
        const auto& primitives = model.meshes[static_cast<std::size_t>(instance.mesh)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            Result<PrimitiveData> data = read_primitive(model, instance.mesh, p);
            if (!data) return data;
            triangles += data->triangles;
            if (triangles > max_triangles) {
                return Error{"has more than " + std::to_string(max_triangles) + " triangles"};
            }
            work.emplace_back(std::move(*data), instance);
        }
    }
    return work;
}

Result<GltfModel> load_model(const std::string& path, std::size_t max_triangles) {
    ModelFile file;
    if (Result<void> read = read_model_file(path, file); !read) return read;
    KeptImages kept;
    tinygltf::Model model;
    std::vector<std::string> files{path};
    if (Result<void> parsed = parse_sandboxed(file.bytes, file.json_text, file.binary, file.folder, kept, model, files);
        !parsed) {
        return parsed;
    }
    if (Result<void> checked = check_parsed(model); !checked) return checked;
    std::vector<LightInstance> light_nodes;
    const Result<std::vector<MeshInstance>> instances = collect_instances(model, light_nodes);
    if (!instances) return instances;
    std::vector<std::string> directional;
    Result<std::vector<ModelLight>> lights = read_lights(model, light_nodes, directional);
    if (!lights) return lights;

    std::size_t triangles = 0;
    const Result<PrimitiveWork> work = read_primitives(model, *instances, max_triangles, triangles);
    if (!work) return work;
    GltfModel out;
    out.files = std::move(files);
    out.lights = std::move(*lights);
    out.directional_lights = std::move(directional);
    out.triangles.reserve(triangles);
    for (const auto& [data, instance] : *work) {
        if (Result<void> emitted = emit_triangles(data, instance, out.triangles); !emitted) return emitted;
    }
    if (out.triangles.empty()) {
        return Error{"has no triangles"};
    }
    if (Result<void> built =
            build_materials(model, kept, file.folder, out.triangles, out.materials, out.textures, out.texels);
        !built) {
        return built;
    }
    return out;
}

}  // namespace

Result<GltfModel> load_gltf_model(const std::string& path, std::size_t max_triangles) {
    try {
        return load_model(path, max_triangles);
    } catch (const std::bad_alloc&) {
        return Error{"is too large to read (out of memory)"};
    } catch (const std::exception& e) {
        // tinygltf throws on some malformed input (e.g. std::out_of_range).
        return Error{"is not a valid glTF 2.0 file: " + printable(e.what())};
    }
}

Result<std::vector<ModelTriangle>> load_gltf_triangles(const std::string& path, std::size_t max_triangles) {
    Result<GltfModel> model = load_gltf_model(path, max_triangles);
    if (!model) return model;
    return std::move(model->triangles);
}

}  // namespace impossible::assets
