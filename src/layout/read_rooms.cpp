#include <algorithm>
#include <array>
#include <map>
#include <memory>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout::detail {

namespace {

// A box room: `min` and `max`, max > min on every axis.
void read_box(Checker& check, const Path& at, const json& value, RoomDraft& draft) {
    std::optional<glm::dvec3> min, max;
    if (const json* v = field(value, "min")) min = check.read_vec3(at / "min", *v, NumberKind::Coordinate);
    if (const json* v = field(value, "max")) max = check.read_vec3(at / "max", *v, NumberKind::Coordinate);
    if (!min || !max) return;
    Room& room = draft.room;
    room.min = *min;
    room.max = *max;
    draft.shape_ok = true;
    static const char* const axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3 && draft.shape_ok; ++a) {
        if (!((*max)[a] > (*min)[a])) {
            check.error(at / "max", std::string("must be greater than min on every axis (") + axes[a] + ": " +
                                        format_number((*max)[a]) + " <= " + format_number((*min)[a]) + ")");
            draft.shape_ok = false;
        } else if ((*max)[a] - (*min)[a] < limits::kMinLength) {
            check.error(at / "max", std::string("the room is too thin (") + axes[a] + ": " +
                                        format_number((*max)[a] - (*min)[a]) + " m; the minimum is " +
                                        format_number(limits::kMinLength) + " m)");
            draft.shape_ok = false;
        }
    }
}

// A prism room's `floor` polygon into room.floor (its corners, as soon as
// they can be read, so that the wall keys can be checked); true if it is a
// simple polygon with walls no shorter than kMinLength.
bool read_floor(Checker& check, const Path& list, const json& corners, Room& room) {
    if (!check.expect_array(list, corners, limits::kMaxRoomCorners)) return false;
    math::Polygon2 poly;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const auto p = check.read_vec2(list / i, corners[i], NumberKind::Coordinate);
        if (!p) return false;
        poly.push_back(*p);
    }
    room.floor = poly;
    if (const auto problem = math::simple_polygon_problem(poly)) {
        const bool at_corner = poly.size() >= 3 && problem->corner > 0;
        check.error(at_corner ? list / static_cast<std::size_t>(problem->corner) : list,
                    "the floor must be a simple polygon: " + problem->message);
        return false;
    }
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const double length = glm::distance(poly[i], poly[(i + 1) % poly.size()]);
        if (length < limits::kMinLength) {
            check.error(list / ((i + 1) % poly.size()),
                        "wall " + std::to_string(i) + " is too short (corners " + std::to_string(i) + " and " +
                            std::to_string((i + 1) % poly.size()) + " are " + format_number(length) +
                            " m apart; the minimum is " + format_number(limits::kMinLength) + " m)");
            return false;
        }
    }
    return true;
}

// A prism room's `y`: [y0, y1], y1 - y0 at least kMinLength.
std::optional<glm::dvec2> read_height(Checker& check, const Path& at, const json& value) {
    if (!value.is_array() || value.size() != 2) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        check.error(at, "must be an array of 2 numbers [y0, y1] (got " + got + ")");
        return std::nullopt;
    }
    const auto y = check.read_vec2(at, value, NumberKind::Coordinate);
    if (!y) return std::nullopt;
    if (!(y->y > y->x)) {
        check.error(at, "the ceiling y1 must be above the floor y0 (" + format_number(y->y) +
                            " <= " + format_number(y->x) + ")");
        return std::nullopt;
    }
    if (y->y - y->x < limits::kMinLength) {
        check.error(at, "the room is too thin (y: " + format_number(y->y - y->x) + " m; the minimum is " +
                            format_number(limits::kMinLength) + " m)");
        return std::nullopt;
    }
    return y;
}

// A prism room (layout-format.md, "Rooms of any shape"): `floor` and `y`;
// min/max become its bounding box.
void read_prism(Checker& check, const Path& at, const json& value, RoomDraft& draft) {
    draft.prism = true;
    Room& room = draft.room;
    bool ok = true;
    for (const char* name : {"floor", "y"}) {
        if (field(value, name) == nullptr) {
            check.error(at, std::string("missing required field ") + quote(name) + " (a room with " +
                                quote(name[0] == 'f' ? "y" : "floor") + " needs it)");
            ok = false;
        }
    }
    if (const json* v = field(value, "floor")) ok = read_floor(check, at / "floor", *v, room) && ok;
    std::optional<glm::dvec2> y;
    if (const json* v = field(value, "y")) y = read_height(check, at / "y", *v);
    if (!ok || !y) return;
    room.min = room.max = glm::dvec3(room.floor[0].x, y->x, room.floor[0].y);
    for (const glm::dvec2& c : room.floor) {
        room.min = glm::min(room.min, glm::dvec3(c.x, y->x, c.y));
        room.max = glm::max(room.max, glm::dvec3(c.x, y->y, c.y));
    }
    if (math::area(room.floor) < limits::kMinLength * limits::kMinLength) {
        check.error(at / "floor",
                    "the floor is too small (its area is " + format_number(math::area(room.floor)) + " m2)");
        return;
    }
    draft.shape_ok = true;
}

