// Internal to src/render: recursive stencil portals inside the single
// instanced stereo pass (portal_recursion.cpp). The steps each level is made
// of are portal_draw.hpp's; mirrors and windows, render-to-texture portals
// and z-clear portals have their own headers here.
#pragma once

#include <array>
#include <vector>

#include "render/draw/draw_state.hpp"

namespace impossible::render {

// Draws `view` where the stencil equals view.level, then every portal of its
// cell that either eye can see, recursively.
void draw_level(const DrawContext& ctx, const LevelView& view);

// A level's portal boxes of `portals` visible in `visible` (per portal, the
// eyes' rectangles) into depth, then the cell's surfaces, its objects'
// instances and its volumes' rooms, before any portal is marked.
void draw_level_surfaces(const DrawContext& ctx, const LevelView& view, const std::vector<int>& portals,
                         const std::vector<std::array<NdcRect, 2>>& visible);

}  // namespace impossible::render
