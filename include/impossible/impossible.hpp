// The public C++ API of impossible: load and check a layout, render it with
// the OpenGL rasteriser (headless, or in a context the caller owns), trace it
// with the reference ray tracer, walk physical head poses through its doors,
// and the designer's tools. docs/api.md has a complete example.
//
// Nothing here throws: every call that can fail returns an Expected<T>, whose
// error is a message for humans ("FILE:LINE:COLUMN: message" lines for a bad
// layout). Objects are cheap to move; a Renderer belongs to one thread and the
// GL context it was made for.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "impossible/version.hpp"

namespace impossible::api {

// What went wrong, for humans: one line, or one line per problem of a layout.
struct Error {
    std::string message;
};

// A value or an Error (std::expected is C++23).
template <class T>
class Expected {
public:
    Expected(T value) : v_(std::move(value)) {}      // NOLINT: implicit by design
    Expected(Error error) : v_(std::move(error)) {}  // NOLINT
    bool has_value() const { return v_.index() == 0; }
    explicit operator bool() const { return has_value(); }
    T& value() & { return std::get<0>(v_); }
    const T& value() const& { return std::get<0>(v_); }
    T&& value() && { return std::get<0>(std::move(v_)); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    const Error& error() const { return std::get<1>(v_); }

private:
    std::variant<T, Error> v_;
};

template <>
class Expected<void> {
public:
    Expected() = default;
    Expected(Error error) : error_(std::move(error)) {}  // NOLINT
    bool has_value() const { return !error_; }
    explicit operator bool() const { return has_value(); }
    const Error& error() const { return *error_; }

private:
    std::optional<Error> error_;
};

// A head pose as `--pose` takes it: the centre between the eyes in metres,
// yaw, pitch and roll in degrees (layout-format.md, "Head pose and eyes").
struct Pose {
    double x = 0, y = 0, z = 0;
    double yaw = 0, pitch = 0, roll = 0;
};

struct LayoutData;

// A loaded, valid layout (immutable; copies share it).
class Layout {
public:
    // Reads and checks a layout file (JSON, its textures and glTF models).
    static Expected<Layout> load(const std::string& path);
    // Layout text; `name` names it in messages and `base_dir` resolves the
    // relative paths of its textures and models.
    static Expected<Layout> parse(const std::string& text, const std::string& name, const std::string& base_dir);
    // The built-in default layout (what `impossible render` draws).
    static Layout builtin();

    const std::string& source() const;  // the file, or "<default>"
    const std::string& name() const;
    std::vector<std::string> room_ids() const;
    std::vector<std::string> portal_ids() const;
    std::string start_room() const;
    Pose start() const;  // the start: head centre and yaw
    // Warnings the loader found (legal but suspicious), one a line.
    const std::vector<std::string>& warnings() const;

    // The designer's report, as `impossible validate` prints it, and as JSON
    // (`validate --json`).
    std::string report_text() const;
    std::string report_json() const;

