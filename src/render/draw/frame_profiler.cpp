#include "render/draw/frame_profiler.hpp"

#include <algorithm>

namespace impossible::render {

void FrameProfiler::begin_top_portal(int portal) {
    glFinish();
    start_ = std::chrono::steady_clock::now();
    top_portal_ = portal;
}

void FrameProfiler::end_top_portal(FrameStats& stats) {
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    const int p = top_portal_;
    top_portal_ = -1;
    std::vector<FrameStats::PortalCost>& costs = stats.portal_costs;
    auto it = std::find_if(costs.begin(), costs.end(), [p](const auto& c) { return c.portal == p; });
    if (it == costs.end())
        costs.push_back({p, ms, 0});
    else
        it->ms += ms;
}

void FrameProfiler::collect(FrameStats& stats) {
    for (const ColourQuery& q : queries_) {
        GLuint64 samples = 0;
        glGetQueryObjectui64v(q.query.get(), GL_QUERY_RESULT, &samples);
        stats.colour_fragments += static_cast<long>(samples);
        for (FrameStats::PortalCost& c : stats.portal_costs)
            if (c.portal == q.top_portal) c.colour_fragments += static_cast<long>(samples);
    }
    queries_.clear();
}

ColourQueryScope::ColourQueryScope(FrameProfiler* profiler) : profiler_(profiler) {
    if (!profiler_) return;
    profiler_->queries_.push_back({gl::create_query(GL_SAMPLES_PASSED), profiler_->top_portal_});
    glBeginQuery(GL_SAMPLES_PASSED, profiler_->queries_.back().query.get());
}

ColourQueryScope::~ColourQueryScope() {
    if (profiler_) glEndQuery(GL_SAMPLES_PASSED);
}

}  // namespace impossible::render
