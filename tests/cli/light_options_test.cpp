// --light-depth, --shadow-size and --no-shadows (cli.md, "Time, hands and
// lights"): their fields and ranges, trace without the shadow options, and
// the warning on a "fixed" layout.
#include <string>

#include <gtest/gtest.h>

#include "cli/view_options.hpp"

namespace impossible::cli {
namespace {

ViewOptions parse_lights(const Args& args, const ViewTables& table = view_options()) {
    return parse_view_options(parse_args(args, 1, table), table);
}

std::string light_input_error(const Args& args) {
    try {
        parse_lights(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

TEST(LightOptions, EachReachesItsField) {
    const ViewOptions none = parse_lights({});
    EXPECT_FALSE(none.frame.light_depth);
    EXPECT_TRUE(none.frame.shadows);
    EXPECT_EQ(none.frame.shadow_map_size, render::kDefaultShadowMapSize);
    EXPECT_FALSE(none.shadow_options);
    const ViewOptions o = parse_lights({"--light-depth", "16", "--shadow-size", "0", "--no-shadows"});
    EXPECT_EQ(o.frame.light_depth, 16);
    EXPECT_EQ(o.frame.shadow_map_size, 0);
    EXPECT_FALSE(o.frame.shadows);
    EXPECT_TRUE(o.shadow_options);
    EXPECT_EQ(parse_lights({"--light-depth", "0", "--shadow-size", "4096"}).frame.light_depth, 0);
}

TEST(LightOptions, OutOfRangeValuesNameTheirOption) {
    EXPECT_EQ(light_input_error({"--light-depth", "17"}), "--light-depth: 17 is out of range 0..16");
    EXPECT_EQ(light_input_error({"--light-depth", "-1"}), "--light-depth: -1 is out of range 0..16");
    EXPECT_EQ(light_input_error({"--light-depth", "2.5"}), "--light-depth: '2.5' is not an integer");
    EXPECT_EQ(light_input_error({"--shadow-size", "4097"}), "--shadow-size: 4097 is out of range 0..4096");
}

TEST(LightOptions, TraceHasNoShadowOptions) {
    EXPECT_THROW(parse_args({"--shadow-size", "8"}, 1, trace_view_options()), UsageError);
    EXPECT_THROW(parse_args({"--no-shadows"}, 1, trace_view_options()), UsageError);
    EXPECT_EQ(parse_lights({"--light-depth", "3"}, trace_view_options()).frame.light_depth, 3);
}

TEST(LightOptions, AFixedLayoutWarnsOnce) {
    layout::Layout fixed;
    fixed.source = "a.json";
    EXPECT_EQ(light_options_warning(session::Session(fixed), std::nullopt, false), "");
    EXPECT_EQ(light_options_warning(session::Session(fixed), 3, false),
              "warning: --light-depth has no effect: a.json's lighting is \"fixed\"\n");
    EXPECT_EQ(light_options_warning(session::Session(fixed), std::nullopt, true),
              "warning: the shadow options have no effect: a.json's lighting is \"fixed\"\n");
    layout::Layout lit = fixed;
    lit.lighting = layout::Lighting::Lights;
    EXPECT_EQ(light_options_warning(session::Session(lit), 3, true), "");
}

}  // namespace
}  // namespace impossible::cli
