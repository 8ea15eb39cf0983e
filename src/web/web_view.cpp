#include "web/web_view.hpp"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "base/format.hpp"
#include "gl/gl.hpp"
#include "math/eyes.hpp"

namespace impossible::web {
namespace {

using nlohmann::json;

glm::dvec3 vec3_of(const json& v, const char* field) {
    if (!v.is_array() || v.size() != 3) throw std::runtime_error(std::string(field) + ": expected [x, y, z]");
    glm::dvec3 p(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw std::runtime_error(std::string(field) + ": not finite");
    return p;
}

glm::dmat3 rotation_of(const json& q, const char* field) {
    if (!q.is_array() || q.size() != 4) throw std::runtime_error(std::string(field) + ": expected [x, y, z, w]");
    const glm::dquat r(q[3].get<double>(), q[0].get<double>(), q[1].get<double>(), q[2].get<double>());
    const double n = glm::length(r);
    if (!(std::abs(n - 1.0) < 1e-3)) throw std::runtime_error(std::string(field) + ": not a unit quaternion");
    return glm::mat3_cast(r / n);
}

struct Rigid {
    glm::dvec3 position{0.0};
    glm::dmat3 rotation{1.0};
};

Rigid rigid_of(const json& pose, const char* field) {
    Rigid r;
    r.position = vec3_of(pose.at("position"), field);
    if (pose.contains("orientation")) r.rotation = rotation_of(pose.at("orientation"), field);
    return r;
}

// The physical frame the page's poses are in: the layout's own ("layout"),
// WebXR's local-floor space with the layout's start on the floor at its
// origin, facing its way ("floor"), or WebXR's local space, whose origin
// is at the eyes, with the start's head there ("local").
Rigid floor_to_layout(const layout::Layout& layout, const std::string& space) {
    Rigid t;
    if (space == "layout") return t;
    if (space != "floor" && space != "local") throw std::runtime_error("space: layout, floor or local");
    t.position = {layout.start.position.x, space == "local" ? layout.start.position.y : 0.0, layout.start.position.z};
    t.rotation = math::rotation_y_deg(layout.start.yaw_deg);
    return t;
}

math::HeadPose pose_in(const Rigid& frame, const Rigid& local) {
    return math::head_pose_from(frame.position + frame.rotation * local.position, frame.rotation * local.rotation);
}

}  // namespace

FrameRequest parse_frame_request(const json& request, const layout::Layout& layout) {
    FrameRequest r;
    const Rigid frame = floor_to_layout(layout, request.value("space", std::string("layout")));
    const Rigid head = rigid_of(request.at("head"), "head");
    r.physical_head = pose_in(frame, head);
    if (request.contains("hands") && request["hands"].is_array() && request["hands"].size() == 2)
        r.hands = std::array<math::HeadPose, 2>{pose_in(frame, rigid_of(request["hands"][0], "hands[0]")),
                                                pose_in(frame, rigid_of(request["hands"][1], "hands[1]"))};
    r.time = request.value("time", 0.0);
    r.finish = request.value("finish", false);
    render::FrameDesc& f = r.frame;
    f.time = r.time;
    const json& size = request.at("size");
    f.eye_width = size.at(0).get<int>();
    f.eye_height = size.at(1).get<int>();
    if (f.eye_width < 1 || f.eye_height < 1 || f.eye_width > 8192 || f.eye_height > 8192)
        throw std::runtime_error("size: each eye 1..8192 pixels");
    f.max_depth = request.value("max_depth", f.max_depth);
    if (request.value("depth", std::string("reversed-z")) == "standard") f.depth = render::DepthMode::Standard;
    if (request.value("clip", std::string("clip-distance")) == "oblique") f.clip = render::ClipMode::Oblique;
    if (!request.value("cull", true)) f.cull_portals = false;
    if (request.contains("eyes")) {
        const json& eyes = request["eyes"];
        if (!eyes.is_array() || eyes.size() != 2) throw std::runtime_error("eyes: expected two eyes");
        std::array<math::EyeOptics, 2> optics;
        std::array<math::EyeOffset, 2> offsets;
        for (std::size_t e = 0; e < 2; ++e) {
            const json& o = eyes[e].at("orientation");
            math::QuaternionPose pose;
            pose.position = vec3_of(eyes[e].at("position"), "eyes[].position");
            pose.orientation = {o.at(0).get<double>(), o.at(1).get<double>(), o.at(2).get<double>(),
                                o.at(3).get<double>()};
            offsets[e] = math::eye_offset(pose);
            const json& fov = eyes[e].at("fov");
            optics[e].fov = {fov.at(0).get<double>(), fov.at(1).get<double>(), fov.at(2).get<double>(),
                             fov.at(3).get<double>()};
        }
        f.eye_optics = optics;
        f.eye_offsets = offsets;
    } else {
        f.ipd = request.value("ipd", f.ipd);
        f.fov_y_deg = request.value("fov_y", f.fov_y_deg);
    }
    if (request.contains("target")) {
        const json& t = request["target"];
        r.framebuffer = t.value("framebuffer", 0u);
        if (t.contains("viewports"))
            for (std::size_t e = 0; e < 2; ++e)
                for (std::size_t k = 0; k < 4; ++k) r.viewports[e][k] = t["viewports"].at(e).at(k).get<int>();
    }
    return r;
}

std::string frame_view_options(const FrameRequest& request) {
    const render::FrameDesc& f = request.frame;
    std::string list;
    const auto add = [&](double v) { list += (list.empty() ? "" : ",") + format_number(v); };
    const auto pose = [&](const math::HeadPose& p) {
        for (const double v : {p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg}) add(v);
    };
    pose(request.physical_head);
    std::string text = "--pose " + list;
    if (f.eye_offsets) {
        list.clear();
        for (const math::EyeOffset& e : *f.eye_offsets) pose(math::head_pose_from(e.position, e.rotation));
        text += " --eye-poses " + list;
    } else {
        list.clear();
        add(f.ipd);
        text += " --ipd " + list;
    }
    list.clear();
    if (f.eye_optics) {
        for (const math::EyeOptics& e : *f.eye_optics)
            for (const double v : {e.fov.left, e.fov.right, e.fov.up, e.fov.down}) add(v);
        text += " --fov-angles " + list;
    } else {
        add(f.fov_y_deg);
        text += " --fov " + list;
    }
    return text + " --size " + std::to_string(f.eye_width) + "x" + std::to_string(f.eye_height);
}

void present(const render::Target& target, const FrameRequest& request) {
    const int w = target.width / 2, h = target.height;
    glDisable(GL_SCISSOR_TEST);  // a blit obeys the scissor
    glNamedFramebufferReadBuffer(target.framebuffer.get(), GL_COLOR_ATTACHMENT0);
    for (int e = 0; e < 2; ++e) {
        std::array<int, 4> v = request.viewports[static_cast<std::size_t>(e)];
        if (v[2] == 0) v = {e * w, 0, w, h};
        glBlitNamedFramebuffer(target.framebuffer.get(), request.framebuffer, e * w, 0, (e + 1) * w, h, v[0], v[1],
                               v[0] + v[2], v[1] + v[3], GL_COLOR_BUFFER_BIT, GL_LINEAR);
    }
}

}  // namespace impossible::web
