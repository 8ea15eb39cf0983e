// What `impossible bench` measures: the configurations of a sweep (layout
// variants and frame settings) and the head poses they are measured at.
#pragma once

#include <string>
#include <vector>

#include "bench/options.hpp"
#include "layout/layout.hpp"
#include "render/frame.hpp"
#include "session/session.hpp"
#include "walk/replay.hpp"

namespace impossible::bench {

// The layout with only portals[0..n) kept whose targets are also among them
// (a mirror, which has no target, is kept when it is among them); the others
// are closed (removed). Targets are renumbered; the result has no changes
// (the walk makes them on the layout given, bench_poses).
layout::Layout keep_first_portals(const layout::Layout& layout, int n);

// One configuration measured: a layout variant (index into the bench's
// layouts), and the frame settings (head and room are set per pose).
struct BenchConfig {
    std::string name;   // e.g. "base", "stereo=two-pass", "portals=4"
    std::string group;  // "base", "stereo", "clip", "cull", "depth", "portals", "size"
    int layout_variant = 0;
    render::FrameDesc frame;
};

struct BenchPlan {
    std::vector<session::Session> sessions;  // layout variants; [0]: the layout as loaded (and --portals applied)
    std::vector<BenchConfig> configs;        // [0]: the base configuration (the options as given)
    // With --path through a layout's changes: the same variants made from
    // the layout with the pairing of each stage of the walk (stages[s - 1]
    // for stage s, BenchPose::stage), e.g. --portals N keeps the first N
    // portals of the layout in force there.
    std::vector<std::vector<session::Session>> stages;

    // The variant of configuration `variant` with the pairing of `stage`.
    const session::Session& session_of(int variant, int stage) const {
        return stage == 0 ? sessions[static_cast<std::size_t>(variant)]
                          : stages[static_cast<std::size_t>(stage - 1)][static_cast<std::size_t>(variant)];
    }
};

// The configurations of the options' sweep over `layout`. Throws InputError.
BenchPlan plan_bench(const session::Session& session, const BenchOptions& options);

// The virtual head, room, time and hands of each frame: the options' pose
// (or the layout's start) once, or every line of the --path walk walked as
// `walk` does (session::WalkDriver), with the layout's changes made where
// the eyes of the bench's view options see none of their doors, so that
// line k is drawn as `render --path FILE --frame k` draws it. Throws
// InputError.
struct BenchPose {
    math::HeadPose head;
    int room = 0;
    double time = 0.0;      // --time, or line k / fps of the walk
    walk::HandPoses hands;  // --hands, or the walk's line's hands mapped by its W
    int stage = 0;          // the pairing in force: 0 the layout's, s after the s-th frame that made changes
};
// `stages`, when given, receives the session of each stage from 1 on (the
// pairing after the frames that made changes, in walk order).
std::vector<BenchPose> bench_poses(const session::Session& session, const BenchOptions& options,
                                   std::vector<session::Session>* stages = nullptr);

// Adds to the plan the variants of each stage of the walk (BenchPlan::stages).
void add_stages(BenchPlan& plan, const std::vector<session::Session>& stages, const BenchOptions& options);

}  // namespace impossible::bench
