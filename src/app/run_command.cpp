#include <exception>
#include <ostream>

#include "app/commands.hpp"
#include "base/text.hpp"
#include "cli/errors.hpp"

namespace impossible::app {

int run_command(const Command& command, const Args& rest, std::ostream& out, std::ostream& err) {
    const std::string name = command.name;
    try {
        return command.run(rest, out, err);
    } catch (const UsageError& e) {
        // Messages name paths and values the user gave, which may hold
        // newlines or megabytes: each is printed as one line, cut.
        err << "impossible " << name << ": " << one_line(e.what()) << " (see impossible " << name << " --help)\n";
        return kExitUsage;
    } catch (const InputError& e) {
        err << "impossible " << name << ": " << one_line(e.what()) << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        err << "impossible " << name << ": " << one_line(e.what()) << "\n";
        return kExitBadInput;
    }
}

}  // namespace impossible::app
