// Headless OpenGL 4.5 core contexts: EGL surfaceless (Mesa) or OSMesa.
//
// Both backends live in one binary, so nothing links against GL entry points:
// after the context is current, the glad loader generated at build time pulls
// every function through eglGetProcAddress or OSMesaGetProcAddress. The
// context only provides a current GL; all rendering goes to framebuffer
// objects, so the default framebuffer of either backend is never read.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "base/result.hpp"

namespace impossible::gl {

enum class Backend { Egl, OSMesa };

const char* backend_name(Backend backend);
std::optional<Backend> parse_backend(const std::string& name);

class StateCache;
struct ContextImpl;
void destroy_context(ContextImpl* impl);

// A current GL context; the GL functions are loaded while it lives.
// Move-only; destroying it releases the context.
struct Context {
    Backend backend = Backend::Egl;
    std::string renderer;  // GL_RENDERER
    std::string version;   // GL_VERSION
    std::unique_ptr<ContextImpl, void (*)(ContextImpl*)> impl{nullptr, destroy_context};

    // The context's one state cache (gl/state.hpp), for every renderer drawn
    // with it. Stays at its address when the context is moved.
    StateCache& state() const;
};

// Creates a GL 4.5 core context with the given backend and makes it current.
// The error says why it failed, for humans.
Result<Context> create_context(Backend backend);

// Makes the context current on this thread, unless it was the last one made
// current here, reloading the GL functions when they came from the other
// backend: for a program with several contexts (the public API's renderers).
Result<void> make_current(const Context& context);

// Loads the GL 4.5 core functions of a context someone else made current
// (a program embedding the library), through that context's loader, e.g.
// eglGetProcAddress or glfwGetProcAddress; nothing to do if they came from
// that loader last. The next make_current makes its context current again.
Result<void> load_functions(void* (*get_proc_address)(const char* name));

// The CLI's default: EGL, falling back to OSMesa when EGL fails.
// `fallback_note` receives the EGL failure when the fallback was taken.
Result<Context> create_context_with_fallback(std::optional<Backend> requested, std::string* fallback_note = nullptr);

}  // namespace impossible::gl
