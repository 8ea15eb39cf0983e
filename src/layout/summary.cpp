// The numbers `impossible validate` prints about a valid layout.
#include <cstdio>
#include <set>

#include "base/text.hpp"
#include "layout/layout.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout {

namespace {

// Whether the room's floor lies inside the play area's outline, edges
// included. A convex floor (a box's rectangle among them) is clipped to the
// area, with a tolerance relative to the floor so rooms exactly on the edge
// fit; any other floor is inside when each of its edges is.
bool floor_inside(const Room& room, const math::Polygon2& area) {
    const math::Polygon2 floor = floor_outline(room);
    if (floor_convex(room)) return math::convex_inside(floor, area, 1e-9 * (1.0 + math::area(floor)));
    for (std::size_t i = 0; i < floor.size(); ++i) {
        if (!math::segment_inside(area, floor[i], floor[(i + 1) % floor.size()])) return false;
    }
    return true;
}

}  // namespace

Summary summarize(const Layout& layout) {
    Summary s;
    s.rooms = static_cast<int>(layout.rooms.size());
    s.portals = static_cast<int>(layout.portals.size());
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const Portal& p = layout.portals[i];
        if (p.kind == PortalKind::Mirror) {
            ++s.mirrors;
            continue;
        }
        // Count each linked pair once, at its first portal (a mirror has no target).
        if (p.target <= static_cast<int>(i)) continue;
        ++s.pairs;
        ++(p.kind == PortalKind::Window ? s.window_pairs : s.door_pairs);
    }
    s.volumes = static_cast<int>(layout.volumes.size());
    std::set<const image::Pixels*> images;
    for (const Room& room : layout.rooms) {
        s.floor_area += layout::floor_area(room);
        for (const auto& texture : room.face_texture) {
            if (texture == nullptr) continue;
            ++s.textured_faces;
            images.insert(texture.get());
        }
        for (const Prop& prop : room.props) {
            if (!prop_motion(prop).keys.empty()) ++s.moving_props;
            if (const auto* gltf = std::get_if<GltfProp>(&prop)) {
                for (const assets::Texture& texture : gltf->textures) images.insert(texture.image.get());
            }
        }
    }
    s.images = static_cast<int>(images.size());
    if (layout.play_area) {
        const std::vector<glm::dvec2> area = outline(*layout.play_area);
        s.play_area_area = math::area(area);
        s.expansion_ratio = s.floor_area / *s.play_area_area;
        for (const Room& room : layout.rooms) {
            if (!floor_inside(room, area)) s.rooms_outside_play_area.push_back(room.id);
        }
    }
    return s;
}

namespace {

// "hands: ..." for a glTF model or a box other than the default; "" for the default.
std::string hands_line(const HandShape& hands) {
    char line[256];
    if (hands.model) {
        std::snprintf(line, sizeof line, ", scale %g\n", hands.model->scale);
        return "hands: the glTF model " + one_line(hands.model->path, 200) + line;
    }
    const HandShape standard;
    if (hands.box == standard.box && hands.color == standard.color) return "";
    std::snprintf(line, sizeof line, "hands: a box %g x %g x %g m, colour [%g, %g, %g]\n", hands.box.x, hands.box.y,
                  hands.box.z, hands.color.r, hands.color.g, hands.color.b);
    return line;
}

}  // namespace

std::string summary_text(const Layout& layout, const Summary& summary) {
    char line[256];
    std::string out;
    // A name may be megabytes long or hold newlines; the summary shows 200 bytes of it.
    if (!layout.name.empty()) out += "name: " + one_line(layout.name, 200) + "\n";
    out += "rooms: " + std::to_string(summary.rooms) + "\n";
    out += "portals: " + std::to_string(summary.portals) + "\n";
    out += "pairs: " + std::to_string(summary.pairs) + "\n";
    // Only doors: the lines above say it all, as they always have.
    if (summary.window_pairs > 0 || summary.mirrors > 0) {
        out += "door pairs: " + std::to_string(summary.door_pairs) + "\n";
        out += "window pairs: " + std::to_string(summary.window_pairs) + "\n";
        out += "mirrors: " + std::to_string(summary.mirrors) + "\n";
    }
    // Only with textures, so that the summaries of layouts without stay as they were.
    if (summary.images > 0) {
        out += "textures: " + std::to_string(summary.images) + (summary.images == 1 ? " image" : " images") + ", " +
               std::to_string(summary.textured_faces) + " textured room faces\n";
    }
    // Only with volumes, moving props or hands other than the default box.
    if (summary.volumes > 0) out += "volumes: " + std::to_string(summary.volumes) + "\n";
    if (summary.moving_props > 0) out += "moving props: " + std::to_string(summary.moving_props) + "\n";
    out += hands_line(layout.hands);
    if (!summary.play_area_area) {
        out += "play area: none\n";
        std::snprintf(line, sizeof line, "floor area: %.2f m2\n", summary.floor_area);
        out += line;
        out += "expansion ratio: n/a (no play area)\n";
        return out;
    }
    std::snprintf(line, sizeof line, "play area: %.2f m2\n", *summary.play_area_area);
    out += line;
    out += "rooms outside the play area:";
    if (summary.rooms_outside_play_area.empty()) out += " none";
    for (const std::string& id : summary.rooms_outside_play_area) out += " " + id;
    out += "\n";
    std::snprintf(line, sizeof line, "floor area: %.2f m2\n", summary.floor_area);
    out += line;
    std::snprintf(line, sizeof line, "expansion ratio: %.3f\n", *summary.expansion_ratio);
    out += line;
    return out;
}

}  // namespace impossible::layout
