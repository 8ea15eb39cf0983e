#include "layout/path_file.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "base/file_io.hpp"
#include "base/user_text.hpp"

namespace impossible::layout {
namespace {

std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t i = 0;
    auto blank = [](char c) { return c == ' ' || c == '\t'; };
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        std::size_t j = i;
        while (j < line.size() && !blank(line[j])) ++j;
        if (j > i) fields.push_back(line.substr(i, j - i));
        i = j;
    }
    return fields;
}

}  // namespace

PathFile read_path_stream(std::istream& in, const std::string& name) {
    static const char* const kNames[6] = {"X", "Y", "Z", "YAW", "PITCH", "ROLL"};
    std::vector<math::HeadPose> poses;
    std::string line;
    int number = 0;
    auto fail = [&](const std::string& message) { return Error{name + ":" + std::to_string(number) + ": " + message}; };
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::vector<std::string> f = fields_of(line);
        if (f.empty() || f[0][0] == '#') continue;
        if (f.size() != 6)
            return fail("expected 6 numbers (X Y Z YAW PITCH ROLL), found " + std::to_string(f.size()) + " fields");
        double v[6];
        for (int k = 0; k < 6; ++k) {
            const char* first = f[k].data();
            const char* last = first + f[k].size();
            if (*first == '+') ++first;
            const auto [ptr, ec] = std::from_chars(first, last, v[k]);
            if (ec != std::errc() || ptr != last || !std::isfinite(v[k]))
                return fail(std::string(kNames[k]) + ": '" + printable(f[k]) + "' is not a finite number");
            if (std::abs(v[k]) > 1e6)
                return fail(std::string(kNames[k]) + ": " + printable(f[k]) + " is out of range (|" + kNames[k] +
                            "| <= " + (k < 3 ? "1e6 m" : "1e6 degrees") + ")");
        }
        poses.push_back(math::HeadPose{{v[0], v[1], v[2]}, v[3], v[4], v[5]});
    }
    if (in.bad()) {
        ++number;
        return fail("read error");
    }
    return poses;
}

PathFile read_path_file(const std::string& path) {
    // Through the one input reader: a size limit (so /dev/zero fails fast
    // instead of filling memory) and no waiting forever on a FIFO.
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path, kMaxPathFileBytes, false);
    if (!bytes) return Error{path + ": " + bytes.error()};
    std::istringstream in(std::string(bytes->begin(), bytes->end()));
    PathFile file = read_path_stream(in, path);
    if (file && file->empty()) return Error{path + ": the path file holds no poses"};
    return file;
}

}  // namespace impossible::layout
