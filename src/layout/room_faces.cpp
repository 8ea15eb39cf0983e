// A room's `face_colors` and `textures` (layout-format.md, "Rooms" and "Rooms
// of any shape"): the keys that name its faces. A box room's faces are
// "floor", "ceiling", "-x", "+x", "-z", "+z"; a prism room's are "floor",
// "ceiling", "walls" (every wall) and "wall0", "wall1", … (one wall each).
// `textures` also takes "all". Precedence, most specific first: a face's own
// key, then "walls" (walls only), then "all" (textures) or `color`.
#include <algorithm>
#include <optional>
#include <vector>

#include "base/file_io.hpp"
#include "base/user_text.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"

namespace impossible::layout::detail {

namespace {

// What a key names in one room.
struct FaceKey {
    int face = -1;        // one face (a Face, or 2 + wall for a prism)
    bool walls = false;   // "walls"
    bool all = false;     // "all" (textures only)
    std::string problem;  // the key is an error: this message
};

// "wall" followed by a whole number without leading zeros (up to 9 digits),
// or -1.
long long wall_number(const std::string& key) {
    if (key.size() <= 4 || key.size() > 13 || key.compare(0, 4, "wall") != 0) return -1;
    if (key[4] == '0' && key.size() > 5) return -1;
    long long n = 0;
    for (std::size_t i = 4; i < key.size(); ++i) {
        if (key[i] < '0' || key[i] > '9') return -1;
        n = n * 10 + (key[i] - '0');
    }
    return n;
}

// "wall0" to "wallK" for `walls` walls ("wall0", "wall1", … if unknown).
std::string wall_keys(int walls) {
    if (walls < 0) return "\"wall0\", \"wall1\", …";
    if (walls <= 1) return "\"wall0\"";
    return "\"wall0\" to " + quote("wall" + std::to_string(walls - 1));
}

// The faces a prism room's keys may name.
std::string prism_keys(int walls, bool textures) {
    return "\"floor\", \"ceiling\", \"walls\", " + wall_keys(walls) + (textures ? " and \"all\"" : "");
}

std::string box_keys(bool textures) {
    return textures ? "\"floor\", \"ceiling\", \"-x\", \"+x\", \"-z\", \"+z\" and \"all\""
                    : "\"floor\", \"ceiling\", \"-x\", \"+x\", \"-z\", \"+z\"";
}

FaceKey box_face_key(const std::string& key, bool textures) {
    FaceKey k;
    for (int f = 0; f < kFaceCount; ++f)
        if (key == kFaceNames[static_cast<std::size_t>(f)]) k.face = f;
    if (k.face >= 0 || (textures && key == "all")) {
        k.all = k.face < 0;
        return k;
    }
    if (key == "walls" || wall_number(key) >= 0) {
        k.problem = "the face " + quote(key) + " is only for a room with a floor polygon (\"floor\" and \"y\"); " +
                    "a box room's faces are " + box_keys(textures);
    } else if (textures) {
        k.problem = "unknown face " + quote(key) + " (textures are named by " + box_keys(true) + ")";
    } else {
        k.problem = "unknown face " + quote(key) + " (faces are " + box_keys(false) + ")";
    }
    return k;
}

// `walls`: the prism's wall count, -1 if its floor could not be read.
FaceKey prism_face_key(const std::string& key, int walls, bool textures) {
    FaceKey k;
    const long long n = wall_number(key);
    if (key == "floor" || key == "ceiling") {
        k.face = key == "floor" ? static_cast<int>(Face::Floor) : static_cast<int>(Face::Ceiling);
    } else if (key == "walls") {
        k.walls = true;
    } else if (textures && key == "all") {
        k.all = true;
    } else if (n >= 0 && (walls < 0 || n < walls)) {
        k.face = walls < 0 ? -1 : 2 + static_cast<int>(n);
    } else if (n >= 0) {
        k.problem = "there is no wall " + quote(key) + ": the room's floor has " + std::to_string(walls) +
                    " corners, so its walls are " + wall_keys(walls);
    } else {
        const bool box_key =
            std::any_of(kFaceNames.begin() + 2, kFaceNames.end(), [&](const char* b) { return key == b; });
        k.problem = (box_key ? "the face " + quote(key) + " is only for a box room (\"min\" and \"max\"); "
                             : "unknown face " + quote(key) + "; ") +
                    "a room with a floor polygon has the faces " + prism_keys(walls, textures);
    }
    return k;
}

FaceKey face_key(const RoomDraft& draft, const std::string& key, bool textures) {
    // Without a readable floor the walls are not known.
    const int walls = draft.room.floor.empty() ? -1 : static_cast<int>(draft.room.floor.size());
    return draft.prism ? prism_face_key(key, walls, textures) : box_face_key(key, textures);
}

// Which value a face takes: its own, else "walls" for a wall, else the
// fallback (`all`, or nothing).
template <class T>
std::optional<T> pick(const RoomDraft& draft, int face, const std::vector<std::optional<T>>& own,
                      const std::optional<T>& walls, const std::optional<T>& fallback) {
    if (own[static_cast<std::size_t>(face)]) return own[static_cast<std::size_t>(face)];
    if (draft.prism && face >= 2 && walls) return walls;
    return fallback;
}

}  // namespace

void read_face_colors(Checker& check, const Path& at, const json& value, RoomDraft& draft) {
    Room& room = draft.room;
    if (!check.expect_object(at, value)) return;
    std::vector<std::optional<glm::dvec3>> own(room.face_color.size());
    std::optional<glm::dvec3> walls;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string& key = it.key();
        if (!key.empty() && key.front() == '_') continue;  // a comment
        const FaceKey face = face_key(draft, key, false);
        if (!face.problem.empty()) {
            check.error_at_key(at / key, face.problem);
            continue;
        }
        const auto c = check.read_colour(at / key, it.value());
        if (!c) continue;
        if (face.walls) walls = c;
        if (face.face >= 0 && static_cast<std::size_t>(face.face) < own.size())
            own[static_cast<std::size_t>(face.face)] = c;
    }
    for (std::size_t f = 0; f < own.size(); ++f) {
        room.face_color[f] = *pick(draft, static_cast<int>(f), own, walls, std::optional(room.face_color[f]));
    }
}

// `textures`: a PNG or JPEG image per face. Each file is read once per
// layout (the cache shares it).
void read_textures(Checker& check, const Path& at, const json& value, assets::AssetCache& models, RoomDraft& draft) {
    using Image = std::shared_ptr<const image::Pixels>;
    Room& room = draft.room;
    if (!check.expect_object(at, value)) return;
    std::vector<std::optional<Image>> own(room.face_texture.size());
    std::optional<Image> walls, all;
    for (auto it = value.begin(); it != value.end(); ++it) {
        const std::string& key = it.key();
        if (!key.empty() && key.front() == '_') continue;  // a comment
        const FaceKey face = face_key(draft, key, true);
        if (!face.problem.empty()) {
            check.error_at_key(at / key, face.problem);
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
        const Result<Image>& image = models.load_image(resolved);
        if (!image) {
            check.error(key_at, "the image " + quote(resolved, kQuotedPathCharacters) + " " + image.error());
            continue;
        }
        if (face.all) all = *image;
        if (face.walls) walls = *image;
        if (face.face >= 0 && static_cast<std::size_t>(face.face) < own.size())
            own[static_cast<std::size_t>(face.face)] = *image;
    }
    for (std::size_t f = 0; f < own.size(); ++f) {
        room.face_texture[f] = pick(draft, static_cast<int>(f), own, walls, all).value_or(nullptr);
    }
}

}  // namespace impossible::layout::detail
