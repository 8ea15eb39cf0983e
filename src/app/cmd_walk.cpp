// `impossible walk` (see cmd_walk.hpp).
#include "app/cmd_walk.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "math/pose.hpp"
#include "scene/walk.hpp"

namespace impossible::app {

namespace {

constexpr double kMaxPosition = 1e6;
constexpr double kMaxAngle = 1e6;

struct ParseError {
    int line = 0;
    std::string message;
};

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// Splits a line at spaces and tabs.
std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        std::size_t j = i;
        while (j < line.size() && !is_blank(line[j])) ++j;
        if (j > i) fields.push_back(line.substr(i, j - i));
        i = j;
    }
    return fields;
}

// Reads all poses, or the first problem.
bool read_path(std::istream& in, std::vector<math::HeadPose>& poses, ParseError& error) {
    static const char* const kNames[6] = {"X", "Y", "Z", "YAW", "PITCH", "ROLL"};
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::vector<std::string> fields = fields_of(line);
        if (fields.empty() || fields[0][0] == '#') continue;
        if (fields.size() != 6) {
            error = {number, "expected 6 numbers (X Y Z YAW PITCH ROLL), found " +
                                 std::to_string(fields.size()) + " fields"};
            return false;
        }
        double v[6];
        for (int k = 0; k < 6; ++k) {
            const std::string& f = fields[k];
            const char* first = f.data();
            if (*first == '+') ++first;  // from_chars does not take a leading '+'
            const auto [ptr, ec] = std::from_chars(first, f.data() + f.size(), v[k]);
            if (ec != std::errc() || ptr != f.data() + f.size() || !std::isfinite(v[k])) {
                error = {number, std::string(kNames[k]) + ": '" + f + "' is not a finite number"};
                return false;
            }
            const double limit = k < 3 ? kMaxPosition : kMaxAngle;
            if (std::abs(v[k]) > limit) {
                error = {number, std::string(kNames[k]) + ": " + f + " is out of range (|" +
                                     kNames[k] + "| <= " + (k < 3 ? "1e6 m" : "1e6 degrees") + ")"};
                return false;
            }
        }
        poses.push_back(math::HeadPose{{v[0], v[1], v[2]}, v[3], v[4], v[5]});
    }
    if (in.bad()) {
        error = {number + 1, "read error"};
        return false;
    }
    return true;
}

void write_vec(std::string& s, const math::dvec3& v) {
    s += '[';
    for (int k = 0; k < 3; ++k) {
        if (k) s += ',';
        s += format_number(v[k]);
    }
    s += ']';
}

}  // namespace

std::string format_number(double value) {
    if (value == 0.0) return "0";  // also -0
    char buf[64];
    const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
    if (ec != std::errc() || !std::isfinite(value)) return "null";  // never for finite input
    return std::string(buf, ptr);
}

int run_walk_stream(const layout::Layout& layout, std::istream& in, const std::string& name,
                    std::ostream& out, std::ostream& err) {
    std::vector<math::HeadPose> poses;
    ParseError error;
    if (!read_path(in, poses, error)) {
        err << name << ':' << error.line << ": " << error.message << '\n';
        return 1;
    }
    scene::Walker walker(layout);
    std::string line;
    for (std::size_t frame = 0; frame < poses.size(); ++frame) {
        const std::vector<int> passed = walker.step(poses[frame]);
        line = "{\"frame\":" + std::to_string(frame) + ",\"room\":";
        const int room = walker.room();
        line += nlohmann::json(room >= 0 && static_cast<std::size_t>(room) < layout.rooms.size()
                                   ? layout.rooms[room].id
                                   : std::string())
                    .dump();
        line += ",\"teleports\":[";
        for (std::size_t k = 0; k < passed.size(); ++k) {
            if (k) line += ',';
            line += nlohmann::json(layout.portals[passed[k]].id).dump();
        }
        line += "],\"position\":";
        write_vec(line, walker.position());
        line += ",\"forward\":";
        write_vec(line, walker.forward());
        line += "}\n";
        out << line;
    }
    out.flush();
    return 0;
}

int run_walk(const layout::Layout& layout, const std::string& path_file, std::ostream& out,
             std::ostream& err) {
    std::error_code ec;
    if (std::filesystem::is_directory(path_file, ec)) {
        err << path_file << ": is a directory, not a path file\n";
        return 1;
    }
    std::ifstream in(path_file, std::ios::binary);
    if (!in) {
        err << path_file << ": cannot open the path file\n";
        return 1;
    }
    return run_walk_stream(layout, in, path_file, out, err);
}

}  // namespace impossible::app
