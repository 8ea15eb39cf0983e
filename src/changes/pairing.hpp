// The door pairing in force while a layout is walked (layout-format.md,
// "Changes while walking"), and the layout that pairing gives: the same
// rooms and portals, doors re-targeted, closed doors taken out. A closed
// door that lay in a face leaves no hole there (the face is whole, with its
// colour and material); a free-standing one is not there at all. Everything
// that draws, traces, lights or walks a layout then handles a change without
// knowing about it.
#pragma once

#include <vector>

#include "layout/layout.hpp"

namespace impossible::changes {

// target[i] for each portal i of the layout as loaded: a door's partner,
// or -1 when it is closed; mirrors and windows keep the loaded target.
struct Pairing {
    std::vector<int> target;
    bool operator==(const Pairing&) const = default;
};

// The pairing the layout's `portals` give.
Pairing loaded_pairing(const layout::Layout& layout);

// The doors a change affects: those its pairs name, then each one's partner
// under `pairing` (not named itself, not closed), each once, ascending.
std::vector<int> affected_doors(const layout::Change& change, const Pairing& pairing);

// Makes the change: each named pair targets each other; a former partner
// left without a pair is closed.
void make_change(const layout::Change& change, Pairing& pairing);

// The layout walked with `pairing`: base with every door's target set by it
// and the closed doors removed from `portals` (the others keep their order).
// base_index[k] is the index in base of the result's portal k. Its
// `changes` are empty: they name base's portals, and the walk keeps them.
struct PairedLayout {
    layout::Layout layout;
    std::vector<int> base_index;
};
PairedLayout paired_layout(const layout::Layout& base, const Pairing& pairing);

}  // namespace impossible::changes
