// The fixed-function state of every pass of the portal renderer, one
// immutable PassState each, kept in a table named by an enum. The stencil
// reference of every pass is the recursion level (given when applied).
//
// Depth is reversed-Z by default (glClipControl ZERO_TO_ONE, cleared to 0):
// nearer surfaces have greater depth. DepthMode::Standard flips every test.
#pragma once

#include <array>

#include "gl/state.hpp"

namespace impossible::render {

enum class Pass {
    Scene,          // the cell's rooms and props: colour, ids and depth where stencil == level
    PortalDepth,    // portal boxes into depth only, so they occlude and are occluded
    PortalTest,     // nothing written: an occlusion query of where the box is visible
    PortalMark,     // stencil level → level + 1 where the box is the visible surface
    ClearDepth,     // depth → far where stencil == level + 1 (drawn with ref = level + 1)
    PortalUnmark,   // stencil level + 1 → level, and the box's depth back (ref = level + 1)
    PortalFill,     // the flat fill colour and id (shading::kFillId) at the recursion limit
    PortalTexture,  // render-to-texture portals: the box shows its texture
    // Full-target triangles limited by the stencil to a mirror's or window's
    // pixels (ref = level + 1), after the view through it is drawn:
    Tint,         // colour ← colour · tint (the blend colour); ids kept
    ClearRegion,  // colour, ids and depth back to the background, between a window's two views
    WindowBlend,  // colour ← (r · reflected view) + colour · (1 - r) · tint; ids kept
    Count
};

// Every pass of the scene shader writes gl_ClipDistance[0..4]: the eye's
// rectangle (four) and the portal plane.
inline constexpr int kSceneClipDistances = 5;
// An object's instance also writes gl_ClipDistance[5..6]: the doors that cut
// it (shaders/scene.vert.glsl, OBJECT_CUTS).
inline constexpr int kObjectClipDistances = 7;

// A pass of the portal renderer: depth test on, stencil == reference, clip
// distances on, no blending.
inline constexpr gl::PassState portal_pass(bool depth_write, GLenum depth_func, GLuint color_mask, bool cull,
                                           GLenum stencil_pass_op) {
    gl::PassState s;
    s.depth_test = true;
    s.depth_write = depth_write;
    s.depth_func = depth_func;
    s.color_mask = color_mask;
    s.cull_back_faces = cull;
    s.stencil.enabled = true;
    s.stencil.func = GL_EQUAL;
    s.stencil.pass = stencil_pass_op;
    s.clip_distances = kSceneClipDistances;
    return s;
}

inline constexpr GLuint kColor = gl::kColorAll, kNoColor = gl::kColorNone;

// A full-target triangle where stencil == reference: no depth test unless it
// writes depth, no culling, no clip distances (the triangle has none).
inline constexpr gl::PassState region_pass(bool write_depth, bool write_ids, gl::Blend blend) {
    gl::PassState s;
    s.depth_test = write_depth;  // with GL_ALWAYS: only so that depth is written
    s.depth_write = write_depth;
    s.depth_func = GL_ALWAYS;
    s.write_ids = write_ids;
    s.cull_back_faces = false;
    s.stencil.enabled = true;
    s.stencil.func = GL_EQUAL;
    s.blend = blend;
    return s;
}

inline constexpr std::array<gl::PassState, static_cast<size_t>(Pass::Count)> kPassStates = {{
    // depth_write, depth_func, colour, cull_back_faces, stencil pass op
    portal_pass(true, GL_GREATER, kColor, true, GL_KEEP),    // Scene
    portal_pass(true, GL_GREATER, kNoColor, true, GL_KEEP),  // PortalDepth
    portal_pass(false, GL_GEQUAL, kNoColor, true, GL_KEEP),  // PortalTest
    portal_pass(false, GL_GEQUAL, kNoColor, true, GL_INCR),  // PortalMark
    portal_pass(true, GL_ALWAYS, kNoColor, false, GL_KEEP),  // ClearDepth
    portal_pass(true, GL_ALWAYS, kNoColor, true, GL_DECR),   // PortalUnmark
    portal_pass(false, GL_GEQUAL, kColor, true, GL_KEEP),    // PortalFill
    portal_pass(false, GL_GEQUAL, kColor, true, GL_KEEP),    // PortalTexture
    region_pass(false, false, gl::Blend::ScaleTarget),       // Tint
    region_pass(true, true, gl::Blend::Replace),             // ClearRegion
    region_pass(false, false, gl::Blend::AddScaledTarget),   // WindowBlend
}};

// Clearing a target (glClearNamedFramebuffer* obeys the write masks and the
// scissor): every write on. The clip distances stay as the passes want them.
inline constexpr gl::PassState kClearState = [] {
    gl::PassState s;
    s.clip_distances = kSceneClipDistances;
    return s;
}();

// The table above is for reversed-Z; with standard depth (nearer is less)
// every comparison flips.
inline constexpr gl::PassState with_standard_depth(gl::PassState s) {
    if (s.depth_func == GL_GREATER)
        s.depth_func = GL_LESS;
    else if (s.depth_func == GL_GEQUAL)
        s.depth_func = GL_LEQUAL;
    return s;
}

inline constexpr std::array<gl::PassState, static_cast<size_t>(Pass::Count)> kStandardDepthPassStates = [] {
    std::array<gl::PassState, static_cast<size_t>(Pass::Count)> out{};
    for (size_t i = 0; i < out.size(); ++i) out[i] = with_standard_depth(kPassStates[i]);
    return out;
}();

// The pass's state for the depth mode; a view with an odd number of
// reflections sees every triangle wound the other way.
inline gl::PassState pass_state(Pass pass, bool reversed_z, bool mirrored = false) {
    gl::PassState s = (reversed_z ? kPassStates : kStandardDepthPassStates)[static_cast<size_t>(pass)];
    s.front_clockwise = mirrored;
    return s;
}

}  // namespace impossible::render
