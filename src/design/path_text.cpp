// Path files in and out; see path_text.hpp.
#include "design/path_text.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace impossible::design {
namespace {

std::string number(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4f", v);
    std::string s = text;
    if (s == "-0.0000") s = "0.0000";
    return s;
}

}  // namespace

std::string path_text(const std::vector<math::HeadPose>& poses, const std::string& header) {
    std::string out;
    std::istringstream lines(header);
    for (std::string line; std::getline(lines, line);) out += "# " + line + "\n";
    out += "# X Y Z YAW PITCH ROLL (physical head poses, metres and degrees)\n";
    for (const math::HeadPose& p : poses) {
        out += number(p.position.x) + " " + number(p.position.y) + " " + number(p.position.z) + " " +
               number(p.yaw_deg) + " " + number(p.pitch_deg) + " " + number(p.roll_deg) + "\n";
    }
    return out;
}

Result<std::vector<math::HeadPose>> read_path(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return Error{file + ": cannot open the path file"};
    std::vector<math::HeadPose> poses;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream fields(line);
        std::string first;
        if (!(fields >> first) || first[0] == '#') continue;
        fields.str(line);
        fields.clear();
        double v[6];
        std::string extra;
        for (double& x : v) fields >> x;
        if (fields.fail() || (fields >> extra) || !std::isfinite(v[0] + v[1] + v[2] + v[3] + v[4] + v[5]))
            return Error{file + ":" + std::to_string(number) + ": expected 6 numbers X Y Z YAW PITCH ROLL"};
        poses.push_back(math::HeadPose{{v[0], v[1], v[2]}, v[3], v[4], v[5]});
    }
    if (in.bad()) return Error{file + ": read error"};
    if (poses.empty()) return Error{file + ": the path file holds no poses"};
    return poses;
}

}  // namespace impossible::design
