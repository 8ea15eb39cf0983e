#include "layout/path_file.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include "base/file_io.hpp"
#include "base/number_text.hpp"
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

// One pose's six fields from f[first..first + 6): an empty string, or the
// message naming the field ("left hand YAW: ...").
std::string parse_pose(const std::vector<std::string>& f, std::size_t first, const char* prefix, math::HeadPose& pose) {
    static const char* const kNames[6] = {"X", "Y", "Z", "YAW", "PITCH", "ROLL"};
    double v[6];
    for (int k = 0; k < 6; ++k) {
        const std::string& field = f[first + static_cast<std::size_t>(k)];
        const std::string name = std::string(prefix) + kNames[k];
        const NumberText n = read_number_text(field);
        if (!n.problem.empty()) return name + ": '" + printable(field, kQuotedCharacters) + "' " + n.problem;
        v[k] = n.value;
        if (std::abs(v[k]) > 1e6)
            return name + ": " + printable(field, kQuotedCharacters) + " is out of range (|" + kNames[k] +
                   "| <= " + (k < 3 ? "1e6 m" : "1e6 degrees") + ")";
    }
    pose = math::HeadPose{{v[0], v[1], v[2]}, v[3], v[4], v[5]};
    return {};
}

// One line's fields as a frame: 6 numbers (the head) or 18 (the head, the
// left hand, the right hand); an empty string or the message.
std::string parse_frame(const std::vector<std::string>& f, PathFrame& frame) {
    if (f.size() != 6 && f.size() != 18)
        return "expected 6 or 18 numbers (X Y Z YAW PITCH ROLL of the head, then of the left and the right hand), "
               "found " +
               std::to_string(f.size()) + " fields";
    if (std::string message = parse_pose(f, 0, "", frame.head); !message.empty()) return message;
    frame.hands.reset();
    if (f.size() == 6) return {};
    std::array<math::HeadPose, 2> hands{};
    if (std::string message = parse_pose(f, 6, "left hand ", hands[0]); !message.empty()) return message;
    if (std::string message = parse_pose(f, 12, "right hand ", hands[1]); !message.empty()) return message;
    frame.hands = hands;
    return {};
}

// The heads of a file's frames (the readers that drop the hands).
PathFile heads_of(const PathFrames& frames) {
    if (!frames) return Error{frames.error()};
    std::vector<math::HeadPose> heads;
    heads.reserve(frames->size());
    for (const PathFrame& frame : *frames) heads.push_back(frame.head);
    return heads;
}

}  // namespace

PathFrames read_path_frames_stream(std::istream& in, const std::string& name) {
    std::vector<PathFrame> frames;
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
        PathFrame frame;
        if (const std::string message = parse_frame(f, frame); !message.empty()) return fail(message);
        frames.push_back(frame);
    }
    if (in.bad()) {
        ++number;
        return fail("read error");
    }
    if (frames.empty()) return Error{name + ": the path file holds no poses"};
    return frames;
}

PathFrames read_path_frames_file(const std::string& path) {
    // Through the one input reader: a size limit (so /dev/zero fails fast
    // instead of filling memory) and no waiting forever on a FIFO.
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path, kMaxPathFileBytes, false);
    if (!bytes) return Error{path + ": " + bytes.error()};
    std::istringstream in(std::string(bytes->begin(), bytes->end()));
    return read_path_frames_stream(in, path);
}

PathFile read_path_stream(std::istream& in, const std::string& name) {
    return heads_of(read_path_frames_stream(in, name));
}

PathFile read_path_file(const std::string& path) { return heads_of(read_path_frames_file(path)); }

}  // namespace impossible::layout
