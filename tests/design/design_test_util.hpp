// Helpers for the design tests: layouts written inline as JSON.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "layout/layout.hpp"

namespace design_test {

using namespace impossible;

// A room line of a layout: "{ "id": ID, "min": [x0, 0, z0], "max": [x1, 3, z1] }".
inline std::string room(const std::string& id, double x0, double z0, double x1, double z1) {
    return "{ \"id\": \"" + id + "\", \"min\": [" + std::to_string(x0) + ", 0, " + std::to_string(z0) +
           "], \"max\": [" + std::to_string(x1) + ", 3, " + std::to_string(z1) + "] }";
}

// A coincident door pair at (x, z): `a`'s door faces +z into `a`, `b`'s -z.
inline std::string door_pair(const std::string& a, const std::string& b, double x, double z) {
    const std::string c = "[" + std::to_string(x) + ", 1.05, " + std::to_string(z) + "]";
    return "{ \"id\": \"" + a + "_" + b + "\", \"room\": \"" + a + "\", \"center\": " + c +
           ", \"normal\": [0, 0, 1], \"width\": 0.9, \"height\": 2.1, \"target\": \"" + b + "_" + a + "\" },\n" +
           "{ \"id\": \"" + b + "_" + a + "\", \"room\": \"" + b + "\", \"center\": " + c +
           ", \"normal\": [0, 0, -1], \"width\": 0.9, \"height\": 2.1, \"target\": \"" + a + "_" + b + "\" }";
}

inline layout::Layout load(const std::string& play_area, const std::string& start_room, const std::string& rooms,
                           const std::string& portals) {
    const std::string text = "{ \"format\": \"impossible-layout\", \"version\": 1,\n" +
                             (play_area.empty() ? "" : "\"play_area\": " + play_area + ",\n") +
                             "\"start\": { \"room\": \"" + start_room + "\", \"position\": [0.5, 1.6, 0.5] },\n" +
                             "\"rooms\": [" + rooms + "],\n\"portals\": [" + portals + "] }";
    const layout::LoadResult r = layout::load_layout_text(text, "t.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors << text;
    return r.layout.value_or(layout::Layout{});
}

inline layout::Layout load_file(const std::string& name) {
    const layout::LoadResult r = layout::load_layout_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name);
    EXPECT_TRUE(r.layout.has_value()) << name;
    return r.layout.value_or(layout::Layout{});
}

}  // namespace design_test
