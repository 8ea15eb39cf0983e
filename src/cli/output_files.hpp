// The files one command writes: declared (with the files it reads) before
// any work, so that two of them naming the same file is a usage error
// rather than one silently replacing the other (`--out x --ids x`, `render
// lay.json --out lay.json`); then given their bytes, and written together
// only once all of them exist (base/output_file.hpp: nothing left behind or
// replaced on failure, links and devices written through).
#pragma once

#include <string>
#include <vector>

#include "base/output_file.hpp"

namespace impossible::cli {

class CommandOutputs {
public:
    // A file the command reads; `what` names it in messages ("the layout").
    // Throws UsageError when it is one of the outputs (declared before or
    // after it; inputs known only once the layout is loaded come after).
    void input(const std::string& what, const std::string& path);
    // A file the command writes, named by its option ("--out"). Throws
    // UsageError when it names the same file as another output or an input
    // (character devices such as /dev/null may be named more than once).
    void output(const std::string& option, const std::string& path);

    // The bytes of a declared output.
    void set(const std::string& path, std::string bytes);
    // Writes every output that was set; throws InputError ("PATH: cannot
    // write: reason") and writes nothing if any of them fails.
    void commit();

private:
    struct Named {
        std::string label;  // "--out x.png", "the layout l.json"
        bool is_output = false;
        FileIdentity id;
    };
    void add(Named named);
    std::vector<Named> files_;
    std::vector<OutputBytes> pending_;
};

}  // namespace impossible::cli