    const LayoutData& data() const { return *data_; }  // for the library itself
    static Layout of(std::shared_ptr<const LayoutData> data) { return Layout(std::move(data)); }  // the same

private:
    explicit Layout(std::shared_ptr<const LayoutData> data) : data_(std::move(data)) {}
    std::shared_ptr<const LayoutData> data_;
};

// An eye's field of view as OpenXR's XrFovf: degrees from the eye's view
// axis, left and down negative (`--fov-angles`, docs/headsets.md). Each
// within ±89.5; right at least 1 degree right of left, up 1 above down.
struct FovAngles {
    double left = -45, right = 45, up = 45, down = -45;
};

// One eye of a headset: its asymmetric field of view, and the part of its
// image the lenses show.
struct EyeOptics {
    FovAngles fov;
    // The visible area: a simple polygon of 3..4096 corners (u, v), u from 0
    // at the image's left edge to 1 at its right, v from 0 at the top to 1 at
    // the bottom. Pixels whose centre lies outside it are masked (black, id
    // 0) by both the renderer and the tracer. Empty: every pixel is visible.
    std::vector<std::array<double, 2>> visible_area;
};

// One eye's pose relative to the head (docs/headsets.md), as OpenXR's
// XrView.pose relative to the view space and WebXR's XRView.transform
// relative to the viewer pose give it: the position in metres in the head's
// coordinates (x right, y up, z back), at most 1 m from the head centre, and
// the orientation, a unit quaternion (x, y, z, w) whose length is 1 within
// 1e-6 (the Valve Index's eyes are turned about ±5° about y, "canted").
struct EyePose {
    std::array<double, 3> position{0, 0, 0};
    std::array<double, 4> orientation{0, 0, 0, 1};
};

// An eye's pose as `--eye-poses` gives it: position and yaw, pitch and roll
// in degrees (as `--pose`), in the head's coordinates.
EyePose eye_pose(const Pose& pose);

// A headset profile (`--hmd FILE.json`, docs/headsets.md).
struct HmdProfile {
    std::string name;
    std::string source;  // where its numbers come from
    double ipd = 0.064;  // none with eye_poses
    int eye_width = 0, eye_height = 0;  // each eye's image
    std::array<EyeOptics, 2> eyes;      // left, right
    // Each eye's "position" and "orientation", left then right; none: the
    // eyes at ±ipd/2 along the head's x axis, looking the head's way.
    std::optional<std::array<EyePose, 2>> eye_poses;
};

// Reads and checks a profile; a bad one is an Error "FILE:LINE:COLUMN:
// field: message", as a layout's.
Expected<HmdProfile> load_hmd_profile(const std::string& path);

// One stereo view: where the head is and how it is drawn. The defaults are
// those of `impossible render`.
struct View {
    std::optional<Pose> pose;  // none: the layout's start
    std::string room;          // empty: with a pose, the one room holding the head; else start.room
    int width = 1280;          // each eye; the image is 2 × width
    int height = 720;
    double ipd = 0.064;   // not read with eye_poses
    double fov_deg = 90;  // vertical, each eye
    int max_depth = 8;
    int samples = 1;                 // 1, 2, 4, 8 or 16
    int max_portal_passes = 10'000;  // the rasteriser's budget (docs/bounded-work.md)
    // Seconds: moving props stand where their motion puts them at this time
    // (layout-format.md, "Moving props"; a negative time reads as 0).
    double time = 0;
    // The tracked hands, left then right, in the coordinates of `pose` (as
    // `render --hands`); none: no hands are drawn.
    std::optional<std::array<Pose, 2>> hands;
    // Portals light may pass (0..16) under "lighting": "lights", instead of
    // the layout's light_depth (as `render --light-depth`); none: the
    // layout's. No effect on a "fixed" layout.
    std::optional<int> light_depth;
    // Exposure in EV (-20..20, as `render --exposure`): each surface's colour
    // times 2^EV before its clamp to 0..1, in render and trace alike; none:
    // the layout's "exposure" (0 unless it says).
    std::optional<double> exposure;
    // Each eye's optics, left then right (as `--fov-angles` or `--hmd`): the
    // eyes' frusta are these angles (fov_deg is not read) and each eye's
    // hidden area is masked; none: symmetric frusta of fov_deg.
    std::optional<std::array<EyeOptics, 2>> eye_optics;
    // Each eye's pose relative to the head, left then right (as
    // `--eye-poses` or a profile's poses): the eyes stand and look so, and
    // ipd is not read; none: at ±ipd/2 along the head's x axis, looking the
    // head's way.
    std::optional<std::array<EyePose, 2>> eye_poses;
};

// The view through a headset, as `render --hmd FILE` without --size,
// --ipd and --eye-poses: the profile's optics, eye size, and IPD or eye
// poses.
void use_hmd_profile(View& view, const HmdProfile& profile);

// Counters of a rasterised frame (render --stats).
struct FrameStats {
    long draw_calls = 0;
    long triangles = 0;
    int portal_passes_drawn = 0;
    int portal_passes_culled = 0;
    int portal_fills = 0;
    int budget_fills = 0;
    int max_level = 0;
};

// A side-by-side stereo frame, left eye left, top row first.
struct Frame {
    int width = 0;  // 2 × the eye width
    int height = 0;
    std::vector<std::uint8_t> rgb;  // width × height × 3
    std::vector<std::uint8_t> ids;  // width × height cell ids (layout-format.md, "Cell-id maps")
    FrameStats stats;               // zero for a traced frame
};

enum class Backend { Egl, OSMesa, Any };  // Any: EGL, falling back to OSMesa

// The OpenGL function loader of a context the caller made current, e.g.
// eglGetProcAddress or glfwGetProcAddress.
using GetProcAddress = void* (*)(const char* name);

struct RendererParts;

// How the rasteriser draws (`render`'s technique options, docs/cli.md): what
// only the rasteriser reads. The View holds what both renderers read
// (samples, max_portal_passes, light_depth). The defaults are `render`'s.
enum class Stereo { ClipShift, ViewportIndex, TwoPass };  // --stereo
enum class Clip { ClipDistance, Oblique };                // --clip
enum class Depth { ReversedZ, Standard };                 // --depth
enum class Technique { Stencil, Hybrid, ZClear };         // --technique
struct RenderOptions {
    Stereo stereo = Stereo::ClipShift;
    Clip clip = Clip::ClipDistance;
    Depth depth = Depth::ReversedZ;
    Technique technique = Technique::Stencil;
    // Hybrid: the doors seen at this recursion level, and deeper ones inside
    // them, are drawn through textures of texture_scale × the eye size, (0, 4]
    // (--texture-from-level, --portal-texture).
    int texture_from_level = 0;
    double texture_scale = 1.0;
    bool shadows = true;     // props' shadows on lit layouts (--no-shadows)
    int shadow_size = 512;   // texels per cube-map face side, 0..4096 (--shadow-size)
    bool occlusion_test = false;  // --occlusion-test
    bool cull = true;             // per-eye culling and scissor (--no-cull: off)
};

// The OpenGL 4.5 rasteriser for one layout.
class Renderer {
public:
    // Draws in a headless context (EGL surfaceless or OSMesa) that the
    // headless renderers made on this thread share, one per backend; they
    // keep no more frame buffers between frames together than one frame may
    // use (docs/bounded-work.md, "Other bounds").
    static Expected<Renderer> headless(const Layout& layout, Backend backend = Backend::Any);
    // Draws in the caller's context, current on this thread now and at every
    // call; the caller's GL state is saved nowhere: the renderer sets what it
    // needs, and leaves its own bindings at 0 after each frame.
    static Expected<Renderer> in_current_context(const Layout& layout, GetProcAddress load);

    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;
    ~Renderer();

