#include "assets/gltf_preflight.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>
#include <nlohmann/json.hpp>

#include "assets/limits.hpp"
#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"

namespace impossible::assets {

namespace {

using nlohmann::json;

std::uint32_t read_u32(const std::vector<unsigned char>& bytes, std::size_t at) {
    return std::uint32_t(bytes[at]) | std::uint32_t(bytes[at + 1]) << 8 | std::uint32_t(bytes[at + 2]) << 16 |
           std::uint32_t(bytes[at + 3]) << 24;  // little-endian, as glTF
}

Error invalid(const std::string& reason) { return Error{"is not a valid glTF 2.0 file: " + reason}; }

// An index field (`buffer`, `bufferView`, `indices`) that must name one of
// `count` things. Returns the message's tail, or "" when fine or absent.
std::string bad_reference(const json& object, const char* key, std::size_t count, const char* singular,
                          const char* plural, const std::string& who) {
    const auto it = object.find(key);
    if (it == object.end()) return "";
    if (!it->is_number_integer()) return who + " whose " + key + " is not a whole number";
    const std::int64_t index = it->get<std::int64_t>();
    if (index >= 0 && static_cast<std::uint64_t>(index) < count) return "";
    return who + " that refers to " + singular + " " + std::to_string(index) +
           ", which does not exist (the model has " + count_of(count, singular, plural) + ")";
}

Result<void> check_extensions(const json& doc) {
    const auto required = doc.find("extensionsRequired");
    if (required == doc.end() || !required->is_array() || required->empty()) return {};
    // The loader implements only KHR_lights_punctual (its point and spot
    // lights): every other required extension is refused.
    std::string names;
    bool draco = false;
    std::size_t listed = 0;
    for (const json& name : *required) {
        if (!name.is_string()) continue;
        const std::string& text = name.get_ref<const std::string&>();
        if (text == "KHR_lights_punctual") continue;
        draco = draco || text == "KHR_draco_mesh_compression";
        if (listed == 5) {
            names += " and more";
            break;
        }
        names += std::string(listed == 0 ? "" : ", ") + quote(text.substr(0, 100));
        ++listed;
    }
    if (listed == 0) return {};
    std::string message = std::string("requires the unsupported glTF extension") + (listed > 1 ? "s " : " ") + names;
    if (draco) message += " (Draco mesh compression; export the model without it)";
    return Error{message};
}

// doc[key] when it is an array, else an empty array.
const json& member_array(const json& doc, const char* key) {
    static const json empty = json::array();
    const auto it = doc.find(key);
    return it != doc.end() && it->is_array() ? *it : empty;
}

// Each buffer view's buffer.
Result<void> check_view_references(const json& views, const json& buffers) {
    for (std::size_t i = 0; i < views.size(); ++i) {
        if (!views[i].is_object()) continue;
        const std::string who = "has bufferView " + std::to_string(i);
        if (!views[i].contains("buffer")) return Error{who + " without a buffer"};
        if (std::string e = bad_reference(views[i], "buffer", buffers.size(), "buffer", "buffers", who); !e.empty())
            return Error{e};
    }
    return {};
}

// Each accessor's buffer view, and those of its sparse indices and values.
Result<void> check_accessor_references(const json& accessors, const json& views) {
    for (std::size_t i = 0; i < accessors.size(); ++i) {
        const json& accessor = accessors[i];
        if (!accessor.is_object()) continue;
        const std::string who = "has accessor " + std::to_string(i);
        if (std::string e = bad_reference(accessor, "bufferView", views.size(), "bufferView", "bufferViews", who);
            !e.empty())
            return Error{e};
        const auto sparse = accessor.find("sparse");
        if (sparse == accessor.end() || !sparse->is_object()) continue;
        for (const char* part : {"indices", "values"}) {
            const auto it = sparse->find(part);
            if (it == sparse->end() || !it->is_object()) continue;
            const std::string whose = who + " whose sparse " + part;
            if (!it->contains("bufferView")) return Error{whose + " have no bufferView"};
            if (std::string e = bad_reference(*it, "bufferView", views.size(), "bufferView", "bufferViews", whose);
                !e.empty())
                return Error{e};
        }
    }
    return {};
}

// That buffer view `v` (which exists) of an image lies inside its buffer.
// `who` is "has image N".
Result<void> check_image_view(const json& views, std::size_t v, const json& buffers, const std::string& who) {
    const json& view = views[v];
    if (!view.is_object()) return {};
    const auto offset = view.find("byteOffset");
    const auto length = view.find("byteLength");
    const auto buffer = view.find("buffer");
    const bool numbers = (offset == view.end() || offset->is_number_unsigned()) && length != view.end() &&
                         length->is_number_unsigned() && buffer != view.end() && buffer->is_number_unsigned();
    const std::size_t b = numbers ? buffer->get<std::size_t>() : 0;
    const json* buffer_object = numbers && b < buffers.size() && buffers[b].is_object() ? &buffers[b] : nullptr;
    const auto size = buffer_object != nullptr ? buffer_object->find("byteLength") : json::const_iterator();
    if (buffer_object == nullptr || size == buffer_object->end() || !size->is_number_unsigned()) {
        return Error{who + " whose bufferView " + std::to_string(v) +
                     " has no valid buffer, byteOffset and byteLength"};
    }
    const std::uint64_t from = offset == view.end() ? 0 : offset->get<std::uint64_t>();
    const std::uint64_t bytes = length->get<std::uint64_t>();
    const std::uint64_t total = size->get<std::uint64_t>();
    if (bytes == 0 || from > total || bytes > total - from) {
        return Error{who + " whose bufferView " + std::to_string(v) + " (" + std::to_string(bytes) +
                     " bytes from byte " + std::to_string(from) + ") does not lie inside its buffer of " +
                     std::to_string(total) + " bytes"};
    }
    return {};
}

// tinygltf hands an image's bufferView to the image loader without
// checking that it lies inside its buffer.
Result<void> check_image_references(const json& images, const json& views, const json& buffers) {
    for (std::size_t i = 0; i < images.size(); ++i) {
        const json& image = images[i];
        if (!image.is_object() || !image.contains("bufferView")) continue;
        const std::string who = "has image " + std::to_string(i);
        if (std::string e = bad_reference(image, "bufferView", views.size(), "bufferView", "bufferViews", who);
            !e.empty())
            return Error{e};
        const std::size_t v = image["bufferView"].get<std::size_t>();
        if (Result<void> inside = check_image_view(views, v, buffers, who); !inside) return inside;
    }
    return {};
}

// tinygltf keeps the default (white) for a baseColorFactor of the wrong length.
Result<void> check_base_colour_factors(const json& materials) {
    for (std::size_t i = 0; i < materials.size(); ++i) {
        if (!materials[i].is_object()) continue;
        const auto pbr = materials[i].find("pbrMetallicRoughness");
        if (pbr == materials[i].end() || !pbr->is_object()) continue;
        const auto factor = pbr->find("baseColorFactor");
        if (factor == pbr->end()) continue;
        const bool four_numbers =
            factor->is_array() && factor->size() == 4 &&
            std::all_of(factor->begin(), factor->end(), [](const json& v) { return v.is_number(); });
        if (!four_numbers)
            return Error{"has material " + std::to_string(i) + " whose baseColorFactor is not 4 numbers"};
    }
    return {};
}

// Each primitive's index accessor, which must exist and have data.
Result<void> check_index_references(const json& meshes, const json& accessors) {
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const auto primitives = meshes[m].is_object() ? meshes[m].find("primitives") : meshes[m].end();
        if (!meshes[m].is_object() || primitives == meshes[m].end() || !primitives->is_array()) continue;
        for (std::size_t p = 0; p < primitives->size(); ++p) {
            const json& primitive = (*primitives)[p];
            if (!primitive.is_object()) continue;
            const std::string who = "has mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            if (std::string e = bad_reference(primitive, "indices", accessors.size(), "accessor", "accessors",
                                              who + " whose indices are");
                !e.empty())
                return Error{e};
            const auto indices = primitive.find("indices");
            if (indices == primitive.end()) continue;
            const json& accessor = accessors[indices->get<std::size_t>()];
            if (accessor.is_object() && !accessor.contains("bufferView")) {
                return Error{who + " whose indices accessor " + std::to_string(indices->get<std::size_t>()) +
                             " has no bufferView (its data is missing)"};
            }
        }
    }
    return {};
}

