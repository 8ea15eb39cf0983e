#include "gl/context.hpp"

#include "gl/context_backends.hpp"
#include "gl/gl.hpp"
#include "gl/state.hpp"

namespace impossible::gl {

struct ContextImpl {
    BackendContext backend;
    StateCache state;
};

namespace {

// The context last made current on this thread (none: unknown), and the
// loader the GL functions were last loaded through (they are process-wide).
thread_local const ContextImpl* current_context = nullptr;
const void* functions_from = nullptr;

}  // namespace

StateCache& Context::state() const { return impl->state; }

void destroy_context(ContextImpl* impl) {
    // Destroying a context leaves none current.
    current_context = nullptr;
    delete impl;
}

Result<void> make_current(const Context& context) {
    const ContextImpl* impl = context.impl.get();
    if (impl == current_context) return {};
    if (!impl->backend.make_current(impl->backend.state.get()))
        return Error{std::string(backend_name(context.backend)) + ": cannot make the context current again"};
    current_context = impl;
#if !defined(__EMSCRIPTEN__)
    if (functions_from != reinterpret_cast<const void*>(impl->backend.load)) {
        gladLoadGL(reinterpret_cast<GLADloadfunc>(impl->backend.load));
        functions_from = reinterpret_cast<const void*>(impl->backend.load);
    }
#endif
    return {};
}

const char* backend_name(Backend backend) {
#if defined(__EMSCRIPTEN__)
    if (backend == Backend::Egl) return "webgl";
#endif
    return backend == Backend::Egl ? "egl" : "osmesa";
}

std::optional<Backend> parse_backend(const std::string& name) {
    if (name == "egl") return Backend::Egl;
    if (name == "osmesa") return Backend::OSMesa;
    return std::nullopt;
}

Result<Context> create_context(Backend backend) {
    current_context = nullptr;  // whatever happens, the new context or none is current
    BackendContext made = backend == Backend::Egl ? create_egl_context() : create_osmesa_context();
    if (!made.error.empty()) return Error{made.error};
#if !defined(__EMSCRIPTEN__)
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(made.load));
    functions_from = reinterpret_cast<const void*>(made.load);
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45)
        return Error{std::string(backend_name(backend)) + ": OpenGL 4.5 core functions could not be loaded"};
#endif
    Context context;
    context.backend = backend;
    context.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    context.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    context.impl.reset(new ContextImpl{std::move(made), {}});
    current_context = context.impl.get();
    return context;
}

Result<void> load_functions(void* (*get_proc_address)(const char* name)) {
    if (get_proc_address == nullptr) return Error{"no GL function loader was given"};
    current_context = nullptr;
#if defined(__EMSCRIPTEN__)
    return Error{"the web build loads no GL functions: it calls WebGL 2"};
#else
    if (functions_from == reinterpret_cast<const void*>(get_proc_address)) return {};
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc_address));
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45) {
        functions_from = nullptr;
        return Error{"the current context does not offer OpenGL 4.5 core (or none is current)"};
    }
    functions_from = reinterpret_cast<const void*>(get_proc_address);
    return {};
#endif
}

Result<Context> create_context_with_fallback(std::optional<Backend> requested, std::string* fallback_note) {
    if (requested) return create_context(*requested);
    Result<Context> egl = create_context(Backend::Egl);
    if (egl) return egl;
    Result<Context> osmesa = create_context(Backend::OSMesa);
    if (!osmesa) return Error{egl.error() + "; " + osmesa.error()};
    if (fallback_note) *fallback_note = egl.error() + "; using osmesa";
    return osmesa;
}

}  // namespace impossible::gl
