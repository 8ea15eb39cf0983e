// load_layout_file / load_layout_text: the top level of a layout, and the
// assembly of a Layout once every part has been read without error.
#include <algorithm>
#include <filesystem>
#include <new>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/json_doc.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout {

namespace {

using detail::Checker;
using detail::field;
using detail::json;
using detail::NumberKind;
using detail::Path;
using impossible::quote;

// The Path of a JSON pointer, for messages about keys found by the scanner.
Path path_of_pointer(const json& root, const std::string& pointer) {
    Path path;
    const json* node = &root;
    std::size_t begin = 1;
    while (begin <= pointer.size() && !pointer.empty()) {
        std::size_t end = pointer.find('/', begin);
        if (end == std::string::npos) end = pointer.size();
        std::string token = pointer.substr(begin, end - begin);
        for (std::size_t i = 0; (i = token.find('~', i)) != std::string::npos; ++i) {
            token.replace(i, 2, token.compare(i, 2, "~1") == 0 ? "/" : "~");
        }
        if (node != nullptr && node->is_array()) {
            const std::size_t index = std::stoul(token);
            path = path / index;
            node = index < node->size() ? &(*node)[index] : nullptr;
        } else {
            path = path / token;
            node = node != nullptr ? field(*node, token.c_str()) : nullptr;
            if (node != nullptr && !node->is_structured()) node = nullptr;
        }
        begin = end + 1;
    }
    return path;
}

// The polygon form: {"polygon": [[x, z], ...]}, at least 3 corners, no
// repeated corner, no self-intersection (math/polygon.hpp).
std::optional<PlayArea> read_play_polygon(Checker& check, const Path& at, const json& value) {
    check.check_fields(at, value, {"polygon"}, {"polygon"});
    const Path list = at / "polygon";
    const json& corners = value.at("polygon");
    if (!check.expect_array(list, corners, limits::kMaxPlayAreaCorners)) return std::nullopt;
    PlayArea area;
    bool ok = true;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        if (const auto p = check.read_vec2(list / i, corners[i], NumberKind::Coordinate)) {
            area.polygon.push_back(*p);
        } else {
            ok = false;
        }
    }
    if (!ok) return std::nullopt;
    if (const auto problem = math::simple_polygon_problem(area.polygon)) {
        const bool at_corner = area.polygon.size() >= 3 && problem->corner > 0;
        check.error(at_corner ? list / static_cast<std::size_t>(problem->corner) : list,
                    "the play area must be a simple polygon: " + problem->message);
        return std::nullopt;
    }
    if (math::area(area.polygon) < limits::kMinLength * limits::kMinLength) {
        check.error(list,
                    "the play area is too small (its area is " + format_number(math::area(area.polygon)) + " m2)");
        return std::nullopt;
    }
    area.min = area.max = area.polygon[0];
    for (const glm::dvec2& p : area.polygon) {
        area.min = glm::min(area.min, p);
        area.max = glm::max(area.max, p);
    }
    return area;
}

std::optional<PlayArea> read_play_area(Checker& check, const Path& at, const json& value) {
    if (!check.expect_object(at, value)) return std::nullopt;
    if (field(value, "polygon") != nullptr) return read_play_polygon(check, at, value);
    check.check_fields(at, value, {"min", "max"}, {"min", "max"});
    std::optional<glm::dvec2> min, max;
    if (const json* v = field(value, "min")) min = check.read_vec2(at / "min", *v, NumberKind::Coordinate);
    if (const json* v = field(value, "max")) max = check.read_vec2(at / "max", *v, NumberKind::Coordinate);
    if (!min || !max) return std::nullopt;
    static const char* const axes[] = {"x", "z"};
    for (int a = 0; a < 2; ++a) {
        if (!((*max)[a] > (*min)[a])) {
            check.error(at / "max", std::string("must be greater than min on both axes (") + axes[a] + ": " +
                                        format_number((*max)[a]) + " <= " + format_number((*min)[a]) + ")");
            return std::nullopt;
        }
        if ((*max)[a] - (*min)[a] < limits::kMinLength) {
            check.error(at / "max", std::string("the play area is too small (") + axes[a] + ": " +
                                        format_number((*max)[a] - (*min)[a]) + " m; the minimum is " +
                                        format_number(limits::kMinLength) + " m)");
            return std::nullopt;
        }
    }
    return PlayArea{*min, *max, {}};
}

struct StartDraft {
    Start start;
    std::optional<std::string> room_id;
    bool ok = false;
};

