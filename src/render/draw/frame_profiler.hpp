// Per-frame measurements when FrameDesc::profile is set (for `impossible
// bench`): one GL_SAMPLES_PASSED query per colour draw, tagged with the
// level-0 portal whose subtree it belongs to, and the time of each level-0
// portal's subtree between two glFinish calls.
#pragma once

#include <chrono>
#include <vector>

#include "gl/handles.hpp"
#include "render/frame.hpp"

namespace impossible::render {

class FrameProfiler {
public:
    // Times the subtree of level-0 portal `portal`: glFinish before and after,
    // so the time is the GPU work of the whole subtree (and the CPU work of
    // submitting it). Two-pass stereo adds both eyes' times.
    void begin_top_portal(int portal);
    void end_top_portal(FrameStats& stats);

    // Reads the queries back into stats (colour_fragments, the portal_costs'
    // fragments) and deletes them.
    void collect(FrameStats& stats);

private:
    friend class ColourQueryScope;
    struct ColourQuery {
        gl::Query query;
        int top_portal = -1;  // -1: the head's own cell
    };
    std::vector<ColourQuery> queries_;
    int top_portal_ = -1;
    std::chrono::steady_clock::time_point start_;
};

// Brackets the colour draws of a pass with a GL_SAMPLES_PASSED query when
// profiling (a profiler is given); nothing otherwise.
class ColourQueryScope {
public:
    explicit ColourQueryScope(FrameProfiler* profiler);
    ~ColourQueryScope();
    ColourQueryScope(const ColourQueryScope&) = delete;
    ColourQueryScope& operator=(const ColourQueryScope&) = delete;

private:
    FrameProfiler* profiler_;
};

}  // namespace impossible::render
