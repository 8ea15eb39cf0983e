// What the preview's keys mean, apart from any window system: the window
// (window.cpp) turns key presses into Actions and the held keys into
// HeldKeys, so no other part of the preview sees a GLFW key code.
#pragma once

namespace impossible::preview {

// One key press (a held key acts once).
enum class Action {
    Escape,         // Esc: releases a captured cursor, or quits
    ToggleHud,      // H
    ToggleMinimap,  // M
    NextView,       // V: parallel, cross, anaglyph
    DepthDown,      // [
    DepthUp,        // ]
    IpdDown,        // - (also the keypad's)
    IpdUp,          // = (also the keypad's +)
    NextClip,       // C: clip distances or oblique projection
    ToggleCulling,  // X
    Screenshot,     // P or F12
    Reset,          // R: back to the start
    ToggleHand,     // G: a hand held out in front of the head
    HandCloser,     // , : the hand nearer the head
    HandFurther,    // . : the hand further out
    ToggleShadows,  // L: the shadows props cast in lit layouts, on or off
    ExposureDown,   // 9: exposure 0.5 EV lower
    ExposureUp,     // 0: exposure 0.5 EV higher
};

// The movement keys held down now: -1, 0 or +1 on each axis.
struct HeldKeys {
    int forward = 0;    // W or Up / S or Down
    int right = 0;      // D or Right / A or Left
    int up = 0;         // E / Q
    bool fast = false;  // Shift
};

}  // namespace impossible::preview
