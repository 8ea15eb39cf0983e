// The side-by-side render target: RGBA8 colour, R8UI cell ids, and a
// DEPTH32F_STENCIL8 buffer (reversed-Z float depth; DEPTH24_STENCIL8 for
// standard depth); the stencil holds the portal level. A multisampled target
// has the same attachments with N samples each, the ids in a multisample
// texture so that the id resolve pass can read every sample.
#pragma once

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "render/frame.hpp"

namespace impossible::render {

struct Target {
    int width = 0;
    int height = 0;
    DepthMode depth = DepthMode::ReversedZ;
    int samples = 1;            // > 1: a multisampled target
    gl::Texture color_texture;  // instead of the renderbuffers, for a target that is sampled
    gl::Texture ids_texture;    // also the ids of a multisampled target (GL_TEXTURE_2D_MULTISAMPLE)
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

// A target of `samples` (> 1) samples per pixel: colour and depth-stencil in
// multisample renderbuffers, ids in a multisample texture. The caller checks
// first that the driver offers the count (render/targets/multisample.hpp).
Result<Target> create_multisampled_target(int width, int height, DepthMode depth, int samples);

// Reads colour and ids back, rows from the top, binding the target as the
// read framebuffer through the context's cache (left bound: the cache's user
// releases its bindings when it is done, gl/state.hpp).
image::Image read_target(gl::StateCache& state, const Target& target);

}  // namespace impossible::render
