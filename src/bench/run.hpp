// Measuring the configurations of a bench plan (bench/README.md, "Method").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/plan.hpp"
#include "bench/stats.hpp"
#include "gl/state.hpp"

namespace impossible::bench {

struct PortalResult {
    int pose = 0;
    std::string portal;                // its id
    double ms_median = 0.0;            // subtree time, median over the profiled frames
    double fragments_per_pixel = 0.0;  // colour fragments of its subtree per output pixel
};

struct ConfigResult {
    BenchConfig config;
    std::string error;              // e.g. a stereo mode the driver cannot do: not measured
    std::vector<double> frame_ms;   // every timed frame (all poses)
    std::vector<double> submit_ms;  // CPU time of the draw calls (before glFinish)
    // Per frame, averaged over the poses (exact counts for one pose).
    double draw_calls = 0, triangles = 0, portal_passes_drawn = 0, portal_passes_culled = 0, portal_fills = 0;
    double fragments_per_pixel = 0;  // from the profiled frames
    double profiled_frame_ms = 0;    // median of the profiled frames (perturbed by glFinish)
    std::vector<PortalResult> portals;
    // With --error: against the tracer at the reference depth, averaged over poses.
    bool has_error = false;
    double id_mismatch_percent = 0, worst_id_mismatch_percent = 0, psnr_db = 0;
};

struct BenchResult {
    std::string gl_renderer;
    unsigned cores = 0;
    int poses = 0;
    std::vector<ConfigResult> configs;
};

// Needs a current GL context and its state cache. Throws InputError when the
// base configuration cannot be drawn.
BenchResult run_bench(const BenchPlan& plan, const std::vector<BenchPose>& poses, const BenchOptions& options,
                      gl::StateCache& state, const std::string& gl_renderer);

}  // namespace impossible::bench