Result<void> check_references(const json& doc) {
    const json& buffers = member_array(doc, "buffers");
    const json& views = member_array(doc, "bufferViews");
    const json& accessors = member_array(doc, "accessors");
    if (Result<void> ok = check_view_references(views, buffers); !ok) return ok;
    if (Result<void> ok = check_accessor_references(accessors, views); !ok) return ok;
    if (Result<void> ok = check_image_references(member_array(doc, "images"), views, buffers); !ok) return ok;
    if (Result<void> ok = check_base_colour_factors(member_array(doc, "materials")); !ok) return ok;
    return check_index_references(member_array(doc, "meshes"), accessors);
}

}  // namespace

bool inside_folder(const std::string& path, const std::string& folder) {
    std::error_code ec;
    const std::string where = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec).string();
    return !ec && where.size() > folder.size() && where.compare(0, folder.size(), folder) == 0 &&
           where[folder.size()] == '/';
}

std::string decode_uri(const std::string& uri) {
    const auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;  // as dlib's from_hex: a bad digit counts as 0
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += static_cast<char>(hex(uri[i + 1]) << 4 | hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

bool absolute_uri(const std::string& uri) {
    const std::string name = decode_uri(uri);
    if (!name.empty() && name[0] == '/') return true;
    // RFC 3986, 3.1: scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ), then ':'.
    if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (const char c : uri) {
        if (c == ':') return true;
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
    }
    return false;
}

Result<GlbChunks> split_glb(const std::vector<unsigned char>& bytes) {
    if (bytes.size() < 12 || std::memcmp(bytes.data(), "glTF", 4) != 0)
        return invalid("it does not start with the .glb header (\"glTF\")");
    if (const std::uint32_t version = read_u32(bytes, 4); version != 2)
        return Error{"is a .glb file of version " + std::to_string(version) + "; only 2 is supported"};
    const std::size_t length = read_u32(bytes, 8);
    if (length > bytes.size()) {
        return invalid("its header gives a length of " + std::to_string(length) + " bytes, but the file has " +
                       std::to_string(bytes.size()) + " (cut short?)");
    }
    if (length < 20) return invalid("it has no JSON chunk");
    const std::size_t json_length = read_u32(bytes, 12);
    if (read_u32(bytes, 16) != 0x4E4F534Au) return invalid("its first chunk is not JSON");
    if (json_length > length - 20) return invalid("its JSON chunk reaches past the end of the file");
    GlbChunks out;
    out.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20, json_length);
    const std::size_t next = 20 + json_length;  // tinygltf does not require the 4-byte padding
    if (length - next >= 8) {
        const std::size_t bin_length = read_u32(bytes, next);
        if (read_u32(bytes, next + 4) == 0x004E4942u) {
            if (bin_length > length - next - 8) return invalid("its binary chunk reaches past the end of the file");
            out.has_bin = true;
            out.bin_offset = next + 8;
            out.bin_size = bin_length;
        }
    }
    return out;
}

Result<void> check_json_shape(std::string_view text) {
    std::size_t depth = 0, values = 0;
    bool in_string = false, escape = false, in_word = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (escape) {
                escape = false;
            } else if (c == '\\') {
                escape = true;
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        const bool word = !(c == '"' || c == '{' || c == '[' || c == '}' || c == ']' || c == ':' || c == ',' ||
                            std::isspace(static_cast<unsigned char>(c)));
        if (word) {
            if (!in_word) ++values;  // a number, true, false or null
        } else if (c == '"') {
            in_string = true;
            ++values;
        } else if (c == '{' || c == '[') {
            ++values;
            if (++depth > limits::kMaxModelJsonDepth) {
                return Error{"nests its JSON more than " + std::to_string(limits::kMaxModelJsonDepth) +
                             " levels deep (at byte offset " + std::to_string(i) + "); a glTF file needs about 8"};
            }
        } else if (c == '}' || c == ']') {
            if (depth > 0) --depth;
        } else if (c == ':' && values > 0) {
            --values;  // the string before it was a key
        }
        in_word = word;
        // A key counts until its colon: allow one over before the end.
        if (values > limits::kMaxModelJsonValues + 1) break;
    }
    if (values > limits::kMaxModelJsonValues)
        return Error{"has more than " + std::to_string(limits::kMaxModelJsonValues) + " JSON values"};
    return {};
}

Result<void> check_gltf_document(std::string_view text, bool binary, long long glb_bin_size,
                                 const std::string& folder) {
    const json doc = json::parse(text.begin(), text.end(), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return {};  // tinygltf says what is wrong
    if (Result<void> r = check_extensions(doc); !r) return r;
    if (Result<void> r = check_references(doc); !r) return r;
    return check_buffers(doc, binary, glb_bin_size, folder);
}

}  // namespace impossible::assets
