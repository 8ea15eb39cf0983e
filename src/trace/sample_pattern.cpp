#include "trace/sample_pattern.hpp"

namespace impossible::trace {
namespace {

// In sixteenths of a pixel, as the Direct3D "standard sample patterns" table
// gives them (offsets from the centre, here plus 8), read as GL window
// coordinates the way llvmpipe does (its 4-sample table is the D3D one and
// GL_SAMPLE_POSITION reports it unchanged).
constexpr double kUnit = 1.0 / 16.0;

constexpr SamplePosition at(int x, int y) { return {x * kUnit, y * kUnit}; }

constexpr SamplePosition kOne[] = {at(8, 8)};
constexpr SamplePosition kTwo[] = {at(12, 12), at(4, 4)};
constexpr SamplePosition kFour[] = {at(6, 2), at(14, 6), at(2, 10), at(10, 14)};
constexpr SamplePosition kEight[] = {at(9, 5),  at(7, 11), at(13, 9),  at(5, 3),
                                     at(3, 13), at(1, 7),  at(11, 15), at(15, 1)};
constexpr SamplePosition kSixteen[] = {at(9, 9),   at(7, 5),  at(5, 10),  at(12, 7), at(3, 6), at(10, 13),
                                       at(13, 11), at(11, 3), at(6, 14),  at(8, 1),  at(4, 2), at(2, 12),
                                       at(0, 8),   at(15, 4), at(14, 15), at(1, 0)};

}  // namespace

std::span<const SamplePosition> sample_pattern(int samples) {
    switch (samples) {
        case 1: return kOne;
        case 2: return kTwo;
        case 4: return kFour;
        case 8: return kEight;
        case 16: return kSixteen;
        default: return {};
    }
}

}  // namespace impossible::trace
