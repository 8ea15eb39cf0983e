// Frame time of the three stereo modes on one layout, measured in one run:
// clip-space shift vs gl_ViewportIndex (both single-pass instanced) vs two
// passes. Times with glFinish and a monotonic clock (llvmpipe's timer queries
// read ~0); modes are interleaved frame by frame so that machine noise hits
// all of them alike; prints medians and the 10th-90th percentile spread.
//
// usage: bench_stereo_modes [LAYOUT] [--frames N] [--size WxH]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/stats.hpp"
#include "cli/layout_source.hpp"
#include "gl/context.hpp"
#include "gl/gl.hpp"
#include "render/renderer.hpp"
#include "session/session.hpp"

using namespace impossible;

using bench::percentile;

int main(int argc, char** argv) {
    std::optional<std::string> path;
    int frames = 30, width = 1280, height = 720;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--size" && i + 1 < argc)
            std::sscanf(argv[++i], "%dx%d", &width, &height);
        else
            path = a;
    }
    try {
        const session::Session session(cli::load_layout_or_default(path));
        const layout::Layout& l = session.layout();
        Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
        if (!context) throw std::runtime_error(context.error());
        Result<render::Renderer> r = session.make_renderer(context->state());
        if (!r) throw std::runtime_error(r.error());

        const render::StereoMode modes[] = {render::StereoMode::ClipShift, render::StereoMode::ViewportIndex,
                                            render::StereoMode::TwoPass};
        const char* names[] = {"clip-shift", "viewport-index", "two-pass"};
        std::vector<double> ms[3], submit_ms[3];
        render::FrameStats stats[3];
        for (int f = -3; f < frames; ++f) {  // three warm-up rounds
            for (int m = 0; m < 3; ++m) {
                render::FrameDesc frame;
                frame.head.position = l.start.position;
                frame.head.yaw_deg = l.start.yaw_deg;
                frame.room = l.start.room;
                frame.eye_width = width;
                frame.eye_height = height;
                frame.stereo = modes[m];
                glFinish();
                const auto t0 = std::chrono::steady_clock::now();
                const Result<void> drawn = r->draw(frame, &stats[m]);
                const auto t1 = std::chrono::steady_clock::now();
                glFinish();
                const auto t2 = std::chrono::steady_clock::now();
                if (!drawn) throw std::runtime_error(drawn.error());
                if (f >= 0) {
                    submit_ms[m].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
                    ms[m].push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
                }
            }
        }
        std::printf("%s, %dx%d per eye, %d frames per mode, %s\n", l.source.c_str(), width, height, frames,
                    context->renderer.c_str());
        std::printf("%-15s %10s %10s %10s %12s %10s %10s\n", "mode", "median ms", "p10 ms", "p90 ms", "submit ms",
                    "draws", "vs clip");
        const double base = percentile(ms[0], 0.5);
        for (int m = 0; m < 3; ++m)
            std::printf("%-15s %10.3f %10.3f %10.3f %12.4f %10ld %10.3f\n", names[m], percentile(ms[m], 0.5),
                        percentile(ms[m], 0.1), percentile(ms[m], 0.9), percentile(submit_ms[m], 0.5),
                        stats[m].draw_calls, percentile(ms[m], 0.5) / base);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_stereo_modes: %s\n", e.what());
        return 1;
    }
    return 0;
}
