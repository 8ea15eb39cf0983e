#include "layout/path_file.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

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

// A path file is 8-bit text (ASCII or UTF-8). UTF-16 and UTF-32 files, common
// from Windows editors, start with a byte order mark: name the encoding
// instead of complaining about the first field.
const char* wide_encoding(const std::string& first_line) {
    const auto starts = [&](std::string_view bom) { return first_line.rfind(bom, 0) == 0; };
    using namespace std::string_view_literals;
    if (starts("\xFF\xFE\0\0"sv) || starts("\0\0\xFE\xFF"sv)) return "UTF-32";
    if (starts("\xFF\xFE"sv) || starts("\xFE\xFF"sv)) return "UTF-16";
    return nullptr;
}

// One field as a number: from_chars plus an optional leading '+' (not "+-").
bool parse_field(const std::string& field, double& value) {
    const char* first = field.data();
    const char* last = first + field.size();
    if (*first == '+') {
        ++first;
        if (first == last || *first == '-' || *first == '+') return false;
    }
    const auto [ptr, ec] = std::from_chars(first, last, value);
    return ec == std::errc() && ptr == last && std::isfinite(value);
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
        if (number == 1) {
            if (const char* encoding = wide_encoding(line))
                return Error{name + ": is " + encoding + " text; save it as UTF-8 or ASCII"};
            if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
        }
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find('\0') != std::string::npos)
            return fail("holds a NUL byte; a path file is text (ASCII or UTF-8, not UTF-16)");
        const std::vector<std::string> f = fields_of(line);
        if (f.empty() || f[0][0] == '#') continue;
        if (f.size() != 6)
            return fail("expected 6 numbers (X Y Z YAW PITCH ROLL), found " + std::to_string(f.size()) + " fields");
        double v[6];
        for (int k = 0; k < 6; ++k) {
            if (!parse_field(f[k], v[k]))
                return fail(std::string(kNames[k]) + ": '" + printable(f[k], kQuotedCharacters) +
                            "' is not a finite number");
            if (std::abs(v[k]) > 1e6)
                return fail(std::string(kNames[k]) + ": " + printable(f[k], kQuotedCharacters) + " is out of range (|" +
                            kNames[k] + "| <= " + (k < 3 ? "1e6 m" : "1e6 degrees") + ")");
        }
        poses.push_back(math::HeadPose{{v[0], v[1], v[2]}, v[3], v[4], v[5]});
    }
    if (in.bad()) {
        ++number;
        return fail("read error");
    }
    if (poses.empty()) return Error{name + ": the path file holds no poses"};
    return poses;
}

PathFile read_path_file(const std::string& path) {
    // Through the one input reader: a size limit (so /dev/zero fails fast
    // instead of filling memory) and no waiting forever on a FIFO.
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path, kMaxPathFileBytes, false);
    if (!bytes) return Error{path + ": " + bytes.error()};
    std::istringstream in(std::string(bytes->begin(), bytes->end()));
    return read_path_stream(in, path);
}

}  // namespace impossible::layout
