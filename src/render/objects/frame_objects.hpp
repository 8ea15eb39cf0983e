// Internal to src/render: a frame's dynamic objects placed once
// (walk::place_objects) and looked up per cell (frame_objects.cpp).
#pragma once

#include <vector>

#include "render/frame.hpp"
#include "scene/scene.hpp"
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"

namespace impossible::render {

struct SceneData;

// What a frame's dynamic objects are (walk::place_objects), placed once per
// frame and looked up per cell by every level that draws the cell.
struct FrameObjects {
    std::vector<walk::ObjectInstance> instances;
    std::vector<int> mesh;                  // per instance: its SceneData::object_meshes index
    std::vector<scene::CellObjects> cells;  // per room: its instances' bounds (first_batch: the instance) and tree
    std::vector<int> touched;               // the rooms whose `cells` entry is not empty
};

// The frame's dynamic objects placed (walk::place_objects), grouped per cell
// with their bounds and a culling tree per cell.
// `walks` (may be null) walks the moving props on from the last frame.
void place_frame_objects(const SceneData& r, const FrameDesc& frame, FrameObjects& out, walk::PropWalks* walks);

}  // namespace impossible::render
