#include "preview/keys.hpp"

#include <algorithm>

namespace impossible::preview {

KeyEffects apply_actions(const std::vector<Action>& actions, bool cursor_captured, PreviewOptions& o,
                         double layout_exposure) {
    KeyEffects e;
    render::FrameDesc& f = o.frame;
    for (Action a : actions) {
        switch (a) {
            case Action::Escape:
                if (cursor_captured) {
                    e.release_cursor = true;
                    cursor_captured = false;
                } else {
                    e.quit = true;
                }
                break;
            case Action::ToggleHud: o.hud = !o.hud; break;
            case Action::ToggleMinimap: o.minimap = !o.minimap; break;
            case Action::NextView: o.view = next_view(o.view); break;
            case Action::DepthDown: f.max_depth = std::max(0, f.max_depth - 1); break;
            case Action::DepthUp: f.max_depth = std::min(kMaxPreviewDepth, f.max_depth + 1); break;
            // With each eye's pose (--eye-poses, a profile's) there is no
            // IPD to change: the keys do nothing.
            case Action::IpdDown:
                if (!f.eye_offsets) f.ipd = std::max(0.0, f.ipd - kIpdStep);
                break;
            case Action::IpdUp:
                if (!f.eye_offsets) f.ipd = std::min(kMaxIpd, f.ipd + kIpdStep);
                break;
            case Action::NextClip:
                f.clip = f.clip == render::ClipMode::ClipDistance ? render::ClipMode::Oblique
                                                                  : render::ClipMode::ClipDistance;
                break;
            case Action::ToggleCulling: f.cull_portals = !f.cull_portals; break;
            case Action::Screenshot: e.screenshot = true; break;
            case Action::Reset: e.reset = true; break;
            case Action::ToggleHand: o.hand = !o.hand; break;
            case Action::ToggleShadows: f.shadows = !f.shadows; break;
            case Action::HandCloser: o.hand_distance = std::max(kMinHandDistance, o.hand_distance - kHandStep); break;
            case Action::ExposureDown:
            case Action::ExposureUp: {
                const double step = a == Action::ExposureUp ? kExposureStep : -kExposureStep;
                const auto range = math::limits::kExposure;
                f.exposure = std::clamp(f.exposure.value_or(layout_exposure) + step, range.min, range.max);
                break;
            }
            case Action::HandFurther: o.hand_distance = std::min(kMaxHandDistance, o.hand_distance + kHandStep); break;
        }
    }
    return e;
}

MoveInput move_input(const HeldKeys& held, double dt, bool cursor_captured, double mouse_dx, double mouse_dy) {
    MoveInput move;
    move.dt = std::min(dt, 0.1);
    move.forward = held.forward;
    move.right = held.right;
    move.up = held.up;
    move.fast = held.fast;
    if (cursor_captured) {
        move.mouse_dx = mouse_dx;
        move.mouse_dy = mouse_dy;
    }
    return move;
}

}  // namespace impossible::preview
