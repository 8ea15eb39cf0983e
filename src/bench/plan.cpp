#include "bench/plan.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "bench/light_sweep.hpp"
#include "layout/path_file.hpp"
#include "layout/room_shape.hpp"
#include "session/walk_driver.hpp"
#include "walk/walker.hpp"

namespace impossible::bench {

using cli::frame_for;
using cli::ViewOptions;

using cli::value_or_throw;

layout::Layout keep_first_portals(const layout::Layout& layout, int n) {
    layout::Layout out = layout;
    out.portals.clear();
    out.changes.clear();  // they name the given layout's portals; bench walks that layout, and draws this one
    std::vector<int> renumbered(layout.portals.size(), -1);
    for (size_t i = 0; i < layout.portals.size(); ++i) {
        const int target = layout.portals[i].target;  // -1 for a mirror, which needs no partner
        if (static_cast<int>(i) < n && target < n) {
            renumbered[i] = static_cast<int>(out.portals.size());
            out.portals.push_back(layout.portals[i]);
        }
    }
    for (layout::Portal& p : out.portals)
        if (p.target >= 0) p.target = renumbered[p.target];
    return out;
}

namespace {

// The layout without its volume portals.
layout::Layout without_volumes(const layout::Layout& layout) {
    layout::Layout out = layout;
    out.volumes.clear();
    return out;
}

// Whether a box's footprint lies on the room's floor: always in a box room;
// in a prism room, its corners inside the floor and no corner of the floor
// inside the footprint.
bool box_on_floor(const layout::Room& room, const layout::BoxProp& box) {
    if (!layout::is_prism(room)) return true;
    for (const double x : {box.min.x, box.max.x})
        for (const double z : {box.min.z, box.max.z})
            if (!inside_floor(room, {x, room.min.y, z}, 0.0)) return false;
    return std::none_of(room.floor.begin(), room.floor.end(), [&](const glm::dvec2& c) {
        return c.x > box.min.x && c.x < box.max.x && c.y > box.min.z && c.y < box.max.z;
    });
}

}  // namespace

// The layout with `n` small boxes (12 triangles each) added on the floor of
// every room, in a grid: scene triangles without changing which rooms show
// (in a prism room, those of the grid that stand on its floor).
layout::Layout with_extra_boxes(const layout::Layout& layout, int n) {
    layout::Layout out = layout;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    for (layout::Room& room : out.rooms) {
        const glm::dvec3 extent = room.max - room.min;
        const double size = 0.4 * std::min(extent.x, extent.z) / std::max(side, 1);
        for (int i = 0; i < n; ++i) {
            layout::BoxProp box;
            const double x = room.min.x + (i % side + 0.5) * extent.x / side;
            const double z = room.min.z + (i / side + 0.5) * extent.z / side;
            box.min = {x - 0.5 * size, room.min.y, z - 0.5 * size};
            box.max = {x + 0.5 * size, room.min.y + size, z + 0.5 * size};
            box.color = {0.7, 0.5, 0.3};
            if (box_on_floor(room, box)) room.props.push_back(box);
        }
    }
    return out;
}

namespace {

// Adds configurations to a plan: the base frame, changed.
struct PlanBuilder {
    BenchPlan& plan;
    render::FrameDesc base;
    std::map<int, int> box_layouts;  // boxes per room → its layout variant

