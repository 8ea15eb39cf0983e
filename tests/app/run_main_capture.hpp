// run_main with its standard output and error captured: how the app tests
// run a command line.
#pragma once

#include <sstream>
#include <string>

#include "app/commands.hpp"

namespace impossible::app::testing {

struct Ran {
    int status = -1;
    std::string out, err;
};

inline Ran run(const Args& args) {
    std::ostringstream out, err;
    Ran r;
    r.status = run_main(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

}  // namespace impossible::app::testing
