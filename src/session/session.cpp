#include "session/session.hpp"

#include "lights/light_bound.hpp"

namespace impossible::session {

Session::Session(layout::Layout layout)
    : layout_(std::make_shared<const layout::Layout>(std::move(layout))),
      links_(std::make_shared<const links::PortalLinks>(links::link_portals(*layout_))) {}

Session::Session(std::shared_ptr<const layout::Layout> layout, std::shared_ptr<const links::PortalLinks> links)
    : layout_(std::move(layout)), links_(std::move(links)) {}

scene::Scene Session::build_scene() const { return scene::build_scene(*layout_, *links_); }

Result<render::Renderer> Session::make_renderer(gl::StateCache& state, render::SharedPrograms programs) const {
    return render::Renderer::create(state, build_scene(), std::move(programs));
}

Result<trace::Scene> Session::make_trace_scene() const { return trace::prepare_scene(*layout_, *links_); }

walk::Walker Session::make_walker(int room) const {
    return walk::Walker(*layout_, room >= 0 ? room : layout_->start.room, links_);
}

lights::LightBound Session::light_bound() const { return lights::light_bound(*layout_, *links_); }

}  // namespace impossible::session