    template <class Change>
    void add(const std::string& name, const std::string& group, Change change) {
        BenchConfig c{name, group, 0, base};
        change(c);
        plan.configs.push_back(c);
    }
};

// --sweep techniques: each technique against the default, and depths.
void add_techniques(PlanBuilder& b) {
    b.add("stereo=two-pass", "stereo", [](BenchConfig& c) { c.frame.stereo = render::StereoMode::TwoPass; });
    b.add("stereo=viewport-index", "stereo",
          [](BenchConfig& c) { c.frame.stereo = render::StereoMode::ViewportIndex; });
    b.add("clip=oblique", "clip", [](BenchConfig& c) { c.frame.clip = render::ClipMode::Oblique; });
    b.add("clip=clip-distance", "clip", [](BenchConfig& c) { c.frame.clip = render::ClipMode::ClipDistance; });
    b.add("cull=off", "cull", [](BenchConfig& c) { c.frame.cull_portals = false; });
    b.add("cull=on", "cull", [](BenchConfig& c) { c.frame.cull_portals = true; });
    b.add("occlusion=on", "occlusion", [](BenchConfig& c) { c.frame.occlusion_test = true; });
    b.add("multi-draw=off", "multi-draw", [](BenchConfig& c) { c.frame.multi_draw = false; });
    b.add("volumes=one-variant", "volumes", [](BenchConfig& c) { c.frame.split_volume_draws = false; });
    for (double scale : {0.25, 0.5, 1.0}) {
        char name[32];
        std::snprintf(name, sizeof name, "texture=%g", scale);
        b.add(name, "technique", [scale](BenchConfig& c) { c.frame.portal_texture_scale = scale; });
    }
    // Hybrid (stencil above level K, textures at full scale from it on) and
    // z-clear (depth 1 only: compare it with depth=1).
    for (int k : {1, 2, 4})
        b.add("hybrid=" + std::to_string(k), "technique", [k](BenchConfig& c) {
            c.frame.portal_texture_scale = 1.0;
            c.frame.portal_texture_level = k;
        });
    b.add("z-clear", "technique", [](BenchConfig& c) {
        c.frame.z_clear = true;
        c.frame.max_depth = 1;
    });
    for (int d : {1, 2, 4, 8, 16, 64})
        b.add("depth=" + std::to_string(d), "depth", [d](BenchConfig& c) { c.frame.max_depth = d; });
}

// One item of --sweep boxes: "N", or "N/all" (the same boxes with per-object
// culling off), or "N/separate" (one draw per run of visible props instead of
// a multi-draw), or "N/all-faces" (every face of a visible box, back faces
// too: FrameDesc::cull_box_faces off), to compare in one run.
void add_boxes(PlanBuilder& b, const SweepItem& item) {
    // One layout per count, shared by its variants (the tracer then
    // draws each count's reference once).
    BenchPlan& plan = b.plan;
    auto [at, made] = b.box_layouts.try_emplace(item.n, static_cast<int>(plan.sessions.size()));
    if (made) plan.sessions.emplace_back(with_extra_boxes(plan.sessions[0].layout(), item.n));
    const int variant = at->second;
    b.add(item.name, "boxes", [&](BenchConfig& c) {
        c.layout_variant = variant;
        c.frame.cull_objects = item.suffix != "all";
        c.frame.multi_draw = item.suffix != "separate";
        c.frame.cull_box_faces = item.suffix != "all-faces";
    });
}

// One item of --sweep volumes: "split" (the default), "whole-target" (split,
// but each volume's target room drawn whole within the volume's bounds, not
// in pieces), "one-variant" (the discarding variant over the whole level) or
// "none" (the layout without its volumes).
void add_volumes(PlanBuilder& b, const layout::Layout& layout, const SweepItem& item) {
    int variant = 0;
    if (item.suffix == "none") {
        b.plan.sessions.emplace_back(without_volumes(layout));
        variant = static_cast<int>(b.plan.sessions.size()) - 1;
    }
    const bool split = item.suffix != "one-variant";
    const bool pieces = item.suffix != "whole-target";
    b.add(item.name, item.kind, [variant, split, pieces](BenchConfig& c) {
        c.layout_variant = variant;
        c.frame.split_volume_draws = split;
        c.frame.volume_pieces = pieces;
    });
}

// One item of --sweep KIND:ITEM,... (parsed with the options, bench/sweep.hpp).
void add_sweep_item(PlanBuilder& b, const layout::Layout& layout, const SweepItem& item) {
    const std::string& kind = item.kind;
    const int n = item.n;
    if (kind == "portals") {
        // "N/all-steps": the same N portals with every door pass
        // (FrameDesc::portal_steps off), to compare in one run.
        const bool all_steps = item.suffix == "all-steps";
        b.plan.sessions.emplace_back(keep_first_portals(layout, n));
        const int variant = static_cast<int>(b.plan.sessions.size()) - 1;
        b.add(item.name, kind, [variant, all_steps](BenchConfig& c) {
            c.layout_variant = variant;
            c.frame.portal_steps = !all_steps;
        });
    } else if (kind == "boxes") {
        add_boxes(b, item);
    } else if (kind == "samples") {
        b.add(item.name, kind, [n](BenchConfig& c) { c.frame.samples = n; });
    } else if (kind == "lights") {
        b.plan.sessions.emplace_back(with_lights(b.plan.sessions[0].layout(), n));
        const int variant = static_cast<int>(b.plan.sessions.size()) - 1;
        // The same lights without the portal tests; with each lit room in
        // one part (not split by where its path images can light it,
        // render/objects/object_draw.hpp); without the light cache.
        const bool naive = item.suffix == "naive", one_part = item.suffix == "one-part";
        const bool no_cache = item.suffix == "no-cache";
        b.add(item.name, kind, [variant, naive, one_part, no_cache](BenchConfig& c) {
            c.layout_variant = variant;
            c.frame.naive_lights = naive;
            c.frame.split_light_draws = !one_part;
            c.frame.light_cache = !no_cache;
        });
    } else if (kind == "light-depth") {
        if (layout.lighting != impossible::layout::Lighting::Lights)
            throw cli::InputError("--sweep light-depth: the layout's lighting is \"fixed\" (try --sweep lights:...)");
        b.add(item.name, kind, [n](BenchConfig& c) { c.frame.light_depth = n; });
    } else if (kind == "shadow-size") {
        b.add(item.name, kind, [n](BenchConfig& c) {
            c.frame.shadow_map_size = n;
            c.frame.shadows = n > 0;
        });
    } else if (kind == "mask") {
        // With --hmd: the profile's hidden areas masked, or the same frusta
        // drawing every pixel (docs/headsets.md).
        if (!math::has_hidden_area(b.base)) throw cli::InputError("--sweep mask: needs --hmd with a visible_area");
        const bool on = item.on;
        b.add(item.name, kind, [on](BenchConfig& c) {
            if (!on)
                for (math::EyeOptics& e : *c.frame.eye_optics) e.visible_area.clear();
        });
    } else if (kind == "volumes") {
        add_volumes(b, layout, item);
    } else if (kind == "depth") {
        b.add(item.name, kind, [n](BenchConfig& c) { c.frame.max_depth = n; });
    } else {
        b.add(item.name, kind, [w = item.width, h = item.height](BenchConfig& c) {
            c.frame.eye_width = w;
            c.frame.eye_height = h;
        });
    }
}

}  // namespace

BenchPlan plan_bench(const session::Session& session, const BenchOptions& o) {
    const layout::Layout& layout = session.layout();
    BenchPlan plan;
    if (o.portals)
        plan.sessions.emplace_back(keep_first_portals(layout, *o.portals));
    else
        plan.sessions.push_back(session);
    // Head and room come per pose; frame_for only needs a valid room here.
    ViewOptions view = o.view;
    view.pose.reset();
    view.room.reset();
    PlanBuilder builder{plan, frame_for(plan.sessions[0], view), {}};
    builder.add("base", "base", [](BenchConfig&) {});
    if (o.sweep == "techniques") {
        add_techniques(builder);
    } else {
        for (const SweepItem& item : o.sweep_items) add_sweep_item(builder, layout, item);
    }
    return plan;
}

void add_stages(BenchPlan& plan, const std::vector<session::Session>& stages, const BenchOptions& o) {
    for (const session::Session& stage : stages) plan.stages.push_back(plan_bench(stage, o).sessions);
}

std::vector<BenchPose> bench_poses(const session::Session& session, const BenchOptions& o,
                                   std::vector<session::Session>* stages) {
    if (!o.path) {
        session::Session placed = session;  // without --path, frame_for keeps it
        const render::FrameDesc f = frame_for(placed, o.view);
        return {{f.head, f.room, f.time, f.hands, 0}};
    }
    const std::vector<layout::PathFrame> file = value_or_throw(layout::read_path_frames_file(*o.path));
    const double fps = o.fps.value_or(layout::kDefaultPathFps);
    // The eyes of the seen test: the bench's view options (the head is the walk's).
    ViewOptions seen = o.view;
    seen.pose.reset();
    seen.room.reset();
    session::Session start = session;
    const math::View eyes = frame_for(start, seen);
    session::WalkDriver driver(session, eyes);
    std::vector<BenchPose> poses;
    int stage = 0;
    for (std::size_t k = 0; k < file.size(); ++k) {
        const double time = walk::line_time(k, fps);
        if (!driver.step(file[k].head, std::nullopt, time).changes.empty()) {
            ++stage;
            if (stages) stages->push_back(driver.session());
        }
        math::View view;
        walk::set_walked_view(view, driver.walker(), file[k].hands);
        poses.push_back({view.head, view.room, time, view.hands, stage});
    }
    return poses;
}

}  // namespace impossible::bench
