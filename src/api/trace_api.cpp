// impossible::api::trace: the reference ray tracer behind the public API.
#include "api/api_data.hpp"
#include "trace/tracer.hpp"

namespace impossible::api {

Expected<Frame> trace(const Layout& layout, const View& view, int threads) {
    return no_throw([&]() -> Expected<Frame> {
        const layout::Layout& l = layout.data().layout;
        Result<math::View> resolved = resolve_view(l, view);
        if (!resolved) return Error{resolved.error()};
        if (threads < 0) return Error{"threads must be 0 (every core) or more"};
        trace::TraceDesc desc;
        static_cast<math::View&>(desc) = *resolved;
        desc.threads = threads;
        desc.samples = view.samples;
        Result<trace::Scene> scene = layout.data().session.make_trace_scene();
        if (!scene) return Error{scene.error()};
        Result<image::Image> image = trace::trace_frame(*scene, desc);
        if (!image) return Error{image.error()};
        Frame frame;
        frame.width = image->width;
        frame.height = image->height;
        frame.rgb = std::move(image->rgb);
        frame.ids = std::move(image->ids);
        return frame;
    });
}

}  // namespace impossible::api
