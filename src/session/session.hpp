// The one seam between a loaded layout and everything that draws, traces or
// walks it. A Session owns the layout and its portal links (linked once, here
// and nowhere else), and makes the engine's parts from them: the
// rasteriser's scene and renderer, the tracer's scene and walkers. The
// commands, the public API, the Python module, the preview and bench all
// assemble the engine through it (docs/architecture.md).
#pragma once

#include <memory>
#include <vector>

#include "base/result.hpp"
#include "gl/state.hpp"
#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "lights/light_bound.hpp"
#include "links/portal_links.hpp"
#include "math/view.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "trace/trace_scene.hpp"
#include "walk/walker.hpp"

namespace impossible::session {

class Session {
public:
    // Takes the loaded (valid) layout and links its portals.
    explicit Session(layout::Layout layout);
    // A layout and its links made already (changes::ChangeWalker's layout of
    // the pairing in force); `links` must be link_portals(*layout).
    Session(std::shared_ptr<const layout::Layout> layout, std::shared_ptr<const links::PortalLinks> links);

    const layout::Layout& layout() const { return *layout_; }
    const links::PortalLinks& links() const { return *links_; }
    // The links shared with walkers, which keep them.
    const std::shared_ptr<const links::PortalLinks>& shared_links() const { return links_; }

    // The rasteriser's cells and meshes.
    scene::Scene build_scene() const;
    // A renderer in the current GL context, whose state cache is `state`
    // (it must outlive the renderer); `programs`: the context's, where its
    // renderers share them (render::SharedPrograms).
    Result<render::Renderer> make_renderer(gl::StateCache& state, render::SharedPrograms programs = {}) const;
    // The tracer's scene (trace::trace_frame draws from it).
    Result<trace::Scene> make_trace_scene() const;
    // A walker from the layout's start pose in `room` (the start room when
    // -1). It reads the session's layout: the session must outlive it.
    walk::Walker make_walker(int room = -1) const;
    // Where a lit layout's lighting is cut (docs/bounded-work.md): the
    // light depth past which it has more than lights::kMaxLightPaths light
    // paths or lights::kMaxLightRects path rectangles, and the lights that
    // light frames. The renderer's and the tracer's scenes are cut so.
    lights::LightBound light_bound() const;

private:
    // On the heap: walkers and renderers made from a session point into it,
    // and a session may move.
    std::shared_ptr<const layout::Layout> layout_;
    std::shared_ptr<const links::PortalLinks> links_;
};

}  // namespace impossible::session
