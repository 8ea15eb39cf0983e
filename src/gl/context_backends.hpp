// Internal to src/gl: each backend in its own file, so that the EGL and OSMesa
// headers (which pull in their own GL declarations) never meet glad's.
#pragma once

#include <memory>
#include <string>

namespace impossible::gl {

using ProcAddress = void (*)();
using LoadProc = ProcAddress (*)(const char*);  // the shape of glad's GLADloadfunc

struct BackendContext {
    std::unique_ptr<void, void (*)(void*)> state{nullptr, [](void*) {}};
    LoadProc load = nullptr;  // set when the context is current
    // Makes the context current on this thread again; false when that fails.
    bool (*make_current)(void* state) = nullptr;
    std::string error;
};

BackendContext create_egl_context();
BackendContext create_osmesa_context();

}  // namespace impossible::gl
