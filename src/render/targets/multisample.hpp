// Multisampling (FrameDesc::samples > 1): which sample counts the driver
// offers, the multisampled targets a renderer keeps, and the resolve of one
// into the single-sample target that is read back or shown.
//
// Colour is resolved by glBlitNamedFramebuffer, which averages the samples
// (Mesa: the mean of the stored 8-bit values). Integer attachments cannot be
// averaged, and a blit would keep one sample of the driver's choosing (GL 4.5
// §18.3.1), so the cell ids are resolved by a fragment pass of their own
// (shaders/id_resolve.frag.glsl): the id most samples of the pixel hold; in a
// tie, the tied id holding more samples of the symmetric block of pixels
// around it (3 × 3 inside the image), then the lowest-numbered sample's. The
// id map then names the cell that contributes most to the pixel's averaged
// colour, and agrees with the tracer's centre rays wherever a feature is
// wider than half a pixel (docs/accuracy.md, "Anti-aliasing").
#pragma once

#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "render/frame.hpp"
#include "render/target.hpp"

namespace impossible::render {

// Sample counts that every attachment of a target with this depth mode can
// have (RGBA8 and depth-stencil renderbuffers, an R8UI multisample texture),
// ascending; 1 always. Needs a current context.
std::vector<int> offered_sample_counts(DepthMode depth);

// An error naming the counts on offer when `samples` is not one of them.
Result<void> check_sample_count(int samples, DepthMode depth);

// What a renderer keeps for multisampled frames (the id resolve's programs
// are with its others, render/programs/programs.hpp).
struct Multisampling {
    // A few multisampled targets, by size, depth mode and count, so that a
    // benchmark alternating sample counts frame by frame does not re-create
    // them every frame.
    std::vector<Target> targets;
    // Framebuffers around the single-sample target's colour and ids alone:
    // a blit writes every draw buffer, and RGBA8 cannot go into R8UI.
    gl::Framebuffer colour_out;
    gl::Framebuffer ids_out;
};

struct FrameTargets;
struct Programs;

// For FrameDesc::samples > 1: checks the count, makes the multisampled
// target of the frame's size, the framebuffers the resolve writes through
// and the id resolve's program; nothing for 1 sample. Call after
// `targets.target` is made.
Result<void> ensure_multisampled(Programs& programs, FrameTargets& targets, const FrameDesc& frame);

// The target the frame's passes draw into: `target`, or the multisampled one.
const Target& drawing_target(const FrameTargets& targets, const FrameDesc& frame);

// Resolves the frame's multisampled target into `target` (colour averaged,
// ids by majority) through the context's cache; nothing for 1 sample.
void resolve_multisampled(gl::StateCache& state, const Programs& programs, const FrameTargets& targets,
                          const FrameDesc& frame);

}  // namespace impossible::render
