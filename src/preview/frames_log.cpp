#include "preview/frames_log.hpp"

#include <cstdint>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "base/format.hpp"
#include "cli/errors.hpp"
#include "image/png.hpp"

namespace impossible::preview {

namespace fs = std::filesystem;
using cli::check;
using cli::InputError;

namespace {

void dump_to(std::string& out, const nlohmann::ordered_json& j) {
    using Type = nlohmann::ordered_json::value_t;
    if (j.type() == Type::number_float) {
        out += impossible::format_number(j.get<double>());
    } else if (j.type() == Type::array) {
        out += '[';
        for (std::size_t k = 0; k < j.size(); ++k) {
            if (k) out += ',';
            dump_to(out, j[k]);
        }
        out += ']';
    } else if (j.type() == Type::object) {
        out += '{';
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (it != j.begin()) out += ',';
            out += nlohmann::ordered_json(it.key()).dump() + ':';
            dump_to(out, it.value());
        }
        out += '}';
    } else {
        out += j.dump();  // strings (escaped), integers, booleans, null
    }
}

nlohmann::ordered_json pose_json(const math::HeadPose& p) {
    return {p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg};
}

nlohmann::ordered_json vec_json(const math::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

std::string dump_json(const nlohmann::ordered_json& value) {
    std::string out;
    dump_to(out, value);
    return out;
}

std::string frame_line(const FrameRecord& r) {
    nlohmann::ordered_json j;
    j["frame"] = r.frame;
    j["room"] = r.room;
    j["teleports"] = r.teleports;
    j["pose"] = pose_json(r.pose);
    j["physical"] = pose_json(r.physical);
    j["position"] = vec_json(r.position);
    j["forward"] = vec_json(r.forward);
    j["eye_size"] = {r.eye_width, r.eye_height};
    if (!r.changes.empty()) j["changes"] = r.changes;
    return dump_json(j) + "\n";
}

FrameFiles open_frame_files(const std::optional<std::string>& screenshots) {
    FrameFiles files;
    if (!screenshots) return files;
    files.dir = *screenshots;
    files.every_frame = true;
    std::error_code ec;
    fs::create_directories(files.dir, ec);
    if (!fs::is_directory(files.dir)) throw InputError(*screenshots + ": cannot create the screenshot directory");
    files.log.open(files.dir / "frames.jsonl", std::ios::binary | std::ios::trunc);
    if (!files.log) throw InputError((files.dir / "frames.jsonl").string() + ": cannot write");
    return files;
}

namespace {

// NAME is STEM-NNNN followed by `suffix` (four digits or more).
bool numbered_name(const std::string& name, const std::string& stem, const std::string& suffix) {
    const std::size_t digits = name.size() - std::min(name.size(), stem.size() + 1 + suffix.size());
    if (digits < 4 || name.compare(0, stem.size() + 1, stem + "-") != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
    const std::string number = name.substr(stem.size() + 1, digits);
    return number.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

void declare_frame_files(cli::CommandOutputs& files, const std::optional<std::string>& screenshots) {
    if (!screenshots) return;
    std::error_code ec;
    for (fs::directory_iterator it(*screenshots, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name == "frames.jsonl" || numbered_name(name, "frame", ".png") ||
            numbered_name(name, "frame", "-ids.png") || numbered_name(name, "window", ".png"))
            files.output("--screenshots", (fs::path(*screenshots) / name).string());
    }
}

std::string numbered(const fs::path& dir, const char* stem, long n, const char* suffix) {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%04ld%s", stem, n, suffix);
    return (dir / name).string();
}

void save_frame(FrameFiles& files, const image::Image& image, const FrameRecord& record) {
    check(image::write_png(numbered(files.dir, "frame", record.frame), image.width, image.height, 3, image.rgb));
    check(image::write_png(numbered(files.dir, "frame", record.frame, "-ids.png"), image.width, image.height, 1,
                           image.ids));
    files.log << frame_line(record) << std::flush;
}

void save_window(const FrameFiles& files, long frame, int w, int h, const std::vector<std::uint8_t>& rgb) {
    check(image::write_png(numbered(files.dir, "window", frame), w, h, 3, rgb));
}

std::string save_screenshot(FrameFiles& files, int w, int h, const std::vector<std::uint8_t>& rgb) {
    while (fs::exists(numbered(files.dir, "screenshot", files.shot_number))) ++files.shot_number;
    const std::string name = numbered(files.dir, "screenshot", files.shot_number);
    check(image::write_png(name, w, h, 3, rgb));
    return name;
}

}  // namespace impossible::preview
