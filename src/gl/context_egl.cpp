// EGL surfaceless platform (EGL_MESA_platform_surfaceless): a 4.5 core
// context with no window system and no surface (EGL_KHR_surfaceless_context).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>

#include "gl/context_backends.hpp"

namespace impossible::gl {
namespace {

struct EglState {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

void destroy_egl_state(void* p) {
    auto* s = static_cast<EglState*>(p);
    if (s->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(s->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (s->context != EGL_NO_CONTEXT) eglDestroyContext(s->display, s->context);
        // The display stays initialised: every context is on this one
        // surfaceless display, which eglTerminate would end for the others
        // too, and Mesa 22 leaks about 24 KB each time it is initialised
        // again (a program making renderers one after another). Mesa ends
        // it at exit.
        eglReleaseThread();  // frees this thread's EGL state (else it leaks at exit)
    }
    delete s;
}

bool make_egl_current(void* p) {
    const auto* s = static_cast<const EglState*>(p);
    // EGL takes a context it holds as current for current and does nothing,
    // though an OSMesa context may have taken the thread since: release it
    // first, so it is bound again.
    if (eglGetCurrentContext() == s->context)
        eglMakeCurrent(s->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    return eglMakeCurrent(s->display, EGL_NO_SURFACE, EGL_NO_SURFACE, s->context) == EGL_TRUE;
}

ProcAddress egl_proc(const char* name) { return reinterpret_cast<ProcAddress>(eglGetProcAddress(name)); }

}  // namespace

BackendContext create_egl_context() {
    BackendContext out;
    // Mesa's EGL prints warnings of its own ("libEGL warning: egl: failed to
    // create dri2 screen") on stderr, which would make our one-line error
    // messages several lines long; the failure still comes back to us.
    // Unless the user asked for a log level.
    ::setenv("EGL_LOG_LEVEL", "fatal", 0);
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) {
        out.error = "EGL: eglGetPlatformDisplayEXT is not available";
        return out;
    }
    auto* state = new EglState;
    out.state = {state, destroy_egl_state};
    state->display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (state->display == EGL_NO_DISPLAY || !eglInitialize(state->display, &major, &minor)) {
        state->display = EGL_NO_DISPLAY;
        out.error = "EGL: no surfaceless display (EGL_MESA_platform_surfaceless)";
        return out;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        out.error = "EGL: desktop OpenGL is not available";
        return out;
    }
    const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    state->context = eglCreateContext(state->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (state->context == EGL_NO_CONTEXT) {
        out.error = "EGL: cannot create an OpenGL 4.5 core context";
        return out;
    }
    if (!eglMakeCurrent(state->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state->context)) {
        out.error = "EGL: cannot make the context current without a surface";
        return out;
    }
    out.load = egl_proc;
    out.make_current = make_egl_current;
    return out;
}

}  // namespace impossible::gl
