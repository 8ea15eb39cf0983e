// Which of a door's passes a level may leave out (portal_steps.hpp,
// PortalSteps), decided from the level's visible portals on screen.
//
// Every draw of a portal's subtree lies within its rectangle in each eye,
// widened by at most two pixels: its box and its view's draws by their clip
// distances (one pixel, set_eye_uniforms), the depth resets and marks by
// their quads (two pixels). The full-target triangles of mirrors and windows
// are bounded only by the scissor of the pair, which spans the seam between
// the eyes. Two portals whose rectangles, so widened, do not meet touch
// disjoint pixels:
// - the mark: where no other visible portal of the level comes near, only
//   this portal's box can have set the box bit in its quads, so the quads
//   mark it and reset its depth in one draw (passes.hpp);
// - the unmark: where no later portal of the level comes near, no later draw
//   of the level tests its pixels, so they may keep their deeper levels; the
//   unmark of an outer portal (which tests "deeper than my level") or the end
//   of the frame takes them back. Where the layout has mirrors or windows, a
//   later portal's reach is its whole scissor.
// Without culling every draw covers the whole target: both steps as before,
// as with FrameDesc::portal_steps off.
#include <algorithm>
#include <cmath>

#include "render/portals/portal_steps.hpp"

namespace impossible::render {
namespace {

// Pixels beyond an eye's rectangle that a portal's draws may touch: the
// quads' two, and one for rounding.
constexpr int kStepsMargin = 3;

struct StepsBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // target pixels, [x0, x1) × [y0, y1)
    bool empty = true;
};

// Eye `e`'s rectangle in the target's pixels (the eyes side by side), widened.
StepsBox steps_box(const FrameDesc& f, const NdcRect& r, int e) {
    if (r.empty()) return {};
    const int w = f.eye_width, h = f.eye_height;
    StepsBox b;
    b.x0 = e * w + static_cast<int>(std::floor((r.x0 + 1.0) * 0.5 * w)) - kStepsMargin;
    b.x1 = e * w + static_cast<int>(std::ceil((r.x1 + 1.0) * 0.5 * w)) + kStepsMargin;
    b.y0 = static_cast<int>(std::floor((r.y0 + 1.0) * 0.5 * h)) - kStepsMargin;
    b.y1 = static_cast<int>(std::ceil((r.y1 + 1.0) * 0.5 * h)) + kStepsMargin;
    b.empty = false;
    return b;
}

StepsBox steps_union(const StepsBox& a, const StepsBox& b) {
    if (a.empty) return b;
    if (b.empty) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1), false};
}

bool steps_meet(const StepsBox& a, const StepsBox& b) {
    return !a.empty && !b.empty && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

bool steps_has_glass(const SceneData& r) {
    return std::any_of(r.portals.begin(), r.portals.end(),
                       [](const scene::PortalInfo& p) { return p.kind != layout::PortalKind::Door; });
}

}  // namespace

std::vector<PortalSteps> portal_steps(const DrawContext& ctx, const LevelView& view,
                                      const std::vector<std::array<NdcRect, 2>>& visible) {
    const FrameDesc& f = ctx.frame;
    std::vector<PortalSteps> steps(visible.size());
    if (!f.cull_portals || !f.portal_steps) return steps;
    const size_t n = visible.size();
    std::vector<std::array<StepsBox, 2>> eyes(n);
    std::vector<StepsBox> reach(n);  // what a later portal's draws may touch
    const bool glass = steps_has_glass(ctx.scene);
    for (size_t k = 0; k < n; ++k)
        for (int e = 0; e < 2; ++e) {
            eyes[k][e] = view.eyes[e].active ? steps_box(f, visible[k][e], e) : StepsBox{};
            reach[k] = steps_union(reach[k], eyes[k][e]);
        }
    const bool box_bit = has_box_bit(f.max_depth);
    // Only the portals some eye sees take part: a level may hold thousands of
    // culled ones, and the pairs below are quadratic in what is left.
    // (An unseen one meets nothing: one draw, no unmark, as the loop gives.)
    std::vector<size_t> seen;
    for (size_t k = 0; k < n; ++k) {
        steps[k].one_draw_mark = box_bit;
        steps[k].unmark = false;
        if (!reach[k].empty) seen.push_back(k);
    }
    for (const size_t k : seen) {
        bool near_any = false, near_later = false;
        for (const size_t j : seen) {
            if (j == k) continue;
            const bool near = steps_meet(eyes[k][0], eyes[j][0]) || steps_meet(eyes[k][1], eyes[j][1]);
            near_any = near_any || near;
            if (j > k)
                near_later = near_later || near ||
                             (glass && (steps_meet(eyes[k][0], reach[j]) || steps_meet(eyes[k][1], reach[j])));
        }
        steps[k].one_draw_mark = box_bit && !near_any;
        steps[k].unmark = near_later;
    }
    return steps;
}

}  // namespace impossible::render
