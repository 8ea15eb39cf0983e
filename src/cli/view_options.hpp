// The options that `render`, `trace` and `bench` share (cli.md), parsed into
// plain data, and how they become a frame description.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "cli/args.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "cli/technique_options.hpp"
#include "gl/context.hpp"
#include "layout/layout.hpp"
#include "render/frame.hpp"
#include "trace/tracer.hpp"

namespace impossible::cli {

struct ViewOptions {
    std::optional<std::string> layout_path;  // none: the built-in default
    std::optional<math::HeadPose> pose;
    std::optional<std::string> room;
    // --path FILE --frame K [--fps N]: the head, room, hands and time of
    // line K of a walk (instead of --pose, --room, --time and --hands).
    std::optional<std::string> path;
    std::optional<int> path_frame;
    std::optional<double> fps;
    std::string out = "stereo.png";
    std::optional<std::string> ids;
    std::optional<gl::Backend> backend;  // none: EGL, falling back to OSMesa
    // Every frame setting but the head and room, which frame_for resolves
    // against the layout (--time and --hands are here too).
    render::FrameDesc frame;
    bool stats = false;
    // --technique and --texture-from-level as given; parse_view_options puts
    // them (with --portal-texture) into frame.
    std::optional<Technique> technique;
    std::optional<int> texture_from_level;
    bool shadow_options = false;     // --shadow-size or --no-shadows given (frame has their values)
    std::optional<std::string> hmd;  // --hmd FILE.json (its optics are in frame)
};

// The view options of render and trace (bench drops the image files), in
// the order of the help and of the checks; their help column.
OptionTable<ViewOptions> view_options();
// trace's: the view options without the rasteriser's shadow maps
// (--shadow-size, --no-shadows); the tracer's shadows are exact.
OptionTable<ViewOptions> trace_view_options();
inline constexpr std::size_t kViewHelpColumn = 29;

// The layout (the first positional argument) and the options of `table`
// that were given; throws InputError for a bad value.
ViewOptions parse_view_options(const ParsedArgs& args, OptionTable<ViewOptions> table = view_options());

// The narrowest field of view that renders like the tracer at every size.
inline constexpr double kMinFovDeg = 1.0;

// The values of single options, shared with `preview`; InputError if bad.
double parse_ipd(const std::string& text);
double parse_fov(const std::string& text);
render::StereoMode parse_stereo(const std::string& text);
render::ClipMode parse_clip(const std::string& text);
int parse_samples(const std::string& text);  // 1, 2, 4, 8 or 16
// --fps of the commands that replay a path: in kMinFps..kMaxFps.
inline constexpr double kMinFps = 1e-3, kMaxFps = 1e6;
double parse_fps(const std::string& text);
// --fov-angles: LEFT,RIGHT,UP,DOWN in degrees (OpenXR's XrFovf) for the
// left eye, mirrored for the right (-RIGHT,-LEFT,UP,DOWN); or eight numbers,
// the left eye's then the right eye's. No hidden area.
std::array<math::EyeOptics, 2> parse_fov_angles(const std::string& text);
// The usage errors of --fov, --fov-angles and --hmd (each excludes the others).
void check_headset_combinations(const ParsedArgs& args);
// --hmd FILE: the profile's optics into `frame`, and its eye size and IPD
// unless --size (`size_given`) or --ipd (`ipd_given`) replace them; throws
// InputError FILE:LINE:COLUMN: field: message for a bad profile.
void apply_hmd_profile(const std::string& path, math::View& frame, bool size_given, bool ipd_given);
// --hands: twelve numbers, the left then the right hand (as --pose).
std::array<math::HeadPose, 2> parse_hands(const std::string& text);
// --light-depth: 0..layout::kMaxLightDepth; --shadow-size: 0..kMaxShadowMapSize.
int parse_light_depth(const std::string& text);
int parse_shadow_size(const std::string& text);

// The warning line (ending in '\n') for --light-depth (`light_depth` set)
// or the shadow options (`shadow_options`) on a layout whose lighting is
// "fixed", where they change nothing; on a lit layout, for a light depth
// (asked for, or the layout's) that gives more than lights::kMaxLightPaths
// light paths, which both renderers lower (docs/bounded-work.md); "" otherwise.
std::string light_options_warning(const layout::Layout& layout, const std::optional<int>& light_depth,
                                  bool shadow_options);

// The head pose and room of the frame: the layout's start without --pose;
// with --pose, --room or else the one room whose box or prism holds the
// head; with --path, line K's after walking lines 0..K (walk/replay.hpp),
// at time K / fps. Throws InputError for a bad path file, UsageError for a K past
// its last line.
render::FrameDesc frame_for(const layout::Layout& layout, const ViewOptions& options);

// The same frame for the reference tracer (threads: 0 = all cores).
trace::TraceDesc trace_desc_for(const render::FrameDesc& frame, int threads = 0);

// The outputs (--out, --ids) and the layout, declared before any work: a
// UsageError when two of them are the same file.
CommandOutputs frame_outputs(const ViewOptions& options);

// Writes the colour image and, with --ids, the id map, both or neither;
// throws InputError naming the file that could not be written.
void write_frame_pngs(CommandOutputs& outputs, const ViewOptions& options, int width, int height,
                      const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& ids);

}  // namespace impossible::cli
