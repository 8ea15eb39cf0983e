// Small public helpers of layout.hpp: diagnostics, room lookup, prop placement.
#include <cmath>

#include "base/text.hpp"
#include "layout/layout.hpp"
#include "math/conventions.hpp"
#include "math/polygon.hpp"

namespace impossible::layout {

std::string Diagnostic::str() const {
    // The file name as given, which may hold a newline: one line always.
    const std::string name = one_line(file, 1000);
    if (line > 0) return name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
    return name + ": " + message;
}

std::vector<glm::dvec2> outline(const PlayArea& area) {
    if (!area.polygon.empty()) return area.polygon;
    return math::rectangle(area.min, area.max);
}

const char* kind_name(PortalKind kind) {
    switch (kind) {
        case PortalKind::Door: return "door";
        case PortalKind::Mirror: return "mirror";
        case PortalKind::Window: return "window";
    }
    return "door";
}

int find_room(const Layout& layout, const std::string& id) {
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        if (layout.rooms[i].id == id) return static_cast<int>(i);
    }
    return -1;
}

namespace {

// Yaw about +Y; positive turns counter-clockwise seen from above (-Z → -X),
// like the head's yaw.
glm::dvec3 yaw_about_y(const glm::dvec3& v, double yaw_deg) {
    const double a = math::radians(yaw_deg);
    const double c = std::cos(a);
    const double s = std::sin(a);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

}  // namespace

glm::dvec3 place_model_point(const GltfProp& prop, const glm::dvec3& p) {
    return yaw_about_y(p * prop.scale, prop.yaw_deg) + prop.position;
}

glm::dvec3 place_model_normal(const GltfProp& prop, const glm::dvec3& n) {
    // A uniform positive scale and a rotation keep normals as they are, up to length.
    const glm::dvec3 turned = yaw_about_y(n, prop.yaw_deg);
    const double length = std::sqrt(turned.x * turned.x + turned.y * turned.y + turned.z * turned.z);
    return length > 0.0 ? turned / length : turned;
}

}  // namespace impossible::layout

namespace impossible::layout {

const std::string& prop_id(const Prop& prop) {
    return std::visit([](const auto& p) -> const std::string& { return p.id; }, prop);
}

const Motion& prop_motion(const Prop& prop) {
    return std::visit([](const auto& p) -> const Motion& { return p.motion; }, prop);
}

glm::dvec3 prop_anchor(const Prop& prop) {
    if (const auto* box = std::get_if<BoxProp>(&prop)) return 0.5 * (box->min + box->max);
    return std::get<GltfProp>(prop).position;
}

}  // namespace impossible::layout
