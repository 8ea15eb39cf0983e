// The layout generator; see generate.hpp.
#include "design/generate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/area_index.hpp"
#include "design/overlap.hpp"

namespace impossible::design {
namespace {

using nlohmann::ordered_json;

// splitmix64 (Steele, Lea and Flood 2014): tiny, fast, and the same everywhere.
struct Rng {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    int uniform(int lo, int hi) {  // inclusive; lo if hi < lo
        return hi <= lo ? lo : lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }
};

struct Box {  // decimetres
    int x0 = 0, z0 = 0, x1 = 0, z1 = 0, height = 28;
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

// The options and the play area's index (design/area_index.hpp).
struct Floor {
    const GenerateOptions& o;
    AreaIndex area;
};

bool fits(const Floor& f, const Draft& d, const Box& b) {
    const GenerateOptions& o = f.o;
    if (!f.area.box_inside({b.x0 / 10.0, b.z0 / 10.0}, {b.x1 / 10.0, b.z1 / 10.0})) return false;
    const math::Polygon2 floor = b.floor();
    for (const Box& other : d.rooms) {
        const Overlap ov = overlap_of(floor, other.floor());
        const double limit = o.max_overlap ? *o.max_overlap : ov.limit;
        if (ov.percent > limit + 1e-9) return false;
    }
    return true;
}

// Tries once to grow a new room out of a wall of an existing one.
bool grow(const Floor& f, Draft& d, Rng& rng, int max_side) {
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
    B.height = rng.uniform(26, 32);
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

std::optional<Draft> attempt(const Floor& f, Rng& rng) {
    const GenerateOptions& o = f.o;
    glm::dvec2 lo = o.play_area[0], hi = lo;
    for (const glm::dvec2& p : o.play_area) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const int bx0 = static_cast<int>(std::ceil(lo.x * 10 - 1e-9)), bz0 = static_cast<int>(std::ceil(lo.y * 10 - 1e-9));
    const int bx1 = static_cast<int>(std::floor(hi.x * 10 + 1e-9)),
              bz1 = static_cast<int>(std::floor(hi.y * 10 + 1e-9));
    const int max_side = std::min(kMaxRoomSide, std::max(bx1 - bx0, bz1 - bz0));
    Draft d;
    for (int tries = 0; tries < 2000 && d.rooms.empty(); ++tries) {
        Box b;
        b.height = rng.uniform(26, 32);
        const int w = rng.uniform(kMinRoomSide + 5, std::min(max_side, bx1 - bx0));
        const int depth = rng.uniform(kMinRoomSide + 5, std::min(max_side, bz1 - bz0));
        b.x0 = rng.uniform(bx0, bx1 - w), b.z0 = rng.uniform(bz0, bz1 - depth);
        b.x1 = b.x0 + w, b.z1 = b.z0 + depth;
        if (w <= bx1 - bx0 && depth <= bz1 - bz0 && fits(f, d, b)) d.rooms.push_back(b);
    }
    if (d.rooms.empty()) return std::nullopt;
    for (int tries = 0; tries < 4000 && static_cast<int>(d.rooms.size()) < o.rooms; ++tries) grow(f, d, rng, max_side);
    if (static_cast<int>(d.rooms.size()) < o.rooms) return std::nullopt;
    return d;
}

}  // namespace

// In generate_json.cpp: the draft as layout JSON text.
std::string layout_text(const GenerateOptions& o, const std::vector<std::array<int, 5>>& rooms,
                        const std::vector<std::array<int, 4>>& doors, std::uint64_t prop_seed);

Result<std::string> generate_layout(const GenerateOptions& o) {
    if (o.rooms < 1 || o.rooms > kMaxGeneratedRooms)
        return Error{"--rooms must be 1.." + std::to_string(kMaxGeneratedRooms)};
    if (math::simple_polygon_problem(o.play_area)) return Error{"the play area is not a simple polygon"};
    Rng rng{o.seed * 0x2545F4914F6CDD1Dull + 1};
    const Floor floor{o, AreaIndex(o.play_area)};
    for (int restart = 0; restart < 200; ++restart) {
        const std::optional<Draft> d = attempt(floor, rng);
        if (!d) continue;
        std::vector<std::array<int, 5>> rooms;
        for (const Box& b : d->rooms) rooms.push_back({b.x0, b.z0, b.x1, b.z1, b.height});
        std::vector<std::array<int, 4>> doors;
        for (const Door& dr : d->doors) doors.push_back({dr.a, dr.b, dr.side, dr.along});
        return layout_text(o, rooms, doors, rng.next());
    }
    return Error{"could not fit " + std::to_string(o.rooms) + " rooms of at least " +
                 std::to_string(kMinRoomSide / 10.0).substr(0, 3) + " m, joined by doors, in this play area" +
                 " within the overlap limit (try fewer rooms, a larger floor or a higher --max-overlap)"};
}

}  // namespace impossible::design
