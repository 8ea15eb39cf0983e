// Poses on every layout in layouts/ for the rasteriser-against-tracer tests:
// start views, crossed eyes, an eye within the near distance, grazing views,
// rolled heads, deep recursion.
#pragma once

#include "math/pose.hpp"

namespace impossible::testing {

struct PoseCase {
    const char* layout;
    const char* room;
    math::dvec3 position;
    double yaw, pitch, roll;
    const char* what;
};

inline const PoseCase kPoseCases[] = {
    {"default.json", "hall", {0.3, 1.6, 1.6}, 8, 0, 0, "start"},
    {"default.json", "hall", {0.0, 1.6, 0.005}, 0, 0, 0, "5 mm in front of the door"},
    {"default.json", "hall", {0.1, 1.6, 0.002}, 90, 0, 0, "right eye inside the box"},
    {"default.json", "hall", {0.0, 1.6, -0.01}, 180, -10, 0, "looking back out of the box"},
    {"default.json", "annex", {0.0, 1.6, -0.002}, -90, 0, 0, "crossed eye, other direction"},
    {"default.json", "hall", {1.4, 1.2, 0.3}, 89.9, 0, 0, "grazing the door plane"},
    {"default.json", "hall", {-0.8, 2.0, 1.2}, -30, -25, 20, "rolled and pitched"},
    {"four_rooms.json", "hall", {0.0, 1.6, 1.5}, 0, 0, 0, "start"},
    {"four_rooms.json", "library", {0.2, 1.6, -1.2}, 160, 0, 0, "library to studio"},
    {"tunnel.json", "yard", {0.6, 1.6, 2.6}, 8, 0, 0, "start"},
    {"tunnel.json", "tunnel", {0.1, 1.53, -6.0}, 0, 0, 0, "out of the far end"},
    {"rotated.json", "hall", {0.2, 1.6, 1.6}, 5, 0, 0, "start"},
    {"rotated.json", "gallery", {1.2, 1.5, 0.3}, 80, 0, -10, "back through the turned door"},
    {"corridor.json", "corridor", {0.25, 1.6, 2.0}, 4, 0, 0, "start, deep recursion"},
    {"corridor.json", "corridor", {0.0, 1.2, 3.5}, 0, 0, 0, "straight down the corridor"},
    {"loop.json", "red", {0.0, 1.6, -0.8}, 0, 0, 0, "start"},
    {"loop.json", "red", {0.3, 1.6, -4.5}, -70, 0, 0, "through the side door"},
    {"mirror_hall.json", "hall", {0.6, 1.6, 2.4}, 35, 0, 0, "start"},
    {"glass_gallery.json", "gallery", {-0.8, 1.6, 1.8}, -20, 0, 0, "start"},
    {"window_pair.json", "studio", {0.6, 1.45, 0.3}, 86, 0, 0, "start"},
    {"three_kinds.json", "atelier", {0.05, 1.55, 0.45}, 0, 0, 0, "start"},
    // Rooms of any shape (issue 23).
    {"l_flat.json", "hall", {-1.6, 1.6, 1.8}, -20, 0, 0, "start"},
    {"l_flat.json", "hall", {-1.5, 1.6, -1.5}, -118.6, 0, 0, "through the bedroom door"},
    {"l_flat.json", "hall", {-2.0, 1.6, 2.2}, -55.9, 0, 0, "the inner corner hides a door"},
    {"l_flat.json", "study", {1.5, 1.5, 1.25}, 90, -5, 0, "back into the hall"},
    {"turned_room.json", "hall", {-1.4, 1.6, 2.424871}, -30, 0, 0, "start"},
    {"turned_room.json", "reading_room", {0.0, 1.5, 0.0}, 150, 0, 0, "back through the slanted wall"},
    {"curved_corridor.json", "studio", {-1.0, 1.6, -1.5}, -90, 0, 0, "start"},
    {"curved_corridor.json", "corridor", {2.0, 1.5, 0.0}, 180, 0, 0, "along the curve"},
    {"curved_corridor.json", "library", {-1.0, 1.6, 1.5}, -90, 0, 0, "into the corridor's far end"},
    {"trapdoor.json", "tower", {0.4, 1.6, 0.6}, 0, -60, 0, "down through the trapdoor"},
    {"trapdoor.json", "cellar", {0.4, -1.4, 0.5}, 0, 70, 0, "up through the trapdoor"},
};

}  // namespace impossible::testing
