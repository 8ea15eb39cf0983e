// The light images of a lit room (see light_images.hpp).
//
// The paths are enumerated from each light outwards, the way its light
// travels, so that the aperture test prunes whole branches: a node holds
// the part of the last aperture's rectangle that some ray from the light
// reaches through every aperture before it (the "window"), in the light's
// room's coordinates. A portal P is appended when the light's image lies
// behind P's plane, P does not lie in the plane of an aperture already
// passed (a straight ray crosses a plane once), and P's rectangle meets the
// part of the cone from the light through the window that lies beyond the
// window. Every node is then an image for the room of its last portal;
// the images are sorted into the order of a depth-first walk from that room.
#include "lights/light_images.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <glm/geometric.hpp>

#include "layout/room_shape.hpp"
#include "lights/aperture_clip.hpp"
#include "lights/light_blockers.hpp"
#include "math/rigid.hpp"
#include "shading/lighting.hpp"

namespace impossible::lights {

using math::dmat4;
using math::dvec3;
using math::dvec4;

namespace {

// A portal whose shadow ray leaves it into a room (the light travels back
// through it): a door's or window's target's room, or a mirror's (or a
// window's reflection's) own room.
struct LiArrival {
    int portal = -1;
    bool reflect = false;
};

// One portal of the path being built, from the light outwards.
struct LiStep {
    int portal = -1;
    bool reflect = false;
    int room = -1;          // the portal's room (the shadow ray meets it there)
    dmat4 to_light{1.0};    // that room's coordinates to the light's room's
    math::PortalRect rect;  // in the light's room's coordinates
    dvec4 plane{0.0};       // ditto
};

struct LiPending {
    int room = -1;  // C
    std::vector<int> key;
    LightImage image;
};

struct LiWalk {
    const layout::Layout& layout;
    const links::PortalLinks& links;
    int depth = 0;
    bool cull = true;
    std::vector<std::vector<LiArrival>> arrivals;
    std::vector<std::vector<int>> crossable;  // per room: layout::crossable_walls
    int light_room = -1;
    int light = -1;
    std::vector<LiStep> steps{};
    std::vector<LiPending> out{};
    // Counting only (light_depth_within): no images are made, and the walk
    // stops once more than `budget` nodes were counted.
    bool count_only = false;
    std::size_t budget = 0;
    std::size_t count = 0;
    // light_work: each node's image is made to count its rectangles, then
    // dropped.
    LightWork* work = nullptr;
};

std::vector<std::vector<int>> li_crossable(const layout::Layout& layout) {
    std::vector<std::vector<int>> out;
    for (const layout::Room& room : layout.rooms) out.push_back(layout::crossable_walls(room));
    return out;
}

std::vector<std::vector<LiArrival>> li_arrivals(const layout::Layout& layout, const links::PortalLinks& links) {
    std::vector<std::vector<LiArrival>> arrivals(layout.rooms.size());
    for (const std::vector<int>& portals : links.room_portals) {
        for (const int p : portals) {
            const layout::Portal& portal = layout.portals[static_cast<std::size_t>(p)];
            const bool pair = portal.kind != layout::PortalKind::Mirror;
            if (pair && links::valid_index(portal.target, layout.portals.size())) {
                const int to = layout.portals[static_cast<std::size_t>(portal.target)].room;
                if (links::valid_index(to, arrivals.size()))
                    arrivals[static_cast<std::size_t>(to)].push_back({p, false});
            }
            if (portal.kind != layout::PortalKind::Door) {
                arrivals[static_cast<std::size_t>(portal.room)].push_back({p, true});
            }
        }
    }
    return arrivals;
}

dvec3 li_portal_factor(const layout::Portal& portal, bool reflect) {
    switch (portal.kind) {
        case layout::PortalKind::Mirror: return portal.tint;
        case layout::PortalKind::Window:
            return reflect ? dvec3(portal.reflectance) : (1.0 - portal.reflectance) * portal.tint;
        default: return dvec3(1.0);
    }
}

const layout::Light& li_light(const LiWalk& walk) {
    return walk.layout.rooms[static_cast<std::size_t>(walk.light_room)].lights[static_cast<std::size_t>(walk.light)];
}

// Where a depth-first walk from the step's room meets the step: the
// portal's place among its room's portals, its through branch first.
int li_order_key(const LiWalk& walk, const LiStep& step) {
    const std::vector<int>& portals = walk.links.room_portals[static_cast<std::size_t>(step.room)];
    const auto place = std::find(portals.begin(), portals.end(), step.portal) - portals.begin();
    return 2 * static_cast<int>(place) + (step.reflect ? 1 : 0);
}

// The image of the current node, for the room of the last portal appended
// (the light's own room at k = 0).
LiPending li_make_image(const LiWalk& walk, const dvec3& factor) {
    const std::size_t k = walk.steps.size();
    const layout::Light& light = li_light(walk);
    LiPending pending;
    LightImage& image = pending.image;
    image.light_room = walk.light_room;
    image.light = walk.light;
    image.factor = factor;
    // Leg i runs in the room of P(i+1) (steps are stored light first).
    std::vector<dmat4> leg_to_light(k + 1, dmat4(1.0));
    image.rooms.assign(k + 1, walk.light_room);
    for (std::size_t i = 0; i < k; ++i) {
        const LiStep& step = walk.steps[k - 1 - i];
        leg_to_light[i] = step.to_light;
        image.rooms[i] = step.room;
        pending.key.push_back(li_order_key(walk, step));
    }
    pending.room = image.rooms[0];
    const dmat4 from_light = math::rigid_inverse(leg_to_light[0]);
    image.position = dvec3(from_light * dvec4(light.position, 1.0));
    const dvec3 axis = light.spot ? light.spot->direction : image.spot_direction;
    image.spot_direction = glm::normalize(dvec3(from_light * dvec4(axis, 0.0)));
    for (std::size_t i = 0; i <= k; ++i)
        image.to_room.push_back(math::rigid_inverse(leg_to_light[i]) * leg_to_light[0]);
    for (std::size_t i = 0; i < k; ++i) {
        const LiStep& step = walk.steps[k - 1 - i];
        const math::PortalRect& rect = walk.layout.portals[static_cast<std::size_t>(step.portal)].rect;
        image.apertures.push_back(
            {transform_rect(math::rigid_inverse(image.to_room[i]), rect), step.portal, step.reflect});
    }
    add_blockers({walk.layout, walk.links, walk.crossable, walk.cull}, image);
    return pending;
}

// The part of `rect` (the new aperture, in the light's room's coordinates)
// that rays from the light reach through the window of the aperture before
// it; empty when the path cannot be passed.
Polygon3 li_clip(const LiWalk& walk, const math::PortalRect& rect, const Polygon3& window) {
    const dvec3 light = li_light(walk).position;
    const double eps = 1e-9 * (1.0 + glm::length(light) + glm::length(rect.center) + rect.width + rect.height);
    if (math::signed_distance(rect, light) >= eps) return {};
    // A rectangle within eps of the plane of an aperture already passed
    // counts as lying in it: the path would cross that plane twice.
    Polygon3 corners = rect_polygon(rect, 0.0);
    for (const LiStep& step : walk.steps) {
        const bool coplanar = std::all_of(corners.begin(), corners.end(), [&](const dvec3& c) {
            return std::abs(glm::dot(dvec3(step.plane), c) + step.plane.w) <= eps;
        });
        if (coplanar) return {};
    }
    Polygon3 poly = rect_polygon(rect, eps);
    if (walk.steps.empty()) return poly;
    const dvec4 before = walk.steps.back().plane;  // beyond the window: in front of its aperture
    poly = clip_half_space(poly, dvec3(before), before.w, eps);
    if (poly.empty()) return poly;
    return clip_to_cone(poly, light, window, eps);
}

bool li_out_of_range(const LiWalk& walk, const Polygon3& window) {
    const layout::Light& light = li_light(walk);
    if (light.range <= 0.0) return false;
    const double slack = 1e-9 * (1.0 + glm::length(light.position) + light.range);
    return distance_to_polygon(light.position, window) >= light.range + slack;
}

LiStep li_step(const LiWalk& walk, const LiArrival& arrival, const dmat4& to_light) {
    const std::size_t index = static_cast<std::size_t>(arrival.portal);
    LiStep step;
    step.portal = arrival.portal;
    step.reflect = arrival.reflect;
    step.room = walk.layout.portals[index].room;
    step.to_light = to_light * (arrival.reflect ? walk.links.reflection[index] : walk.links.transfer[index]);
    step.rect = transform_rect(step.to_light, walk.layout.portals[index].rect);
    step.plane = math::portal_plane(step.rect);
    return step;
}

bool li_over_budget(const LiWalk& walk) { return walk.budget > 0 && walk.count > walk.budget; }

// A spot whose cone no ray from the light through the window lies in
// lights nothing along this path (spot = 0), nor along a longer one.
bool li_outside_spot(const LiWalk& walk, const Polygon3& window) {
    const layout::Light& light = li_light(walk);
    if (!light.spot) return false;
    const double cos_outer = std::cos(math::radians(light.spot->outer_deg));
    return max_cos_to_polygon(light.position, light.spot->direction, window) < cos_outer - 1e-9;
}

void li_count_work(LiWalk& walk, const dvec3& factor) {
    const std::size_t rects = path_rect_count(li_make_image(walk, factor).image);
    const std::size_t k = walk.steps.size();
    ++walk.work->images[k];
    walk.work->rects[k] += rects;
    if (k == 0)
        walk.work->own_rects[static_cast<std::size_t>(walk.light_room)][static_cast<std::size_t>(walk.light)] = rects;
}

void li_visit(LiWalk& walk, const Polygon3& window, const dvec3& factor) {
    ++walk.count;
    if (walk.work) li_count_work(walk, factor);
    if (!walk.count_only) walk.out.push_back(li_make_image(walk, factor));
    if (static_cast<int>(walk.steps.size()) >= walk.depth) return;
    const int room = walk.steps.empty() ? walk.light_room : walk.steps.back().room;
    const dmat4 to_light = walk.steps.empty() ? dmat4(1.0) : walk.steps.back().to_light;
    for (const LiArrival& arrival : walk.arrivals[static_cast<std::size_t>(room)]) {
        if (li_over_budget(walk)) return;
        const layout::Portal& portal = walk.layout.portals[static_cast<std::size_t>(arrival.portal)];
        const dvec3 next_factor = factor * li_portal_factor(portal, arrival.reflect);
        if (std::max({next_factor.x, next_factor.y, next_factor.z}) < shading::kMinLightFactor) continue;
        const LiStep step = li_step(walk, arrival, to_light);
        Polygon3 next_window;
        if (walk.cull) {
            next_window = li_clip(walk, step.rect, window);
            if (next_window.empty() || li_out_of_range(walk, next_window) || li_outside_spot(walk, next_window))
                continue;
        }
        walk.steps.push_back(step);
        li_visit(walk, next_window, next_factor);
        walk.steps.pop_back();
    }
}

// Every light of every room, outwards.
void li_walk_lights(LiWalk& walk) {
    for (std::size_t r = 0; r < walk.layout.rooms.size(); ++r) {
        for (std::size_t l = 0; l < walk.layout.rooms[r].lights.size() && !li_over_budget(walk); ++l) {
            walk.light_room = static_cast<int>(r);
            walk.light = static_cast<int>(l);
            li_visit(walk, {}, dvec3(1.0));
        }
    }
}

}  // namespace

std::vector<RoomLights> light_images(const layout::Layout& layout, const links::PortalLinks& links, int light_depth,
                                     const LightImageOptions& options) {
    std::vector<RoomLights> result;
    if (layout.lighting != layout::Lighting::Lights) return result;
    result.resize(layout.rooms.size());
    for (std::size_t r = 0; r < layout.rooms.size(); ++r) result[r].ambient = layout.rooms[r].ambient;
    LiWalk walk{layout,
                links,
                std::clamp(light_depth, 0, layout::kMaxLightDepth),
                options.cull,
                li_arrivals(layout, links),
                li_crossable(layout)};
    li_walk_lights(walk);
    // By path length, then as a depth-first walk from C meets them.
    std::stable_sort(walk.out.begin(), walk.out.end(), [](const LiPending& a, const LiPending& b) {
        return std::forward_as_tuple(a.key.size(), a.key, a.image.light) <
               std::forward_as_tuple(b.key.size(), b.key, b.image.light);
    });
    for (LiPending& pending : walk.out) {
        result[static_cast<std::size_t>(pending.room)].images.push_back(std::move(pending.image));
    }
    return result;
}

std::vector<RoomLights> light_images(const layout::Layout& layout, const links::PortalLinks& links, int light_depth) {
    return light_images(layout, links, light_depth, LightImageOptions{});
}

int light_depth_within(const layout::Layout& layout, const links::PortalLinks& links, int light_depth,
                       std::size_t max_images) {
    const int depth = std::clamp(light_depth, 0, layout::kMaxLightDepth);
    if (layout.lighting != layout::Lighting::Lights || max_images == 0) return depth;
    LiWalk walk{layout, links, 0, true, li_arrivals(layout, links), li_crossable(layout)};
    walk.count_only = true;
    walk.budget = max_images;
    for (int d = 1; d <= depth; ++d) {
        walk.depth = d;
        walk.count = 0;
        li_walk_lights(walk);
        if (li_over_budget(walk)) return d - 1;
    }
    return depth;
}

LightWork light_work(const layout::Layout& layout, const links::PortalLinks& links, int light_depth) {
    LightWork work;
    if (layout.lighting != layout::Lighting::Lights) return work;
    for (const layout::Room& room : layout.rooms) work.own_rects.emplace_back(room.lights.size(), 0);
    LiWalk walk{layout,
                links,
                std::clamp(light_depth, 0, layout::kMaxLightDepth),
                true,
                li_arrivals(layout, links),
                li_crossable(layout)};
    walk.count_only = true;
    walk.work = &work;
    li_walk_lights(walk);
    return work;
}

}  // namespace impossible::lights
