#include "layout/file_io.hpp"

#include "layout/text_util.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace impossible::layout::detail {

namespace fs = std::filesystem;

namespace {

std::string too_large(std::uintmax_t size, std::size_t max_bytes, bool exact) {
    return "is too large (" + std::string(exact ? "" : "more than ") + format_bytes(size) +
           "; the limit is " + format_bytes(max_bytes) + ")";
}

}  // namespace

Result<void> check_readable_file(const std::string& path, std::size_t max_bytes, bool regular_only) {
    if (path.empty()) {
        return Error{"has an empty path"};
    }
    if (path.find('\0') != std::string::npos) {
        return Error{"has a NUL character in its path"};
    }
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
        return Error{ec && ec != std::errc::no_such_file_or_directory
                    ? "cannot be opened: " + ec.message()
                    : "does not exist"};
    }
    if (fs::is_directory(status)) {
        return Error{"is a directory"};
    }
    const bool regular = fs::is_regular_file(status);
    if (regular_only && !regular) {
        return Error{"is not a regular file"};
    }
    if (regular) {
        const std::uintmax_t size = fs::file_size(path, ec);
        if (!ec && size > max_bytes) {
            return Error{too_large(size, max_bytes, true)};
        }
    }
    return {};
}

Result<std::vector<unsigned char>> read_file_bytes(const std::string& path, std::size_t max_bytes,
                                                  bool regular_only) {
    if (Result<void> readable = check_readable_file(path, max_bytes, regular_only); !readable)
        return Error{readable.error()};
    errno = 0;
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                                &std::fclose);
    if (!file) {
        return Error{std::string("cannot be opened: ") + (errno ? std::strerror(errno) : "unknown error")};
    }
    // Read in chunks up to one byte past the limit (sizes of special files lie).
    std::vector<unsigned char> out;
    unsigned char chunk[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(chunk, 1, sizeof chunk, file.get());
        out.insert(out.end(), chunk, chunk + n);
        if (out.size() > max_bytes) {
            return Error{too_large(max_bytes, max_bytes, false)};
        }
        if (n < sizeof chunk) break;
    }
    if (std::ferror(file.get())) {
        return Error{std::string("cannot be read: ") + (errno ? std::strerror(errno) : "I/O error")};
    }
    return out;
}

}  // namespace impossible::layout::detail
