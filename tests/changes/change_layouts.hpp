// Layouts built in code for the changes tests (no loader involved).
#pragma once

#include <string>

#include "common/layouts.hpp"
#include "layout/layout.hpp"

namespace impossible::changes::testing {

using test::add_pair;
using test::add_room;
using test::make_portal;

// Suma's door swap in miniature: "hall" (x -2..2) has a door at x = 2,
// hall_east, into "study" (x 2..6, coincident: M = I), and a door at
// x = -2, hall_west, into "garden" (x 2..6 too, overlapping the study)
// through garden_west at x = 2, which stands where study_west does.
// Portal indices: hall_east 0, study_west 1, hall_west 2, garden_west 3.
// Change "swap" (enter study): hall_east leads into the garden.
inline layout::Layout door_swap() {
    layout::Layout l;
    l.source = "<door swap>";
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int study = add_room(l, "study", {2, 0, -2}, {6, 3, 2});
    const int garden = add_room(l, "garden", {2, 0, -2}, {6, 3, 2});
    add_pair(l, make_portal("hall_east", hall, {2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2),
             make_portal("study_west", study, {2, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    add_pair(l, make_portal("hall_west", hall, {-2, 1.1, 0}, {1, 0, 0}, 1.0, 2.2),
             make_portal("garden_west", garden, {2, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    l.start = {hall, {0, 1.6, 0}, 0.0};
    layout::Change swap;
    swap.id = "swap";
    swap.when.enter = study;
    swap.pairs = {{0, 3}};
    l.changes.push_back(swap);
    return l;
}

}  // namespace impossible::changes::testing
