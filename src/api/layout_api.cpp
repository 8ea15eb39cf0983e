// impossible::api::Layout: loading, checking and reporting.
#include <cassert>
#include <utility>

#include "api/api_data.hpp"
#include "base/embedded.hpp"
#include "design/report.hpp"

#include <nlohmann/json.hpp>

namespace impossible::api {

namespace {

constexpr const char* kBuiltinName = "layouts/default.json";

// Every error of a load, one a line; or the loaded layout and its warnings.
Expected<std::shared_ptr<const LayoutData>> data_of(layout::LoadResult&& loaded) {
    if (!loaded.errors.empty()) {
        std::string message;
        for (const layout::Diagnostic& d : loaded.errors) message += (message.empty() ? "" : "\n") + d.str();
        return Error{message};
    }
    auto data = std::make_shared<LayoutData>(std::move(*loaded.layout));
    data->warnings = std::move(loaded.warnings);
    for (const layout::Diagnostic& d : data->warnings) data->warning_lines.push_back(d.str());
    return std::shared_ptr<const LayoutData>(std::move(data));
}

}  // namespace

Expected<Layout> Layout::load(const std::string& path) {
    return no_throw([&]() -> Expected<Layout> {
        Expected<std::shared_ptr<const LayoutData>> data = data_of(layout::load_layout_file(path));
        if (!data) return data.error();
        return Layout(std::move(*data));
    });
}

Expected<Layout> Layout::parse(const std::string& text, const std::string& name, const std::string& base_dir) {
    return no_throw([&]() -> Expected<Layout> {
        Expected<std::shared_ptr<const LayoutData>> data = data_of(layout::load_layout_text(text, name, base_dir));
        if (!data) return data.error();
        return Layout(std::move(*data));
    });
}

Layout Layout::builtin() {
    // The built-in layout is part of the program and checked by its tests.
    Expected<std::shared_ptr<const LayoutData>> data = data_of(layout::load_layout_text(
        std::string(embedded::find(kBuiltinName)), "<built-in " + std::string(kBuiltinName) + ">", "."));
    assert(data);
    return Layout(std::move(*data));
}

const std::string& Layout::source() const { return data_->layout.source; }
const std::string& Layout::name() const { return data_->layout.name; }
const std::vector<std::string>& Layout::warnings() const { return data_->warning_lines; }

std::vector<std::string> Layout::room_ids() const {
    std::vector<std::string> ids;
    for (const layout::Room& r : data_->layout.rooms) ids.push_back(r.id);
    return ids;
}

std::vector<std::string> Layout::portal_ids() const {
    std::vector<std::string> ids;
    for (const layout::Portal& p : data_->layout.portals) ids.push_back(p.id);
    return ids;
}

std::string Layout::start_room() const { return data_->layout.rooms[data_->layout.start.room].id; }

Pose Layout::start() const {
    const layout::Start& s = data_->layout.start;
    return {s.position.x, s.position.y, s.position.z, s.yaw_deg, 0, 0};
}

std::string Layout::report_text() const {
    const layout::Layout& l = data_->layout;
    const design::Report report = design::make_report(l);
    return layout::summary_text(l, report.summary) + design::report_text(l, report);
}

std::string Layout::report_json() const {
    const layout::Layout& l = data_->layout;
    return design::report_json(l, design::make_report(l), data_->warnings).dump(2);
}

}  // namespace impossible::api

namespace impossible::api {
const char* version() { return IMPOSSIBLE_VERSION; }
}  // namespace impossible::api