// The room's shape: a box (`min`, `max`) or a prism (`floor`, `y`), never
// both.
void read_shape(Checker& check, const Path& at, const json& value, RoomDraft& draft) {
    const bool box = field(value, "min") != nullptr || field(value, "max") != nullptr;
    const char* prism_key = field(value, "floor") != nullptr ? "floor" : field(value, "y") != nullptr ? "y" : nullptr;
    if (box && prism_key != nullptr) {
        check.error_at_key(at / prism_key,
                           "a room is either a box (\"min\" and \"max\") or a prism over a floor "
                           "polygon (\"floor\" and \"y\"), never both");
        // The face keys are read for the form the room has "floor" for.
        draft.prism = field(value, "floor") != nullptr;
        return;
    }
    if (prism_key != nullptr) return read_prism(check, at, value, draft);
    for (const char* name : {"min", "max"}) {
        if (field(value, name) == nullptr) check.error(at, std::string("missing required field ") + quote(name));
    }
    read_box(check, at, value, draft);
}

RoomDraft read_room(Checker& check, const Path& at, const json& value, assets::AssetCache& models, PropIds& prop_ids) {
    RoomDraft draft;
    draft.path = at;
    if (!check.expect_object(at, value)) return draft;
    check.check_fields(at, value,
                       {"id", "min", "max", "floor", "y", "color", "face_colors", "checker", "textures", "texture_size",
                        "props", "ambient", "lights"},
                       {"id"});
    Room& room = draft.room;
    if (const json* id = field(value, "id")) {
        if (auto text = check.read_id(at / "id", *id)) {
            room.id = std::move(*text);
            draft.has_id = true;
        }
    }
    // The shape first: the face keys depend on it, whatever the key order.
    read_shape(check, at, value, draft);
    glm::dvec3 colour(0.8);
    if (const json* v = field(value, "color")) {
        if (const auto c = check.read_colour(at / "color", *v)) colour = *c;
    }
    room.face_color.assign(static_cast<std::size_t>(face_count(room)), colour);
    room.face_texture.assign(static_cast<std::size_t>(face_count(room)), nullptr);
    if (const json* v = field(value, "face_colors")) read_face_colors(check, at / "face_colors", *v, draft);
    if (const json* v = field(value, "checker")) {
        if (const auto c = check.read_number(at / "checker", *v, NumberKind::Length)) room.checker = *c;
    }
    if (const json* v = field(value, "textures")) read_textures(check, at / "textures", *v, models, draft);
    if (const json* v = field(value, "texture_size")) {
        if (const auto size = check.read_number(at / "texture_size", *v, NumberKind::Length)) {
            room.texture_size = *size;
        }
    }
    if (const json* v = field(value, "props")) {
        if (check.expect_array(at / "props", *v, limits::kMaxPropsPerRoom)) {
            read_props(check, at / "props", *v, colour, models, prop_ids, room.props);
        }
    }
    return draft;
}

}  // namespace

std::vector<RoomDraft> read_rooms(Checker& check, const Path& at, const json& rooms, assets::AssetCache& models) {
    std::vector<RoomDraft> drafts;
    if (!check.expect_array(at, rooms, limits::kMaxRooms)) return drafts;
    if (rooms.empty()) {
        check.error(at, "must hold at least one room");
        return drafts;
    }
    std::map<std::string, std::size_t> first_use;
    PropIds prop_ids;  // props are unique among all the rooms' props
    for (std::size_t i = 0; i < rooms.size(); ++i) {
        RoomDraft draft = read_room(check, at / i, rooms[i], models, prop_ids);
        if (draft.has_id) {
            const auto [it, inserted] = first_use.emplace(draft.room.id, i);
            if (!inserted) {
                check.error(at / i / "id", "duplicate room id " + quote(draft.room.id) + " (also used by rooms[" +
                                               std::to_string(it->second) + "])");
            }
        }
        drafts.push_back(std::move(draft));
    }
    return drafts;
}

}  // namespace impossible::layout::detail
