// What the headless renderers of one thread share (api::Renderer::headless):
// one GL context per backend, and a bound on the frame buffers they keep
// between frames together (docs/bounded-work.md, "Other bounds").
//
// A context of its own cost each renderer about 4 MB on llvmpipe (the
// context, and the rasteriser's bins it makes at its first frame), and 200
// renderers of a lit layout, each keeping its targets and its props' shadow
// maps, took 4.1 GB. Now the renderers made on a thread draw in one context,
// made by the first and destroyed with the last (the state cache is the
// context's, so each renderer finds GL as the cache says), and together they
// keep what one frame may use: before a renderer draws, the targets of the
// others are released, least recently drawn first, until theirs and the
// frame's samples are within math::limits::kMaxFrameSamples; after it drew,
// their shadow maps, until all the renderers' are within
// render::kMaxShadowMapBytes. A released renderer makes them again at its
// next frame (the same pixels; its maps drawn again). One renderer's own
// buffers are bounded as its frames are. They draw with the context's
// programs (render::SharedPrograms): each variant is compiled once for all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "base/result.hpp"
#include "gl/context.hpp"
#include "render/renderer.hpp"

namespace impossible::api {

// How many of `kept` (least recently drawn first) to release, from the
// front, so that the rest plus `need` is within `bound`; none when `need`
// alone passes it (that frame is refused before it makes anything).
std::size_t releases_needed(const std::vector<std::int64_t>& kept, std::int64_t need, std::int64_t bound);

class HeadlessShare {
public:
    // This thread's share for the backend, made when it has none. Nothing
    // requested: the thread's EGL share, else a new EGL context, else the
    // OSMesa share or a new OSMesa context (the commands' fallback).
    static Result<std::shared_ptr<HeadlessShare>> of_this_thread(std::optional<gl::Backend> requested);

    explicit HeadlessShare(gl::Context context)
        : context_(std::move(context)), programs_(render::make_shared_programs()) {}
    HeadlessShare(const HeadlessShare&) = delete;
    HeadlessShare& operator=(const HeadlessShare&) = delete;

    const gl::Context& context() const { return context_; }
    // The programs its renderers draw with.
    const render::SharedPrograms& programs() const { return programs_; }

    // A renderer made in the context joins as the most recently drawn, and
    // leaves before it is destroyed.
    void join(render::Renderer& r);
    void leave(render::Renderer& r);

    // Around each frame of `r` (the context current): before, the others'
    // targets released for a frame of `frame_samples`; after, `r` is the
    // most recently drawn and the others' shadow maps are released.
    void before_frame(const render::Renderer& r, std::int64_t frame_samples);
    void after_frame(const render::Renderer& r);

private:
    gl::Context context_;
    // After the context: freed before it, while it is current (the last
    // renderer's RendererParts makes it so).
    render::SharedPrograms programs_;
    // A renderer may leave from another thread (a Python object collected
    // there) while this one draws.
    std::mutex mutex_;
    std::vector<render::Renderer*> renderers_;  // least recently drawn first

    void move_to_back(const render::Renderer& r);
};

// Gives the memory the allocator holds free back to the system (glibc's
// malloc_trim), after buffers were released: the driver's textures live on
// the C heap, and glibc keeps freed blocks of their size for itself, so the
// process's resident set would not go down.
void return_free_memory();

}  // namespace impossible::api
