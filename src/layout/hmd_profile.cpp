// Headset profiles; see hmd_profile.hpp.
#include "layout/hmd_profile.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "layout/checker.hpp"
#include "layout/json_doc.hpp"
#include "math/polygon.hpp"
#include "math/view_limits.hpp"
#include "math/visibility_mask.hpp"

namespace impossible::layout {

namespace {

using detail::Checker;
using detail::json;
using detail::NumberKind;
using detail::Path;

// The shortest decimal that reads back to v: -89.50000001 is not "-89.5".
std::string degrees(double v) { return format_number(v); }

std::optional<math::FovAngles> read_fov(Checker& check, const Path& at, const json& j) {
    if (!check.expect_object(at, j) ||
        !check.check_fields(at, j, {"left", "right", "up", "down"}, {"left", "right", "up", "down"}))
        return std::nullopt;
    double v[4] = {};
    const char* names[4] = {"left", "right", "up", "down"};
    for (int k = 0; k < 4; ++k) {
        const std::optional<double> n = check.read_number(at / names[k], j[names[k]], NumberKind::Angle);
        if (!n) return std::nullopt;
        if (!(std::abs(*n) <= kMaxFovAngleDeg)) {
            check.error(at / names[k], degrees(*n) + " is not within ±89.5 degrees");
            return std::nullopt;
        }
        v[k] = *n;
    }
    const math::FovAngles fov{v[0], v[1], v[2], v[3]};
    if (const std::optional<std::string> problem = fov_angles_problem(fov)) {
        check.error(at, *problem);
        return std::nullopt;
    }
    return fov;
}

std::optional<std::array<int, 2>> read_resolution(Checker& check, const Path& at, const json& j) {
    if (!check.expect_array(at, j, 2)) return std::nullopt;
    if (j.size() != 2) {
        check.error(at, "expected [width, height]");
        return std::nullopt;
    }
    std::array<int, 2> out{};
    for (std::size_t k = 0; k < 2; ++k) {
        const json& n = j[k];
        if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 8192) {
            check.error(at / k, "expected a whole number of pixels, 1..8192");
            return std::nullopt;
        }
        out[k] = static_cast<int>(n.get<long long>());
    }
    return out;
}

// Corners [a, b], finite (|v| at most 1e5), 3..max of them; `names` names
// the coordinates in messages ("[u, v]" in the image, "[x, y]" in tangent
// space).
std::optional<math::Polygon2> read_corners(Checker& check, const Path& at, const json& j, std::size_t max,
                                           const char* names) {
    if (!check.expect_array(at, j, max)) return std::nullopt;
    if (j.size() < 3) {
        check.error(at, "a polygon needs at least 3 corners");
        return std::nullopt;
    }
    math::Polygon2 poly;
    for (std::size_t k = 0; k < j.size(); ++k) {
        const std::optional<glm::dvec2> p = check.read_vec2(at / k, j[k], NumberKind::Direction, names);
        if (!p) return std::nullopt;
        poly.push_back(*p);
    }
    return poly;
}

bool simple_or_error(Checker& check, const Path& at, const math::Polygon2& poly, const char* what) {
    const std::optional<math::PolygonProblem> problem = math::simple_polygon_problem(poly);
    if (problem) check.error(at / static_cast<std::size_t>(problem->corner), std::string(what) + problem->message);
    return !problem;
}

// The visible area in the normalised image: `area` ∩ the image.
std::optional<math::Polygon2> inside_image(Checker& check, const Path& at, const math::Polygon2& area) {
    const math::Polygon2 clipped = math::clip_to_image(area);
    if (clipped.size() < 3 || !(math::area(clipped) > 0.0)) {
        check.error(at, "no part of the visible area lies inside the image");
        return std::nullopt;
    }
    if (const std::optional<math::PolygonProblem> problem =
            clipped == area ? std::nullopt : math::simple_polygon_problem(clipped)) {
        check.error(at, "the visible area's part inside the image is not one simple polygon (" + problem->message +
                            "): it falls apart where it crosses the image's edge");
        return std::nullopt;
    }
    if (clipped.size() > kMaxVisibleAreaCorners) {
        check.error(at, "the visible area has " + std::to_string(clipped.size()) +
                            " corners inside the image, more than " + std::to_string(kMaxVisibleAreaCorners));
        return std::nullopt;
    }
    return clipped;
}

// "visible_area": corners [u, v] in the normalised image; the part inside
// the image is kept.
std::optional<math::Polygon2> read_visible_area(Checker& check, const Path& at, const json& j) {
    const std::optional<math::Polygon2> poly = read_corners(check, at, j, kMaxVisibleAreaCorners, "[u, v]");
    if (!poly || !simple_or_error(check, at, *poly, "the visible area must be a simple polygon: ")) return std::nullopt;
    return inside_image(check, at, *poly);
}

std::optional<std::vector<std::uint32_t>> read_indices(Checker& check, const Path& at, const json& j) {
    if (!check.expect_array(at, j, kMaxVisibilityMaskIndices)) return std::nullopt;
    if (j.size() < 3 || j.size() % 3 != 0) {
        check.error(at, "expected whole triangles, three indices each (got " + std::to_string(j.size()) + ")");
        return std::nullopt;
    }
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < j.size(); ++k) {
        if (!j[k].is_number_integer() || j[k].get<long long>() < 0 || j[k].get<long long>() > 0xffffffffLL) {
            check.error(at / k, "expected an index into vertices, a whole number from 0");
            return std::nullopt;
        }
        out.push_back(static_cast<std::uint32_t>(j[k].get<long long>()));
    }
    return out;
}

