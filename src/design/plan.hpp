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
// blue lines with a dashed arrow to the partner window; lamps (a sun:
// amber disc and rays; a spot's direction as an arrow); each moving prop's
// path (dashed, an arrow at its last key, closed where it loops); the
// start; a walk path if given; room names. Rooms take colours of their own
// (Okabe and Ito's palette for the first seven, then golden-ratio hues) and
// hatching at angles of their own, so that three rooms on one spot can
// still be told apart. Below the floor, a legend (plan_overlay): every
// room's colour and name, then each kind of mark the drawing holds. The SVG
// and the PNG draw the same shapes, text included.
#pragma once

#include <array>
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
    std::string text;     // Text
    double size = 0.2;    // Text: m (overlay: pixels)
    bool centred = true;  // Text: centred on its anchor, else starting there
};

// A line of the legend: a sample of a mark and what it means.
struct LegendEntry {
    enum class Sample { Swatch, Line, Dashed, Dot };
    Sample sample = Sample::Swatch;
    Rgba fill, line;      // a swatch's fill and outline; a line's or dot's colour is `line`
    double hatch = -1.0;  // a swatch's hatching angle, radians (< 0: none)
    std::string text;
};

struct Drawing {
    std::string title;
    glm::dvec2 min{0.0}, max{0.0};  // the floor shown, m
    std::vector<PlanShape> shapes;
    std::vector<LegendEntry> legend;
};

// `path` holds physical head poses (may be empty).
Drawing plan_drawing(const layout::Layout& layout, const Report& report, const std::vector<math::HeadPose>& path);

// Pixels per metre for a drawing at most `max_pixels` wide and high.
double plan_scale(const Drawing& drawing, int max_pixels);

// The picture's size in pixels: the title, the floor and the legend.
struct PlanSize {
    int width = 0, height = 0;
    double floor_top = 0.0;   // pixels above the floor (the title's band)
    double legend_top = 0.0;  // where the legend starts
};
PlanSize plan_size(const Drawing& drawing, double px_per_m);

// The title and the legend as shapes in pixels of the picture (text sizes
// in pixels), drawn over the floor by plan_svg and plan_raster alike.
std::vector<PlanShape> plan_overlay(const Drawing& drawing, double px_per_m);

// A floor label's font size in pixels: its size, but never below 9 px.
double label_pixels(const PlanShape& text, double px_per_m);

// Hatching of a polygon: lines at `angle` (radians) `spacing` apart, cut to
// the polygon (even-odd), as segments.
std::vector<std::array<glm::dvec2, 2>> hatch_lines(const math::Polygon2& polygon, double angle, double spacing);

std::string plan_svg(const Drawing& drawing, double px_per_m);

// RGB, rows from the top.
image::Pixels plan_raster(const Drawing& drawing, double px_per_m);

}  // namespace impossible::design
