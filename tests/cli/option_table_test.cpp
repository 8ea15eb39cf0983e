// The option table (cli/option_table.hpp): the help rows keep the layout of
// every command's help (the help at a column, two spaces after a longer left
// column, continuation lines indented to the column), parse_args accepts only
// the tables' names and applies the cli.md rules, and each parser sees its
// value.
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/option_table.hpp"

namespace impossible::cli {
namespace {

struct Toy {
    std::optional<std::string> name;
    int count = 0;
    bool loud = false;
    std::vector<std::string> seen;  // "NAME=VALUE" in the order the parsers ran
};

constexpr Option<Toy> kToyOptions[] = {
    {"--name", "TEXT", "what to call it",
     [](Toy& t, const OptionValue& v) {
         t.name = v.text;
         t.seen.push_back(v.name + "=" + v.text);
     }},
    {"--count", "N", "how many (default 0, at most 9);\nmore than one line",
     [](Toy& t, const OptionValue& v) {
         t.count = parse_int(v.name, v.text, 0, 9);
         t.seen.push_back(v.name + "=" + v.text);
     }},
    {"--loud", nullptr, "a flag",
     [](Toy& t, const OptionValue& v) {
         t.loud = true;
         t.seen.push_back(v.name + "=" + v.text);
     }},
};

struct Extra {
    std::optional<std::string> colour;
};

constexpr Option<Extra> kExtraOptions[] = {
    {"--colour", "C", "the colour", [](Extra& e, const OptionValue& v) { e.colour = v.text; }, "--colour C, --color C",
     "Extra options:"},
    {"--color", "C", nullptr, [](Extra& e, const OptionValue& v) { e.colour = v.text; }},
};

Toy parse_toy(const Args& args) {
    Toy t;
    apply_options(kToyOptions, parse_args(args, 1, kToyOptions), t);
    return t;
}

TEST(OptionTable, AHelpRowPutsTheHelpAtItsColumn) {
    // As render's --help: "  --room ID", the help at column 29.
    EXPECT_EQ(help_row("--room ID", "the room the head is in", 29),
              "  --room ID                  the room the head is in\n");
    EXPECT_EQ(help_row("--ipd M", "distance between the eyes (default 0.064)", 29),
              std::string("  --ipd M") + std::string(20, ' ') + "distance between the eyes (default 0.064)\n");
}

TEST(OptionTable, ALongLeftColumnGetsTwoSpaces) {
    // "  --pose X,Y,Z,YAW,PITCH,ROLL" is 29 characters: the help follows after two.
    EXPECT_EQ(help_row("--pose X,Y,Z,YAW,PITCH,ROLL", "head centre", 29),
              "  --pose X,Y,Z,YAW,PITCH,ROLL  head centre\n");
    // Exactly two spaces short of the column: the column, which is two spaces.
    EXPECT_EQ(help_row("--abcdefghijklmnopqrstuvw", "x", 29), "  --abcdefghijklmnopqrstuvw  x\n");
}

TEST(OptionTable, ContinuationLinesAreIndentedToTheColumn) {
    EXPECT_EQ(help_row("--depth MODE", "reversed-z or standard\n(24-bit depth)", 29),
              "  --depth MODE               reversed-z or standard\n"
              "                             (24-bit depth)\n");
}

TEST(OptionTable, AHelpStartingWithANewlineStartsBelowALongLeftColumn) {
    // No spaces at the end of the first line (--hands LX,...,RROLL).
    EXPECT_EQ(help_row("--hands A,B,C,D,E,F,G,H,I,J,K,L", "\nthe hands\n(default: none)", 29),
              "  --hands A,B,C,D,E,F,G,H,I,J,K,L\n"
              "                             the hands\n"
              "                             (default: none)\n");
}

TEST(OptionTable, TheHelpListsTheTableInOrderWithLabelsAndHeadings) {
    EXPECT_EQ(options_help(kToyOptions, 12),
              "  --name TEXT  what to call it\n"
              "  --count N  how many (default 0, at most 9);\n"
              "            more than one line\n"
              "  --loud    a flag\n");
    // A label replaces the left column; an option without help is not listed.
    EXPECT_EQ(options_help(kExtraOptions, 26),
              "Extra options:\n"
              "  --colour C, --color C   the colour\n");
}

TEST(OptionTable, EachParserSeesItsValue) {
    const Toy t = parse_toy({"--count", "3", "--name=a=b", "--loud", "layout.json"});
    EXPECT_EQ(t.name, "a=b");
    EXPECT_EQ(t.count, 3);
    EXPECT_TRUE(t.loud);
    // In table order, whatever the order on the command line; a flag gets "".
    EXPECT_EQ(t.seen, (std::vector<std::string>{"--name=a=b", "--count=3", "--loud="}));
}

TEST(OptionTable, AValueMayStartWithADash) {
    EXPECT_EQ(parse_toy({"--name", "-1.5,2"}).name, "-1.5,2");
    EXPECT_EQ(parse_toy({"--name", "--loud"}).name, "--loud");
}

TEST(OptionTable, TheLastOfARepeatedOptionWins) {
    const Toy t = parse_toy({"--count", "12", "--count", "2"});
    EXPECT_EQ(t.count, 2);
    EXPECT_EQ(t.seen.size(), 1u);
}

TEST(OptionTable, OptionsNotGivenAreNotParsed) {
    const Toy t = parse_toy({});
    EXPECT_FALSE(t.name);
    EXPECT_FALSE(t.loud);
    EXPECT_TRUE(t.seen.empty());
}

TEST(OptionTable, AnUnknownOptionIsAUsageError) {
    EXPECT_THROW(parse_toy({"--nmae", "x"}), UsageError);
    EXPECT_THROW(parse_toy({"-n"}), UsageError);
    try {
        parse_toy({"--colour", "red"});  // another table's option
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "unknown option --colour");
    }
}

TEST(OptionTable, AValueOptionWithoutAValueIsAUsageError) {
    try {
        parse_toy({"--loud", "--count"});
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "option --count needs a value");
    }
}