// "visibility_mask": OpenXR's line loop or visible triangles in the eye's
// tangent space (math/visibility_mask.hpp), in the image through `fov`.
std::optional<math::Polygon2> read_visibility_mask(Checker& check, const Path& at, const json& j,
                                                   const math::FovAngles& fov) {
    if (!check.expect_object(at, j) || !check.check_fields(at, j, {"line_loop", "vertices", "indices"}, {}))
        return std::nullopt;
    const bool loop = j.contains("line_loop"), mesh = j.contains("vertices") || j.contains("indices");
    if (loop == mesh) {
        check.error(at, loop ? "give either line_loop or vertices and indices, not both"
                             : "expected line_loop, or vertices and indices");
        return std::nullopt;
    }
    math::Polygon2 outline;
    if (loop) {
        const std::optional<math::Polygon2> poly =
            read_corners(check, at / "line_loop", j["line_loop"], kMaxVisibleAreaCorners, "[x, y]");
        if (!poly || !simple_or_error(check, at / "line_loop", *poly, "the line loop must be a simple polygon: "))
            return std::nullopt;
        outline = *poly;
    } else {
        if (!check.check_fields(at, j, {"vertices", "indices"}, {"vertices", "indices"})) return std::nullopt;
        const std::optional<math::Polygon2> vertices =
            read_corners(check, at / "vertices", j["vertices"], kMaxVisibilityMaskIndices, "[x, y]");
        const std::optional<std::vector<std::uint32_t>> indices =
            vertices ? read_indices(check, at / "indices", j["indices"]) : std::nullopt;
        if (!indices) return std::nullopt;
        const math::MeshOutline mesh_outline = math::triangles_outline(*vertices, *indices);
        if (mesh_outline.problem) {
            check.error(
                at / "indices" / (3 * mesh_outline.problem->triangle),
                "triangle " + std::to_string(mesh_outline.problem->triangle) + ": " + mesh_outline.problem->message);
            return std::nullopt;
        }
        outline = mesh_outline.outline;
    }
    const math::FovTangents tangents = math::fov_tangents(fov);
    for (glm::dvec2& p : outline) p = math::tangent_to_image(tangents, p);
    return inside_image(check, at, outline);
}

