// Fixed-function state as plain data, applied through one shadow cache that
// compares before it calls GL (as filament's OpenGLContext does). Render code
// describes each pass with one immutable PassState and never calls
// glEnable/glDepthFunc/... itself; the bindings (program, vertex array, the
// texture on each unit, the draw and read framebuffers, the indirect draw
// buffer), the viewports and
// the clip control go through the same cache. Each draw names all of its
// state; what GL already holds costs nothing, so nothing is ever put back.
//
// One cache per GL context, shared by everything that draws with it (every
// renderer, the preview's present and overlays): the cache then always knows
// what GL holds, and nothing saves or restores state with glGet. Code that
// changes any of this state behind the cache's back must call invalidate()
// before the cache is used again. Objects must not be deleted while the cache
// thinks them bound (a new object may get the same name, and the cache would
// skip binding it): a user either releases its bindings through the cache
// when it is done (release_bindings(), as the renderer does after each
// frame), or tells the cache about an object it deletes while bound
// (deleting_texture, deleting_framebuffer).
#pragma once

#include "gl/gl.hpp"

namespace impossible::gl {

// Colour write masks: bit i is channel i (R, G, B, A) of every attachment.
inline constexpr GLuint kColorAll = 0xF;
inline constexpr GLuint kColorNone = 0x0;
inline constexpr GLuint color_channels(bool r, bool g, bool b, bool a) {
    return (r ? 1u : 0u) | (g ? 2u : 0u) | (b ? 4u : 0u) | (a ? 8u : 0u);
}

// Enough for every user here (the scene shader writes five).
inline constexpr int kMaxClipDistances = 8;

// Texture units the cache tracks (the renderer uses 0 to 4: scene data,
// shadow maps, moving-prop instance records).
inline constexpr int kTextureUnits = 8;

// Viewport indices the cache tracks: 0, which every draw uses, and 1, the
// right eye's when the vertex shader writes gl_ViewportIndex. No shader here
// writes a higher index.
inline constexpr int kViewports = 2;

struct StencilState {
    bool enabled = false;
    GLenum func = GL_ALWAYS;  // compared against the reference given with apply()
    GLuint read_mask = 0xff;
    GLenum fail = GL_KEEP, depth_fail = GL_KEEP, pass = GL_KEEP;
    GLuint write_mask = 0xff;
    bool operator==(const StencilState&) const = default;
};

// How a fragment's colour meets the one in the target (integer attachments
// are never blended). K is the blend colour (StateCache::blend_color).
enum class Blend {
    Replace,
    AlphaOver,       // straight alpha "over" (overlays)
    ScaleTarget,     // target · K: the fragment's colour is ignored
    AddScaledTarget  // fragment + target · K
};

struct PassState {
    bool depth_test = true;
    bool depth_write = true;
    GLenum depth_func = GL_GREATER;  // reversed-Z: nearer is greater
    GLuint color_mask = kColorAll;   // all colour attachments
    bool write_ids = true;           // draw buffer 1 (ids) too, as color_mask says; false: never
    bool cull_back_faces = true;
    bool front_clockwise = false;  // fronts wind clockwise (a view through a mirror)
    StencilState stencil;
    int clip_distances = 0;  // GL_CLIP_DISTANCE0 .. n - 1 enabled
    Blend blend = Blend::Replace;
    // glPolygonOffset(factor, units) on filled polygons; off while both are 0.
    float offset_factor = 0.0f;
    float offset_units = 0.0f;
    bool operator==(const PassState&) const = default;
};

// Plain 2D drawing (overlays, an image shown in a window): no depth,
// stencil, culling or clip distances; the given colour channels; straight
// alpha blending or none.
inline constexpr PassState plain_2d_state(bool blend, GLuint color_mask = kColorAll) {
    PassState s;
    s.depth_test = false;
    s.depth_write = false;
    s.color_mask = color_mask;
    s.cull_back_faces = false;
    s.blend = blend ? Blend::AlphaOver : Blend::Replace;
    return s;
}

// A rectangle in GL window coordinates (origin bottom-left).
struct WindowRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool operator==(const WindowRect&) const = default;
};
using ScissorRect = WindowRect;

class StateCache {
public:
    // Forgets what GL holds, so that the next call of each kind sets it. Only
    // for when code outside the cache has changed state on this context.
    void invalidate();

    void apply(const PassState& state, GLint stencil_ref);
    // The constant K of Blend::ScaleTarget and Blend::AddScaledTarget.
    void blend_color(float r, float g, float b, float a);
    void scissor(const WindowRect& rect);  // enables the scissor test
    void no_scissor();
    // Every viewport index at once (glViewport).
    void viewport(const WindowRect& rect);
    // One viewport index below kViewports (per-eye viewports, or the whole
    // target through index 0 for a draw without an eye).
    void viewport_indexed(GLuint index, const WindowRect& rect);
    void program(GLuint program);
    void vertex_array(GLuint vertex_array);
    void draw_framebuffer(GLuint framebuffer);
    void read_framebuffer(GLuint framebuffer);
    // GL_DRAW_INDIRECT_BUFFER, which glMultiDrawElementsIndirect reads.
    void draw_indirect_buffer(GLuint buffer);
    // glBindTextureUnit: `texture` on its own target of unit `unit` (below
    // kTextureUnits); 0 unbinds every target of the unit.
    void texture(GLuint unit, GLuint texture);
    // glClipControl with a lower-left origin and the given depth mode
    // (GL_ZERO_TO_ONE or GL_NEGATIVE_ONE_TO_ONE).
    void clip_control(GLenum depth);

    // Before `texture` (`framebuffer`) is deleted while the cache may hold it
    // bound: GL unbinds it, and a new object may get its name, so the cache
    // forgets what those units (bindings) hold and binds them when next asked.
    void deleting_texture(GLuint texture);
    void deleting_framebuffer(GLuint framebuffer);

    // Binds 0 for every object binding the cache holds (program, vertex
    // array, framebuffers, indirect buffer, texture units), so that the objects of whoever
    // drew last may be deleted. Called once when a user is done with the
    // context for now (the renderer, at the end of a frame).
    void release_bindings();

private:
    static constexpr GLuint kUnknown = ~GLuint{0};

    bool known_ = false;  // state_ and stencil_ref_ are what GL holds
    PassState state_;
    GLint stencil_ref_ = 0;
    bool blend_color_known_ = false;
    float blend_color_[4] = {0, 0, 0, 0};
    bool scissor_known_ = false;
    bool scissor_on_ = false;
    WindowRect scissor_;
    bool viewport_known_[kViewports] = {};
    WindowRect viewport_[kViewports];
    GLuint program_ = kUnknown;
    GLuint vertex_array_ = kUnknown;
    GLuint draw_framebuffer_ = kUnknown;
    GLuint read_framebuffer_ = kUnknown;
    GLuint draw_indirect_buffer_ = kUnknown;
    static_assert(kTextureUnits == 8, "one kUnknown per texture unit below");
    GLuint textures_[kTextureUnits] = {kUnknown, kUnknown, kUnknown, kUnknown, kUnknown, kUnknown, kUnknown, kUnknown};
    GLenum clip_depth_ = kUnknown;
};

}  // namespace impossible::gl