TEST(OptionTable, AFlagGivenAValueIsAUsageError) {
    try {
        parse_toy({"--loud=yes"});
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "option --loud takes no value");
    }
}

TEST(OptionTable, TooManyPositionalArgumentsAreAUsageError) {
    EXPECT_EQ(parse_args({"a"}, 1, kToyOptions).positional, (std::vector<std::string>{"a"}));
    EXPECT_EQ(parse_args({"-"}, 1, kToyOptions).positional, (std::vector<std::string>{"-"}));
    EXPECT_THROW(parse_args({"a", "b"}, 1, kToyOptions), UsageError);
}

TEST(OptionTable, HelpIsSeenAmongTheArguments) {
    EXPECT_TRUE(parse_args({"x", "--help"}, 1, kToyOptions).help);
    EXPECT_TRUE(parse_args({"-h"}, 1, kToyOptions).help);
    EXPECT_THROW(parse_args({"--help", "--bogus"}, 1, kToyOptions), UsageError);
}

TEST(OptionTable, ABadValueIsAnInputErrorNamingTheOption) {
    try {
        parse_toy({"--count", "10"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "--count: 10 is out of range 0..9");
    }
}

TEST(OptionTable, SeveralTablesMakeOneCommand) {
    const ParsedArgs parsed = parse_args({"--color", "red", "--count", "1"}, 0, kToyOptions, kExtraOptions);
    Toy t;
    Extra e;
    apply_options(kToyOptions, parsed, t);
    apply_options(kExtraOptions, parsed, e);
    EXPECT_EQ(t.count, 1);
    EXPECT_EQ(e.colour, "red");
}

TEST(OptionTable, WithoutDropsTheNamedOptions) {
    const auto kept = without(kToyOptions, {"--count", "--nothing"});
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_STREQ(kept[0].name, "--name");
    EXPECT_STREQ(kept[1].name, "--loud");
    EXPECT_THROW(parse_args({"--count", "1"}, 0, kept), UsageError);
}

}  // namespace
}  // namespace impossible::cli
