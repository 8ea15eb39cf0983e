// The smallest program on the library (docs/api.md): render a layout in a
// headless context of the library's own, trace the same view with the
// reference ray tracer, and compare their cell ids. Usage: headless [LAYOUT.json]
// Build: c++ -std=c++17 main.cpp -o headless $(pkg-config --cflags --libs impossible)
#include <cstdio>

#include <impossible/impossible.hpp>

namespace api = impossible::api;

int main(int argc, char** argv) {
    api::Expected<api::Layout> layout = argc > 1 ? api::Layout::load(argv[1]) : api::Layout::builtin();
    if (!layout) {  // e.g. "FILE:LINE:COLUMN: message", one line a problem
        std::fprintf(stderr, "%s\n", layout.error().message.c_str());
        return 1;
    }
    api::Expected<api::Renderer> renderer = api::Renderer::headless(*layout);
    if (!renderer) {
        std::fprintf(stderr, "%s\n", renderer.error().message.c_str());
        return 1;
    }
    api::View view;  // the layout's start; each eye 320 × 240
    view.width = 320;
    view.height = 240;
    api::Expected<api::Frame> drawn = renderer->render(view);
    api::Expected<api::Frame> traced = api::trace(*layout, view);
    if (!drawn || !traced) {
        std::fprintf(stderr, "%s\n", (!drawn ? drawn.error() : traced.error()).message.c_str());
        return 1;
    }
    long differ = 0;
    for (std::size_t i = 0; i < drawn->ids.size(); ++i) differ += drawn->ids[i] != traced->ids[i];
    std::printf("impossible %s, %s: %s, rooms", api::version(), renderer->gl_renderer().c_str(),
                layout->name().c_str());
    for (const std::string& room : layout->room_ids()) std::printf(" %s", room.c_str());
    std::printf("\nrender %dx%d: %ld draw calls, %d portal passes; trace: %ld of %zu cell ids differ\n", drawn->width,
                drawn->height, drawn->stats.draw_calls, drawn->stats.portal_passes_drawn, differ, drawn->ids.size());
    return 0;
}
