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

std::string path_text(const std::vector<math::HeadPose>& poses, const std::string& header,
                      const std::vector<PathNote>& notes) {
    std::string out;
    std::istringstream lines(header);
    for (std::string line; std::getline(lines, line);) out += "# " + line + "\n";
    out += "# X Y Z YAW PITCH ROLL (physical head poses, metres and degrees)\n";
    std::size_t next = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        for (; next < notes.size() && notes[next].first <= k; ++next) out += "# " + notes[next].second + "\n";
        const math::HeadPose& p = poses[k];
        out += number(p.position.x) + " " + number(p.position.y) + " " + number(p.position.z) + " " +
               number(p.yaw_deg) + " " + number(p.pitch_deg) + " " + number(p.roll_deg) + "\n";
    }
    for (; next < notes.size(); ++next) out += "# " + notes[next].second + "\n";
    return out;
}

}  // namespace impossible::design