    // Draws and reads back. A bad option is an error naming its field
    // ("technique z-clear draws one level of doors: max_depth 8 ...").
    Expected<Frame> render(const View& view, const RenderOptions& options = {});
    // Draws, then copies the colour into the caller's framebuffer object
    // `framebuffer` (0: the default one) at (0, 0), 2 × width by height.
    Expected<FrameStats> draw_to(const View& view, unsigned framebuffer, const RenderOptions& options = {});

    std::string gl_renderer() const;  // GL_RENDERER of the context

private:
    explicit Renderer(std::unique_ptr<RendererParts> parts);
    std::unique_ptr<RendererParts> parts_;
};

// The same view by the double-precision reference ray tracer (`trace`);
// `threads` 0 uses every core.
Expected<Frame> trace(const Layout& layout, const View& view, int threads = 0);

// A tracked hand of a walked frame.
struct WalkHand {
    Pose virtual_pose;  // its physical pose mapped as the head's is (for View::hands with the head's virtual_pose)
    std::string room;   // the room it is in, walked from the head centre (`walk`'s "hands")
};

// One walked frame, as a line of `impossible walk`.
struct WalkStep {
    std::string room;                              // the room the head is in after the frame
    std::vector<std::string> teleports;            // the portals passed during it, in order
    double position[3] = {0, 0, 0};                // the virtual head centre
    double forward[3] = {0, 0, 0};                 // the virtual view direction
    Pose virtual_pose;                             // the virtual head as a pose (to render the frame)
    std::optional<std::array<WalkHand, 2>> hands;  // left, right: only for a frame walked with hands
    // Each moving prop's id and room at the frame's time (walk() with an
    // fps; `impossible walk`'s "props" key), in layout order; empty from a
    // Walker's step, which has no time.
    std::vector<std::pair<std::string, std::string>> props;
    // The ids of the changes made at this frame, in file order (`impossible
    // walk`'s "changes" key; layout-format.md, "Changes while walking"):
    // the frame's picture and the steps after it have their pairing.
    std::vector<std::string> changes;
};

// What a walk knows of one of the layout's changes.
struct ChangeState {
    std::string id;
    bool armed = false;   // its condition has held at some frame
    int made_frame = -1;  // the frame it was made at (numbered from 0); -1: not yet
};

// One line of a path file: the physical head, and the two physical hands on
// a line of 18 numbers.
struct PathLine {
    Pose head;
    std::optional<std::array<Pose, 2>> hands;
};

struct WalkerData;

// Physical head poses to the virtual head, teleporting at doors exactly as
// `impossible walk` does (layout-format.md, "Walking"). A layout with
// `changes` is walked with the pairing in force ("Changes while walking"):
// whether a door is seen, which decides when a change is made, is asked of
// the eyes the view options place (ipd, fov_deg, width × height,
// eye_optics, eye_poses, max_depth; its pose, room, time and hands are not
// read), render's defaults unless given.
class Walker {
public:
    explicit Walker(const Layout& layout);
    // With the view options of the seen test; a bad one is an Error naming
    // its field, as Renderer::render's.
    static Expected<Walker> make(const Layout& layout, const View& view);
    Walker(Walker&&) noexcept;
    Walker& operator=(Walker&&) noexcept;
    ~Walker();
    WalkStep step(const Pose& physical);
    // The same, with the physical hands (left, right) of this frame: the
    // step's `hands` hold their virtual poses and rooms.
    WalkStep step(const Pose& physical, const std::array<Pose, 2>& hands);

