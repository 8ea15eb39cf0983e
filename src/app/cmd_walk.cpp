// `impossible walk` (see cmd_walk.hpp).
#include "app/cmd_walk.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/text.hpp"
#include "layout/path_file.hpp"
#include "math/pose.hpp"
#include "session/walk_driver.hpp"
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

// A room's id as a JSON string ("" for no room).
std::string room_json(const layout::Layout& layout, int room) {
    return nlohmann::json(links::valid_index(room, layout.rooms.size())
                              ? layout.rooms[static_cast<std::size_t>(room)].id
                              : std::string())
        .dump();
}

// `,"hands":["ROOM","ROOM"]` for a line with hands: each hand's room, walked
// from the head centre after this frame's teleports to the hand's virtual
// position.
void write_hands(std::string& line, const layout::Layout& layout, const std::array<session::WalkedHand, 2>& hands) {
    line += ",\"hands\":[";
    for (std::size_t h = 0; h < 2; ++h) {
        if (h) line += ',';
        line += room_json(layout, hands[h].room);
    }
    line += ']';
}

// `,"props":{"ID":"ROOM",...}`: the room of every moving prop at the line's time.
void write_props(std::string& line, const layout::Layout& layout, const std::vector<session::WalkedProp>& props) {
    line += ",\"props\":{";
    for (std::size_t k = 0; k < props.size(); ++k) {
        if (k) line += ',';
        line += nlohmann::json(*props[k].id).dump();
        line += ':';
        line += room_json(layout, props[k].room);
    }
    line += '}';
}

// One frame's JSON line, without the newline.
std::string frame_line(const layout::Layout& layout, const session::WalkedFrame& f, std::size_t frame) {
    std::string line = "{\"frame\":" + std::to_string(frame) + ",\"room\":" + room_json(layout, f.room);
    line += ",\"teleports\":[";
    for (std::size_t k = 0; k < f.teleports.size(); ++k) {
        if (k) line += ',';
        line += nlohmann::json(layout.portals[static_cast<std::size_t>(f.teleports[k])].id).dump();
    }
    line += "],\"position\":";
    write_vec(line, f.position);
    line += ",\"forward\":";
    write_vec(line, f.forward);
    if (f.hands) write_hands(line, layout, *f.hands);
    if (!f.props.empty()) write_props(line, layout, f.props);
    if (!f.changes.empty()) {
        line += ",\"changes\":[";
        for (std::size_t k = 0; k < f.changes.size(); ++k) {
            if (k) line += ',';
            line += nlohmann::json(layout.changes[static_cast<std::size_t>(f.changes[k])].id).dump();
        }
        line += ']';
    }
    return line + "}\n";
}

// The seen test's cost over a walk (--stats).
struct SeenCost {
    std::vector<double> seconds;
    int passes_max = 0;
    void add(const session::WalkDriver& driver) {
        if (!driver.seen_asked()) return;
        seconds.push_back(driver.seen_seconds());
        passes_max = std::max(passes_max, driver.seen_passes());
    }
    std::string line(std::size_t frames) {
        std::sort(seconds.begin(), seconds.end());
        const double median = seconds.empty() ? 0.0 : seconds[seconds.size() / 2];
        const double most = seconds.empty() ? 0.0 : seconds.back();
        char times[96];
        std::snprintf(times, sizeof times, " seen_us_median=%.1f seen_us_max=%.1f\n", median * 1e6, most * 1e6);
        return "stats: frames=" + std::to_string(frames) + " seen_tests=" + std::to_string(seconds.size()) +
               " seen_passes_max=" + std::to_string(passes_max) + times;
    }
};

}  // namespace

int run_walk_stream(const session::Session& session, std::istream& in, const std::string& name, std::ostream& out,
                    std::ostream& err, const WalkSettings& settings) {
    const layout::PathFrames path = layout::read_path_frames_stream(in, name);
    if (!path) {
        err << one_line(path.error()) << '\n';
        return 1;
    }
    const std::vector<layout::PathFrame>& frames = *path;
    session::WalkDriver driver(session, settings.view);
    SeenCost cost;
    for (std::size_t frame = 0; frame < frames.size(); ++frame) {
        const session::WalkedFrame f =
            driver.step(frames[frame].head, frames[frame].hands, static_cast<double>(frame) / settings.fps);
        cost.add(driver);
        // The walker stops testing at the cap (a head moving absurdly far in
        // one frame, or doors that lead into each other): say so, once a frame.
        if (static_cast<int>(f.teleports.size()) >= walk::kMaxCrossingsPerFrame)
            err << "warning: " << one_line(name, 1000) << ": frame " << frame << " reached the limit of "
                << walk::kMaxCrossingsPerFrame
                << " teleports in one frame; portals beyond it were not crossed and the room may be wrong\n";
        out << frame_line(session.layout(), f, frame);
        if (!out) break;  // standard output failed (a full disk): main reports it
    }
    out.flush();
    if (settings.stats) err << cost.line(frames.size());
    return 0;
}

int run_walk(const session::Session& session, const std::string& path_file, std::ostream& out, std::ostream& err,
             const WalkSettings& settings) {
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path_file, layout::kMaxPathFileBytes, false);
    if (!bytes) {
        err << one_line(path_file + ": " + bytes.error()) << '\n';
        return 1;
    }
    std::istringstream in(std::string(bytes->begin(), bytes->end()));
    return run_walk_stream(session, in, path_file, out, err, settings);
}

}  // namespace impossible::app
