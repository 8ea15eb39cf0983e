// The preview's GLFW window with an OpenGL 4.5 core context, GL loaded with
// glad through glfwGetProcAddress, and the input of each frame collected from
// GLFW's callbacks. GLFW's key codes stay in window.cpp: the input holds the
// preview's actions and held movement keys (actions.hpp).
#pragma once

#include <memory>

#include <string>
#include <vector>

#include "base/result.hpp"
#include "preview/actions.hpp"

struct GLFWwindow;

namespace impossible::preview {

struct WindowInput {
    std::vector<Action> actions;  // keys pressed since the last frame, in order (no repeats)
    HeldKeys held;                // the movement keys down after the last poll
    double mouse_dx = 0.0, mouse_dy = 0.0;
    bool clicked = false;
    bool have_cursor = false;  // last_x/last_y are valid
    double last_x = 0.0, last_y = 0.0;
};

struct PreviewWindow {
    GLFWwindow* window = nullptr;
    WindowInput input;
    std::string gl_renderer, gl_version;
    PreviewWindow() = default;
    PreviewWindow(const PreviewWindow&) = delete;
    PreviewWindow& operator=(const PreviewWindow&) = delete;
    ~PreviewWindow();  // destroys the window and ends GLFW
};

// Opens a visible, resizable window of width × height with a current 4.5 core
// context. Fails with one clear line: no display, no 4.5 core context, ...
Result<std::unique_ptr<PreviewWindow>> open_window(int width, int height, const std::string& title, bool vsync);

// Captures (hides and locks) the cursor for mouse look, or releases it.
void capture_cursor(PreviewWindow& window, bool capture);
bool cursor_captured(const PreviewWindow& window);

// Polls events into window.input (cleared first).
void poll_input(PreviewWindow& window);

bool should_close(const PreviewWindow& window);
void request_close(PreviewWindow& window);
void framebuffer_size(const PreviewWindow& window, int& width, int& height);
void swap_buffers(PreviewWindow& window);
void set_title(PreviewWindow& window, const std::string& title);

}  // namespace impossible::preview
