// Help texts (`impossible COMMAND --help`) list only what the command
// accepts: every option they name is one its parser knows.
#include <regex>
#include <set>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostileHelp : public Hostile {};

// Every option a command's --help names, in its usage lines or its option
// list, is one the command knows (bench once listed --out and --ids, which it
// refused).
TEST_F(HostileHelp, NamesOnlyOptionsTheCommandAccepts) {
    const std::regex option_name(R"((^|[\s\[|])(--[a-z][a-z0-9-]*))");
    for (const char* command :
         {"render", "trace", "bench", "preview", "walk", "validate", "plan", "tour", "generate", "compare"}) {
        const Outcome help = run(std::string("$BIN ") + command + " --help");
        ASSERT_EQ(help.status, 0) << command;
        // The usage lines and the option list: prose may name other
        // commands' options ("for walk, preview --path and bench --path").
        std::istringstream lines(help.out + help.err);
        std::set<std::string> options;
        for (std::string line; std::getline(lines, line);) {
            const std::size_t first = line.find_first_not_of(' ');
            const bool usage = line.rfind("usage:", 0) == 0;
            if (!usage && (first == 0 || first == std::string::npos || (line[first] != '[' && line[first] != '-')))
                continue;
            for (auto it = std::sregex_iterator(line.begin(), line.end(), option_name); it != std::sregex_iterator();
                 ++it)
                options.insert((*it)[2]);
        }
        options.erase("--help");
        EXPECT_GE(options.size(), 1u) << command;
        // The option and a value (or, for a flag, a layout name), then an
        // option the parser must refuse: parsing fails, no work starts.
        for (const std::string& option : options) {
            const Outcome r = run(std::string("$BIN ") + command + " " + option + " 1 --zzz-end </dev/null");
            EXPECT_EQ(r.status, 2) << command << " " << option << ": " << r.err;
            EXPECT_EQ(r.err.find("unknown option " + option + " ("), std::string::npos)
                << command << " " << option << ": " << r.err;
        }
    }
}

}  // namespace
}  // namespace impossible::hostile
