#include "cli/output_files.hpp"

#include "cli/errors.hpp"

namespace impossible::cli {

void CommandOutputs::add(Named named) {
    for (const Named& other : files_) {
        if (!named.is_output && !other.is_output) continue;  // reading a file twice is fine
        if (named.id.shareable || other.id.shareable || !(named.id == other.id)) continue;
        // The output first, whichever was declared first: "--out x is the
        // same file as the texture x; it would be overwritten".
        const Named& written = named.is_output ? named : other;
        const Named& second = named.is_output ? other : named;
        throw UsageError(written.label + " is the same file as " + second.label +
                         (second.is_output ? "" : "; it would be overwritten"));
    }
    files_.push_back(std::move(named));
}

void CommandOutputs::input(const std::string& what, const std::string& path) {
    add({what + " " + path, false, identify_file(path)});
}

void CommandOutputs::output(const std::string& option, const std::string& path) {
    add({option + " " + path, true, identify_file(path)});
}

void CommandOutputs::set(const std::string& path, std::string bytes) {
    for (OutputBytes& p : pending_)
        if (p.path == path) {
            p.bytes = std::move(bytes);
            return;
        }
    pending_.push_back({path, std::move(bytes)});
}

void CommandOutputs::commit() {
    check(write_output_files(pending_));
    pending_.clear();
}

}  // namespace impossible::cli
