// What the preview does with the keys of one frame: toggles and steps of the
// options, and the head's movement input. No window, no GL.
#pragma once

#include <vector>

#include "math/view_limits.hpp"
#include "preview/actions.hpp"
#include "preview/head.hpp"
#include "preview/options.hpp"

namespace impossible::preview {

// What the caller must do after the frame's actions.
struct KeyEffects {
    bool quit = false;
    bool release_cursor = false;
    bool screenshot = false;
    bool reset = false;
};

inline constexpr int kMaxPreviewDepth = math::limits::kMaxDepth.max;
inline constexpr double kIpdStep = 0.002, kMaxIpd = 10.0;
inline constexpr double kExposureStep = 0.5;  // EV a press of 9 or 0

// Applies the actions in order to `options`. Esc releases a captured cursor;
// with the cursor free (or released by an earlier Esc of the frame) it quits.
// The exposure keys start from --exposure, else `layout_exposure` (the
// layout's "exposure"), and stay within math::limits::kExposure.
KeyEffects apply_actions(const std::vector<Action>& actions, bool cursor_captured, PreviewOptions& options,
                         double layout_exposure = 0.0);

// The head's movement for one frame: the held keys, and the mouse only while
// it is captured. dt is capped at 0.1 s (a stalled frame does not jump).
MoveInput move_input(const HeldKeys& held, double dt, bool cursor_captured, double mouse_dx, double mouse_dy);

}  // namespace impossible::preview
