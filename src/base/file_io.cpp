#include "base/file_io.hpp"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace impossible {

namespace fs = std::filesystem;

namespace {

std::string too_large(std::uintmax_t size, std::size_t max_bytes, bool exact) {
    return "is too large (" + std::string(exact ? "" : "more than ") + format_bytes(size) + "; the limit is " +
           format_bytes(max_bytes) + ")";
}

int idle_timeout_ms() {
    if (const char* v = std::getenv("IMPOSSIBLE_INPUT_TIMEOUT_MS")) {
        char* end = nullptr;
        const long ms = std::strtol(v, &end, 10);
        if (end != v && *end == '\0' && ms > 0 && ms <= 3'600'000) return static_cast<int>(ms);
    }
    return kInputIdleTimeoutMs;
}

// Closes the descriptor when it goes out of scope.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

// Reads everything from a non-blocking descriptor, stopping one byte past the
// limit. Waits in poll() before each read, at most the idle timeout: for a
// FIFO that no writer has opened yet, read() would say end-of-file at once,
// while poll() waits for the writer (Linux reports no hang-up on a FIFO until
// a writer has come and gone).
Result<std::vector<unsigned char>> read_all(int fd, std::size_t max_bytes) {
    std::vector<unsigned char> out;
    unsigned char chunk[1 << 16];
    const int timeout = idle_timeout_ms();
    for (;;) {
#if !defined(__EMSCRIPTEN__)  // the web build has no FIFOs to wait for, and no poll() under node
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, timeout);
        if (ready < 0) {
            if (errno == EINTR) continue;
            return Error{std::string("cannot be read: ") + std::strerror(errno)};
        }
        if (ready == 0) {
            return Error{"sent no data for " + std::to_string(timeout / 1000) + "." +
                         std::to_string(timeout % 1000 / 100) + " s (a pipe or FIFO that nobody writes to?)"};
        }
#else
        (void)timeout;
#endif
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n > 0) {
            out.insert(out.end(), chunk, chunk + n);
            if (out.size() > max_bytes) return Error{too_large(max_bytes, max_bytes, false)};
            continue;
        }
        if (n == 0) return out;
        if (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK)
            return Error{std::string("cannot be read: ") + std::strerror(errno)};
    }
}

}  // namespace

std::string format_bytes(std::uint64_t bytes) {
    constexpr std::uint64_t mib = 1u << 20;
    if (bytes >= mib && bytes % mib == 0) return std::to_string(bytes / mib) + " MiB";
    return std::to_string(bytes) + " bytes";
}

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
        return Error{ec && ec != std::errc::no_such_file_or_directory ? "cannot be opened: " + ec.message()
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

Result<std::vector<unsigned char>> read_file_bytes(const std::string& path, std::size_t max_bytes, bool regular_only) {
    if (Result<void> readable = check_readable_file(path, max_bytes, regular_only); !readable) return readable;
    // O_NONBLOCK: opening a FIFO for reading otherwise waits for a writer,
    // forever if none comes; reads then wait in poll() with a timeout.
    Fd file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) return Error{std::string("cannot be opened: ") + std::strerror(errno)};
    struct stat st {};
    if (::fstat(file.fd, &st) != 0) return Error{std::string("cannot be read: ") + std::strerror(errno)};
    if (S_ISDIR(st.st_mode)) return Error{"is a directory"};
    if (regular_only && !S_ISREG(st.st_mode)) return Error{"is not a regular file"};
    if (S_ISREG(st.st_mode) && static_cast<std::uintmax_t>(st.st_size) > max_bytes)
        return Error{too_large(static_cast<std::uintmax_t>(st.st_size), max_bytes, true)};
    return read_all(file.fd, max_bytes);
}

}  // namespace impossible
