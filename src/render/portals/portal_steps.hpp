// Internal to src/render: which of a door's passes a level may leave out,
// decided from the level's visible portals on screen (portal_steps.cpp).
#pragma once

#include <array>
#include <vector>

#include "render/draw/draw_state.hpp"

namespace impossible::render {

// How a visible portal of a level is marked and unmarked.
struct PortalSteps {
    // One quad per eye marks the portal and resets its depth (the box bit,
    // passes.hpp): no other visible portal of the level comes near it on
    // screen. Else its box marks and a quad resets depth, two draws.
    bool one_draw_mark = false;
    // Unmarked after its view: some later portal of the level comes near it
    // on screen (or no culling). Else its pixels keep their deeper levels,
    // which no later draw of the level touches, until an unmark of an outer
    // level or the end of the frame.
    bool unmark = true;
};

// The steps of each portal of the level with a non-empty rectangle in
// `visible` (one per portal of view.cell).
std::vector<PortalSteps> portal_steps(const DrawContext& ctx, const LevelView& view,
                                      const std::vector<std::array<NdcRect, 2>>& visible);

}  // namespace impossible::render
