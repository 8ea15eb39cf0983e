// `impossible walk` (see cmd_walk.hpp).
#include "app/cmd_walk.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
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
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"
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

// What `walk` needs for the "hands" and "props" keys (cli.md, "Time, hands
// and lights"): the layout's objects, and the props that move, in layout
// order (the indices of set.props), and their walks, kept from line to line
// (the lines' times only grow: each line walks only the keys passed since).
struct WalkObjects {
    walk::ObjectSet set;
    std::vector<int> moving;
    std::optional<walk::PropWalks> walks;  // of set
};

bool any_hands(const std::vector<layout::PathFrame>& frames) {
    return std::any_of(frames.begin(), frames.end(), [](const layout::PathFrame& f) { return f.hands.has_value(); });
}

bool any_motion(const layout::Layout& layout) {
    for (const layout::Room& room : layout.rooms)
        for (const layout::Prop& prop : room.props)
            if (!layout::prop_motion(prop).keys.empty()) return true;
    return false;
}

// None when no line has hands and no prop moves: the lines are then the
// same as before hands and motion existed, and no object set is built.
std::unique_ptr<WalkObjects> walk_objects(const layout::Layout& layout, const walk::Walker& walker,
                                          const std::vector<layout::PathFrame>& frames) {
    if (!any_hands(frames) && !any_motion(layout)) return nullptr;
    auto objects = std::make_unique<WalkObjects>();
    objects->set = walk::build_object_set(layout, walker.links());
    for (std::size_t k = 0; k < objects->set.props.size(); ++k)
        if (!objects->set.props[k].motion.keys.empty()) objects->moving.push_back(static_cast<int>(k));
    objects->walks.emplace(objects->set);
    return objects;
}

// A physical pose mapped by W (rigid): its virtual pose.
math::HeadPose virtual_pose(const math::dmat4& w, const math::HeadPose& physical) {
    const math::dvec3 position(w * math::dvec4(physical.position, 1.0));
    return math::head_pose_from(position, math::dmat3(w) * math::head_rotation(physical));
}

// `,"hands":["ROOM","ROOM"]` for a line with hands: each hand's room, walked
// from the head centre after this frame's teleports to the hand's virtual
// position.
void write_hands(std::string& line, const layout::Layout& layout, const WalkObjects& objects,
                 const walk::Walker& walker, const std::array<math::HeadPose, 2>& hands) {
    line += ",\"hands\":[";
    for (std::size_t h = 0; h < 2; ++h) {
        if (h) line += ',';
        const math::HeadPose hand = virtual_pose(walker.physical_to_virtual(), hands[h]);
        line += room_json(layout, walk::place_hand(objects.set, walker.room(), walker.position(), hand).room);
    }
    line += ']';
}

// `,"props":{"ID":"ROOM",...}`: the room of every moving prop at `time`.
void write_props(std::string& line, const layout::Layout& layout, WalkObjects& objects, double time) {
    line += ",\"props\":{";
    for (std::size_t k = 0; k < objects.moving.size(); ++k) {
        if (k) line += ',';
        const walk::DynamicProp& p = objects.set.props[static_cast<std::size_t>(objects.moving[k])];
        line +=
            nlohmann::json(layout::prop_id(
                               layout.rooms[static_cast<std::size_t>(p.room)].props[static_cast<std::size_t>(p.index)]))
                .dump();
        line += ':';
        line += room_json(layout, objects.walks->at(objects.moving[k], time).room);
    }
    line += '}';
}

// One frame's JSON line, without the newline.
std::string frame_line(const layout::Layout& layout, const walk::Walker& walker, std::size_t frame,
                       const std::vector<int>& passed) {
    std::string line = "{\"frame\":" + std::to_string(frame) + ",\"room\":" + room_json(layout, walker.room());
    line += ",\"teleports\":[";
    for (std::size_t k = 0; k < passed.size(); ++k) {
        if (k) line += ',';
        line += nlohmann::json(layout.portals[static_cast<std::size_t>(passed[k])].id).dump();
    }
    line += "],\"position\":";
    write_vec(line, walker.position());
    line += ",\"forward\":";
    write_vec(line, walker.forward());
    return line;
}

}  // namespace

int run_walk_stream(const session::Session& session, std::istream& in, const std::string& name, std::ostream& out,
                    std::ostream& err, double fps) {
    const layout::Layout& layout = session.layout();
    const layout::PathFrames path = layout::read_path_frames_stream(in, name);
    if (!path) {
        err << one_line(path.error()) << '\n';
        return 1;
    }
    const std::vector<layout::PathFrame>& frames = *path;
    walk::Walker walker = session.make_walker();
    const std::unique_ptr<WalkObjects> objects = walk_objects(layout, walker, frames);
    for (std::size_t frame = 0; frame < frames.size(); ++frame) {
        const std::vector<int> passed = walker.step(frames[frame].head);
        // The walker stops testing at the cap (a head moving absurdly far in
        // one frame, or doors that lead into each other): say so, once a frame.
        if (static_cast<int>(passed.size()) >= walk::kMaxCrossingsPerFrame)
            err << "warning: " << one_line(name, 1000) << ": frame " << frame << " reached the limit of "
                << walk::kMaxCrossingsPerFrame
                << " teleports in one frame; portals beyond it were not crossed and the room may be wrong\n";
        std::string line = frame_line(layout, walker, frame, passed);
        if (objects && frames[frame].hands) write_hands(line, layout, *objects, walker, *frames[frame].hands);
        if (objects && !objects->moving.empty()) write_props(line, layout, *objects, static_cast<double>(frame) / fps);
        line += "}\n";
        out << line;
        if (!out) break;  // standard output failed (a full disk): main reports it
    }
    out.flush();
    return 0;
}

int run_walk(const session::Session& session, const std::string& path_file, std::ostream& out, std::ostream& err,
             double fps) {
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path_file, layout::kMaxPathFileBytes, false);
    if (!bytes) {
        err << one_line(path_file + ": " + bytes.error()) << '\n';
        return 1;
    }
    std::istringstream in(std::string(bytes->begin(), bytes->end()));
    return run_walk_stream(session, in, path_file, out, err, fps);
}

}  // namespace impossible::app
