// The light paths of layout-format.md, "Lights", enumerated per lit room on
// the CPU, for the rasteriser: every image of every light that may reach a
// surface of room C through at most `light_depth` portals, with the portal
// rectangles (apertures) a shadow ray must pass, mapped into C's coordinates.
// The fragment shader then lights a point p by an image only if the segment
// from p to the image passes its apertures in order (and meets no blocker):
// exact for convex rooms and portals. Props' shadows are the shadow maps'
// (render/lights/shadow_maps.hpp). The tracer follows shadow rays on its own and
// does not use this (it is the oracle this is checked against).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/portal.hpp"

namespace impossible::lights {

// A portal rectangle that a light path passes, in the lit room's
// coordinates. The shadow ray from the surface crosses it from its front
// side (rect.normal points towards the surface's side); depth is 0 (a door
// box counts as its front rectangle for every shadow ray).
struct Aperture {
    math::PortalRect rect;
    int portal = -1;       // index into Layout::portals: the portal the shadow ray meets
    bool reflect = false;  // a mirror, or a window's reflected branch (else: through)
};

// A portal rectangle standing free in a room of the path (not a hole in a
// face), which would block a shadow ray meeting it, on leg `leg`: leg 0 runs
// from the surface to aperture 0, leg i from aperture i-1 to aperture i, the
// last (leg == apertures.size()) from the last aperture to the light.
// A wall of a non-convex prism room that the leg may cross
// (layout::crossable_walls) blocks it too, and so does the plane of a face
// the leg would leave its room by where a door on it reaches outside.
// Those that no shadow ray of the image can meet from the front (the image
// lies in front of their plane) or within the light's range are left out
// (light_blockers.hpp).
struct Blocker {
    math::PortalRect rect;  // in the lit room's coordinates, depth 0
    int portal = -1;        // -1 for a wall or a face's plane
    int leg = 0;
    int wall = -1;  // the wall's index in the leg's room, or -1 for a portal
    // A face whose plane the leg leaves its room by (where a door on the leg
    // reaches outside the room): its index in the leg's room, or -1.
    int face = -1;
};

// One image of a light as the surfaces of a room C see it:
// L' = M⁻¹ · L with M = M_k · … · M_1 mapping C's coordinates to the light's
// room R's (k = apertures.size(); k = 0: a light of C itself, seen directly).
struct LightImage {
    int light_room = -1;       // R, index into Layout::rooms
    int light = -1;            // index into rooms[R].lights
    glm::dvec3 position{0.0};  // L', in C's coordinates
    // The spot's axis mapped into C's coordinates (M⁻¹ applied as a
    // direction; M is orthogonal, so dot(axis, -w) is dot(s, -w_L)).
    glm::dvec3 spot_direction{0.0, -1.0, 0.0};
    glm::dvec3 factor{1.0};            // product of the portals' factors along the path
    std::vector<int> rooms;            // the rooms the legs run in: C first, R last (apertures.size() + 1)
    std::vector<math::dmat4> to_room;  // per leg: C's coordinates to that leg's room's (to_room[0] = identity)
    std::vector<Aperture> apertures;   // P1 … Pk, P1 nearest the surface
    std::vector<Blocker> blockers;
};

// The images that may light room C, in a fixed order: by path length, then
// depth-first in the order of the rooms' portals and lights.
struct RoomLights {
    glm::dvec3 ambient{0.0};
    std::vector<LightImage> images;
};

// Every room's images at the given light depth (0..kMaxLightDepth), culled:
// paths whose factor falls below shading::kMinLightFactor (largest channel),
// paths whose apertures no straight segment passes in order (checked by
// clipping each aperture with the cone from the light's image through the
// next), paths that end beyond the light's range, and paths of a spot
// whose cone holds no ray through the apertures. Empty for a "fixed"
// layout. Valid layouts only (from the loader).
//
// Culling is conservative: clipping keeps what lies within 1e-9 · (1 + |L|
// + |aperture centre| + its size) outside, so a path is dropped only when no
// shadow ray from any point of C passes its apertures in order (blockers
// and props aside, which the shader tests per point) or every such ray is
// at least the light's range long or outside its spot's cone (where the
// contribution is 0); the one exception is a portal whose
// rectangle lies within that tolerance of the plane of an aperture passed
// before it (a straight ray crosses a plane once), which layouts avoid as
// they avoid coplanar surfaces. Paths are followed from each light
// outwards, so the work is proportional to the paths kept, not to all
// sequences of portals.
std::vector<RoomLights> light_images(const layout::Layout& layout, const links::PortalLinks& links, int light_depth);

// For tests: `cull = false` keeps every path the factor rule keeps (no
// aperture, order or range test) and every blocker, to check that culling
// only drops paths no shadow ray passes and blockers none meets.
struct LightImageOptions {
    bool cull = true;
};
std::vector<RoomLights> light_images(const layout::Layout& layout, const links::PortalLinks& links, int light_depth,
                                     const LightImageOptions& options);

// The number of light paths that may light a room (what `validate` reports).
inline std::size_t light_path_count(const RoomLights& room) { return room.images.size(); }

// The largest depth, at most light_depth (clamped to 0..kMaxLightDepth), at
// which light_images() gives at most max_images images over all rooms
// together (depth 0 always counts: its images are the lights themselves);
// light_depth itself when max_images is 0 or the layout is not lit. The
// count grows fast with the depth where portals face each other (a 2 m cube
// of six windows, paired face to face: 6,197 paths at depth 4, 1.6 million
// from depth 8 on); each try stops after max_images + 1 paths, so this costs
// at most light_depth times the work of max_images paths.
int light_depth_within(const layout::Layout& layout, const links::PortalLinks& links, int light_depth,
                       std::size_t max_images);

// The most light paths a frame is lit by, all rooms together
// (docs/bounded-work.md): a layout whose light depth would give more is
// lit at the largest light depth that gives at most this many, by the
// rasteriser and the tracer alike (lights::light_bound, light_bound.hpp),
// and the commands warn. A 2 m cube of six paired windows has 133 paths at
// light depth 2 and over 1,300 at 3.
inline constexpr std::size_t kMaxLightPaths = 1024;

// The rectangles a fragment tests for an image: its apertures and its
// blockers (shaders/lighting.frag.glsl, light_path_open).
inline std::size_t path_rect_count(const LightImage& image) { return image.apertures.size() + image.blockers.size(); }

// What lighting at a light depth costs (light_bound.cpp): the number of
// images light_images(layout, links, light_depth) gives and of their path
// rectangles, by path length (index k: paths of k portals), and each
// light's own image's rectangles (its path of no portal), per room, per
// light. It makes every image (less the lists' memory), so its time is
// light_images's: call it at a depth within kMaxLightPaths.
struct LightWork {
    std::array<std::size_t, layout::kMaxLightDepth + 1> images{};
    std::array<std::size_t, layout::kMaxLightDepth + 1> rects{};
    std::vector<std::vector<std::size_t>> own_rects;
};
LightWork light_work(const layout::Layout& layout, const links::PortalLinks& links, int light_depth);

// The exact aperture test of the lit shader, in double precision (its
// reference): the segment from p (in C's coordinates) to the image's
// position crosses every aperture's plane from its front to its back,
// strictly inside its rectangle, in order (P1 nearest p), and on each leg
// meets no blocker from the blocker's front (edges included; on leg 0 not
// within shading::shadow_ray_start_tolerance(p) of p).
bool segment_passes(const LightImage& image, const glm::dvec3& p);

}  // namespace impossible::lights
