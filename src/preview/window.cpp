#include "preview/window.hpp"

#include <cstdlib>
#include <optional>

#include "gl/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace impossible::preview {
namespace {

std::string glfw_error() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR) return "unknown GLFW error";
    return description ? description : "GLFW error " + std::to_string(code);
}

WindowInput& input_of(GLFWwindow* w) { return static_cast<PreviewWindow*>(glfwGetWindowUserPointer(w))->input; }

std::optional<Action> action_of_key(int key) {
    switch (key) {
        case GLFW_KEY_ESCAPE: return Action::Escape;
        case GLFW_KEY_H: return Action::ToggleHud;
        case GLFW_KEY_M: return Action::ToggleMinimap;
        case GLFW_KEY_V: return Action::NextView;
        case GLFW_KEY_LEFT_BRACKET: return Action::DepthDown;
        case GLFW_KEY_RIGHT_BRACKET: return Action::DepthUp;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: return Action::IpdDown;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD: return Action::IpdUp;
        case GLFW_KEY_C: return Action::NextClip;
        case GLFW_KEY_X: return Action::ToggleCulling;
        case GLFW_KEY_P:
        case GLFW_KEY_F12: return Action::Screenshot;
        case GLFW_KEY_R: return Action::Reset;
        case GLFW_KEY_G: return Action::ToggleHand;
        case GLFW_KEY_L: return Action::ToggleShadows;
        case GLFW_KEY_9: return Action::ExposureDown;
        case GLFW_KEY_0: return Action::ExposureUp;
        case GLFW_KEY_COMMA: return Action::HandCloser;
        case GLFW_KEY_PERIOD: return Action::HandFurther;
        default: return std::nullopt;
    }
}

void on_key(GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;  // a held key toggles once
    if (const std::optional<Action> a = action_of_key(key)) input_of(w).actions.push_back(*a);
}

HeldKeys held_keys(GLFWwindow* w) {
    auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
    auto axis = [&](int plus_a, int plus_b, int minus_a, int minus_b) {
        return int(down(plus_a) || down(plus_b)) - int(down(minus_a) || down(minus_b));
    };
    HeldKeys held;
    held.forward = axis(GLFW_KEY_W, GLFW_KEY_UP, GLFW_KEY_S, GLFW_KEY_DOWN);
    held.right = axis(GLFW_KEY_D, GLFW_KEY_RIGHT, GLFW_KEY_A, GLFW_KEY_LEFT);
    held.up = int(down(GLFW_KEY_E)) - int(down(GLFW_KEY_Q));
    held.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
    return held;
}

void on_cursor(GLFWwindow* w, double x, double y) {
    WindowInput& in = input_of(w);
    if (in.have_cursor) {
        in.mouse_dx += x - in.last_x;
        in.mouse_dy += y - in.last_y;
    }
    in.have_cursor = true;
    in.last_x = x;
    in.last_y = y;
}

void on_button(GLFWwindow* w, int button, int action, int) {
    if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS) input_of(w).clicked = true;
}

}  // namespace

PreviewWindow::~PreviewWindow() {
    if (window) glfwDestroyWindow(window);
    glfwTerminate();
}

Result<std::unique_ptr<PreviewWindow>> open_window(int width, int height, const std::string& title, bool vsync) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) {
        return Error{"no display: DISPLAY is not set (run it in a desktop session, or under 'xvfb-run -a')"};
    }
    if (!glfwInit()) {
        const std::string why = glfw_error();
        glfwTerminate();
        return Error{"no display: " + why};
    }
    auto made = std::make_unique<PreviewWindow>();  // from here on, its destructor ends GLFW
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    made->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!made->window) {
        return Error{"no OpenGL 4.5 core window: " + glfw_error()};
    }
    glfwMakeContextCurrent(made->window);
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress));
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45) {
        return Error{"the window's OpenGL context lacks 4.5 core functions"};
    }
    made->gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    made->gl_version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    glfwSwapInterval(vsync ? 1 : 0);
    glfwSetWindowUserPointer(made->window, made.get());
    glfwSetKeyCallback(made->window, on_key);
    glfwSetCursorPosCallback(made->window, on_cursor);
    glfwSetMouseButtonCallback(made->window, on_button);
    return made;
}

void capture_cursor(PreviewWindow& w, bool capture) {
    glfwSetInputMode(w.window, GLFW_CURSOR, capture ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
    if (capture && glfwRawMouseMotionSupported()) glfwSetInputMode(w.window, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    w.input.have_cursor = false;  // no jump from the old cursor position
}

bool cursor_captured(const PreviewWindow& w) { return glfwGetInputMode(w.window, GLFW_CURSOR) == GLFW_CURSOR_DISABLED; }

void poll_input(PreviewWindow& w) {
    w.input.actions.clear();
    w.input.mouse_dx = w.input.mouse_dy = 0.0;
    w.input.clicked = false;
    glfwPollEvents();
    w.input.held = held_keys(w.window);
}

bool should_close(const PreviewWindow& w) { return glfwWindowShouldClose(w.window); }
void request_close(PreviewWindow& w) { glfwSetWindowShouldClose(w.window, GLFW_TRUE); }
void framebuffer_size(const PreviewWindow& w, int& width, int& height) {
    glfwGetFramebufferSize(w.window, &width, &height);
}
void swap_buffers(PreviewWindow& w) { glfwSwapBuffers(w.window); }
void set_title(PreviewWindow& w, const std::string& title) { glfwSetWindowTitle(w.window, title.c_str()); }

}  // namespace impossible::preview
