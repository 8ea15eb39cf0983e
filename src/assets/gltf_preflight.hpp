// Checks a glTF file before tinygltf parses it: the JSON's nesting depth and
// size (deep nesting crashes tinygltf), the .glb container, the required
// extensions, the buffers against their byteLength and the references from
// accessors and images to buffer views and from buffer views to buffers. tinygltf's own
// messages for these are missing, misleading or dump base64 data.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "base/result.hpp"

namespace impossible::assets {

// The two chunks of a .glb file (glTF 2.0 spec, "GLB File Format
// Specification"): the JSON text and the binary chunk, if any.
struct GlbChunks {
    std::string_view json;
    std::size_t bin_offset = 0;  // into the file's bytes
    std::size_t bin_size = 0;
    bool has_bin = false;
};

// Splits a .glb file; errors are sentences as load_gltf_triangles returns.
Result<GlbChunks> split_glb(const std::vector<unsigned char>& bytes);

// Depth and number of values of JSON text, without building it: nesting
// deeper than limits::kMaxModelJsonDepth or more than kMaxModelJsonValues
// values is an error. Malformed JSON is left to the parser.
Result<void> check_json_shape(std::string_view text);

// The checks on the parsed document. `folder` is the model's folder
// (canonical; "" for the root), where external buffers are looked for;
// `glb_bin_size` is the .glb binary chunk's size (or -1: a .gltf file, or a
// .glb without one).
Result<void> check_gltf_document(std::string_view text, bool binary, long long glb_bin_size, const std::string& folder);

// The buffers of the parsed document (gltf_buffers.cpp): each byteLength
// against the .glb's binary chunk (`glb_bin_size`, -1 without one), its
// data: URI or its file in `folder`.
Result<void> check_buffers(const nlohmann::json& doc, bool binary, long long glb_bin_size, const std::string& folder);

// Whether `path` lies in `folder` (canonical, "" for the root) or below it,
// symbolic links followed: a model reads files only there.
bool inside_folder(const std::string& path, const std::string& folder);

// A buffer URI as tinygltf decodes it (dlib::urldecode: %XX and '+').
std::string decode_uri(const std::string& uri);

// Whether a URI that is not a data: URI names a file by an absolute path
// ("/etc/passwd", "%2Fetc/passwd") or with a scheme ("file:///etc/passwd"),
// which lies outside the model's folder: tinygltf would look for it inside
// (joined to the folder), so such a URI is refused.
bool absolute_uri(const std::string& uri);

}  // namespace impossible::assets
