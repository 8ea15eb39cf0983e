// Plain data in and out of the GL renderer: a frame description in, an image
// (and counters) out.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.hpp"
#include "layout/limits.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"
#include "math/view_limits.hpp"

namespace impossible::render {

// How both eyes reach their halves of the side-by-side target.
enum class StereoMode {
    ClipShift,      // one instanced draw per mesh; clip-space x shifted per eye (default)
    ViewportIndex,  // one instanced draw per mesh; gl_ViewportIndex from the vertex shader
    TwoPass,        // one draw per mesh per eye, viewport per eye (the reference)
};

// How the target room is cut at the target portal's plane.
enum class ClipMode {
    ClipDistance,  // gl_ClipDistance with the plane (default)
    Oblique,       // Lengyel's oblique near plane
};

// Depth buffer and projection.
enum class DepthMode {
    ReversedZ,  // DEPTH32F, glClipControl ZERO_TO_ONE, infinite far plane (default)
    Standard,   // DEPTH24, classic -1..1 projection with a far plane at FrameDesc::far
};

// The near plane. Under reversed-Z float depth (depth = near / distance) the
// smallest resolvable separation at a distance z is about z · 2^-24 whatever
// the near distance, so the near plane can sit 10 µm from the eye: an eye
// 0.1 mm from a wall, a prop or a door box's back face still sees it, as the
// tracer does (docs/accuracy.md has the figures). 24-bit standard depth
// resolves z² / (near · 2^24): its near plane stays at 1 cm, and it cannot
// show a surface closer than that to an eye.
inline constexpr double kNearReversedZ = layout::limits::kNearReversedZ;  // 10 µm
inline constexpr double kNearStandard = layout::limits::kNearStandard;    // 1 cm

// The default budget of portal passes per frame (--max-portal-passes).
inline constexpr int kDefaultMaxPortalPasses = math::kDefaultMaxPortalPasses;

// Cube shadow maps' texels per face side (--shadow-size, FrameDesc).
inline constexpr int kDefaultShadowMapSize = 512;
inline constexpr int kMaxShadowMapSize = math::limits::kShadowMapSize.max;

// How the rasteriser draws a view: the settings a user picks (the command
// line's technique options, the library's RenderOptions, Python's keyword
// arguments). The view's own max_portal_passes and light_depth are
// math::View's, as the tracer reads them too.
struct Technique {
    StereoMode stereo = StereoMode::ClipShift;
    ClipMode clip = ClipMode::ClipDistance;
    DepthMode depth = DepthMode::ReversedZ;
    // Multisampling: 1 draws into single-sample buffers exactly as before;
    // N > 1 draws into N-sample colour, id and depth-stencil buffers (the
    // stencil portals then work per sample) and resolves them into the
    // single-sample target at the end of the frame: colour by averaging
    // (glBlitNamedFramebuffer), ids by a majority vote over the samples
    // (docs/accuracy.md, "Anti-aliasing"). A count the driver does not offer
    // is an error.
    int samples = 1;
    // Render-to-texture portals, the classic technique, for comparison: with a
    // scale > 0, each portal of the head's cell is drawn by rendering its view
    // (both eyes side by side, recursion inside by stencil) into a texture of
    // scale × the eye size, which the portal's box then shows. 0: stencil
    // portals all the way (the default). Needs StereoMode::ClipShift.
    double portal_texture_scale = 0.0;
    // Hybrid portals (--technique hybrid --texture-from-level K, Valve's
    // scheme as Rinsma describes it): with portal_texture_scale > 0, the
    // doors seen at this recursion level are drawn through textures (all
    // deeper levels inside them by stencil); the levels above it by stencil.
    // 0: the doors of the head's cell, as above. A level at or past max_depth
    // draws no texture (byte for byte the stencil frame).
    int portal_texture_level = 0;
    // z-clear portals (--technique z-clear, the PowerVR scheme;
    // render/portals/technique_zclear.cpp): each visible door's target room drawn
    // first within its rectangle, depth cleared, the doors into depth, then
    // the head's room. Depth 1 (max_depth <= 1), doors only, with culling,
    // no portal textures; anything else is an error.
    bool z_clear = false;
    // With culling: also test each visible portal of the head's cell for
    // occlusion (a query after the cell's surfaces) and drop the subtree of a
    // hidden one by conditional rendering. Exact, but the driver must
    // synchronise once a frame (about 1 ms on llvmpipe), so it pays only
    // where portals hide behind props or a concave room's own walls; off by
    // default (without it such a portal is drawn and hidden by depth).
    bool occlusion_test = false;
    // Under "lighting": "lights" (layout-format.md, "Lights"): the shadows
    // props cast, from cube shadow maps of shadow_map_size² texels per face
    // and light image (render/lights/shadow_maps.hpp); off (or a size of 0): light
    // passes props as if they were not there. No effect on "fixed" layouts.
    bool shadows = true;
    int shadow_map_size = kDefaultShadowMapSize;
};

// Switches that exist only to compare (tests, bench) and the profiler: none
// changes the image but the near and far planes, textures_mip_level0 and
// cull_portals' scissor.
struct Diagnostics {
    double near = 0.0;         // 0: the depth mode's own (kNearReversedZ, kNearStandard)
    double far = 2e5;          // only for DepthMode::Standard: beyond any valid layout
    bool cull_portals = true;  // per-eye frustum/facing culling and scissor (off: --no-cull)
    // With culling: props are drawn only where an eye's frustum, narrowed
    // through the portals, may see their bounds, and a portal hidden behind
    // one of its room's large box props is skipped with its subtree
    // (render/objects/object_culling.hpp).
    bool cull_objects = true;
    // The plain batches of a cell a level draws (with per-object culling,
    // runs of the index buffer between culled props) submitted as one
    // glMultiDrawElementsIndirect instead of one draw each (render/objects/multi_draw.hpp);
    // off only to compare the two (bench).
    bool multi_draw = true;
    // With culling: a portal that no other visible portal of its level comes
    // near on screen is marked with its depth reset in one draw, and one that
    // no later one comes near is not unmarked (render/portals/portal_steps.cpp,
    // PortalSteps); the image is the same. Off only to compare (tests, bench).
    bool portal_steps = true;
    // With per-object culling: of each visible box prop, only the faces an
    // eye of the level may see from the front, from a stream written per
    // frame (render/objects/box_faces.hpp); the image is the same. Off only to
    // compare (bench's N/all-faces, tests).
    bool cull_box_faces = true;
    // With culling, in a cell with volume portals: the cell drawn by the
    // plain variants outside the volumes' screen bounds and by the discarding
    // VOLUMES variant only inside them (render/objects/object_draw.hpp,
    // draw_level_colour); the image is the same. Off (the VOLUMES variant
    // over the whole level) only to compare (tests, bench's volumes=one-variant).
    bool split_volume_draws = true;
    // With culling and split_volume_draws: each volume's target room drawn
    // as only its triangles that may lie inside the volume, in pieces, each
    // within the screen bounds of where it meets the volume
    // (scene/volume_pieces.hpp); the image is the same. Off (the target's
    // whole cell within the volume's bounds) only to compare (tests, bench's
    // volumes=whole-target).
    bool volume_pieces = true;
    // With culling, under "lighting": "lights", in a cell some of whose light
    // images come through portals (and no volume): the cell drawn without the
    // loop over those images outside their lit regions' screen bounds
    // (lights::lit_region; render/objects/object_draw.hpp); the image is the
    // same. Off only to compare (tests, bench's lights:N/one-part).
    bool split_light_draws = true;
    // Under "lighting": "lights": every light image of a room added at every
    // point of it, without the portal tests (apertures and blockers) that
    // decide whether its light reaches the point: wrong wherever a path is
    // closed. Only a baseline for what the exact test costs (bench's
    // lights:N/naive), never a mode users pick.
    bool naive_lights = false;
    // Under "lighting": "lights": from a renderer's second frame at a light
    // depth on, the light on still, flat surfaces read from the light cache
    // (render/lights/light_cache.hpp; docs/lighting.md, "The light cache")
    // in a frame that places no moving prop or hand, with only the images
    // whose aperture edge or prop shadow may cross a cell added per fragment
    // there. The first frame, and every frame with it off, draws exactly as
    // before. Off only to compare (tests, bench's lights:N/no-cache).
    bool light_cache = true;
    // Textures read at mip level 0 with the magnification filter, as the
    // tracer reads them, instead of through their mipmaps: for comparing the
    // two (tests, bench's error), never for viewing (minified textures alias).
    bool textures_mip_level0 = false;
    // Measure the frame (for `impossible bench`): GL_SAMPLES_PASSED queries
    // around the colour passes, and glFinish + a monotonic clock around each
    // level-0 portal's subtree. The glFinish calls perturb the frame's own
    // time, so time frames with this off. Off: no queries, no extra work.
    bool profile = false;
};

// One frame for the rasteriser, in three parts: the view (math/view.hpp,
// what the tracer draws too), the technique and the diagnostics.
// View::max_portal_passes is the frame's budget: past it, portals show the
// fill colour (FrameStats::budget_fills). Only a frame that needs more changes.
struct FrameDesc : math::View, Technique, Diagnostics {};

inline double near_distance(const FrameDesc& frame) {
    if (frame.near > 0.0) return frame.near;
    return frame.depth == DepthMode::ReversedZ ? kNearReversedZ : kNearStandard;
}

struct FrameStats {
    long draw_calls = 0;
    long triangles = 0;            // scene and portal-box triangles submitted, all instances
                                   // counted (not the full-screen depth-clear triangles)
    int portal_passes_drawn = 0;   // portals whose target was drawn (both eyes count once)
    int portal_passes_culled = 0;  // portals skipped as invisible to both eyes
    int portal_passes_masked = 0;  // of those, the ones only the hidden area hides (hidden_mask.hpp)
    int portal_fills = 0;          // portals shown as the flat fill (depth limit or budget)
    int budget_fills = 0;          // of those, the ones drawn so because max_portal_passes was spent
    int one_draw_marks = 0;        // portals marked with their depth reset in one draw (PortalSteps)
    int unmarks_skipped = 0;       // portals left marked after their view (PortalSteps)
    int max_level_reached = 0;
    int light_images = 0;       // lit layouts: light images of the cells drawn, summed over the cells' draws
    int cached_levels = 0;      // lit layouts: cells' draws whose light came from the light cache (light_cache.hpp)
    int shadow_maps_drawn = 0;  // cube shadow maps (re)drawn this frame
    // Pixels (both eyes, each level's) of the rectangles in which a cell with
    // volume portals is drawn by the discarding VOLUMES variant (its own
    // batches and instances; FrameDesc::split_volume_draws).
    long volume_variant_pixels = 0;
    // Only with FrameDesc::profile:
    long colour_fragments = 0;  // samples that passed every test in the colour passes (Scene,
                                // PortalFill): fragments written to the colour buffer
    struct PortalCost {
        int portal = -1;            // index into the layout's portals (a portal of the head's room)
        double ms = 0.0;            // its whole subtree (mark, depth reset, the view through it and
                                    // everything visible in that view, unmark), glFinish to glFinish
        long colour_fragments = 0;  // colour fragments written within the subtree
    };
    std::vector<PortalCost> portal_costs;  // level-0 portals drawn (culled ones are absent)
};

}  // namespace impossible::render
