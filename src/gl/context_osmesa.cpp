// OSMesa: Mesa's off-screen software context, 4.5 core through
// OSMesaCreateContextAttribs. Its own colour buffer (bottom-up rows) is a
// 1×1 placeholder: rendering goes to framebuffer objects.
#include <GL/osmesa.h>

#include <cstdlib>
#include <string>

#include "gl/context_backends.hpp"

namespace impossible::gl {
namespace {

struct OSMesaState {
    OSMesaContext context = nullptr;
    unsigned char buffer[4] = {};
};

void destroy_osmesa_state(void* p) {
    auto* s = static_cast<OSMesaState*>(p);
    if (s->context) OSMesaDestroyContext(s->context);
    delete s;
}

bool make_osmesa_current(void* p) {
    auto* s = static_cast<OSMesaState*>(p);
    return OSMesaMakeCurrent(s->context, s->buffer, GL_UNSIGNED_BYTE, 1, 1) == GL_TRUE;
}

ProcAddress osmesa_proc(const char* name) { return reinterpret_cast<ProcAddress>(OSMesaGetProcAddress(name)); }

// OSMesa picks its Gallium driver by the GALLIUM_DRIVER variable and, given
// one it cannot load, crashes inside OSMesaCreateContextAttribs instead of
// failing (Mesa 22). It runs only the software rasterisers, so anything else
// is refused before the call.
bool osmesa_driver_ok(std::string* why) {
    const char* driver = std::getenv("GALLIUM_DRIVER");
    if (!driver || !*driver) return true;
    const std::string name = driver;
    if (name == "llvmpipe" || name == "softpipe") return true;
    std::string shown;
    for (char c : name.substr(0, 40)) shown += (c >= 0x20 && c < 0x7F) ? c : '?';
    *why = "OSMesa: GALLIUM_DRIVER='" + shown + "' is not a driver it can use (llvmpipe or softpipe); unset it";
    return false;
}

}  // namespace

BackendContext create_osmesa_context() {
    BackendContext out;
    if (!osmesa_driver_ok(&out.error)) return out;
    auto* state = new OSMesaState;
    out.state = {state, destroy_osmesa_state};
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    state->context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!state->context) {
        out.error = "OSMesa: cannot create an OpenGL 4.5 core context";
        return out;
    }
    if (!OSMesaMakeCurrent(state->context, state->buffer, GL_UNSIGNED_BYTE, 1, 1)) {
        out.error = "OSMesa: cannot make the context current";
        return out;
    }
    out.load = osmesa_proc;
    out.make_current = make_osmesa_current;
    return out;
}

}  // namespace impossible::gl
