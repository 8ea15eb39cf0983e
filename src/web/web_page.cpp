// The page's walker and renderer (web/page.js, web/xr.js): a layout opened
// once, then frame after frame a physical head pose and each eye's view in,
// the head walked through doors exactly as `walk` walks it, the frame drawn
// and shown in the canvas or the headset's framebuffer.
#include <emscripten.h>

#include <chrono>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/layout_source.hpp"
#include "gl/context.hpp"
#include "gl/gl.hpp"
#include "gl/state.hpp"
#include "image/png.hpp"
#include "math/pose.hpp"
#include "render/renderer.hpp"
#include "session/session.hpp"
#include "session/walk_driver.hpp"
#include "web/web_view.hpp"

namespace impossible::web {
namespace {

using nlohmann::json;

struct Page {
    std::optional<gl::Context> context;
    std::unique_ptr<session::Session> session;
    std::unique_ptr<session::WalkDriver> driver;
    std::optional<render::Renderer> renderer;
    // The layout the renderer draws: the session's, or the walk driver's
    // with the pairing its changes made (docs/changes.md).
    const layout::Layout* drawn_layout = nullptr;
    render::FrameDesc frame;
    bool drawn = false;
    std::string message;  // the last failure, for the page to show
    std::string status;   // the last frame's walk, as JSON
};
Page page;

bool fail(const std::string& message) {
    page.message = message;
    return false;
}

bool ensure_context() {
    if (page.context) return true;
    Result<gl::Context> made = gl::create_context(gl::Backend::Egl);
    if (!made) return fail(made.error());
    page.context.emplace(std::move(*made));
    return true;
}

// The programs of the page's context, from the renderer it has (none before
// the first): another layout or a change while walking costs no compile.
render::SharedPrograms shared_programs() {
    return page.renderer ? page.renderer->programs() : render::SharedPrograms{};
}

// Opens the layout at `path` in the module's file system ("" the built-in
// default); on failure the one before stays open.
bool open_layout(const std::string& path) {
    if (!ensure_context()) return false;
    try {
        auto session = std::make_unique<session::Session>(
            cli::load_layout_or_default(path.empty() ? std::nullopt : std::optional<std::string>(path)));
        page.context->state().invalidate();
        Result<render::Renderer> renderer = session->make_renderer(page.context->state(), shared_programs());
        if (!renderer) return fail(renderer.error());
        page.renderer.reset();
        page.driver.reset();
        page.session = std::move(session);
        page.renderer.emplace(std::move(*renderer));
        page.drawn_layout = &page.session->layout();
        page.driver = std::make_unique<session::WalkDriver>(*page.session);
        page.drawn = false;
        page.message.clear();
        return true;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}

json walked_json(const session::WalkedFrame& w) {
    const layout::Layout& l = page.session->layout();
    json teleports = json::array();
    for (const int p : w.teleports) teleports.push_back(l.portals[static_cast<std::size_t>(p)].id);
    json status{{"room", l.rooms[static_cast<std::size_t>(w.room)].id},
                {"teleports", teleports},
                {"position", {w.position.x, w.position.y, w.position.z}},
                {"forward", {w.forward.x, w.forward.y, w.forward.z}}};
    if (!w.changes.empty()) {
        json changes = json::array();
        for (const int c : w.changes) changes.push_back(l.changes[static_cast<std::size_t>(c)].id);
        status["changes"] = changes;
    }
    return status;
}

// A renderer for the walk driver's session once a change has given it a
// new pairing (or a reset has gone back to the loaded one).
bool follow_pairing() {
    const session::Session& walked = page.driver->session();
    if (&walked.layout() == page.drawn_layout) return true;
    page.context->state().invalidate();
    Result<render::Renderer> renderer = walked.make_renderer(page.context->state(), shared_programs());
    if (!renderer) return fail(renderer.error());
    page.renderer.reset();
    page.renderer.emplace(std::move(*renderer));
    page.drawn_layout = &walked.layout();
    return true;
}

// One frame (web_view.hpp has the request's fields): walk, draw, show.
bool draw_frame(const std::string& request_text) {
    if (!page.session) return fail("no layout is open");
    try {
        const FrameRequest request = parse_frame_request(json::parse(request_text), page.session->layout());
        const auto started = std::chrono::steady_clock::now();
        // The seen test of the changes looks with this frame's eyes.
        page.driver->set_view(request.frame);
        const session::WalkedFrame walked = page.driver->step(request.physical_head, request.hands, request.time);
        if (!follow_pairing()) return false;
        const auto walked_at = std::chrono::steady_clock::now();
        render::FrameDesc frame = request.frame;
        frame.head = walked.virtual_pose;
        frame.room = walked.room;
        if (walked.hands) {
            std::array<math::HeadPose, 2> hands{walked.hands->at(0).virtual_pose, walked.hands->at(1).virtual_pose};
            frame.hands = hands;
        }
        page.context->state().invalidate();
        if (Result<void> drawn = page.renderer->draw(frame); !drawn) return fail(drawn.error());
        present(page.renderer->target(), request);
        page.frame = frame;
        page.drawn = true;
        // The CPU's part: the walk, the portal recursion and culling, and
        // the WebGL calls made (not what the GPU does with them).
        const auto drawn_at = std::chrono::steady_clock::now();
        // With "finish": until the GPU is done too (web/tools/web-bench.mjs).
        // A pixel read back, since Chromium's glFinish does not wait.
        if (request.finish) {
            std::uint8_t pixel[4];
            glBindFramebuffer(GL_READ_FRAMEBUFFER, page.renderer->target().framebuffer.get());
            glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        }
        const auto finished_at = std::chrono::steady_clock::now();
        using ms = std::chrono::duration<double, std::milli>;
        json status = walked_json(walked);
        status["ms"] = ms(drawn_at - started).count();
        status["walk_ms"] = ms(walked_at - started).count();
        // The hands' rooms, walked from the head centre (the controllers).
        if (walked.hands) {
            const layout::Layout& l = page.session->layout();
            json hands = json::array();
            for (const session::WalkedHand& h : *walked.hands)
                hands.push_back(h.room < 0 ? json(nullptr) : json(l.rooms[static_cast<std::size_t>(h.room)].id));
            status["hands"] = hands;
        }
        status["frame_ms"] = ms(finished_at - started).count();
        // The physical head as walked (WebXR's poses are single precision),
        // for a path file that `walk` replays exactly.
        const math::HeadPose& p = request.physical_head;
        status["physical"] = {p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg};
        page.status = status.dump();
        page.message.clear();
        return true;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}

// The command-line options that draw a request's view with `render` or
// `trace` (scripts/web-render --xr): the physical head as --pose (no walk:
// --room names the room), the eyes as --eye-poses and --fov-angles, --size.
std::string view_options(const std::string& request_text) {
    if (!page.session) return "";
    try {
        const FrameRequest r = parse_frame_request(json::parse(request_text), page.session->layout());
        return frame_view_options(r);
    } catch (const std::exception& e) {
        page.message = e.what();
        return "";
    }
}

// The last frame drawn again and written as PNGs (the headset tests).
bool save_frame(const std::string& out, const std::string& ids) {
    if (!page.drawn) return fail("no frame has been drawn");
    page.context->state().invalidate();
    Result<render::RenderedFrame> r = page.renderer->render(page.frame);
    if (!r) return fail(r.error());
    const image::Image& im = r->image;
    if (Result<void> w = image::write_png(out, im.width, im.height, 3, im.rgb); !w) return fail(w.error());
    if (!ids.empty())
        if (Result<void> w = image::write_png(ids, im.width, im.height, 1, im.ids); !w) return fail(w.error());
    return true;
}

}  // namespace
}  // namespace impossible::web

extern "C" {
EMSCRIPTEN_KEEPALIVE int impossible_page_open(const char* path) { return impossible::web::open_layout(path) ? 0 : 1; }
EMSCRIPTEN_KEEPALIVE int impossible_page_frame(const char* request) {
    return impossible::web::draw_frame(request) ? 0 : 1;
}
EMSCRIPTEN_KEEPALIVE int impossible_page_save(const char* out, const char* ids) {
    return impossible::web::save_frame(out, ids) ? 0 : 1;
}
EMSCRIPTEN_KEEPALIVE const char* impossible_page_view_options(const char* request) {
    static std::string text;
    text = impossible::web::view_options(request);
    return text.c_str();
}
EMSCRIPTEN_KEEPALIVE void impossible_page_reset() {
    if (impossible::web::page.session) {
        impossible::web::page.driver =
            std::make_unique<impossible::session::WalkDriver>(*impossible::web::page.session);
        impossible::web::follow_pairing();
    }
}
EMSCRIPTEN_KEEPALIVE const char* impossible_page_message() { return impossible::web::page.message.c_str(); }
EMSCRIPTEN_KEEPALIVE const char* impossible_page_status() { return impossible::web::page.status.c_str(); }
EMSCRIPTEN_KEEPALIVE const char* impossible_page_layout_info() {
    static std::string info;
    if (!impossible::web::page.session) return "";
    const auto& l = impossible::web::page.session->layout();
    nlohmann::json j{{"name", l.name},
                     {"source", l.source},
                     {"start", {l.start.position.x, l.start.position.y, l.start.position.z, l.start.yaw_deg}},
                     {"start_room", l.rooms[static_cast<std::size_t>(l.start.room)].id}};
    info = j.dump();
    return info.c_str();
}
}
