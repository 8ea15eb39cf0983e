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
    Scene,         // the cell's rooms and props: colour, ids and depth where stencil == level
    PortalDepth,   // portal boxes into depth only, so they occlude and are occluded
    PortalTest,    // nothing written: an occlusion query of where the box is visible
    PortalMark,    // stencil level → level + 1 where the box is the visible surface
    ClearDepth,    // depth → far where stencil == level + 1 (drawn with ref = level + 1)
    PortalUnmark,  // stencil level + 1 → level, and the box's depth back (ref = level + 1)
    PortalFill,    // the flat fill colour and id 255 at the recursion limit
    PortalTexture, // render-to-texture portals: the box shows its texture
    Count
};

inline constexpr gl::StencilState stencil_equal(GLenum pass_op) {
    gl::StencilState s;
    s.enabled = true;
    s.func = GL_EQUAL;
    s.pass = pass_op;
    return s;
}

inline constexpr std::array<gl::PassState, static_cast<size_t>(Pass::Count)> kPassStates = {{
    // depth_test, depth_write, depth_func, color_write, cull_back_faces, stencil
    {true, true, GL_GREATER, true, true, stencil_equal(GL_KEEP)},     // Scene
    {true, true, GL_GREATER, false, true, stencil_equal(GL_KEEP)},    // PortalDepth
    {true, false, GL_GEQUAL, false, true, stencil_equal(GL_KEEP)},    // PortalTest
    {true, false, GL_GEQUAL, false, true, stencil_equal(GL_INCR)},    // PortalMark
    {true, true, GL_ALWAYS, false, false, stencil_equal(GL_KEEP)},    // ClearDepth
    {true, true, GL_ALWAYS, false, true, stencil_equal(GL_DECR)},     // PortalUnmark
    {true, false, GL_GEQUAL, true, true, stencil_equal(GL_KEEP)},     // PortalFill
    {true, false, GL_GEQUAL, true, true, stencil_equal(GL_KEEP)},     // PortalTexture
}};

// The table above is for reversed-Z; with standard depth (nearer is less)
// every comparison flips.
inline constexpr gl::PassState with_standard_depth(gl::PassState s) {
    if (s.depth_func == GL_GREATER) s.depth_func = GL_LESS;
    else if (s.depth_func == GL_GEQUAL) s.depth_func = GL_LEQUAL;
    return s;
}

inline constexpr std::array<gl::PassState, static_cast<size_t>(Pass::Count)> kStandardDepthPassStates = [] {
    std::array<gl::PassState, static_cast<size_t>(Pass::Count)> out{};
    for (size_t i = 0; i < out.size(); ++i) out[i] = with_standard_depth(kPassStates[i]);
    return out;
}();

inline const gl::PassState& pass_state(Pass pass, bool reversed_z) {
    return (reversed_z ? kPassStates : kStandardDepthPassStates)[static_cast<size_t>(pass)];
}

}  // namespace impossible::render
