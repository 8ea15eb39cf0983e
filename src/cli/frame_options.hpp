// The frame settings every drawing command shares (render, trace, bench,
// preview), as the command line gives them, declared once: one table of
// option rows per settings struct of the frame (render/frame.hpp). Each row
// is an option's name, parser, range (math/view_limits.hpp) and help; a
// command combines the tables it takes (cli/option_table.hpp), and bench's
// sweeps parse their values with the same parsers.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "cli/args.hpp"
#include "cli/option_table.hpp"
#include "cli/technique_options.hpp"
#include "render/frame.hpp"

namespace impossible::cli {

struct FrameOptions {
    // Every frame setting but the head and room, which a command resolves
    // against the layout (cli/view_options.hpp, frame_for).
    render::FrameDesc frame;
    // --technique and --texture-from-level as given; finish_frame_options
    // puts them (with --portal-texture) into frame.
    std::optional<Technique> technique;
    std::optional<int> texture_from_level;
    bool shadow_options = false;     // --shadow-size or --no-shadows given (frame has their values)
    std::optional<std::string> hmd;  // --hmd FILE.json (its optics are in frame after finish_frame_options)
};

// math::View's: --time --hands --ipd --eye-poses --fov --fov-angles --hmd --size
// --max-depth --max-portal-passes --light-depth.
OptionTable<FrameOptions> view_rows();
// render::Technique's: --stereo --clip --depth --technique --portal-texture
// --texture-from-level --occlusion-test --samples --shadow-size --no-shadows.
OptionTable<FrameOptions> technique_rows();
// render::Diagnostics' that users may give: --no-cull.
OptionTable<FrameOptions> diagnostic_rows();
// The help column of these rows.
inline constexpr std::size_t kViewHelpColumn = 29;

// After the rows ran: the headset profile (--hmd: its optics, and its size
// and IPD or eye poses unless --size, --ipd or --eye-poses) and the
// technique into `o.frame`.
void finish_frame_options(const ParsedArgs& args, FrameOptions& o);
// The usage errors of --fov, --fov-angles and --hmd (each excludes the
// others) and of --eye-poses with --ipd.
void check_headset_combinations(const ParsedArgs& args);

// The parsers of single values, each naming `name` in its InputError
// ("--samples", or bench's "--sweep samples").
math::HeadPose parse_pose(const OptionValue& value);           // six numbers, each within ±1e7
double parse_fps(const OptionValue& value);                    // math::limits::kFps
int parse_max_depth(const OptionValue& value);                 // 0..250
int parse_samples(const OptionValue& value);                   // 1, 2, 4, 8 or 16
int parse_light_depth(const OptionValue& value);               // 0..16
double parse_exposure(const OptionValue& value);               // EV, -20..20
int parse_shadow_size(const OptionValue& value);               // 0..4096
std::pair<int, int> parse_eye_size(const OptionValue& value);  // WxH, each 1..8192
// --fov-angles: LEFT,RIGHT,UP,DOWN in degrees (OpenXR's XrFovf) for the
// left eye, mirrored for the right (-RIGHT,-LEFT,UP,DOWN); or eight numbers,
// the left eye's then the right eye's. No hidden area.
std::array<math::EyeOptics, 2> parse_fov_angles(const std::string& text);

}  // namespace impossible::cli
