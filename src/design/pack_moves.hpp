// The packer's rules on a whole set of rooms, and the local search that
// improves a set: one room at a time is grown, moved, bent into an L, turned
// or made a corridor, and the move is kept when every rule still holds and no
// floor is lost (pack_search.hpp).
#pragma once

#include <optional>
#include <vector>

#include "design/pack_search.hpp"
#include "design/splitmix.hpp"

namespace impossible::design {

struct PackState {
    std::vector<Shape> shapes;
    std::vector<RoomGeom> geoms;
    double area = 0.0;  // m², summed
};

// The rooms with their geometry when every room is at least kRoomMinWidth
// wide and inside the play area, every pair is allowed and doors can join
// them all; nothing otherwise.
std::optional<PackState> evaluate(const PackRules& rules, const std::vector<Shape>& shapes);

// Moves tried per room by `improve`: after a lattice, and after rooms placed
// one at a time (which start small).
inline constexpr int kMovesPerRoom = 200;
inline constexpr int kGreedyMovesPerRoom = 600;

void improve(const PackRules& rules, PackState& state, SplitMix& rng, int moves_per_room = kMovesPerRoom);

// In pack_greedy.cpp, where no lattice fits (a triangle; more rooms than a
// lattice holds): rooms of 1.6 to 2 m by up to 3.5 m, turned to one of
// `angles`, placed one at a time at random spots where every rule holds
// and a door can join them to a room placed before; nothing when a room
// finds no spot in kGreedyTries tries.
inline constexpr int kGreedyTries = 400;
std::optional<PackState> place_greedily(const PackRules& rules, const std::vector<double>& angles, SplitMix& rng);

}  // namespace impossible::design
