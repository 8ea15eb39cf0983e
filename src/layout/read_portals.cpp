#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/text_util.hpp"
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
        check.warning(at / "depth", "the box is " + format_number(depth) + " m deep: with --depth standard (near plane " +
                                        format_number(limits::kNearStandard) + " m) an eye half an IPD behind the "
                                        "door's plane sees through its back; make it at least " +
                                        format_number(needed_standard) + " m");
    }
}

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

// The unit normal, or nothing (reported).
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
        check.error(up_at, up_value ? "must not be parallel to the normal " + angles
                                    : "is parallel to the default up [0, 1, 0] " + angles +
                                          "; give the portal an \"up\"");
        return false;
    }
    rect.normal = n;
    rect.up = glm::normalize(u - glm::dot(u, n) * n);
    return true;
}

// centre, size, depth, normal and up; false if any is missing or bad (reported).
bool read_rect(Checker& check, const Path& at, const json& value, math::PortalRect& rect) {
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
    rect.depth = 0.25;
    if (const json* v = field(value, "depth")) {
        const std::optional<double> depth = check.read_number(at / "depth", *v, NumberKind::Length);
        if (depth) warn_if_shallow(check, at, *depth);
        take(depth, rect.depth);
    }
    const std::optional<glm::dvec3> n = normal ? read_normal(check, at / "normal", *normal) : std::nullopt;
    const bool up_ok = read_up(check, at, value, n, rect);
    return ok && n && up_ok;
}

PortalDraft read_portal(Checker& check, const Path& at, const json& value) {
    PortalDraft draft;
    draft.path = at;
    if (!check.expect_object(at, value)) return draft;
    check.check_fields(at, value,
                       {"id", "room", "center", "normal", "up", "width", "height", "depth", "target"},
                       {"id", "room", "center", "normal", "width", "height", "target"});
    Portal& portal = draft.portal;
    if (const json* v = field(value, "id")) {
        if (auto id = check.read_id(at / "id", *v)) {
            portal.id = std::move(*id);
            draft.has_id = true;
        }
    }
    if (const json* v = field(value, "room")) draft.room_id = check.read_string(at / "room", *v);
    if (const json* v = field(value, "target")) draft.target_id = check.read_string(at / "target", *v);
    draft.rect_ok = read_rect(check, at, value, portal.rect);
    return draft;
}

}  // namespace

std::vector<PortalDraft> read_portals(Checker& check, const Path& at, const json& portals) {
    std::vector<PortalDraft> drafts;
    if (!check.expect_array(at, portals, limits::kMaxPortals)) return drafts;
    std::map<std::string, std::size_t> first_use;
    for (std::size_t i = 0; i < portals.size(); ++i) {
        PortalDraft draft = read_portal(check, at / i, portals[i]);
        if (draft.has_id) {
            const auto [it, inserted] = first_use.emplace(draft.portal.id, i);
            if (!inserted) {
                check.error(at / i / "id", "duplicate portal id " + quote(draft.portal.id) +
                                               " (also used by portals[" +
                                               std::to_string(it->second) + "])");
            }
        }
        drafts.push_back(std::move(draft));
    }
    return drafts;
}

void link_portals(Checker& check, std::vector<PortalDraft>& portals,
                  const std::vector<RoomDraft>& rooms, bool rooms_known) {
    const std::map<std::string, int> room_index = index_by_id(rooms);
    const std::map<std::string, int> portal_index = index_by_id(portals);
    for (std::size_t i = 0; i < portals.size(); ++i) {
        PortalDraft& draft = portals[i];
        if (draft.room_id) {
            const auto it = room_index.find(*draft.room_id);
            if (it == room_index.end()) {
                if (rooms_known) check.error(draft.path / "room", "no room has the id " + quote(*draft.room_id));
            } else {
                draft.portal.room = it->second;
            }
        }
        if (!draft.target_id) continue;
        const auto it = portal_index.find(*draft.target_id);
        if (it == portal_index.end()) {
            check.error(draft.path / "target", "no portal has the id " + quote(*draft.target_id));
            continue;
        }
        if (draft.has_id && *draft.target_id == draft.portal.id) {
            check.error(draft.path / "target", "a portal cannot target itself");
            continue;
        }
        if (static_cast<std::size_t>(it->second) == i) continue;  // a repeated id; reported
        const PortalDraft& other = portals[static_cast<std::size_t>(it->second)];
        if (!draft.has_id || !other.target_id) continue;  // reported where it was read
        if (*other.target_id != draft.portal.id) {
            check.error(draft.path / "target",
                        "portal " + quote(other.portal.id) + " targets " + quote(*other.target_id) +
                            ", not " + quote(draft.portal.id) +
                            " (paired portals must name each other)");
            continue;
        }
        draft.portal.target = it->second;
        // Check the pair's sizes once, at its later portal.
        if (static_cast<std::size_t>(it->second) > i || !draft.rect_ok || !other.rect_ok) continue;
        const math::PortalRect& a = other.portal.rect;
        const math::PortalRect& b = draft.portal.rect;
        if (std::abs(a.width - b.width) > limits::kPairSizeTolerance) {
            check.error(draft.path / "width",
                        format_number(b.width) + " differs from the width " + format_number(a.width) +
                            " of its target " + quote(other.portal.id) +
                            " (paired portals must have the same size)");
        }
        if (std::abs(a.height - b.height) > limits::kPairSizeTolerance) {
            check.error(draft.path / "height",
                        format_number(b.height) + " differs from the height " +
                            format_number(a.height) + " of its target " + quote(other.portal.id) +
                            " (paired portals must have the same size)");
        }
    }
}

}  // namespace impossible::layout::detail
