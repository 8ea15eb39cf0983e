// Internal to src/render: the scratch of one frame, the only thing drawing
// writes besides GL (DrawContext::scratch): pools reused from frame to frame,
// how much of them the frame has used, and its counters; reset by
// begin_frame(). Nothing in it carries a frame's result to the next
// (renderer_parts.hpp, KeptBetweenFrames).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "gl/handles.hpp"
#include "render/frame.hpp"
#include "render/objects/box_faces.hpp"
#include "render/objects/frame_objects.hpp"
#include "render/objects/instance_stream.hpp"
#include "render/objects/multi_draw.hpp"
#include "render/objects/object_culling.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

// A window's reflected view, copied aside while the view through it is drawn
// (portal_glass.cpp): a texture like the target's colour, one per window
// being drawn (a window's views may show windows, drawn inside its own).
struct SavedColour {
    gl::Texture texture;
    int width = 0, height = 0, samples = 1;
};

struct FrameScratch {
    FrameStats stats;
    CullScratch cull;  // reused by every level (object_culling.hpp)
    std::vector<scene::DrawBatch> cull_batches;
    FrameObjects objects;  // the frame's dynamic objects (frame_objects.hpp)
    std::vector<int> visible_instances;
    std::vector<std::pair<int, int>> instance_order;  // a level's visible instances as (mesh, instance)
    InstanceStream instance_records;                  // their per-instance records (instance_stream.hpp)
    IndirectDraws indirect;                           // FrameDesc::multi_draw's commands
    FaceStream faces;                                 // FrameDesc::cull_box_faces's indices (box_faces.hpp)
    std::vector<VisibleDraw> cull_draws;              // a level's draws with box faces culled
    std::vector<gl::Query> mark_queries;              // occlusion queries of portals, made on first use
    size_t mark_queries_used = 0;                     // of mark_queries, by this frame
    std::vector<SavedColour> saved_colours;           // per window being drawn, made on first use
    size_t saved_colours_used = 0;                    // of saved_colours, by the windows being drawn
    bool conditional = false;                         // inside a portal's conditional rendering

    // Empty counters and nothing of the pools used.
    void begin_frame() {
        stats = {};
        begin_indirect_frame(indirect);
        begin_instance_frame(instance_records);
        faces.used = 0;
        mark_queries_used = 0;
        saved_colours_used = 0;
        conditional = false;
    }
};

}  // namespace impossible::render
