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

namespace impossible::gl {

enum class Backend { Egl, OSMesa };

const char* backend_name(Backend backend);
std::optional<Backend> parse_backend(const std::string& name);

struct ContextImpl;
void destroy_context(ContextImpl* impl);

// A current GL context; the GL functions are loaded while it lives.
// Move-only; destroying it releases the context.
struct Context {
    Backend backend = Backend::Egl;
    std::string renderer;  // GL_RENDERER
    std::string version;   // GL_VERSION
    std::unique_ptr<ContextImpl, void (*)(ContextImpl*)> impl{nullptr, destroy_context};
};

struct ContextResult {
    std::optional<Context> context;
    std::string error;  // why it failed, for humans
};

// Creates a GL 4.5 core context with the given backend and makes it current.
ContextResult create_context(Backend backend);

// The CLI's default: EGL, falling back to OSMesa when EGL fails. `errors`
// receives the EGL failure when the fallback was taken.
ContextResult create_context_with_fallback(std::optional<Backend> requested,
                                           std::string* fallback_note = nullptr);

}  // namespace impossible::gl