StartDraft read_start(Checker& check, const Path& at, const json& value) {
    StartDraft draft;
    if (!check.expect_object(at, value)) return draft;
    draft.ok = check.check_fields(at, value, {"room", "position", "yaw_deg"}, {"room", "position"});
    if (const json* v = field(value, "room")) draft.room_id = check.read_string(at / "room", *v);
    if (const json* v = field(value, "position")) {
        if (const auto p = check.read_vec3(at / "position", *v, NumberKind::Coordinate)) {
            draft.start.position = *p;
        } else {
            draft.ok = false;
        }
    }
    if (const json* v = field(value, "yaw_deg")) {
        if (const auto yaw = check.read_number(at / "yaw_deg", *v, NumberKind::Angle)) {
            draft.start.yaw_deg = *yaw;
        } else {
            draft.ok = false;
        }
    }
    draft.ok = draft.ok && draft.room_id.has_value();
    return draft;
}

// "format", "version", "name" and "play_area" of the layout object `root`.
void read_header(Checker& check, const json& root, Layout& layout) {
    const Path top;
    if (const json* v = field(root, "format")) {
        if (const auto format = check.read_string(top / "format", *v)) {
            if (*format != "impossible-layout") {
                check.error(top / "format", "must be \"impossible-layout\" (got " + quote(*format) + ")");
            }
        }
    }
    if (const json* v = field(root, "version")) {
        if (!v->is_number()) {
            check.error(top / "version", "must be the number 1 (got " + detail::json_type_name(*v) + ")");
        } else if (v->get<double>() != 1.0) {
            check.error(top / "version",
                        "unsupported version " + format_number(v->get<double>()) + " (this program reads version 1)");
        }
    }
    if (const json* v = field(root, "name")) {
        if (auto name = check.read_string(top / "name", *v)) layout.name = std::move(*name);
    }
    if (const json* v = field(root, "play_area")) layout.play_area = read_play_area(check, top / "play_area", *v);
}

// The start's room, found by its id; a warning when the head starts
// outside it.
void link_start(Checker& check, StartDraft& start, const std::vector<detail::RoomDraft>& rooms, bool rooms_known) {
    if (!start.room_id) return;
    const Path top;
    const auto room_index = detail::index_by_id(rooms);
    const auto it = room_index.find(*start.room_id);
    if (it == room_index.end()) {
        if (rooms_known) check.error(top / "start" / "room", "no room has the id " + quote(*start.room_id));
        start.ok = false;
        return;
    }
    start.start.room = it->second;
    const detail::RoomDraft& room = rooms[static_cast<std::size_t>(it->second)];
    if (start.ok && room.shape_ok && !room_contains(room.room, start.start.position)) {
        check.warning(top / "start" / "position", "the head starts outside its room " + quote(room.room.id));
    }
}

// The doors, mirrors and windows into layout.portals (their targets
// renumbered without the volumes between them), the volumes into
// layout.volumes.
void add_portals(std::vector<detail::PortalDraft>& portals, Layout& layout) {
    const std::vector<int> index = detail::paired_indices(portals);
    for (detail::PortalDraft& draft : portals) {
        Portal& p = draft.portal;
        if (draft.volume) {
            layout.volumes.push_back({std::move(p.id), p.room, p.rect, draft.target_room, p.tint});
            continue;
        }
        if (p.target >= 0) p.target = index[static_cast<std::size_t>(p.target)];
        layout.portals.push_back(std::move(p));
    }
}

