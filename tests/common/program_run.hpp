// What a run of the built program left: its exit status and its two streams.
#pragma once

#include <string>

namespace impossible::testing {

struct ProgramRun {
    int status = -1;
    std::string out;
    std::string err;
};

}  // namespace impossible::testing
