// Internal to src/render: what a colour pass sets for a lit layout's lights
// (light_draw.cpp): the program flags and the light uniforms of a room.
#pragma once

#include "render/draw/draw_state.hpp"

namespace impossible::render {

// kLights under "lighting": "lights", else 0: what the colour passes of
// surfaces of `room` add to their program's flags; with kLightsAmbient where
// no light image reaches the room (its ambient alone: no loop over images,
// whose code llvmpipe runs, masked, even for none; bench/README.md, "Lights").
// In a level drawn outside its cell's light paths (view.outside_light_paths),
// the cell's own surfaces draw without the path loop (kLightsNoPaths), or by
// the ambient variant where the cell has no direct image.
unsigned light_flags(const DrawContext& ctx, int room, const LevelView* view = nullptr);

// A colour pass's light uniforms for surfaces of `room` (the identity into
// the room's coordinates: the room's own vertices), counting the room's
// images in FrameStats::light_images when `count` is set. Nothing for a
// fixed layout.
void set_room_lights(const DrawContext& ctx, const SceneProgram& program, int room, bool count);

// Whether the frame draws `room`'s own surfaces from the light cache
// (LightBuffers::use_cache, and the room is cached).
bool draws_cached(const DrawContext& ctx, int room);
// The flags of such a room's draws: its cells' cached sums and the images
// their bits name.
unsigned cached_light_flags(const DrawContext& ctx, int room);

}  // namespace impossible::render
