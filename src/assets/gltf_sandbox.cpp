// tinygltf, confined: its file callbacks read only in the model's folder
// and below, bounded like our own reads, and never write; images are kept
// as bytes while parsing (keep_image_bytes), not decoded.
#include <cctype>
#include <filesystem>
#include <system_error>

#include "assets/gltf_import.hpp"
#include "assets/gltf_preflight.hpp"
#include "base/file_io.hpp"
#include "base/user_text.hpp"

namespace impossible::assets {

namespace {

// --- tinygltf callbacks: no shell expansion of paths, no image decoding
// while parsing (keep_image_bytes keeps the bytes; only the images a drawn
// material needs are decoded), no writing, and file reads bounded like ours.
//
// A model reads files only in its own folder and below (its buffers): a URI
// such as "../../../../etc/passwd" must not open, or even reveal whether or
// how large, a file elsewhere. `user_data` is a SandboxFiles: the model's
// folder, canonical, and the list of the files read (its buffers and images).
struct SandboxFiles {
    const std::string* folder;
    std::vector<std::string>* read;
};
bool inside_model_folder(const std::string& path, void* user_data) {
    return assets::inside_folder(path, *static_cast<const SandboxFiles*>(user_data)->folder);
}
bool fs_file_exists(const std::string& path, void* user_data) {
    if (!inside_model_folder(path, user_data)) return true;  // refused when read, whether it exists or not
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}
std::string fs_expand_path(const std::string& path, void*) { return path; }
bool fs_read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user_data) {
    if (!inside_model_folder(path, user_data)) {
        if (err != nullptr) *err += "file " + quote(path) + " lies outside the model's folder\n";
        return false;
    }
    Result<std::vector<unsigned char>> bytes = read_file_bytes(path, limits::kMaxModelBytes, true);
    if (bytes) {
        *out = std::move(*bytes);
        static_cast<SandboxFiles*>(user_data)->read->push_back(path);
        return true;
    }
    if (err != nullptr) *err += "file " + quote(path) + " " + bytes.error() + "\n";
    return false;
}
bool fs_write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err != nullptr) *err += "writing is disabled\n";
    return false;
}
// tinygltf's first message, one short line; a data: URI in it (tinygltf
// quotes whole buffers) is cut to its media type.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    for (std::size_t at = line.find("data:"); at != std::string::npos; at = line.find("data:", at + 5)) {
        const std::size_t comma = line.find(',', at);
        if (comma == std::string::npos) break;
        std::size_t end = comma + 1;
        while (end < line.size() && !std::isspace(static_cast<unsigned char>(line[end]))) ++end;
        line.replace(comma + 1, end - comma - 1, "...");
    }
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (line.size() > 200) line = line.substr(0, 200) + "...";
    return printable(line.empty() ? "unknown reason" : line);
}

}  // namespace

Result<void> parse_sandboxed(const std::vector<unsigned char>& bytes, std::string_view json_text, bool binary,
                             const std::string& folder, KeptImages& kept, tinygltf::Model& model,
                             std::vector<std::string>& files_read) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keep_image_bytes, &kept);
    SandboxFiles files{&folder, &files_read};
    loader.SetFsCallbacks({&fs_file_exists, &fs_expand_path, &fs_read_whole_file, &fs_write_whole_file, &files});
    std::string err, warn;
    const std::string base_dir = folder.empty() ? "/" : folder;
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                         static_cast<unsigned int>(bytes.size()), base_dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, json_text.data(),
                                                        static_cast<unsigned int>(json_text.size()), base_dir);
    if (!kept.error.empty()) return Error{kept.error};
    if (!ok) {
        return Error{"is not a valid glTF 2.0 file: " + first_line(err)};
    }
    return {};
}

}  // namespace impossible::assets