// `ids_reliable`: no object repeats a key (a repeated "id" leaves which one
// counts in doubt).
void read_layout(Checker& check, const json& root, const std::string& base_dir, Layout& layout, bool ids_reliable) {
    const Path top;
    if (!root.is_object()) {
        check.error(top, "a layout must be a JSON object (got " + detail::json_type_name(root) + ")");
        return;
    }
    check.check_fields(top, root,
                       {"format", "version", "name", "play_area", "start", "rooms", "portals", "hands", "lighting",
                        "light_depth", "exposure", "changes"},
                       {"format", "version", "start", "rooms"});
    read_header(check, root, layout);

    assets::AssetCache models(base_dir);
    std::vector<detail::RoomDraft> rooms;
    if (const json* v = field(root, "rooms")) rooms = detail::read_rooms(check, top / "rooms", *v, models);
    detail::read_lighting(check, root, rooms, layout);
    StartDraft start;
    if (const json* v = field(root, "start")) start = read_start(check, top / "start", *v);
    std::vector<detail::PortalDraft> portals;
    if (const json* v = field(root, "portals")) portals = detail::read_portals(check, top / "portals", *v);
    // With a room list that could not be read whole (too long, an entry
    // without a readable id), "no room has the id" would only repeat an
    // error already reported, so it is left out.
    const bool rooms_known = ids_reliable && !rooms.empty() &&
                             std::all_of(rooms.begin(), rooms.end(), [](const auto& r) { return r.has_id; });
    detail::pair_portals(check, portals, rooms, rooms_known);
    detail::link_volumes(check, portals, rooms, rooms_known);
    detail::check_holes(check, portals, rooms);
    detail::warn_doors_facing_out(check, portals, rooms);
    link_start(check, start, rooms, rooms_known);
    std::vector<Change> changes;
    if (const json* v = field(root, "changes")) {
        changes = detail::read_changes(check, top / "changes", *v, portals, rooms, start.start.room, rooms_known,
                                       ids_reliable);
    }
    std::optional<HandShape> hands;
    if (const json* v = field(root, "hands")) hands = detail::read_hands(check, top / "hands", *v, models);
    if (!check.has_errors()) {
        detail::add_prop_lights(check, rooms, layout.lighting == Lighting::Lights, hands);
        detail::warn_lights_in_props(check, rooms);
    }

    if (check.has_errors()) return;
    layout.start = start.start;
    for (detail::RoomDraft& room : rooms) layout.rooms.push_back(std::move(room.room));
    add_portals(portals, layout);
    layout.changes = std::move(changes);
    if (hands) layout.hands = std::move(*hands);
    layout.files_read = models.files_read();
}

bool blank(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
}

Diagnostic diagnostic_at(std::string_view text, const std::string& source, std::size_t offset, std::string message) {
    const TextPosition position = text_position(text, offset);
    return {source, position.line, position.column, std::move(message)};
}

LoadResult load(std::string_view text, const std::string& source, const std::string& base_dir) {
    LoadResult result;
    if (text.size() > limits::kMaxFileBytes) {
        result.errors.push_back({source, 0, 0,
                                 "the file is too large (" + format_bytes(text.size()) + "; the limit is " +
                                     format_bytes(limits::kMaxFileBytes) + ")"});
        return result;
    }
    if (blank(text)) {
        result.errors.push_back({source, 1, 1, "the file is empty (a layout is a JSON object)"});
        return result;
    }
    detail::JsonParse parsed = detail::parse_json(text);
    if (parsed.error) {
        result.errors.push_back(diagnostic_at(text, source, parsed.error->offset, parsed.error->message));
        return result;
    }
    const detail::JsonDocument& document = *parsed.document;
    Checker check(text, source);
    for (const detail::DuplicateKey& duplicate : document.duplicates) {
        const Path at = path_of_pointer(document.root, duplicate.pointer);
        check.error_at_offset(duplicate.key, at.display + ": repeated field (an object names each field once)");
    }
    Layout layout;
    layout.source = source;
    read_layout(check, document.root, base_dir, layout, document.duplicates.empty());
    result.errors = check.take_errors();
    result.warnings = check.take_warnings();
    for (const Diagnostic& d : check.take_model_warnings()) layout.model_warnings.push_back(d.str());
    result.loud_warnings = check.take_loud_warnings();
    if (result.errors.empty()) result.layout = std::move(layout);
    return result;
}

}  // namespace

LoadResult load_layout_text(const std::string& text, const std::string& source, const std::string& base_dir) {
    try {
        return load(text, source, base_dir);
    } catch (const std::bad_alloc&) {
        return {std::nullopt, {{source, 0, 0, "out of memory while reading the layout"}}, {}, {}};
    } catch (const std::exception& e) {
        return {std::nullopt, {{source, 0, 0, "internal error: " + printable(e.what())}}, {}, {}};
    }
}

LoadResult load_layout_file(const std::string& path) {
    try {
        const Result<std::vector<unsigned char>> bytes = read_file_bytes(path, limits::kMaxFileBytes, false);
        if (!bytes) return {std::nullopt, {{path, 0, 0, "the file " + bytes.error()}}, {}, {}};
        const std::string base_dir = std::filesystem::path(path).parent_path().string();
        return load_layout_text(std::string(bytes->begin(), bytes->end()), path, base_dir);
    } catch (const std::exception& e) {
        return {std::nullopt, {{path, 0, 0, "cannot read the file: " + printable(e.what())}}, {}, {}};
    }
}

}  // namespace impossible::layout
