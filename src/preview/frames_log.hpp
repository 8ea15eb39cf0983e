// What `preview --screenshots DIR` saves: frame-NNNN.png and -ids.png (the
// renderer's image), window-NNNN.png, screenshot-NNNN.png (P or F12) and
// frames.jsonl, one JSON line a frame in the number format of `walk`.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "cli/output_files.hpp"
#include "image/image.hpp"
#include "math/pose.hpp"

namespace impossible::preview {

// One line of frames.jsonl.
struct FrameRecord {
    long frame = 0;
    std::string room;                    // the room's id
    std::vector<std::string> teleports;  // ids of the portals passed this frame
    math::HeadPose pose;                 // the virtual head
    math::HeadPose physical;
    math::dvec3 position{0.0}, forward{0.0};  // the walker's, as `walk` prints them
    int eye_width = 0, eye_height = 0;
    std::vector<std::string> changes;  // ids of the layout's changes made this frame, as `walk` prints them
};

// The JSON text of `value` as nlohmann's dump() writes it (compact), but with
// every floating-point number in the form of `walk` (impossible::format_number:
// the shortest round trip, integers without a fraction, -0 as 0). nlohmann's
// own Grisu2 digits are not always the shortest and it writes 1.0 for 1.
std::string dump_json(const nlohmann::ordered_json& value);

// The record as one line of JSON, with its newline; fields in this order:
// frame, room, teleports, pose, physical, position, forward, eye_size, and
// changes on a frame that made some.
std::string frame_line(const FrameRecord& record);

// Where the screenshots go: --screenshots DIR, or the current directory for
// P / F12 alone.
struct FrameFiles {
    std::filesystem::path dir = ".";
    bool every_frame = false;  // --screenshots: frame, window and frames.jsonl
    std::ofstream log;         // frames.jsonl
    long shot_number = 0;      // the next screenshot-NNNN.png to try
};

// Creates DIR and frames.jsonl for --screenshots; throws InputError if not.
FrameFiles open_frame_files(const std::optional<std::string>& screenshots);

// Declares as outputs of `files` ("--screenshots DIR/NAME") the files already
// in DIR under a name that --screenshots writes over (frames.jsonl,
// frame-NNNN.png, frame-NNNN-ids.png, window-NNNN.png; screenshot-NNNN.png
// takes a free name): one that is an input of `files` is a usage error.
void declare_frame_files(cli::CommandOutputs& files, const std::optional<std::string>& screenshots);

// DIR/STEM-NNNN.png (or another suffix).
std::string numbered(const std::filesystem::path& dir, const char* stem, long n, const char* suffix = ".png");

// frame-NNNN.png, frame-NNNN-ids.png and the line of frames.jsonl. The
// savers throw InputError naming a file that could not be written.
void save_frame(FrameFiles& files, const image::Image& image, const FrameRecord& record);

// The window's pixels (RGB rows from the top) as window-NNNN.png, or as the
// next free screenshot-NNNN.png; save_screenshot returns its name.
void save_window(const FrameFiles& files, long frame, int width, int height, const std::vector<std::uint8_t>& rgb);
std::string save_screenshot(FrameFiles& files, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace impossible::preview
