// splitmix64 (Steele, Lea and Flood 2014): the generator's random numbers,
// tiny, fast and the same on every machine, so the same seed writes the
// same layout.
#pragma once

#include <cstdint>

namespace impossible::design {

struct SplitMix {
    std::uint64_t state = 0;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    int uniform(int lo, int hi) {  // inclusive; lo if hi < lo
        return hi <= lo ? lo : lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    double real() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace impossible::design