    // The layout with the pairing in force after the last step: what that
    // frame is drawn with (a Renderer or trace() made for it). The layout
    // given until a change is made; after one, the same rooms and data (shared,
    // not copied) with the doors re-paired and the closed ones left out of
    // portal_ids(), and no changes of its own.
    Layout layout() const;
    // Each of the loaded layout's changes, in file order.
    std::vector<ChangeState> changes() const;

private:
    explicit Walker(std::unique_ptr<WalkerData> data);
    std::unique_ptr<WalkerData> data_;
};

// A path file's poses (the `walk` format).
Expected<std::vector<Pose>> read_path(const std::string& path);
// Every line of a path file, with the hands of its 18-number lines.
Expected<std::vector<PathLine>> read_path_lines(const std::string& path);
// Every frame of a walk, as `impossible walk` prints them.
std::vector<WalkStep> walk(const Layout& layout, const std::vector<Pose>& physical);
// The same with the hands of the lines that have them.
std::vector<WalkStep> walk(const Layout& layout, const std::vector<PathLine>& physical);
// The same with line k at time k / fps (fps > 0, finite; else every step's
// props are those at time 0): each step also lists the moving props' rooms.
std::vector<WalkStep> walk(const Layout& layout, const std::vector<PathLine>& physical, double fps);
// The same with the view options of the seen test (as Walker::make): a bad
// view is an Error.
Expected<std::vector<WalkStep>> walk(const Layout& layout, const std::vector<PathLine>& physical, double fps,
                                     const View& view);
// The layout with the pairing in force at line `frame` of a walk (lines 0..
// frame walked as walk() does, line k at k / fps, the seen test on `view`'s
// eyes): what `render --path FILE --frame K` draws. The layout itself when
// no change was made by then. An Error for a frame past the path's end, an
// fps not > 0 and finite, or a bad view.
Expected<Layout> paired_at(const Layout& layout, const std::vector<PathLine>& physical, std::size_t frame, double fps,
                           const View& view = {});

// The designer's tools, as their commands.
struct GenerateRequest {
    double width = 4, depth = 4;                       // a W × D floor centred on the origin...
    std::vector<std::pair<double, double>> play_area;  // ...or this polygon (x, z), if given
    int rooms = 4;
    std::uint64_t seed = 1;
    std::optional<double> max_overlap;  // percent; default Suma et al.'s thresholds
};
Expected<std::string> generate(const GenerateRequest& request);  // layout JSON text
// A top-down SVG of the floor (`plan`), with an optional walk drawn on it.
Expected<std::string> plan_svg(const Layout& layout, const std::vector<Pose>& path = {});
// A walk that visits every reachable room (`tour`), as physical poses.
struct TourRequest {
    double step = 0.05;
    double head_height = 1.6;
};
Expected<std::vector<Pose>> tour(const Layout& layout, const TourRequest& request = {});

}  // namespace impossible::api
