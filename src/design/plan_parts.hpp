// The pieces plan.cpp draws with, shared by the plan's files: rooms'
// colours and hatching, shape makers, and the marks of lamps, moving props'
// paths and the legend (plan_marks.cpp, plan_legend.cpp).
#pragma once

#include <string>

#include "design/plan.hpp"

namespace impossible::design::plan_parts {

// A room's colours: its floor (translucent), its outline and hatching, its
// name, its props.
enum class Tone { Fill, Line, Dark, Prop };
Rgba room_colour(int room, Tone tone);
double room_hatch_angle(int room);  // radians

// Rooms are hatched only up to this many (each room's lines are shapes of
// their own; 10,000 stacked rooms would make millions).
inline constexpr std::size_t kMaxHatchedRooms = 64;

PlanShape fill(const std::string& group, const std::string& name, math::Polygon2 points, Rgba colour);
PlanShape stroke(const std::string& group, const std::string& name, math::Polygon2 points, Rgba colour, double width,
                 bool closed = false, bool dashed = false);
// A line with a filled arrowhead at `to`.
void arrow(Drawing& d, const std::string& group, const std::string& name, glm::dvec2 from, glm::dvec2 to, Rgba c,
           double width, bool dashed);
math::Polygon2 circle(glm::dvec2 c, double r);

inline constexpr Rgba kLampColour{0.96, 0.70, 0.05, 1.0};
inline constexpr Rgba kLampEdge{0.45, 0.28, 0.0, 1.0};
inline constexpr Rgba kMotionColour{0.80, 0.30, 0.55, 1.0};
inline constexpr Rgba kChangeColour{0.42, 0.12, 0.68, 1.0};

void add_hatching(Drawing& d, const layout::Layout& layout, const Report& r);
void add_motions(Drawing& d, const layout::Layout& layout, const Report& r);
void add_lights(Drawing& d, const layout::Layout& layout, const Report& r);
// "" for a room reachable from the start, " (after ID)" for one reachable
// only after change ID, else `unreachable`.
std::string reach_note(const layout::Layout& layout, const Report& r, std::size_t room, const char* unreachable);
// Each change's new pairs (plan_changes.cpp), group "changes".
void add_changes(Drawing& d, const layout::Layout& layout, const Report& r);
// The legend's entries: every room (the first kMaxLegendRooms), then each
// kind of mark the drawing holds.
inline constexpr std::size_t kMaxLegendRooms = 24;
void add_legend(Drawing& d, const layout::Layout& layout, const Report& r, bool path);

}  // namespace impossible::design::plan_parts
