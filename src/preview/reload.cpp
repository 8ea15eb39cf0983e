#include "preview/reload.hpp"

namespace impossible::preview {
namespace {

// The file's state; false when it cannot be read (e.g. mid-save by an editor
// that deletes and recreates it).
bool stat_file(const std::string& path, std::filesystem::file_time_type& mtime, std::uintmax_t& size) {
    std::error_code ec;
    mtime = std::filesystem::last_write_time(path, ec);
    if (ec) return false;
    size = std::filesystem::file_size(path, ec);
    return !ec;
}

}  // namespace

LayoutWatcher watch_layout(const std::string& path) {
    LayoutWatcher w;
    w.path = path;
    w.seen = stat_file(path, w.mtime, w.size);
    return w;
}

ReloadPoll poll_layout(LayoutWatcher& w) {
    ReloadPoll out;
    std::filesystem::file_time_type mtime;
    std::uintmax_t size = 0;
    if (!stat_file(w.path, mtime, size)) {
        if (!w.seen) return out;  // still missing: reported once already
        w.seen = false;
        out.kind = ReloadPoll::Failed;
        out.errors.push_back(w.path + ": cannot read the layout file");
        return out;
    }
    if (w.seen && mtime == w.mtime && size == w.size) return out;
    w.seen = true;
    w.mtime = mtime;
    w.size = size;
    layout::LoadResult loaded = layout::load_layout_file(w.path);
    if (!loaded.errors.empty()) {
        out.kind = ReloadPoll::Failed;
        for (const layout::Diagnostic& d : loaded.errors) out.errors.push_back(d.str());
        return out;
    }
    out.kind = ReloadPoll::Reloaded;
    out.layout = std::move(loaded.layout);
    return out;
}

}  // namespace impossible::preview