// An eye's "orientation": [x, y, z, w], of length 1 within
// math::kUnitQuaternionTolerance.
std::optional<math::dvec4> read_orientation(Checker& check, const Path& at, const json& j) {
    if (!check.expect_array(at, j, 4)) return std::nullopt;
    if (j.size() != 4) {
        check.error(at, "expected a unit quaternion [x, y, z, w]");
        return std::nullopt;
    }
    math::dvec4 q(0.0);
    for (std::size_t k = 0; k < 4; ++k) {
        const std::optional<double> n = check.read_number(at / k, j[k], NumberKind::Direction);
        if (!n) return std::nullopt;
        q[static_cast<int>(k)] = *n;
    }
    const double length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    if (!(std::abs(length - 1.0) <= math::kUnitQuaternionTolerance)) {
        check.error(at, "is not a unit quaternion [x, y, z, w]: its length is " + format_number(length) +
                            ", not 1 within 1e-6");
        return std::nullopt;
    }
    return q;
}

// An eye's "position": [x, y, z] metres from the head centre, at most
// math::limits::kMaxEyeDistance away.
std::optional<math::dvec3> read_eye_position(Checker& check, const Path& at, const json& j) {
    const std::optional<math::dvec3> p = check.read_vec3(at, j, NumberKind::Coordinate);
    if (!p) return std::nullopt;
    const double distance = std::sqrt(p->x * p->x + p->y * p->y + p->z * p->z);
    if (!(distance <= math::limits::kMaxEyeDistance)) {
        check.error(at, "is " + format_number(distance) + " m from the head centre, more than " +
                            format_number(math::limits::kMaxEyeDistance) + " m");
        return std::nullopt;
    }
    return p;
}

struct EyeRead {
    math::EyeOptics optics;
    std::array<int, 2> resolution{};
    std::optional<math::QuaternionPose> pose;  // "position" and "orientation"
};

// "position" and "orientation", both or neither.
bool read_eye_pose(Checker& check, const Path& at, const json& j, EyeRead& eye) {
    const bool position = j.contains("position"), orientation = j.contains("orientation");
    if (!position && !orientation) return true;
    if (position != orientation) {
        check.error_at_key(at / (position ? "position" : "orientation"),
                           std::string("an eye's pose needs both position and orientation (") +
                               (position ? "orientation" : "position") + " is missing)");
        return false;
    }
    const std::optional<math::dvec3> p = read_eye_position(check, at / "position", j["position"]);
    const std::optional<math::dvec4> q =
        p ? read_orientation(check, at / "orientation", j["orientation"]) : std::nullopt;
    if (!p || !q) return false;
    eye.pose = math::QuaternionPose{*p, *q};
    return true;
}

std::optional<EyeRead> read_eye(Checker& check, const Path& at, const json& j) {
    if (!check.expect_object(at, j) ||
        !check.check_fields(at, j, {"fov", "resolution", "visible_area", "visibility_mask", "position", "orientation"},
                            {"fov", "resolution"}))
        return std::nullopt;
    EyeRead eye;
    const std::optional<math::FovAngles> fov = read_fov(check, at / "fov", j["fov"]);
    const std::optional<std::array<int, 2>> size = read_resolution(check, at / "resolution", j["resolution"]);
    if (!fov || !size) return std::nullopt;
    eye.optics.fov = *fov;
    eye.resolution = *size;
    if (j.contains("visible_area")) {
        const std::optional<math::Polygon2> area = read_visible_area(check, at / "visible_area", j["visible_area"]);
        if (!area) return std::nullopt;
        eye.optics.visible_area = *area;
    }
    if (j.contains("visibility_mask")) {
        if (j.contains("visible_area")) {
            check.error_at_key(at / "visibility_mask", "give either visible_area or visibility_mask, not both");
            return std::nullopt;
        }
        const std::optional<math::Polygon2> area =
            read_visibility_mask(check, at / "visibility_mask", j["visibility_mask"], *fov);
        if (!area) return std::nullopt;
        eye.optics.visible_area = *area;
    }
    if (!read_eye_pose(check, at, j, eye)) return std::nullopt;
    return eye;
}

