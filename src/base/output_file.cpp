#include "base/output_file.hpp"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace impossible {

namespace fs = std::filesystem;

namespace {

// Where and how one output goes.
struct Plan {
    std::string path;        // as given, for messages
    std::string final_path;  // the file that ends up holding the bytes
    bool direct = false;     // a device, FIFO or socket: written in place
    int descriptor = -1;     // /dev/stdout and the like: this open descriptor
    mode_t mode = 0666;      // of a new or replaced regular file
    std::string temp;        // the temporary file, once created
};

std::string errno_text(int error) { return std::strerror(error); }

Error cannot_write(const std::string& path, const std::string& reason) {
    return Error{path + ": cannot write: " + reason};
}

std::string directory_of(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

// Follows a chain of symbolic links that ends at a name that does not exist
// yet (a dangling link): the file to create. Gives up after 40 links, as the
// kernel does.
Result<std::string> dangling_target(std::string path) {
    for (int hops = 0; hops < 40; ++hops) {
        struct stat st {};
        if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
        std::error_code ec;
        const fs::path target = fs::read_symlink(path, ec);
        if (ec) return Error{ec.message()};
        path = target.is_absolute() ? target.string() : (fs::path(directory_of(path)) / target).string();
    }
    return Error{errno_text(ELOOP)};
}

mode_t default_mode() {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

// The descriptor a name such as /dev/stdout or /dev/fd/3 stands for, or -1.
// Written through the descriptor itself, the output goes where the shell
// sent it, appending after `>>` too (reopening the name would start at 0).
int named_descriptor(const std::string& path) {
    if (path == "/dev/stdout") return 1;
    if (path == "/dev/stderr") return 2;
    for (const char* prefix : {"/dev/fd/", "/proc/self/fd/"}) {
        const std::string p = prefix;
        if (path.size() <= p.size() || path.compare(0, p.size(), p) != 0) continue;
        const std::string digits = path.substr(p.size());
        if (digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
        const int fd = std::stoi(digits);
        return ::fcntl(fd, F_GETFD) >= 0 ? fd : -1;
    }
    return -1;
}

Result<Plan> plan_output(const std::string& path) {
    Plan plan{path, path, false, -1, default_mode(), {}};
    if (path.empty()) return cannot_write("''", "empty file name");
    if ((plan.descriptor = named_descriptor(path)) >= 0) {
        plan.direct = true;
        return plan;
    }
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return cannot_write(path, "is a directory");
        if (!S_ISREG(st.st_mode)) {
            plan.direct = true;
            return plan;
        }
        plan.mode = st.st_mode & 07777;
        struct stat lst {};
        if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
            char* real = ::realpath(path.c_str(), nullptr);
            if (!real) return cannot_write(path, errno_text(errno));
            plan.final_path = real;
            std::free(real);
        }
        return plan;
    }
    if (errno != ENOENT) return cannot_write(path, errno_text(errno));
    Result<std::string> target = dangling_target(path);
    if (!target) return cannot_write(path, target.error());
    plan.final_path = *target;
    return plan;
}

Result<void> write_all(int fd, const std::string& bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return Error{errno_text(errno)};
        }
        done += static_cast<size_t>(n);
    }
    return {};
}

// The temporary file next to the final one, written whole and closed.
Result<void> write_temp(Plan& plan, const std::string& bytes) {
    std::string name = directory_of(plan.final_path) + "/.impossible-XXXXXX";
    const int fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd < 0) return cannot_write(plan.path, errno_text(errno));
    plan.temp = name;
    Result<void> written = write_all(fd, bytes);
    if (written && ::fchmod(fd, plan.mode) != 0) written = Error{errno_text(errno)};
    if (::close(fd) != 0 && written) written = Error{errno_text(errno)};
    if (!written) return cannot_write(plan.path, written.error());
    return {};
}

// A device, FIFO or socket. A FIFO without a reader is an error rather than
// a wait (O_NONBLOCK on open); the writes themselves then block as usual.
Result<void> write_direct(const Plan& plan, const std::string& bytes) {
    if (plan.descriptor >= 0) {
        if (plan.descriptor <= 2) std::fflush(plan.descriptor == 1 ? stdout : stderr);  // keep the order
        if (Result<void> written = write_all(plan.descriptor, bytes); !written)
            return cannot_write(plan.path, written.error());
        return {};
    }
    const int fd = ::open(plan.path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return cannot_write(plan.path, errno == ENXIO ? std::string("nothing reads from it") : errno_text(errno));
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    Result<void> written = write_all(fd, bytes);
    if (::close(fd) != 0 && written) written = Error{errno_text(errno)};
    if (!written) return cannot_write(plan.path, written.error());
    return {};
}

void remove_temps(const std::vector<Plan>& plans) {
    for (const Plan& p : plans)
        if (!p.temp.empty()) ::unlink(p.temp.c_str());
}

}  // namespace

Result<void> write_output_files(const std::vector<OutputBytes>& files) {
    std::vector<Plan> plans;
    for (const OutputBytes& f : files) {
        Result<Plan> plan = plan_output(f.path);
        if (!plan) return plan;
        plans.push_back(std::move(*plan));
    }
    // Regular files first, into temporary files; then devices and FIFOs;
    // renames last, once nothing can fail any more (short of the rename).
    for (size_t i = 0; i < plans.size(); ++i) {
        if (plans[i].direct) continue;
        if (Result<void> w = write_temp(plans[i], files[i].bytes); !w) {
            remove_temps(plans);
            return w;
        }
    }
    for (size_t i = 0; i < plans.size(); ++i) {
        if (!plans[i].direct) continue;
        if (Result<void> w = write_direct(plans[i], files[i].bytes); !w) {
            remove_temps(plans);
            return w;
        }
    }
    for (size_t i = 0; i < plans.size(); ++i) {
        if (plans[i].direct) continue;
        if (::rename(plans[i].temp.c_str(), plans[i].final_path.c_str()) != 0) {
            const int error = errno;
            remove_temps(std::vector<Plan>(plans.begin() + static_cast<long>(i), plans.end()));
            return cannot_write(plans[i].path, errno_text(error));
        }
    }
    return {};
}

Result<void> write_output_file(const std::string& path, const std::string& bytes) {
    return write_output_files({OutputBytes{path, bytes}});
}

FileIdentity identify_file(const std::string& path) {
    FileIdentity id;
    struct stat st {};
    if (!path.empty() && ::stat(path.c_str(), &st) == 0) {
        id.exists = true;
        id.device = st.st_dev;
        id.inode = st.st_ino;
        id.shareable = S_ISCHR(st.st_mode);
        return id;
    }
    Result<std::string> target = dangling_target(path);
    std::error_code ec;
    const fs::path where = fs::weakly_canonical(fs::absolute(target ? *target : path, ec), ec);
    id.path = (ec ? fs::path(path) : where).lexically_normal().string();
    return id;
}

}  // namespace impossible
