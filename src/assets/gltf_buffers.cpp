// The buffers of a glTF document against their byteLength, before tinygltf
// reads them: the .glb's binary chunk, base64 data: URIs, and files in the
// model's folder (gltf_preflight.hpp).
#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "assets/gltf_preflight.hpp"
#include "assets/limits.hpp"
#include "base/file_io.hpp"
#include "base/user_text.hpp"

namespace impossible::assets {

namespace {

using nlohmann::json;

// The decoded size of base64 text as tinygltf's decoder reads it: up to the
// first character that is not base64 ('=' padding included).
std::size_t base64_size(std::string_view text) {
    std::size_t n = 0;
    while (n < text.size() && (std::isalnum(static_cast<unsigned char>(text[n])) || text[n] == '+' || text[n] == '/'))
        ++n;
    return n / 4 * 3 + (n % 4 == 0 ? 0 : n % 4 - 1);
}

// What a path is when it is not a regular file, for "is a FIFO, not a regular file".
std::string file_kind_problem(const std::string& path, std::uintmax_t& size) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (errno == ENOENT || errno == ENOTDIR) return "does not exist";
        return std::string("cannot be opened: ") + std::strerror(errno);
    }
    if (S_ISDIR(st.st_mode)) return "is a directory, not a regular file";
    if (S_ISFIFO(st.st_mode)) return "is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "is a device, not a regular file";
    if (S_ISSOCK(st.st_mode)) return "is a socket, not a regular file";
    if (!S_ISREG(st.st_mode)) return "is not a regular file";
    size = static_cast<std::uintmax_t>(st.st_size);
    return "";
}

// A buffer's data: URI, which must be base64 of a type tinygltf decodes and
// hold exactly its byteLength.
Result<void> check_data_uri(const std::string& who, const std::string& says, const std::string& uri,
                            std::uint64_t length) {
    // The media types tinygltf decodes (DecodeDataURI).
    static const char* const headers[] = {"data:application/octet-stream;base64,",
                                          "data:application/gltf-buffer;base64,",
                                          "data:image/jpeg;base64,",
                                          "data:image/png;base64,",
                                          "data:image/bmp;base64,",
                                          "data:image/gif;base64,",
                                          "data:text/plain;base64,"};
    std::size_t header = 0;
    for (const char* h : headers) {
        if (uri.rfind(h, 0) == 0) header = std::strlen(h);
    }
    if (header == 0) {
        return Error{who +
                     " whose data: URI is not base64 data of type application/octet-stream or "
                     "application/gltf-buffer"};
    }
    const std::size_t holds = base64_size(std::string_view(uri).substr(header));
    if (holds != length) return Error{says + "its data: URI holds " + std::to_string(holds)};
    return {};
}

// A buffer's file, which must be a regular file in the model's folder of
// exactly its byteLength.
Result<void> check_buffer_file(const std::string& who, const std::string& says, const std::string& uri,
                               std::uint64_t length, const std::string& folder) {
    const std::string name = decode_uri(uri);
    const std::string file = quote(uri.substr(0, 200));
    if (name.empty() || name.find('\0') != std::string::npos)
        return Error{who + " whose file name " + file + " is empty or holds a NUL"};
    const std::string path = (folder.empty() ? "/" : folder + "/") + name;
    if (absolute_uri(uri) || !inside_folder(path, folder))
        return Error{who + " whose file " + file + " lies outside the model's folder"};
    std::uintmax_t size = 0;
    if (const std::string problem = file_kind_problem(path, size); !problem.empty())
        return Error{who + " whose file " + file + " " + problem};
    if (size > limits::kMaxModelBytes) {
        return Error{who + " whose file " + file + " is too large (" + format_bytes(size) + "; the limit is " +
                     format_bytes(limits::kMaxModelBytes) + ")"};
    }
    if (size != length) return Error{says + "its file " + file + " holds " + std::to_string(size)};
    return {};
}

}  // namespace

Result<void> check_buffers(const json& doc, bool binary, long long glb_bin_size, const std::string& folder) {
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return {};
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const json& buffer = (*buffers)[i];
        const std::string who = "has buffer " + std::to_string(i);
        if (!buffer.is_object()) return Error{who + " that is not a JSON object"};
        const auto length_it = buffer.find("byteLength");
        if (length_it == buffer.end()) return Error{who + " without a byteLength"};
        if (!length_it->is_number_unsigned() || length_it->get<std::uint64_t>() == 0)
            return Error{who + " whose byteLength is not a whole number of bytes above 0"};
        const std::uint64_t length = length_it->get<std::uint64_t>();
        const std::string says = who + " whose byteLength is " + std::to_string(length) + " bytes, but ";
        const auto uri_it = buffer.find("uri");
        if (uri_it == buffer.end()) {
            if (!binary || i != 0) return Error{who + " without a uri (only the first buffer of a .glb may have none)"};
            if (glb_bin_size < 0) return Error{who + " without a uri, but the .glb has no binary chunk"};
            if (length > static_cast<std::uint64_t>(glb_bin_size))
                return Error{says + "the .glb's binary chunk holds " + std::to_string(glb_bin_size)};
            continue;
        }
        if (!uri_it->is_string()) return Error{who + " whose uri is not a string"};
        const std::string& uri = uri_it->get_ref<const std::string&>();
        if (uri.rfind("data:", 0) == 0) {
            if (Result<void> ok = check_data_uri(who, says, uri, length); !ok) return ok;
            continue;
        }
        if (Result<void> ok = check_buffer_file(who, says, uri, length, folder); !ok) return ok;
    }
    return {};
}

}  // namespace impossible::assets
