#include "preview/hud_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impossible::preview {

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

namespace {

// "IPD 64 mm", or with each eye's pose (--eye-poses, a profile's) how far
// apart the eyes are: "eye poses 64 mm apart".
std::string eyes_text(const render::FrameDesc& s) {
    if (!s.eye_offsets) return "IPD " + fixed(s.ipd * 1000.0, 0) + " mm";
    const math::dvec3 d = (*s.eye_offsets)[1].position - (*s.eye_offsets)[0].position;
    return "eye poses " + fixed(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) * 1000.0, 0) + " mm apart";
}

std::vector<std::string> status_lines(const PreviewOptions& o, const HudFacts& f) {
    using std::to_string;
    const render::FrameDesc& s = o.frame;
    const math::dvec3 h = f.physical.position;
    std::vector<std::string> lines = {
        f.title + "   view: " + view_name(o.view),
        "frame " + fixed(f.median_ms, 1) + " ms (median of " + to_string(f.timed_frames) + ")   eye " +
            to_string(f.eye_width) + "x" + to_string(f.eye_height) + "   time " + fixed(f.time, 1) + " s",
        "room " + f.room + "   portal passes " + to_string(f.portal_passes_drawn) + " drawn, " +
            to_string(f.portal_passes_culled) + " culled",
        "recursion depth " + to_string(s.max_depth) + " (reached " + to_string(f.max_level_reached) + ")   " +
            eyes_text(s),
        std::string("clip ") + (s.clip == render::ClipMode::ClipDistance ? "clip-distance" : "oblique") +
            "   culling " + (s.cull_portals ? "on" : "off") + "   exposure " + (f.exposure > 0 ? "+" : "") +
            fixed(f.exposure, 1) + " EV",
        "physical head " + fixed(h.x, 2) + " " + fixed(h.y, 2) + " " + fixed(h.z, 2) + "  yaw " +
            fixed(f.physical.yaw_deg, 0) + "  pitch " + fixed(f.physical.pitch_deg, 0) +
            (o.hand ? "   hand " + fixed(o.hand_distance, 2) + " m" : ""),
        f.cursor_captured ? "Esc releases the mouse" : "click to look around, Esc quits",
        "WASD/arrows Q/E move  H hud  M map  V view  [ ] depth  - = IPD  C clip  X cull  P shot  R reset"
        "  G , . hand  L shadows  9 0 exposure",
    };
    if (!f.changes.empty()) lines.insert(lines.begin() + 3, f.changes);
    if (f.lit)
        lines.insert(lines.begin() + 3, "lights " + to_string(f.room_lights) + " in this room   light images " +
                                            to_string(f.light_images) + "   light depth " + to_string(f.light_depth) +
                                            "   shadows " + (s.shadows && s.shadow_map_size > 0 ? "on" : "off"));
    return lines;
}

}  // namespace

std::string changes_line(const layout::Layout& layout, const changes::ChangeWalk& walk, int seen_passes) {
    std::string armed, made;
    int waiting = 0;
    for (std::size_t c = 0; c < layout.changes.size(); ++c) {
        const changes::ChangeStatus& status = walk.status()[c];
        const std::string& id = layout.changes[c].id;
        if (status.made_frame >= 0)
            made += (made.empty() ? "" : ", ") + id + " (frame " + std::to_string(status.made_frame) + ")";
        else if (status.armed)
            armed += (armed.empty() ? "" : ", ") + id;
        else
            ++waiting;
    }
    return "changes armed: " + (armed.empty() ? "none" : armed) + "   made: " + (made.empty() ? "none" : made) +
           "   not armed: " + std::to_string(waiting) +
           (seen_passes > 0 ? "   seen test " + std::to_string(seen_passes) + " passes" : "");
}

std::vector<std::string> reload_error_lines(const std::vector<std::string>& errors) {
    if (errors.empty()) return {};
    std::vector<std::string> lines = {"layout reload failed; still showing the last good layout:"};
    for (std::size_t i = 0; i < errors.size() && i < kMaxReloadErrors; ++i) lines.push_back(errors[i]);
    if (errors.size() > kMaxReloadErrors)
        lines.push_back("... and " + std::to_string(errors.size() - kMaxReloadErrors) + " more");
    return lines;
}

HudText hud_text(const PreviewOptions& o, const HudFacts& f, const std::vector<std::string>& reload_errors) {
    HudText hud;
    if (o.hud) hud.lines = status_lines(o, f);
    hud.errors = reload_error_lines(reload_errors);
    return hud;
}

float hud_scale(int fb_h) { return fb_h < 400 ? 1.0f : fb_h < 800 ? 1.5f : 2.0f; }

HudText fit_hud(HudText hud, int fb_w, int fb_h, float scale) {
    const float line_h = 12.0f * scale, pad = 3.0f * scale;
    const auto rows = static_cast<std::size_t>(std::max(1.0f, std::floor((0.4f * float(fb_h) - 2.0f * pad) / line_h)));
    const auto chars =
        static_cast<std::size_t>(std::max(4.0f, std::floor((float(fb_w) - 2.0f * pad) / (6.0f * scale))));
    if (hud.errors.size() > rows) hud.errors.resize(rows);
    if (hud.lines.size() > rows - hud.errors.size()) hud.lines.resize(rows - hud.errors.size());
    for (auto* list : {&hud.lines, &hud.errors})
        for (std::string& line : *list)
            if (line.size() > chars) line = line.substr(0, chars - 3) + "...";
    return hud;
}

}  // namespace impossible::preview
