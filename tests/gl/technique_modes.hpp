// The six clip × stereo modes a render-vs-trace test runs in, and their
// test names ("oblique_two_pass"), for INSTANTIATE_TEST_SUITE_P.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "render/frame.hpp"

namespace impossible::testing {

using TechniqueModes = std::tuple<render::ClipMode, render::StereoMode>;

inline auto all_technique_modes() {
    return ::testing::Combine(::testing::Values(render::ClipMode::ClipDistance, render::ClipMode::Oblique),
                              ::testing::Values(render::StereoMode::ClipShift, render::StereoMode::ViewportIndex,
                                                render::StereoMode::TwoPass));
}

inline std::string technique_modes_name(const ::testing::TestParamInfo<TechniqueModes>& info) {
    const render::StereoMode s = std::get<1>(info.param);
    return std::string(std::get<0>(info.param) == render::ClipMode::Oblique ? "oblique_" : "clip_distance_") +
           (s == render::StereoMode::ClipShift ? "clip_shift"
            : s == render::StereoMode::TwoPass ? "two_pass"
                                               : "viewport_index");
}

}  // namespace impossible::testing