Result<HmdProfile> read_profile(Checker& check, const json& j) {
    HmdProfile out;
    const Path root;
    auto first_error = [&]() -> Result<HmdProfile> { return Error{check.take_errors().front().str()}; };
    if (!check.expect_object(root, j) ||
        !check.check_fields(root, j, {"name", "source", "ipd", "left", "right"}, {"name", "source", "left", "right"}))
        return first_error();
    const std::optional<std::string> name = check.read_string(root / "name", j["name"]);
    const std::optional<std::string> source = check.read_string(root / "source", j["source"]);
    if (j.contains("ipd")) {
        const std::optional<double> ipd = check.read_number(root / "ipd", j["ipd"], NumberKind::Coordinate);
        if (ipd && !math::limits::kIpd.contains(*ipd))
            check.error(root / "ipd",
                        format_number(*ipd) + " is not in " + math::limits::range_text(math::limits::kIpd) + " m");
        if (ipd) out.ipd = *ipd;
    }
    const std::optional<EyeRead> left = read_eye(check, root / "left", j["left"]);
    const std::optional<EyeRead> right = left ? read_eye(check, root / "right", j["right"]) : std::nullopt;
    if (check.has_errors() || !name || !source || !left || !right) return first_error();
    if (left->resolution != right->resolution)
        check.error(root / "right" / "resolution",
                    "the eyes' resolutions differ (" + std::to_string(left->resolution[0]) + "x" +
                        std::to_string(left->resolution[1]) + " and " + std::to_string(right->resolution[0]) + "x" +
                        std::to_string(right->resolution[1]) +
                        "): both eyes share one side-by-side target, so they must be the same");
    if (left->pose.has_value() != right->pose.has_value()) {
        const char* without = left->pose ? "right" : "left";
        check.error(root / without, std::string("the ") + (left->pose ? "left" : "right") +
                                        " eye has a position and an orientation, so the " + without +
                                        " eye needs them too");
    } else if (left->pose && j.contains("ipd")) {
        check.error_at_key(root / "ipd", "the eyes' positions give the distance between them: leave ipd out");
    }
    if (check.has_errors()) return first_error();
    if (left->pose) out.eye_poses = std::array<math::QuaternionPose, 2>{*left->pose, *right->pose};
    out.name = *name;
    out.source = *source;
    out.eye_width = left->resolution[0];
    out.eye_height = left->resolution[1];
    out.eyes = {left->optics, right->optics};
    return out;
}

}  // namespace

std::optional<std::string> fov_angles_problem(const math::FovAngles& fov) {
    const double v[4] = {fov.left, fov.right, fov.up, fov.down};
    for (double a : v)
        if (!(std::abs(a) <= kMaxFovAngleDeg)) return degrees(a) + " is not an angle within ±89.5 degrees";
    if (!(fov.right - fov.left >= kMinFovExtentDeg))
        return "right (" + degrees(fov.right) + ") must be at least 1 degree right of left (" + degrees(fov.left) + ")";
    if (!(fov.up - fov.down >= kMinFovExtentDeg))
        return "up (" + degrees(fov.up) + ") must be at least 1 degree above down (" + degrees(fov.down) + ")";
    return std::nullopt;
}

Result<HmdProfile> parse_hmd_profile(std::string_view text, const std::string& file) {
    const detail::JsonParse parsed = detail::parse_json(text);
    Checker check(text, file);
    if (!parsed.document) {
        check.error_at_offset(parsed.error->offset, parsed.error->message);
        return Error{check.take_errors().front().str()};
    }
    return read_profile(check, parsed.document->root);
}

Result<HmdProfile> read_hmd_profile_file(const std::string& path) {
    Result<std::vector<unsigned char>> bytes = read_file_bytes(path, kMaxHmdProfileBytes, false);
    if (!bytes) return Error{path + ": " + bytes.error()};
    const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
    return parse_hmd_profile(text, path);
}

}  // namespace impossible::layout
