// The GL renderer: one side-by-side stereo frame of a layout, drawn with
// single-pass instanced stereo and recursive stencil portals.
//
// Needs a current GL 4.5 context (gl/context.hpp) and that context's state
// cache, which every user of the context shares (gl/state.hpp). Talks to the
// rest of the program through plain data: a FrameDesc in, an Image and
// FrameStats out. Everything it draws comes from the scene (scene::Scene,
// portals included); of the layout it keeps only a lit layout's lights, for
// light images at another light depth (render/scene_data.hpp, SceneLights).
// The scene's vertex
// arrays are uploaded once and not kept; the renderer keeps index ranges, the
// portal links and the portals' plain data.
#pragma once

#include <cstdint>
#include <memory>

#include "base/result.hpp"
#include "gl/state.hpp"
#include "render/frame.hpp"
#include "render/target.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

struct RendererParts;
struct Programs;

// The programs of one GL context (programs/programs.hpp), for the renderers
// that draw in it to share: each is built at the first frame of any of them
// that needs it. A program depends only on its stereo mode and variant, and
// every uniform it reads is set before each draw or frame that uses it, so a
// renderer finds nothing of another's in it. On llvmpipe a program's compiled
// variants are most of what a lit renderer holds (docs/bounded-work.md).
// Freed by its last holder, in its context (current).
using SharedPrograms = std::shared_ptr<Programs>;
SharedPrograms make_shared_programs();

// A frame drawn and read back.
struct RenderedFrame {
    image::Image image;
    FrameStats stats;
};

class Renderer {
public:
    // Uploads the scene and builds the default (clip-shift) program. `state`
    // is the cache of the current context and must outlive the renderer.
    // `programs`: the context's, shared with its other renderers (none: the
    // renderer's own).
    static Result<Renderer> create(gl::StateCache& state, const scene::Scene& scene, SharedPrograms programs = {});

    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;
    ~Renderer();

    // Draws a frame and reads it back. Fails for what the driver cannot do
    // (e.g. a stereo mode it lacks) or an incomplete render target.
    Result<RenderedFrame> render(const FrameDesc& frame);

    // Draws without reading back (for timing and for the preview); same
    // state as render(). `stats` may be null.
    Result<void> draw(const FrameDesc& frame, FrameStats* stats = nullptr);

    // The single-sample target the last frame was drawn into, or resolved
    // into when multisampled (e.g. for a window to show or read back); empty
    // before the first frame.
    const Target& target() const;

    // The programs it draws with, for a renderer that takes its place in the
    // same context (a layout changed while walking) to draw with at once.
    const SharedPrograms& programs() const;

    // The frame buffers it keeps between frames, remade by a frame that
    // finds them gone (kept_buffers.cpp): the samples of its targets (the
    // frame's, the multisampled ones, the portal textures) and the bytes of
    // its shadow maps.
    struct Kept {
        std::int64_t target_samples = 0;
        std::int64_t shadow_map_bytes = 0;
    };
    Kept kept() const;
    // Free them, between frames, in the renderer's context (current): the
    // next frame makes them again and draws the same pixels; the shadow
    // maps are drawn again.
    void release_targets();
    void release_shadow_maps();

private:
    explicit Renderer(std::unique_ptr<RendererParts> parts);
    std::unique_ptr<RendererParts> parts_;
};

}  // namespace impossible::render
