// The web build's context (emscripten only): WebGL 2 on the page's canvas
// "#impossible-gl", with depth and an 8-bit stencil; everything is drawn to
// framebuffer objects, so the canvas's own buffers only show the preview.
// The native build's file is empty.
#if defined(__EMSCRIPTEN__)

#include <emscripten/html5.h>

#include "gl/context_backends.hpp"
#include "gl/webgl.hpp"

namespace impossible::gl {

namespace {

bool make_current(void* state) {
    const auto context = static_cast<EMSCRIPTEN_WEBGL_CONTEXT_HANDLE>(reinterpret_cast<std::intptr_t>(state));
    return emscripten_webgl_make_context_current(context) == EMSCRIPTEN_RESULT_SUCCESS;
}

}  // namespace

BackendContext create_egl_context() {
    BackendContext made;
    // One context for the page: every renderer shares it.
    static EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = 0;
    if (context == 0) {
        EmscriptenWebGLContextAttributes attributes;
        emscripten_webgl_init_context_attributes(&attributes);
        attributes.majorVersion = 2;
        attributes.minorVersion = 0;
        attributes.alpha = false;
        attributes.depth = true;
        attributes.stencil = true;
        attributes.antialias = false;
        attributes.preserveDrawingBuffer = true;
        attributes.enableExtensionsByDefault = true;
        attributes.powerPreference = EM_WEBGL_POWER_PREFERENCE_HIGH_PERFORMANCE;
        context = emscripten_webgl_create_context("#impossible-gl", &attributes);
        if (context <= 0) {
            made.error =
                "webgl: no WebGL 2 context on the canvas #impossible-gl (code " + std::to_string(context) + ")";
            context = 0;
            return made;
        }
    }
    if (emscripten_webgl_make_context_current(context) != EMSCRIPTEN_RESULT_SUCCESS) {
        made.error = "webgl: cannot make the WebGL 2 context current";
        return made;
    }
    webgl::read_extensions();
    made.state = std::unique_ptr<void, void (*)(void*)>(reinterpret_cast<void*>(static_cast<std::intptr_t>(context)),
                                                        [](void*) {});
    made.make_current = make_current;
    return made;
}

BackendContext create_osmesa_context() {
    BackendContext made;
    made.error = "osmesa: the web build draws with WebGL 2 only";
    return made;
}

}  // namespace impossible::gl

#endif  // __EMSCRIPTEN__
