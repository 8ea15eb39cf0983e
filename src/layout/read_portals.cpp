#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "math/conventions.hpp"

namespace impossible::layout::detail {

namespace {

// A box too shallow for an eye half an IPD behind the door's plane (see
// limits::kHalfTypicalIpd): a warning, since a larger-headed layout may want it.
void warn_if_shallow(Checker& check, const Path& at, double depth) {
    // Suggested depths, rounded up to whole millimetres.
    const double needed = std::ceil((limits::kHalfTypicalIpd + limits::kNearReversedZ) * 1e3) / 1e3;
    const double needed_standard = std::ceil((limits::kHalfTypicalIpd + limits::kNearStandard) * 1e3) / 1e3;
    if (depth < limits::kHalfTypicalIpd + limits::kNearReversedZ) {
        check.warning(at / "depth", "the box is " + format_number(depth) + " m deep: an eye half an IPD (" +
                                        format_number(limits::kHalfTypicalIpd) +
                                        " m) behind the door's plane sees out of its back; make it at least " +
                                        format_number(needed) + " m");
    } else if (depth < limits::kHalfTypicalIpd + limits::kNearStandard) {
        check.warning(at / "depth", "the box is " + format_number(depth) +
                                        " m deep: with --depth standard (near plane " +
                                        format_number(limits::kNearStandard) +
                                        " m) an eye half an IPD behind the "
                                        "door's plane sees through its back; make it at least " +
                                        format_number(needed_standard) + " m");
    }
}

// `up` (default [0, 1, 0]) made orthogonal to the unit normal `n`; false when
// it is bad or within 1° of the normal's line (reported). Without a good
// normal, only `up` itself is checked.
bool read_up(Checker& check, const Path& at, const json& value, const std::optional<glm::dvec3>& normal,
             math::PortalRect& rect) {
    glm::dvec3 up(0.0, 1.0, 0.0);
    const json* up_value = field(value, "up");
    // Without an "up", the problem is the normal (a floor or ceiling portal).
    const Path up_at = up_value ? at / "up" : at / "normal";
    if (up_value) {
        const auto u = read_direction(check, up_at, *up_value);
        if (!u) return false;
        up = *u;
    }
    if (!normal) return false;
    const glm::dvec3& n = *normal;
    // The angle between the line of `up` and the normal must exceed 1°.
    const glm::dvec3 u = glm::normalize(up);
    const double cosine = std::min(1.0, std::abs(glm::dot(u, n)));
    const double angle = std::acos(cosine) * 180.0 / math::kPi;
    if (!(angle > limits::kMinUpAngleDeg)) {
        const std::string angles = "(the angle between them is " + format_number(angle) + "°; it must exceed " +
                                   format_number(limits::kMinUpAngleDeg) + "°)";
        check.error(up_at, up_value
                               ? "must not be parallel to the normal " + angles
                               : "is parallel to the default up [0, 1, 0] " + angles + "; give the portal an \"up\"");
        return false;
    }
    rect.normal = n;
    rect.up = glm::normalize(u - glm::dot(u, n) * n);
    return true;
}

// What a portal's `depth` is: none (a mirror or a window: 0, not read), a
// box's (default kDefaultDepth; for a door, too shallow for an eye is a
// warning; Box: a portal of unknown kind) or a volume's extent along its
// normal (required).
enum class DepthRule { None, Box, DoorBox, Volume };

// centre, size, depth, normal and up; false if any is missing or bad
// (reported).
bool read_rect(Checker& check, const Path& at, const json& value, DepthRule rule, math::PortalRect& rect) {
    bool ok = true;
    const auto take = [&ok](auto&& optional, auto& out) {
        if (optional) {
            out = *optional;
        } else {
            ok = false;
        }
    };
    const json* center = field(value, "center");
    const json* normal = field(value, "normal");
    const json* width = field(value, "width");
    const json* height = field(value, "height");
    ok = center && normal && width && height;
    if (center) take(check.read_vec3(at / "center", *center, NumberKind::Coordinate), rect.center);
    if (width) take(check.read_number(at / "width", *width, NumberKind::Length), rect.width);
    if (height) take(check.read_number(at / "height", *height, NumberKind::Length), rect.height);
    rect.depth = rule == DepthRule::DoorBox || rule == DepthRule::Box ? limits::kDefaultDepth : 0.0;
    const json* depth_value = field(value, "depth");
    if (rule == DepthRule::Volume && depth_value == nullptr) ok = false;  // reported as missing
    if (depth_value != nullptr && rule != DepthRule::None) {
        const std::optional<double> depth = check.read_number(at / "depth", *depth_value, NumberKind::Length);
        if (depth && rule == DepthRule::DoorBox) warn_if_shallow(check, at, *depth);
        take(depth, rect.depth);
    }
    const std::optional<glm::dvec3> n = normal ? read_normal(check, at / "normal", *normal) : std::nullopt;
    const bool up_ok = read_up(check, at, value, n, rect);
    return ok && n && up_ok;
}

// `kind`: "door", "mirror", "window" or "volume" (`volume` set); false for
// anything else (reported).
bool read_kind(Checker& check, const Path& at, const json& value, PortalKind& kind, bool& volume) {
    const std::optional<std::string> name = check.read_string(at, value);
    if (!name) return false;
    if (*name == "volume") {
        volume = true;
        return true;
    }
    for (const PortalKind k : {PortalKind::Door, PortalKind::Mirror, PortalKind::Window}) {
        if (*name == kind_name(k)) {
            kind = k;
            return true;
        }
    }
    check.error(at, "unknown kind " + quote(*name) +
                        " (the kinds are \"door\", the default, \"mirror\", \"window\" and \"volume\")");
    return false;
}

// A field the portal's kind does not have (layout-format.md, "Mirrors and
// windows"): an error at its key, saying what to do instead.
void check_kind_fields(Checker& check, const Path& at, const json& value, PortalKind kind, bool volume) {
    const auto refuse = [&](const char* name, const std::string& message) {
        if (field(value, name) != nullptr) check.error_at_key(at / name, message);
    };
    if (volume) {
        refuse("reflectance", "a volume has no reflectance (it shows its target room, times its \"tint\"); remove it");
        return;
    }
    switch (kind) {
        case PortalKind::Door:
            refuse("tint",
                   "a door has no tint (only mirrors and windows tint the light); remove it, or set "
                   "\"kind\" to \"mirror\" or \"window\"");
            refuse("reflectance",
                   "a door has no reflectance (only a window's glass reflects); remove it, or set "
                   "\"kind\" to \"window\"");
            break;
        case PortalKind::Mirror:
            refuse("reflectance",
                   "a mirror has no reflectance (it reflects all the light, times its \"tint\"); "
                   "remove it, or set \"kind\" to \"window\" for glass that shows its target "
                   "and reflects a share");
            refuse("depth",
                   "a mirror has no depth (it has no box, only its rectangle in a face of its room); "
                   "remove it");
            refuse("target",
                   "a mirror has no target (it reflects its own room); remove it, or set \"kind\" "
                   "to \"window\" to look into the target's room");
            break;
        case PortalKind::Window:
            refuse("depth",
                   "a window has no depth (it has no box, only its rectangle in a face of its room); "
                   "remove it");
            break;
    }
}

PortalDraft read_portal(Checker& check, const Path& at, const json& value) {
    PortalDraft draft;
    draft.path = at;
    if (!check.expect_object(at, value)) return draft;
    Portal& portal = draft.portal;
    if (const json* v = field(value, "kind")) {
        draft.has_kind = true;
        draft.kind_ok = read_kind(check, at / "kind", *v, portal.kind, draft.volume);
    }
    // With an unknown kind, which fields belong is unknown: only the fields
    // every kind has are required, and none is refused.
    const bool volume = draft.kind_ok && draft.volume;
    const bool door = draft.kind_ok && !volume && portal.kind == PortalKind::Door;
    const bool mirror = draft.kind_ok && portal.kind == PortalKind::Mirror;
    const bool window = draft.kind_ok && portal.kind == PortalKind::Window;
    const std::initializer_list<const char*> known = {"id",     "room",  "center", "normal", "up",   "width",
                                                      "height", "depth", "kind",   "target", "tint", "reflectance"};
    if (volume) {
        check.check_fields(at, value, known, {"id", "room", "center", "normal", "width", "height", "depth"});
    } else {
        check.check_fields(at, value, known, {"id", "room", "center", "normal", "width", "height"});
    }
    if (field(value, "target") == nullptr) {
        if (volume) check.error(at, "missing required field \"target\" (the id of the room a volume shows)");
        if (door) check.error(at, "missing required field \"target\" (the id of the door it leads to)");
        if (window) {
            check.error(at,
                        "missing required field \"target\" (a window is one of a pair: the id of the window "
                        "whose room it shows)");
        }
    }
    if (draft.kind_ok) check_kind_fields(check, at, value, portal.kind, volume);
    if (const json* v = field(value, "id")) {
        if (auto id = check.read_id(at / "id", *v)) {
            portal.id = std::move(*id);
            draft.has_id = true;
        }
    }
    if (const json* v = field(value, "room")) draft.room_id = check.read_string(at / "room", *v);
    if (const json* v = field(value, "target"); v && !mirror) draft.target_id = check.read_string(at / "target", *v);
    if (const json* v = field(value, "tint"); v && !door) {
        if (const auto tint = check.read_colour(at / "tint", *v)) portal.tint = *tint;
    }
    if (const json* v = field(value, "reflectance"); v && !door && !mirror && !volume) {
        if (const auto r = check.read_number(at / "reflectance", *v, NumberKind::Fraction)) portal.reflectance = *r;
    }
    DepthRule depth = door ? DepthRule::DoorBox : DepthRule::Box;
    if (mirror || window) depth = DepthRule::None;
    if (volume) depth = DepthRule::Volume;
    draft.rect_ok = read_rect(check, at, value, depth, portal.rect);
    return draft;
}

// A pair's kinds and sizes, checked at its later portal `draft`.
void check_pair(Checker& check, const PortalDraft& draft, const PortalDraft& other) {
    if (draft.kind_ok && other.kind_ok && draft.portal.kind != other.portal.kind) {
        // At the "kind" that differs, or at the target of a door by default.
        const std::string kind = kind_name(draft.portal.kind);
        const std::string other_kind = kind_name(other.portal.kind);
        check.error(draft.has_kind ? draft.path / "kind" : draft.path / "target",
                    "a " + kind + " cannot be paired with the " + other_kind + " " + quote(other.portal.id) +
                        " (paired portals must be of the same kind; make both " + kind + "s or both " + other_kind +
                        "s)");
    }
    if (!draft.rect_ok || !other.rect_ok) return;
    const math::PortalRect& a = other.portal.rect;
    const math::PortalRect& b = draft.portal.rect;
    if (std::abs(a.width - b.width) > limits::kPairSizeTolerance) {
        check.error(draft.path / "width", format_number(b.width) + " differs from the width " + format_number(a.width) +
                                              " of its target " + quote(other.portal.id) +
                                              " (paired portals must have the same size)");
    }
    if (std::abs(a.height - b.height) > limits::kPairSizeTolerance) {
        check.error(draft.path / "height", format_number(b.height) + " differs from the height " +
                                               format_number(a.height) + " of its target " + quote(other.portal.id) +
                                               " (paired portals must have the same size)");
    }
}

// A portal's room, found by its id.
void link_room(Checker& check, PortalDraft& draft, const std::map<std::string, int>& room_index, bool rooms_known) {
    if (!draft.room_id) return;
    const auto it = room_index.find(*draft.room_id);
    if (it == room_index.end()) {
        if (rooms_known) check.error(draft.path / "room", "no room has the id " + quote(*draft.room_id));
    } else {
        draft.portal.room = it->second;
    }
}

// Portal `i`'s target, found by its id, which must name it back.
void link_target(Checker& check, std::size_t i, std::vector<PortalDraft>& portals,
                 const std::map<std::string, int>& portal_index) {
    PortalDraft& draft = portals[i];
    if (!draft.target_id) return;
    const auto it = portal_index.find(*draft.target_id);
    if (it == portal_index.end()) {
        check.error(draft.path / "target", "no portal has the id " + quote(*draft.target_id));
        return;
    }
    if (draft.has_id && *draft.target_id == draft.portal.id) {
        check.error(draft.path / "target", "a portal cannot target itself");
        return;
    }
    if (static_cast<std::size_t>(it->second) == i) return;  // a repeated id; reported
    const PortalDraft& other = portals[static_cast<std::size_t>(it->second)];
    if (other.volume) {
        const std::string kind = draft.kind_ok ? kind_name(draft.portal.kind) : "portal";
        check.error(draft.path / "target", quote(other.portal.id) +
                                               " is a volume, which has no partner (its target is a room); a " + kind +
                                               " must target a " + kind + " that names it back");
        return;
    }
    if (other.kind_ok && other.portal.kind == PortalKind::Mirror) {
        const std::string kind = draft.kind_ok ? kind_name(draft.portal.kind) : "portal";
        check.error(draft.path / "target", quote(other.portal.id) +
                                               " is a mirror, which has no partner (it reflects its own room); "
                                               "a " +
                                               kind + " must target a " + kind + " that names it back");
        return;
    }
    if (!draft.has_id || !other.target_id) return;  // reported where it was read
    if (*other.target_id != draft.portal.id) {
        check.error(draft.path / "target", "portal " + quote(other.portal.id) + " targets " + quote(*other.target_id) +
                                               ", not " + quote(draft.portal.id) +
                                               " (paired portals must name each other)");
        return;
    }
    draft.portal.target = it->second;
    // Check the pair's kinds and sizes once, at its later portal.
    if (static_cast<std::size_t>(it->second) > i) return;
    check_pair(check, draft, other);
}

}  // namespace

// A non-zero vector, read for normalisation.
std::optional<glm::dvec3> read_direction(Checker& check, const Path& at, const json& value) {
    const auto v = check.read_vec3(at, value, NumberKind::Direction);
    if (!v) return std::nullopt;
    const double length = glm::length(*v);
    if (!(length > 0.0)) {
        check.error(at, "must not be the zero vector");
        return std::nullopt;
    }
    return v;
}

// readers.hpp: a unit vector (a portal's normal, a spot's direction).
std::optional<glm::dvec3> read_normal(Checker& check, const Path& at, const json& value) {
    std::optional<glm::dvec3> n = read_direction(check, at, value);
    if (!n) return std::nullopt;
    const double length = glm::length(*n);
    if (std::abs(length - 1.0) > limits::kUnitTolerance) {
        check.error(at, "must be a unit vector (its length is " + format_number(length) + "; allowed is 1 ± " +
                            format_number(limits::kUnitTolerance) + ")");
        return std::nullopt;
    }
    return *n / length;
}

std::vector<PortalDraft> read_portals(Checker& check, const Path& at, const json& portals) {
    std::vector<PortalDraft> drafts;
    if (!check.expect_array(at, portals, limits::kMaxPortals)) return drafts;
    std::map<std::string, std::size_t> first_use;
    for (std::size_t i = 0; i < portals.size(); ++i) {
        PortalDraft draft = read_portal(check, at / i, portals[i]);
        if (draft.has_id) {
            const auto [it, inserted] = first_use.emplace(draft.portal.id, i);
            if (!inserted) {
                check.error(at / i / "id", "duplicate portal id " + quote(draft.portal.id) + " (also used by portals[" +
                                               std::to_string(it->second) + "])");
            }
        }
        drafts.push_back(std::move(draft));
    }
    return drafts;
}

std::vector<int> paired_indices(const std::vector<PortalDraft>& portals) {
    std::vector<int> index(portals.size(), -1);
    int next = 0;
    for (std::size_t i = 0; i < portals.size(); ++i) {
        if (!portals[i].volume) index[i] = next++;
    }
    return index;
}

void pair_portals(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                  bool rooms_known) {
    const std::map<std::string, int> room_index = index_by_id(rooms);
    const std::map<std::string, int> portal_index = index_by_id(portals);
    for (std::size_t i = 0; i < portals.size(); ++i) {
        link_room(check, portals[i], room_index, rooms_known);
        if (!portals[i].volume) link_target(check, i, portals, portal_index);  // link_volumes
    }
}

}  // namespace impossible::layout::detail
