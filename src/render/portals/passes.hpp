// The fixed-function state of every pass of the portal renderer, one
// immutable PassState each, kept in a table named by an enum. Each draw names
// a recursion level; the stencil reference it is applied with encodes that
// level (stencil_reference below).
//
// The stencil holds each pixel's level, counted down from the top so that a
// headset's hidden area (255, hidden_mask.hpp) lies above every level and no
// test of "this level or deeper" reaches it. With max_depth <= kMaxBoxBitDepth
// the lowest bit is the box bit: a pixel of level L is 253 - 2L, or 252 - 2L
// where a portal box of the level is the visible surface (PortalDepth clears
// the bit, every Scene fragment that passes sets it again on a level with
// visible portals, LevelView::box_bits), so that one quad
// per eye can mark a portal and reset its depth at once (PortalMarkReset).
// Deeper limits use 254 - L and no box bit. Levels are compared through the
// read mask (0xFE with the box bit): a comparison of levels flips
// (GL_GREATER: the reference's level is the lower one).
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
    ClearDepth,     // depth → far where stencil == level + 1 (drawn with level + 1)
    PortalUnmark,   // stencil deeper than level → level, and the box's depth back
    PortalFill,     // the flat fill colour and id (shading::kFillId) at the recursion limit
    PortalTexture,  // render-to-texture portals: the box shows its texture
    // Full-target triangles limited by the stencil to a mirror's or window's
    // pixels (drawn with level + 1: that level or deeper), after the view
    // through it is drawn:
    Tint,         // colour ← colour · tint (the blend colour); ids kept
    ClearRegion,  // colour, ids, depth and stencil (level + 1) back to the background, between a window's two views
    WindowBlend,  // colour ← (r · reflected view) + colour · (1 - r) · tint; ids kept
    // Mark and depth reset in one (box bit only): quads; where the box bit
    // says a box of the level is visible, stencil → level + 1 and depth → far
    // (drawn with level).
    PortalMarkReset,
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

// A full-target triangle where the stencil's level is the reference's or
// deeper: no depth test unless it writes depth, no culling, no clip distances
// (the triangle has none).
inline constexpr gl::PassState region_pass(bool write_depth, bool write_ids, gl::Blend blend,
                                           GLenum stencil_pass_op = GL_KEEP) {
    gl::PassState s;
    s.depth_test = write_depth;  // with GL_ALWAYS: only so that depth is written
    s.depth_write = write_depth;
    s.depth_func = GL_ALWAYS;
    s.write_ids = write_ids;
    s.cull_back_faces = false;
    s.stencil.enabled = true;
    s.stencil.func = GL_GEQUAL;  // that level or deeper (a skipped unmark's pixels, PortalSteps)
    s.stencil.pass = stencil_pass_op;
    s.blend = blend;
    return s;
}

// The unmark: where the stencil's level is deeper than the reference's
// (levels count down: reference greater), back to it, with the box's depth.
inline constexpr gl::PassState unmark_pass() {
    gl::PassState s = portal_pass(true, GL_ALWAYS, kNoColor, true, GL_REPLACE);
    s.stencil.func = GL_GREATER;
    return s;
}

inline constexpr std::array<gl::PassState, static_cast<size_t>(Pass::Count)> kPassStates = {{
    // depth_write, depth_func, colour, cull_back_faces, stencil pass op
    portal_pass(true, GL_GREATER, kColor, true, GL_KEEP),     // Scene
    portal_pass(true, GL_GREATER, kNoColor, true, GL_KEEP),   // PortalDepth
    portal_pass(false, GL_GEQUAL, kNoColor, true, GL_KEEP),   // PortalTest
    portal_pass(false, GL_GEQUAL, kNoColor, true, GL_DECR),   // PortalMark (levels count down)
    portal_pass(true, GL_ALWAYS, kNoColor, false, GL_KEEP),   // ClearDepth
    unmark_pass(),                                            // PortalUnmark
    portal_pass(false, GL_GEQUAL, kColor, true, GL_KEEP),     // PortalFill
    portal_pass(false, GL_GEQUAL, kColor, true, GL_KEEP),     // PortalTexture
    region_pass(false, false, gl::Blend::ScaleTarget),        // Tint
    region_pass(true, true, gl::Blend::Replace, GL_REPLACE),  // ClearRegion
    region_pass(false, false, gl::Blend::AddScaledTarget),    // WindowBlend
    portal_pass(true, GL_ALWAYS, kNoColor, false, GL_DECR),   // PortalMarkReset
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

// The deepest recursion limit with a box bit in the stencil: level 126 is
// 1 and 0, and 255 (254 under the read mask) is left to the hidden area.
inline constexpr int kMaxBoxBitDepth = 126;

inline constexpr bool has_box_bit(int max_depth) { return max_depth <= kMaxBoxBitDepth; }

// The stencil value of a pixel of `level` (no box visible) in a frame of
// recursion limit max_depth: what a target is cleared to.
inline constexpr GLint stencil_level(int max_depth, int level) {
    return has_box_bit(max_depth) ? 253 - 2 * level : 254 - level;
}

// The stencil reference of a draw of `pass` named with `level`, and its
// state's masks and operation for the frame's encoding. `box_bits`: the
// level has visible portals, whose boxes its surfaces may hide (else its
// surfaces write no stencil).
inline GLint stencil_reference(Pass pass, int level, int max_depth, bool box_bits, gl::StencilState& s) {
    const GLint value = stencil_level(max_depth, level);
    if (!has_box_bit(max_depth)) return value;
    s.read_mask = 0xFE;  // the level, not the box bit
    switch (pass) {
        case Pass::Scene:  // a surface drawn: no box is visible here
            if (!box_bits) return value;
            s.pass = GL_REPLACE;
            s.write_mask = 0x01;
            return value;
        case Pass::PortalDepth:  // a box is the nearest so far: the bit cleared
            s.pass = GL_REPLACE;
            s.write_mask = 0x01;
            return value - 1;
        case Pass::PortalMark:
        case Pass::PortalMarkReset:  // where the bit is clear: level + 1 (one down) and the bit set
            s.read_mask = 0xFF;
            return value - 1;
        default: return value;
    }
}

// The pass's state for the depth mode; a view with an odd number of
// reflections sees every triangle wound the other way.
inline gl::PassState pass_state(Pass pass, bool reversed_z, bool mirrored = false) {
    gl::PassState s = (reversed_z ? kPassStates : kStandardDepthPassStates)[static_cast<size_t>(pass)];
    s.front_clockwise = mirrored;
    return s;
}

}  // namespace impossible::render
