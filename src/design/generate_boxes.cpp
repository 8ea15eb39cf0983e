// Rooms grown out of each other, the generator's first way (and now its
// fallback, for play areas the packer does not take: more than
// kPackMaxCorners corners, or a lattice that does not fit). See generate.hpp.
//
// Rooms are axis-aligned boxes on a 0.1 m grid, each inside the play area.
// The first room is placed at random; each further room B grows out of a
// wall of an existing room A: a door in A's wall, and a coincident door in B
// facing the other way. B reaches at least kMinReach beyond A's wall and may
// reach back into A: that part is the overlap. Where no first room placed at
// random fits (a play area roomy only in one narrow part), rooms centred on
// the play area's widest spot are tried (widest_spot.hpp).
#include <algorithm>
#include <cmath>

#include "design/area_index.hpp"
#include "design/generate.hpp"
#include "design/overlap.hpp"
#include "design/pack_search.hpp"
#include "design/splitmix.hpp"
#include "design/widest_spot.hpp"

namespace impossible::design {
namespace {

struct Box {  // decimetres
    int x0 = 0, z0 = 0, x1 = 0, z1 = 0;
    math::Polygon2 floor() const { return math::rectangle({x0 / 10.0, z0 / 10.0}, {x1 / 10.0, z1 / 10.0}); }
};

struct Door {  // a coincident pair: `a`'s door in its wall, `b`'s facing the other way
    int a = -1, b = -1;
    int side = 0;             // A's wall: 0 -x, 1 +x, 2 -z, 3 +z
    int wall = 0, along = 0;  // dm: the wall's coordinate, the door's centre along it
    glm::dvec2 centre() const {
        return side < 2 ? glm::dvec2(wall / 10.0, along / 10.0) : glm::dvec2(along / 10.0, wall / 10.0);
    }
};

struct Draft {
    std::vector<Box> rooms;
    std::vector<Door> doors;
};

struct Floor {
    const GenerateOptions& o;
    AreaIndex area;
    std::optional<WidestSpot>& spot;  // found when first needed
};

bool fits(const Floor& f, const Draft& d, const Box& b) {
    if (!f.area.box_inside({b.x0 / 10.0, b.z0 / 10.0}, {b.x1 / 10.0, b.z1 / 10.0})) return false;
    const math::Polygon2 floor = b.floor();
    for (const Box& other : d.rooms) {
        const Overlap ov = overlap_of(floor, other.floor());
        const double limit = f.o.max_overlap ? *f.o.max_overlap : ov.limit;
        if (ov.percent > limit + 1e-9) return false;
    }
    return true;
}

// Tries once to grow a new room out of a wall of an existing one.
bool grow(const Floor& f, Draft& d, SplitMix& rng, int max_side) {
    const int a = rng.uniform(0, static_cast<int>(d.rooms.size()) - 1);
    const Box& A = d.rooms[a];
    Door door{a, static_cast<int>(d.rooms.size()), rng.uniform(0, 3)};
    const bool along_z = door.side < 2;  // the wall runs along z
    const int lo = along_z ? A.z0 : A.x0, hi = along_z ? A.z1 : A.x1;
    door.wall = door.side == 0 ? A.x0 : door.side == 1 ? A.x1 : door.side == 2 ? A.z0 : A.z1;
    door.along = rng.uniform(lo + 8, hi - 8);
    if (hi - lo < 16) return false;
    for (const Door& other : d.doors)
        if ((other.a == a || other.b == a) && glm::distance(other.centre(), door.centre()) < 1.5) return false;
    const int depth = rng.uniform(kMinRoomSide, max_side);
    const int reach = rng.uniform(0, 2) == 0 ? depth : rng.uniform(kMinReach, depth);
    const int back = depth - reach;  // how far B reaches into A
    const int need = kDoorWidth + 2 * kDoorSideRoom;
    const int length = rng.uniform(std::max(kMinRoomSide, need), std::max(max_side, need));
    const int start = rng.uniform(door.along + (need + 1) / 2 - length, door.along - (need + 1) / 2);
    const int outward = door.side % 2 == 1 ? 1 : -1;
    const int p0 = door.wall - outward * back, p1 = door.wall + outward * reach;
    Box B;
    if (along_z) {
        B.x0 = std::min(p0, p1), B.x1 = std::max(p0, p1), B.z0 = start, B.z1 = start + length;
    } else {
        B.z0 = std::min(p0, p1), B.z1 = std::max(p0, p1), B.x0 = start, B.x1 = start + length;
    }
    if (!fits(f, d, B)) return false;
    d.rooms.push_back(B);
    d.doors.push_back(door);
    return true;
}

// The first room centred on the widest spot, each side 1.5 m up to the
// circle's width (the circle holds the room when its diagonal is shorter,
// and the play area may hold more): for a first room that the tries at
// random across the bounding box did not place. Returns the longest side
// the rooms grown from it are tried at: that width, as the play area is
// roomy only around the spot.
int place_at_widest_spot(const Floor& f, Draft& d, SplitMix& rng, int max_side) {
    if (!f.spot) f.spot = widest_spot(f.o.play_area, f.area);
    const int most = std::min(max_side, static_cast<int>(std::floor(f.spot->radius * 20)));
    if (most < kMinRoomSide) return max_side;
    const int cx = static_cast<int>(std::lround(f.spot->centre.x * 10)),
              cz = static_cast<int>(std::lround(f.spot->centre.y * 10));
    for (int tries = 0; tries < 200 && d.rooms.empty(); ++tries) {
        const int w = rng.uniform(kMinRoomSide, most), depth = rng.uniform(kMinRoomSide, most);
        const Box b{cx - w / 2, cz - depth / 2, cx - w / 2 + w, cz - depth / 2 + depth};
        if (fits(f, d, b)) d.rooms.push_back(b);
    }
    return most;
}

std::optional<Draft> attempt(const Floor& f, SplitMix& rng) {
    glm::dvec2 lo = f.o.play_area[0], hi = lo;
    for (const glm::dvec2& p : f.o.play_area) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const int bx0 = static_cast<int>(std::ceil(lo.x * 10 - 1e-9)), bz0 = static_cast<int>(std::ceil(lo.y * 10 - 1e-9));
    const int bx1 = static_cast<int>(std::floor(hi.x * 10 + 1e-9)),
              bz1 = static_cast<int>(std::floor(hi.y * 10 + 1e-9));
    int max_side = std::min(kMaxRoomSide, std::max(bx1 - bx0, bz1 - bz0));
    Draft d;
    for (int tries = 0; tries < 2000 && d.rooms.empty(); ++tries) {
        Box b;
        const int w = rng.uniform(kMinRoomSide + 5, std::min(max_side, bx1 - bx0));
        const int depth = rng.uniform(kMinRoomSide + 5, std::min(max_side, bz1 - bz0));
        b.x0 = rng.uniform(bx0, bx1 - w), b.z0 = rng.uniform(bz0, bz1 - depth);
        b.x1 = b.x0 + w, b.z1 = b.z0 + depth;
        if (w <= bx1 - bx0 && depth <= bz1 - bz0 && fits(f, d, b)) d.rooms.push_back(b);
    }
    if (d.rooms.empty()) max_side = place_at_widest_spot(f, d, rng, max_side);
    if (d.rooms.empty()) return std::nullopt;
    for (int tries = 0; tries < 4000 && static_cast<int>(d.rooms.size()) < f.o.rooms; ++tries)
        grow(f, d, rng, max_side);
    if (static_cast<int>(d.rooms.size()) < f.o.rooms) return std::nullopt;
    return d;
}

Packing packing_of(const Draft& d) {
    Packing p;
    for (const Box& b : d.rooms) {
        Shape s;
        s.u0 = b.x0 / 10.0, s.u1 = b.x1 / 10.0, s.v0 = b.z0 / 10.0, s.v1 = b.z1 / 10.0;
        p.shapes.push_back(s);
        p.rooms.push_back(room_geom(s));
        p.floor_area += p.rooms.back().area;
    }
    for (const Door& door : d.doors) {
        const double out = door.side % 2 == 1 ? 1.0 : -1.0;  // A's outward direction along the wall's axis
        const glm::dvec2 n = door.side < 2 ? glm::dvec2(-out, 0) : glm::dvec2(0, -out);
        p.doors.push_back({door.a, door.b, door.centre(), n});
    }
    return p;
}

}  // namespace

std::optional<Packing> grow_boxes(const GenerateOptions& o, std::optional<WidestSpot>& spot) {
    SplitMix rng{o.seed * 0x2545F4914F6CDD1Dull + 1};
    const Floor floor{o, AreaIndex(o.play_area), spot};
    for (int restart = 0; restart < 200 && floor.area.edges_tested() < kMaxBoxWork; ++restart)
        if (const std::optional<Draft> d = attempt(floor, rng)) return packing_of(*d);
    return std::nullopt;
}

}  // namespace impossible::design
