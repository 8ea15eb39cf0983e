// The top-down plan of `impossible plan`: the physical floor as a list of
// shapes in metres (x right, z down the page, so yaw 0 looks up), written as
// SVG (plan_svg.cpp) or rasterised into an RGB image (plan_raster.cpp).
//
// Drawn, bottom to top: a 1 m grid; the play area; every room's floor where
// it lies on the physical floor (design/placement.hpp), each in its own hue,
// unreachable rooms dashed; the floor two rooms share (grey, red where the
// overlap is likely to be noticed, design/overlap.hpp); props; doors as
// thick lines with an arrow through them in the walking direction, and a
// dashed arrow to the partner where the partner lies elsewhere on the floor;
// mirrors as a thick silver line with ticks on the back; windows as two thin
// blue lines with a dashed arrow to the partner window; the start; a walk
// path if given; room names (SVG only).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "design/report.hpp"
#include "image/pixels.hpp"
#include "layout/layout.hpp"
#include "math/pose.hpp"

namespace impossible::design {

struct Rgba {
    double r = 0, g = 0, b = 0, a = 1;
};

struct PlanShape {
    enum class Kind { Fill, Stroke, Text };
    Kind kind = Kind::Fill;
    std::string group;      // "grid", "play-area", "rooms", "overlaps", "props", "doors", "mirrors", "windows",
                            // "start", "path", "labels" (mirrors and windows only where there are some)
    std::string name;       // what it shows (a room or door id), may be empty
    math::Polygon2 points;  // Fill: a polygon; Stroke: a polyline; Text: its anchor
    bool closed = false;    // Stroke: join the last point to the first
    bool dashed = false;
    double width = 0.02;  // Stroke: m
    Rgba colour;
    std::string text;   // Text
    double size = 0.2;  // Text: m
};

struct Drawing {
    std::string title;
    glm::dvec2 min{0.0}, max{0.0};  // the floor shown, m
    std::vector<PlanShape> shapes;
};

// `path` holds physical head poses (may be empty).
Drawing plan_drawing(const layout::Layout& layout, const Report& report, const std::vector<math::HeadPose>& path);

// Pixels per metre for a drawing at most `max_pixels` wide and high.
double plan_scale(const Drawing& drawing, int max_pixels);

std::string plan_svg(const Drawing& drawing, double px_per_m);

// RGB, rows from the top.
image::Pixels plan_raster(const Drawing& drawing, double px_per_m);

}  // namespace impossible::design
