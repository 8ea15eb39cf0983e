// The side-by-side render target: RGBA8 colour, R8UI cell ids, and a
// DEPTH32F_STENCIL8 buffer (reversed-Z float depth; DEPTH24_STENCIL8 for
// standard depth); the stencil holds the portal level.
#pragma once

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "render/frame.hpp"

namespace impossible::render {

struct Target {
    int width = 0;
    int height = 0;
    DepthMode depth = DepthMode::ReversedZ;
    gl::Texture color_texture;  // instead of the renderbuffers, for a target that is sampled
    gl::Texture ids_texture;
    gl::Renderbuffer color;
    gl::Renderbuffer ids;
    gl::Renderbuffer depth_stencil;
    gl::Framebuffer framebuffer;
};

// An incomplete framebuffer is an error, never ignored.
Result<Target> create_target(int width, int height, DepthMode depth);

// The same, with colour and ids in textures that shaders can sample (colour
// filtered linearly, ids by nearest texel).
Result<Target> create_sampled_target(int width, int height, DepthMode depth);

// Reads colour and ids back, rows from the top.
image::Image read_target(const Target& target);

}  // namespace impossible::render
