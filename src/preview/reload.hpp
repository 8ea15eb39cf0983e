// Live reload of the previewed layout: the file is polled (modification time
// and size); a change is loaded and validated. A failed load keeps the last
// good layout and reports every error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "layout/layout.hpp"

namespace impossible::preview {

struct LayoutWatcher {
    std::string path;
    std::filesystem::file_time_type mtime{};
    std::uintmax_t size = 0;
    bool seen = false;  // mtime/size hold the file's last known state
};

// What one poll of the watched file found.
struct ReloadPoll {
    enum Kind { Unchanged, Reloaded, Failed } kind = Unchanged;
    std::optional<layout::Layout> layout;  // when Reloaded
    std::vector<std::string> errors;       // when Failed: one line each
};

// Watches `path` from its current state on (the caller has just loaded it).
LayoutWatcher watch_layout(const std::string& path);

// Checks the file; loads it when it changed since the last poll.
ReloadPoll poll_layout(LayoutWatcher& watcher);

}  // namespace impossible::preview
