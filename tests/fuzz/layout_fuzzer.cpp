// libFuzzer entry point for the layout loader (built with
// -DIMPOSSIBLE_FUZZER=ON and clang). Any input must give either a layout or
// errors, each one line without control characters and valid UTF-8
// (fuzz_check.hpp), never a crash, hang or leak. Texture and glTF paths
// resolve against the current directory: scripts/fuzz.sh runs it where
// gallery/ and models/ are copies of layouts/'s. Seeds: fuzz/layout_corpus.
// A layout it accepts must keep the promises check_layout lists.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "fuzz_check.hpp"
#include "layout/layout.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace {

using impossible::fuzz::require;
namespace layout = impossible::layout;

// What the loader promises of a prism room (layout-format.md, "Rooms of any
// shape"): a simple floor polygon whose bounding box is min/max in x and z,
// and one colour and texture slot per face.
void check_room_shape(const layout::Room& room) {
    const auto faces = static_cast<std::size_t>(layout::face_count(room));
    require(room.face_color.size() == faces && room.face_texture.size() == faces, "one colour and texture per face");
    if (!layout::is_prism(room)) return;
    require(!impossible::math::simple_polygon_problem(room.floor), "a prism's floor is a simple polygon");
    glm::dvec2 lo = room.floor[0], hi = room.floor[0];
    for (const glm::dvec2& c : room.floor) lo = glm::min(lo, c), hi = glm::max(hi, c);
    require(lo == glm::dvec2(room.min.x, room.min.z) && hi == glm::dvec2(room.max.x, room.max.z),
            "a prism's min/max is its floor's bounding box");
    require(room.max.y > room.min.y, "a prism has a height");
}

// What the loader promises of a layout it accepts: paired portals name each
// other within Layout::portals (the volumes left out), a volume shows a room
// without portals, motions start at 0 and increase, moving props have ids and
// prop ids are unique; prism rooms are sound, and holes name a face.
void check_layout(const layout::Layout& l) {
    const int portals = static_cast<int>(l.portals.size());
    const int rooms = static_cast<int>(l.rooms.size());
    std::vector<bool> has_portal(l.rooms.size(), false);
    for (int i = 0; i < portals; ++i) {
        const layout::Portal& p = l.portals[static_cast<std::size_t>(i)];
        require(p.room >= 0 && p.room < rooms, "a portal's room is a room");
        has_portal[static_cast<std::size_t>(p.room)] = true;
        require(p.hole_face >= -1 && p.hole_face < layout::face_count(l.rooms[static_cast<std::size_t>(p.room)]),
                "a hole is in a face of the portal's room");
        if (p.kind == layout::PortalKind::Mirror) continue;
        require(p.target >= 0 && p.target < portals && l.portals[static_cast<std::size_t>(p.target)].target == i,
                "paired portals name each other");
    }
    for (const layout::Volume& v : l.volumes) {
        require(v.room >= 0 && v.room < rooms, "a volume's room is a room");
        has_portal[static_cast<std::size_t>(v.room)] = true;
    }
    for (const layout::Volume& v : l.volumes) {
        require(v.target_room >= 0 && v.target_room < rooms, "a volume's target is a room");
        require(!has_portal[static_cast<std::size_t>(v.target_room)], "a volume's target room has no portals");
        require(v.rect.width > 0 && v.rect.height > 0 && v.rect.depth > 0, "a volume has a size");
    }
    std::set<std::string> ids;
    for (const layout::Room& room : l.rooms) {
        for (const layout::Prop& prop : room.props) {
            const std::string& id = layout::prop_id(prop);
            require(id.empty() || ids.insert(id).second, "prop ids are unique");
            const layout::Motion& m = layout::prop_motion(prop);
            if (m.keys.empty()) continue;
            require(!id.empty(), "a moving prop has an id");
            require(m.keys[0].t == 0.0, "a motion starts at 0");
            for (std::size_t k = 1; k < m.keys.size(); ++k) require(m.keys[k].t > m.keys[k - 1].t, "times increase");
            require(!m.loop || m.keys.size() >= 2, "a loop has two keys");
        }
    }
    for (const layout::Room& room : l.rooms) check_room_shape(room);
    for (const layout::Room& room : l.rooms) {
        const bool lit = l.lighting == layout::Lighting::Lights;
        require(lit || room.lights.empty(), "a fixed layout has no lights");
        for (const layout::Light& light : room.lights) {
            const double tolerance = 1e-9 * (1.0 + glm::length(light.position));
            for (int a = 0; a < 3; ++a) {
                require(light.position[a] - room.min[a] > tolerance && room.max[a] - light.position[a] > tolerance,
                        "a light is strictly inside its room");
            }
            if (layout::is_prism(room)) {
                const glm::dvec2 p{light.position.x, light.position.z};
                require(impossible::math::contains(room.floor, p, 0.0) &&
                            impossible::math::distance_to_boundary(room.floor, p) > tolerance,
                        "a light is strictly inside its prism");
            }
            require(light.intensity > 0 && light.range >= 0, "a light shines");
            require(!light.spot || (light.spot->inner_deg >= 0 && light.spot->outer_deg > light.spot->inner_deg &&
                                    light.spot->outer_deg <= 90),
                    "a spot's cone is 0 <= inner < outer <= 90");
        }
    }
    require(l.light_depth >= 0 && l.light_depth <= layout::kMaxLightDepth, "light_depth is in 0..16");
    if (l.hands.model) require(l.hands.model->scale > 0, "a hand model has a scale");
    require(l.hands.box.x > 0 && l.hands.box.y > 0 && l.hands.box.z > 0, "a hand box has a size");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const impossible::layout::LoadResult result = impossible::layout::load_layout_text(text, "fuzz.json", ".");
    impossible::fuzz::require(result.layout.has_value() == result.errors.empty(),
                              "a layout, or errors, never both or neither");
    for (const impossible::layout::Diagnostic& d : result.errors) {
        impossible::fuzz::require(!d.message.empty(), "a diagnostic with a message");
        impossible::fuzz::require_clean_line(d.str());
    }
    if (result.layout) check_layout(*result.layout);
    return 0;
}
