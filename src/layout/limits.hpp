// Limits the loader enforces where layout-format.md is silent. They keep
// absurd input (huge, deep, non-physical) from reaching the renderer, and are
// documented for users in docs/layout-limits.md; keep the two in step.
#pragma once

#include <cstddef>

#include "assets/limits.hpp"

namespace impossible::layout::limits {

// The limits on models, images, coordinates and scales (assets/limits.hpp)
// are the layout's too.
using namespace assets::limits;

// The text of a layout file, and how deep and how many its JSON values may be.
// A hand-written or generated layout is a few kilobytes; these leave a wide
// margin while bounding memory and time.
inline constexpr std::size_t kMaxFileBytes = 4u << 20;  // 4 MiB
inline constexpr std::size_t kMaxDepth = 64;
inline constexpr std::size_t kMaxValues = 200'000;

inline constexpr std::size_t kMaxRooms = 10'000;
inline constexpr std::size_t kMaxPortals = 20'000;
// layout-format.md, "Changes while walking": entries of `changes`. The walker
// considers each not yet made at every frame.
inline constexpr std::size_t kMaxChanges = 10'000;
inline constexpr std::size_t kMaxPropsPerRoom = 10'000;
inline constexpr std::size_t kMaxPlayAreaCorners = 10'000;
// Corners (so walls) of one prism room's `floor`. A curved corridor in 1°
// steps has a few hundred; the simple-polygon test is quadratic in them, and
// every portal of the room is tested against every wall by the hole rule.
inline constexpr std::size_t kMaxRoomCorners = 1'000;

// Moving props (layout-format.md, "Moving props"): keys of one motion path,
// and its times in seconds. The walker walks a path's keys up to the time
// asked for, so they bound its work per prop and frame.
inline constexpr std::size_t kMaxMotionKeys = 10'000;
inline constexpr double kMaxMotionTime = 1e6;  // about 11.6 days

// Lights (layout-format.md, "Lights"): a room's lights, its glTF props'
// included, bound the rasteriser's light images; intensity (candela) and
// ambient bound the sums (anything past 1 already saturates).
inline constexpr std::size_t kMaxLightsPerRoom = 1'000;  // kMaxLightIntensity: assets/limits.hpp
inline constexpr double kMaxAmbient = 1e3;

// Coordinates and lengths, in metres. Renderers draw in single precision, so
// lengths below a
// micrometre (widths, heights, depths, room and box extents, checker squares)
// cannot be seen and only cause degenerate geometry.
inline constexpr double kMinLength = 1e-6;
inline constexpr double kMaxLength = 1e5;

// Angles in degrees (yaw_deg).
inline constexpr double kMaxAngleDeg = 1e6;

// Components of direction vectors (normal, up) before normalisation.
inline constexpr double kMaxDirectionComponent = 1e5;

// Portal vectors (from layout-format.md).
inline constexpr double kUnitTolerance = 1e-3;  // | |normal| - 1 | allowed
inline constexpr double kMinUpAngleDeg = 1.0;   // angle between up and normal
inline constexpr double kPairSizeTolerance = 1e-6;
inline constexpr double kHolePlaneTolerance = 1e-4;
inline constexpr double kDefaultDepth = 0.25;  // a door's box without "depth"

// Door boxes and the rasteriser's near plane (render/frame.hpp checks these
// are its own). An eye sits half an IPD beside the head, so before the head
// crosses a door one eye can be that far behind the door's plane: the box
// must reach further than that, plus the near distance, or the eye sees out
// of its back (or through a clipped back face) into its own room.
inline constexpr double kHalfTypicalIpd = 0.032;  // half of the default IPD, 0.064 m
inline constexpr double kNearReversedZ = 1e-5;    // the default depth mode
inline constexpr double kNearStandard = 0.01;     // --depth standard

}  // namespace impossible::layout::limits
