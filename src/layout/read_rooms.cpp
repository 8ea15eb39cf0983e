#include <algorithm>
#include <array>
#include <map>
#include <memory>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"

namespace impossible::layout::detail {

namespace {

// The index of a face named as in `face_colors`, or -1.
int face_index(const std::string& key) {
    for (int f = 0; f < kFaceCount; ++f)
        if (key == kFaceNames[static_cast<std::size_t>(f)]) return f;
    return -1;
}

void read_face_colors(Checker& check, const Path& at, const json& value, Room& room) {
    if (!check.expect_object(at, value)) return;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string& key = it.key();
        if (!key.empty() && key.front() == '_') continue;  // a comment
        const int face = face_index(key);
        if (face < 0) {
            check.error_at_key(at / key, "unknown face " + quote(key) +
                                             " (faces are \"floor\", \"ceiling\", \"-x\", "
                                             "\"+x\", \"-z\", \"+z\")");
            continue;
        }
        if (const auto colour = check.read_colour(at / key, it.value())) {
            room.face_color[static_cast<std::size_t>(face)] = *colour;
        }
    }
}

// `textures`: a PNG or JPEG image per face, `all` for the faces without
// their own key. Each file is read once per layout (the cache shares it).
void read_textures(Checker& check, const Path& at, const json& value, assets::AssetCache& models, Room& room) {
    if (!check.expect_object(at, value)) return;
    std::array<std::shared_ptr<const image::Pixels>, kFaceCount> own{};
    std::shared_ptr<const image::Pixels> all;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string& key = it.key();
        if (!key.empty() && key.front() == '_') continue;  // a comment
        const int face = face_index(key);
        if (face < 0 && key != "all") {
            check.error_at_key(at / key, "unknown face " + quote(key) +
                                             " (textures are named by \"floor\", \"ceiling\", \"-x\", "
                                             "\"+x\", \"-z\", \"+z\" and \"all\")");
            continue;
        }
        const Path key_at = at / key;
        const auto path = check.read_string(key_at, it.value());
        if (!path) continue;
        if (path->empty()) {
            check.error(key_at, "must name a PNG or JPEG file (got an empty path)");
            continue;
        }
        if (has_control_character(*path)) {
            check.error(key_at, "the path " + quote(*path, kQuotedPathCharacters) + " contains a control character");
            continue;
        }
        const std::string resolved = models.resolve(*path);
        const Result<std::shared_ptr<const image::Pixels>>& image = models.load_image(resolved);
        if (!image) {
            check.error(key_at, "the image " + quote(resolved, kQuotedPathCharacters) + " " + image.error());
            continue;
        }
        (face < 0 ? all : own[static_cast<std::size_t>(face)]) = *image;
    }
    for (std::size_t f = 0; f < own.size(); ++f) room.face_texture[f] = own[f] != nullptr ? own[f] : all;
}

RoomDraft read_room(Checker& check, const Path& at, const json& value, assets::AssetCache& models, PropIds& prop_ids) {
    RoomDraft draft;
    draft.path = at;
    if (!check.expect_object(at, value)) return draft;
    check.check_fields(at, value,
                       {"id", "min", "max", "color", "face_colors", "checker", "textures", "texture_size", "props",
                        "ambient", "lights"},
                       {"id", "min", "max"});
    Room& room = draft.room;
    if (const json* id = field(value, "id")) {
        if (auto text = check.read_id(at / "id", *id)) {
            room.id = std::move(*text);
            draft.has_id = true;
        }
    }
    std::optional<glm::dvec3> min, max;
    if (const json* v = field(value, "min")) min = check.read_vec3(at / "min", *v, NumberKind::Coordinate);
    if (const json* v = field(value, "max")) max = check.read_vec3(at / "max", *v, NumberKind::Coordinate);
    if (min && max) {
        room.min = *min;
        room.max = *max;
        draft.box_ok = true;
        static const char* const axes[] = {"x", "y", "z"};
        for (int a = 0; a < 3 && draft.box_ok; ++a) {
            if (!((*max)[a] > (*min)[a])) {
                check.error(at / "max", std::string("must be greater than min on every axis (") + axes[a] + ": " +
                                            format_number((*max)[a]) + " <= " + format_number((*min)[a]) + ")");
                draft.box_ok = false;
            } else if ((*max)[a] - (*min)[a] < limits::kMinLength) {
                check.error(at / "max", std::string("the room is too thin (") + axes[a] + ": " +
                                            format_number((*max)[a] - (*min)[a]) + " m; the minimum is " +
                                            format_number(limits::kMinLength) + " m)");
                draft.box_ok = false;
            }
        }
    }
    glm::dvec3 colour(0.8);
    if (const json* v = field(value, "color")) {
        if (const auto c = check.read_colour(at / "color", *v)) colour = *c;
    }
    std::fill(room.face_color.begin(), room.face_color.end(), colour);
    if (const json* v = field(value, "face_colors")) read_face_colors(check, at / "face_colors", *v, room);
    if (const json* v = field(value, "checker")) {
        if (const auto c = check.read_number(at / "checker", *v, NumberKind::Length)) room.checker = *c;
    }
    if (const json* v = field(value, "textures")) read_textures(check, at / "textures", *v, models, room);
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
