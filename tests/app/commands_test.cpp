// The table of commands (app/commands.hpp): run_main dispatches from it and
// prints the overview from it; each command answers --help with its usage,
// and errors become one line and the exit status of cli.md.
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app/commands.hpp"
#include "app/run_main_capture.hpp"

namespace impossible::app {
namespace {

using Dispatched = testing::Ran;
const auto dispatch = testing::run;

TEST(Commands, TheOverviewHasALineForEachCommand) {
    const std::string text = overview();
    std::set<std::string> names;
    for (const Command& c : commands()) {
        EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
        const std::string left = std::string("\n  ") + c.name + " " + c.arguments + "  ";
        EXPECT_NE(text.find(left), std::string::npos) << c.name;
        EXPECT_NE(text.find(c.summary), std::string::npos) << c.name;
    }
    EXPECT_EQ(names.size(), 10u);
    EXPECT_EQ(text.find("usage: impossible COMMAND [options]"), 0u);
    // Summaries start at column 27 after a short synopsis.
    EXPECT_NE(text.find("\n  render [LAYOUT]          one side-by-side stereo frame"), std::string::npos);
}

TEST(Commands, HelpAndNoArguments) {
    for (const char* help : {"--help", "-h", "help"}) {
        const Dispatched r = dispatch({help});
        EXPECT_EQ(r.status, 0);
        EXPECT_EQ(r.out, overview());
        EXPECT_EQ(r.err, "");
    }
    const Dispatched none = dispatch({});
    EXPECT_EQ(none.status, 2);
    EXPECT_EQ(none.out, "");
    EXPECT_EQ(none.err, overview());
}

TEST(Commands, EachCommandAnswersHelpWithItsUsage) {
    for (const Command& c : commands()) {
        const Dispatched r = dispatch({c.name, "--help"});
        EXPECT_EQ(r.status, 0) << c.name;
        EXPECT_EQ(r.out.find(std::string("usage: impossible ") + c.name), 0u) << c.name;
        EXPECT_EQ(r.err, "") << c.name;
    }
}

TEST(Commands, AnUnknownCommandIsAUsageError) {
    const Dispatched r = dispatch({"rendre"});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "impossible: unknown command 'rendre'\n" + overview());
}

TEST(Commands, ErrorsAreOneLineWithTheirStatus) {
    const Dispatched usage = dispatch({"validate", "--bogus"});
    EXPECT_EQ(usage.status, 2);
    EXPECT_EQ(usage.err, "impossible validate: unknown option --bogus (see impossible validate --help)\n");
    const Dispatched input = dispatch({"tour", "layout.json", "--out", "t.txt", "--step", "5"});
    EXPECT_EQ(input.status, 1);
    EXPECT_EQ(input.err, "impossible tour: --step must be in 0.005..1 m\n");
}

}  // namespace
}  // namespace impossible::app
