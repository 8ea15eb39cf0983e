// `impossible walk` (see cmd_walk.hpp).
#include "app/cmd_walk.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/text.hpp"
#include "layout/path_file.hpp"
#include "math/pose.hpp"
#include "walk/walker.hpp"

namespace impossible::app {

namespace {

void write_vec(std::string& s, const math::dvec3& v) {
    s += '[';
    for (int k = 0; k < 3; ++k) {
        if (k) s += ',';
        s += format_number(v[k]);
    }
    s += ']';
}

}  // namespace

int run_walk_stream(const layout::Layout& layout, std::istream& in, const std::string& name, std::ostream& out,
                    std::ostream& err) {
    const layout::PathFile path = layout::read_path_stream(in, name);
    if (!path) {
        err << one_line(path.error()) << '\n';
        return 1;
    }
    const std::vector<math::HeadPose>& poses = *path;
    walk::Walker walker(layout);
    std::string line;
    for (std::size_t frame = 0; frame < poses.size(); ++frame) {
        const std::vector<int> passed = walker.step(poses[frame]);
        // The walker stops testing at the cap (a head moving absurdly far in
        // one frame, or doors that lead into each other): say so, once a frame.
        if (static_cast<int>(passed.size()) >= walk::kMaxCrossingsPerFrame)
            err << "warning: " << one_line(name, 1000) << ": frame " << frame << " reached the limit of "
                << walk::kMaxCrossingsPerFrame
                << " teleports in one frame; portals beyond it were not crossed and the room may be wrong\n";
        line = "{\"frame\":" + std::to_string(frame) + ",\"room\":";
        const int room = walker.room();
        line += nlohmann::json(room >= 0 && static_cast<std::size_t>(room) < layout.rooms.size() ? layout.rooms[room].id
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
        if (!out) break;  // standard output failed (a full disk): main reports it
    }
    out.flush();
    return 0;
}

int run_walk(const layout::Layout& layout, const std::string& path_file, std::ostream& out, std::ostream& err) {
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path_file, layout::kMaxPathFileBytes, false);
    if (!bytes) {
        err << one_line(path_file + ": " + bytes.error()) << '\n';
        return 1;
    }
    std::istringstream in(std::string(bytes->begin(), bytes->end()));
    return run_walk_stream(layout, in, path_file, out, err);
}

}  // namespace impossible::app
