// A program that owns its OpenGL context and draws impossible into it: an EGL
// surfaceless context (no window), a framebuffer object of its own, and the
// layout's tour walked frame by frame, each frame drawn into that framebuffer.
// It reads back the frame with the most portal passes and checks it against
// the library's own read-back of the same view. Usage: embed [LAYOUT.json [FRAME.ppm]]
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <impossible/impossible.hpp>

namespace api = impossible::api;

namespace {

// The few GL calls made here, through eglGetProcAddress: no GL loader needed.
struct Gl {
    PFNGLCREATEFRAMEBUFFERSPROC CreateFramebuffers;
    PFNGLCREATERENDERBUFFERSPROC CreateRenderbuffers;
    PFNGLNAMEDRENDERBUFFERSTORAGEPROC NamedRenderbufferStorage;
    PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC NamedFramebufferRenderbuffer;
    PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC CheckNamedFramebufferStatus;
    PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
    PFNGLPIXELSTOREIPROC PixelStorei;
    PFNGLREADPIXELSPROC ReadPixels;
};

template <class F>
void load(F& f, const char* name) {
    f = reinterpret_cast<F>(eglGetProcAddress(name));
}

void* proc_address(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

int fail(const std::string& what) {
    std::fprintf(stderr, "embed: %s\n", what.c_str());
    return 1;
}

// An OpenGL 4.5 core context without a window (EGL_MESA_platform_surfaceless), made current.
bool make_context(EGLDisplay& display, EGLContext& context) {
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) return false;
    display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API))
        return false;
    const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    return context != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

// Walks the tour, drawing each frame into `fbo`; reads back the frame with
// the most portal passes and compares it with the library's own read-back.
int walk_and_draw(const api::Layout& layout, const Gl& gl, GLuint fbo, api::View view, const char* ppm) {
    api::Expected<api::Renderer> renderer = api::Renderer::in_current_context(layout, proc_address);
    if (!renderer) return fail(renderer.error().message);
    std::printf("impossible %s on %s\n", api::version(), renderer->gl_renderer().c_str());
    api::Expected<std::vector<api::Pose>> poses = api::tour(layout);
    if (!poses) return fail(poses.error().message);
    const int w = 2 * view.width, h = view.height;
    std::vector<unsigned char> ours(std::size_t(w) * h * 3);  // bottom row first, as GL reads
    api::View kept = view;
    int most = -1;
    std::size_t teleports = 0, kept_frame = 0;
    api::Walker walker(layout);
    for (std::size_t i = 0; i < poses->size(); ++i) {
        const api::WalkStep step = walker.step((*poses)[i]);  // the physical head to the virtual one
        view.pose = step.virtual_pose;
        view.room = step.room;
        api::Expected<api::FrameStats> stats = renderer->draw_to(view, fbo);
        if (!stats) return fail(stats.error().message);
        std::printf("frame %zu: room %s, %d portal passes", i, step.room.c_str(), stats->portal_passes_drawn);
        for (const std::string& portal : step.teleports) std::printf(", teleport through %s", portal.c_str());
        std::printf("\n");
        teleports += step.teleports.size();
        if (stats->portal_passes_drawn > most) {
            most = stats->portal_passes_drawn;
            kept = view;
            kept_frame = i;
            gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
            gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
            gl.ReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, ours.data());
            gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        }
    }
    api::Expected<api::Frame> frame = renderer->render(kept);  // top row first
    if (!frame) return fail(frame.error().message);
    std::set<unsigned> colours;
    long differ = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned char* a = &ours[(std::size_t(h - 1 - y) * w + x) * 3];
            const unsigned char* b = &frame->rgb[(std::size_t(y) * w + x) * 3];
            colours.insert(a[0] << 16 | a[1] << 8 | a[2]);
            differ += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
        }
    std::printf(
        "walked %zu frames, %zu teleports; frame %zu (%dx%d, %d portal passes): %zu colours, %ld pixels "
        "differ from render()\n",
        poses->size(), teleports, kept_frame, w, h, most, colours.size(), differ);
    if (ppm != nullptr) {
        std::FILE* f = std::fopen(ppm, "wb");
        if (f == nullptr) return fail(std::string("cannot write ") + ppm);
        std::fprintf(f, "P6\n%d %d\n255\n", w, h);
        std::fwrite(frame->rgb.data(), 1, frame->rgb.size(), f);
        if (std::fclose(f) != 0) return fail(std::string("cannot write ") + ppm);
    }
    return teleports > 0 && colours.size() > 1 && differ == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    api::Expected<api::Layout> layout = argc > 1 ? api::Layout::load(argv[1]) : api::Layout::builtin();
    if (!layout) return fail(layout.error().message);
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    if (!make_context(display, context)) return fail("no OpenGL 4.5 context on the EGL surfaceless platform");
    Gl gl{};
    load(gl.CreateFramebuffers, "glCreateFramebuffers");
    load(gl.CreateRenderbuffers, "glCreateRenderbuffers");
    load(gl.NamedRenderbufferStorage, "glNamedRenderbufferStorage");
    load(gl.NamedFramebufferRenderbuffer, "glNamedFramebufferRenderbuffer");
    load(gl.CheckNamedFramebufferStatus, "glCheckNamedFramebufferStatus");
    load(gl.BindFramebuffer, "glBindFramebuffer");
    load(gl.PixelStorei, "glPixelStorei");
    load(gl.ReadPixels, "glReadPixels");
    api::View view;  // each eye 160 × 120; the framebuffer holds both side by side
    view.width = 160;
    view.height = 120;
    GLuint colour = 0, fbo = 0;
    gl.CreateRenderbuffers(1, &colour);
    gl.NamedRenderbufferStorage(colour, GL_RGBA8, 2 * view.width, view.height);
    gl.CreateFramebuffers(1, &fbo);
    gl.NamedFramebufferRenderbuffer(fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    if (gl.CheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return fail("the framebuffer is not complete");
    // The renderer lives inside walk_and_draw, so it is gone before its context.
    const int status = walk_and_draw(*layout, gl, fbo, view, argc > 2 ? argv[2] : nullptr);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglTerminate(display);
    return status;
}
