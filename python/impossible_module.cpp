// The Python module `impossible` (docs/python.md): the public C++ API
// (include/impossible/impossible.hpp) through Debian's pybind11, and nothing
// else of the library. A frame's pixels become numpy arrays without a copy
// (its vectors move into the arrays' owners); the GIL is released while a
// frame is drawn or traced. Every error of the library is raised as
// impossible.Error, a ValueError carrying its message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "impossible/impossible.hpp"

namespace py = pybind11;
namespace api = impossible::api;

namespace {

// Raised as impossible.Error (registered in the module).
struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <class T>
T value_or_raise(api::Expected<T>&& e) {
    if (!e) throw Failure(e.error().message);
    return std::move(e).value();
}

[[noreturn]] void raise(PyObject* type, const std::string& message) {
    PyErr_SetString(type, message.c_str());
    throw py::error_already_set();
}

// A number in a message as Python writes it: the shortest that reads back
// ("1e+300", not 301 digits).
std::string short_number(double v) { return py::str(py::float_(v)).cast<std::string>(); }

// The Python type's name of `value` ("str", "float").
std::string type_name(py::handle value) {
    return py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
}

// A scalar argument of the wrong type: TypeError naming the argument.
[[noreturn]] void wrong_type(const char* what, const char* expected, py::handle value) {
    raise(PyExc_TypeError, std::string(what) + ": expected " + expected + ", got " + type_name(value));
}

// An integer argument (an int or anything with __index__, not a float) that
// fits an int; the library checks its range.
int integer_of(py::handle value, const char* what) {
    if (py::isinstance<py::float_>(value) || py::isinstance<py::str>(value)) wrong_type(what, "an integer", value);
    long long n = 0;
    try {
        n = value.cast<long long>();
    } catch (const py::cast_error&) {
        if (PyErr_Occurred()) PyErr_Clear();
        if (!PyIndex_Check(value.ptr())) wrong_type(what, "an integer", value);
        n = std::numeric_limits<long long>::max();
    }
    if (n < std::numeric_limits<int>::min() || n > std::numeric_limits<int>::max())
        raise(PyExc_ValueError, std::string(what) + ": " + py::str(value).cast<std::string>() + " is too large");
    return static_cast<int>(n);
}

// A number argument (int or float).
double real_of(py::handle value, const char* what) {
    if (py::isinstance<py::str>(value)) wrong_type(what, "a number", value);
    try {
        return value.cast<double>();
    } catch (const py::cast_error&) {
        wrong_type(what, "a number", value);
    }
}

// A string argument.
std::string text_of(py::handle value, const char* what, const char* expected) {
    if (!py::isinstance<py::str>(value)) wrong_type(what, expected, value);
    return value.cast<std::string>();
}

// size: (width, height), two integers.
std::pair<int, int> size_of(py::handle value) {
    const char* expected = "size: expected (width, height), two integers";
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value))
        raise(PyExc_TypeError, std::string(expected) + ", got " + type_name(value));
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() != 2)
        raise(PyExc_ValueError, std::string(expected) + ", got " + std::to_string(seq.size()) + " items");
    int out[2];
    for (int k = 0; k < 2; ++k) {
        const py::object item = seq[k];
        out[k] = integer_of(item, k == 0 ? "size: width" : "size: height");
    }
    return {out[0], out[1]};
}

// Six numbers (x, y, z, yaw, pitch, roll), each finite and within ±limit:
// 1e7 as `--pose`, 1e6 as a path file's lines.
api::Pose pose_of(py::handle value, double limit, const char* what) {
    const std::string expected = std::string(what) + ": expected 6 numbers (x, y, z, yaw, pitch, roll)";
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) raise(PyExc_TypeError, expected);
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() != 6) raise(PyExc_ValueError, expected + ", got " + std::to_string(seq.size()));
    double v[6];
    for (int k = 0; k < 6; ++k) {
        try {
            v[k] = seq[k].cast<double>();
        } catch (const py::cast_error&) {
            raise(PyExc_TypeError, expected);
        }
        if (!(std::abs(v[k]) <= limit))
            raise(PyExc_ValueError, std::string(what) + ": " + short_number(v[k]) + " is not a finite number within ±" +
                                        std::to_string(static_cast<long>(limit)));
    }
    return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

std::vector<api::Pose> poses_of(py::handle list, const char* what) {
    std::vector<api::Pose> poses;
    if (py::isinstance<py::str>(list) || !py::isinstance<py::iterable>(list))
        raise(PyExc_TypeError, std::string(what) + ": expected a list of poses");
    for (py::handle p : py::reinterpret_borrow<py::iterable>(list)) poses.push_back(pose_of(p, 1e6, what));
    return poses;
}

py::tuple tuple_of(const api::Pose& p) { return py::make_tuple(p.x, p.y, p.z, p.yaw, p.pitch, p.roll); }

py::list tuples_of(const std::vector<api::Pose>& poses) {
    py::list out;
    for (const api::Pose& p : poses) out.append(tuple_of(p));
    return out;
}

// The pixels moved into a capsule that the array keeps alive: no copy.
py::array_t<std::uint8_t> array_of(std::vector<std::uint8_t>&& pixels, std::vector<py::ssize_t> shape) {
    auto owned = std::make_unique<std::vector<std::uint8_t>>(std::move(pixels));
    const std::uint8_t* data = owned->data();
    py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
    owned.release();
    return py::array_t<std::uint8_t>(std::move(shape), data, owner);
}

py::dict stats_of(const api::FrameStats& s) {
    py::dict d;
    d["draw_calls"] = s.draw_calls;
    d["triangles"] = s.triangles;
    d["portal_passes_drawn"] = s.portal_passes_drawn;
    d["portal_passes_culled"] = s.portal_passes_culled;
    d["portal_fills"] = s.portal_fills;
    d["budget_fills"] = s.budget_fills;
    d["max_level"] = s.max_level;
    return d;
}

// {"color": [H, 2W, 3], "ids": [H, 2W]} (and "stats" for a rasterised frame).
py::dict frame_dict(api::Frame&& f, bool with_stats) {
    py::dict d;
    const py::ssize_t h = f.height, w = f.width;
    d["color"] = array_of(std::move(f.rgb), {h, w, 3});
    d["ids"] = array_of(std::move(f.ids), {h, w});
    if (with_stats) d["stats"] = stats_of(f.stats);
    return d;
}

api::Backend backend_of(const std::string& name) {
    if (name == "egl") return api::Backend::Egl;
    if (name == "osmesa") return api::Backend::OSMesa;
    if (name == "any") return api::Backend::Any;
    raise(PyExc_ValueError, "backend must be 'egl', 'osmesa' or 'any', not '" + name + "'");
}

// The rasteriser's options (api::RenderOptions) from the keyword
// arguments, named and spelled as `render`'s flags' values.
template <class E, std::size_t N>
E choice_of(const std::string& name, const std::string& value,
            const std::array<std::pair<const char*, E>, N>& choices) {
    std::string names;
    for (const auto& [text, e] : choices) {
        if (value == text) return e;
        names += (names.empty() ? "'" : ", '") + std::string(text) + "'";
    }
    raise(PyExc_ValueError, name + " must be one of " + names + ", not '" + value + "'");
}

api::RenderOptions render_options_of(const std::string& stereo, const std::string& clip, const std::string& depth,
                                     const std::string& technique, int texture_from_level, double texture_scale,
                                     bool shadows, int shadow_size, bool occlusion_test, bool cull) {
    api::RenderOptions o;
    o.stereo = choice_of<api::Stereo, 3>("stereo", stereo,
                                         {{{"clip-shift", api::Stereo::ClipShift},
                                           {"viewport-index", api::Stereo::ViewportIndex},
                                           {"two-pass", api::Stereo::TwoPass}}});
    o.clip = choice_of<api::Clip, 2>("clip", clip,
                                     {{{"clip-distance", api::Clip::ClipDistance}, {"oblique", api::Clip::Oblique}}});
    o.depth = choice_of<api::Depth, 2>("depth", depth,
                                       {{{"reversed-z", api::Depth::ReversedZ}, {"standard", api::Depth::Standard}}});
    o.technique = choice_of<api::Technique, 3>("technique", technique,
                                               {{{"stencil", api::Technique::Stencil},
                                                 {"hybrid", api::Technique::Hybrid},
                                                 {"z-clear", api::Technique::ZClear}}});
    o.texture_from_level = texture_from_level;
    o.texture_scale = texture_scale;
    o.shadows = shadows;
    o.shadow_size = shadow_size;
    o.occlusion_test = occlusion_test;
    o.cull = cull;
    return o;
}

std::string path_string(py::handle path) { return py::module_::import("os").attr("fspath")(path).cast<std::string>(); }

// What every frame of a renderer shares: size, samples, eyes.
struct ViewBase {
    std::pair<int, int> size{1280, 720};
    int samples = 1;
    int max_portal_passes = 10'000;
    double ipd = 0.064, fov = 90;
    std::optional<std::array<api::EyeOptics, 2>> eye_optics;  // fov_angles=, hmd=
    std::optional<std::array<api::EyePose, 2>> eye_poses;     // eye_poses=, hmd=
};

std::vector<double> numbers_of(py::handle value, const char* what, const std::string& expected) {
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value))
        raise(PyExc_TypeError, std::string(what) + ": expected " + expected);
    std::vector<double> out;
    // Each item held as an object: a handle to the accessor's temporary would
    // dangle once the item is a new object (numpy's and array's numbers are).
    for (const py::object n : py::reinterpret_borrow<py::sequence>(value)) {
        try {
            out.push_back(n.cast<double>());
        } catch (const py::cast_error&) {
            raise(PyExc_TypeError, std::string(what) + ": expected " + expected);
        }
    }
    return out;
}

// fov_angles: (left, right, up, down) in degrees, both eyes mirrored, or 8
// numbers, the left eye's then the right eye's (--fov-angles).
std::array<api::EyeOptics, 2> optics_of(py::handle angles) {
    const std::vector<double> n = numbers_of(angles, "fov_angles", "4 or 8 numbers (left, right, up, down)");
    if (n.size() != 4 && n.size() != 8)
        raise(PyExc_ValueError,
              "fov_angles: expected 4 or 8 numbers (left, right, up, down), got " + std::to_string(n.size()));
    std::array<api::EyeOptics, 2> eyes;
    eyes[0].fov = {n[0], n[1], n[2], n[3]};
    eyes[1].fov = n.size() == 8 ? api::FovAngles{n[4], n[5], n[6], n[7]} : api::FovAngles{-n[1], -n[0], n[2], n[3]};
    return eyes;
}

// visible_area: (left, right), each a list of (u, v) corners or None.
void visible_areas_of(py::handle areas, std::array<api::EyeOptics, 2>& eyes) {
    const char* expected = "visible_area: expected two polygons, the left and the right eye's ([(u, v), ...] or None)";
    if (py::isinstance<py::str>(areas) || !py::isinstance<py::sequence>(areas) || py::len(areas) != 2)
        raise(PyExc_TypeError, expected);
    const auto seq = py::reinterpret_borrow<py::sequence>(areas);
    for (std::size_t e = 0; e < 2; ++e) {
        if (seq[e].is_none()) continue;
        if (py::isinstance<py::str>(seq[e]) || !py::isinstance<py::sequence>(seq[e])) raise(PyExc_TypeError, expected);
        const py::object area = seq[e];
        for (const py::object corner : py::reinterpret_borrow<py::sequence>(area)) {
            const std::vector<double> c = numbers_of(corner, "visible_area", "corners of 2 numbers (u, v)");
            if (c.size() != 2) raise(PyExc_ValueError, "visible_area: expected corners of 2 numbers (u, v)");
            eyes[e].visible_area.push_back({c[0], c[1]});
        }
    }
}

// One eye of eye_poses: six numbers (x, y, z, yaw, pitch, roll) as
// --eye-poses (pitch within ±89.5), or (position, orientation) as a profile
// gives it (3 numbers, and a unit quaternion x, y, z, w).
api::EyePose eye_pose_of(py::handle value, const char* what) {
    const std::string expected =
        std::string(what) + ": expected 6 numbers (x, y, z, yaw, pitch, roll) or (position, orientation)";
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) raise(PyExc_TypeError, expected);
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() == 2) {
        const std::vector<double> p = numbers_of(seq[0], what, "a position of 3 numbers");
        const std::vector<double> q = numbers_of(seq[1], what, "an orientation of 4 numbers (x, y, z, w)");
        if (p.size() != 3 || q.size() != 4)
            raise(PyExc_ValueError, std::string(what) + ": expected a position of 3 numbers and an orientation of 4");
        return {{p[0], p[1], p[2]}, {q[0], q[1], q[2], q[3]}};
    }
    const api::Pose pose = pose_of(value, 1e7, what);
    if (!(std::abs(pose.pitch) <= 89.5))
        raise(PyExc_ValueError, std::string(what) + ": pitch " + py::str(py::float_(pose.pitch)).cast<std::string>() +
                                    " is not within ±89.5 degrees");
    return api::eye_pose(pose);
}

// eye_poses: the left and the right eye's pose relative to the head.
std::array<api::EyePose, 2> eye_poses_of(py::handle value) {
    const char* expected = "eye_poses: expected two poses, the left and the right eye's";
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) raise(PyExc_TypeError, expected);
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() != 2) raise(PyExc_ValueError, std::string(expected) + ", got " + std::to_string(seq.size()));
    return {eye_pose_of(seq[0], "eye_poses[0]"), eye_pose_of(seq[1], "eye_poses[1]")};
}

// The eyes of a renderer or a trace, with the CLI's rules: fov, fov_angles
// and hmd exclude each other, as eye_poses and ipd do; hmd's size and IPD or
// eye poses unless size, ipd or eye_poses is given.
ViewBase base_of(py::handle size, int samples, py::handle ipd, py::handle fov, py::handle fov_angles,
                 py::handle visible_area, py::handle hmd, py::handle eye_poses) {
    if (!eye_poses.is_none() && !ipd.is_none()) raise(PyExc_ValueError, "eye_poses and ipd exclude each other");
    if (!fov.is_none() && !fov_angles.is_none()) raise(PyExc_ValueError, "fov and fov_angles exclude each other");
    if (!hmd.is_none() && !(fov.is_none() && fov_angles.is_none()))
        raise(PyExc_ValueError, std::string(fov.is_none() ? "fov_angles" : "fov") +
                                    " and hmd exclude each other (the profile gives each eye's angles)");
    if (!visible_area.is_none() && fov_angles.is_none())
        raise(PyExc_ValueError, "visible_area needs fov_angles (a profile has its own)");
    ViewBase base;
    base.samples = samples;
    if (!hmd.is_none()) {
        const api::HmdProfile profile = value_or_raise(api::load_hmd_profile(path_string(hmd)));
        base.size = {profile.eye_width, profile.eye_height};
        base.ipd = profile.ipd;
        base.eye_optics = profile.eyes;
        base.eye_poses = profile.eye_poses;
        if (profile.eye_poses && !ipd.is_none())
            raise(PyExc_ValueError, "ipd: " + path_string(hmd) +
                                        " gives each eye's position and orientation, which ipd cannot replace; give "
                                        "eye_poses instead");
    }
    if (!eye_poses.is_none()) base.eye_poses = eye_poses_of(eye_poses);
    if (!fov_angles.is_none()) base.eye_optics = optics_of(fov_angles);
    if (!visible_area.is_none()) visible_areas_of(visible_area, *base.eye_optics);
    if (!size.is_none()) base.size = size_of(size);
    if (!ipd.is_none()) base.ipd = real_of(ipd, "ipd");
    if (!fov.is_none()) base.fov = real_of(fov, "fov");
    return base;
}

py::dict profile_dict(const api::HmdProfile& p) {
    py::dict d;
    d["name"] = p.name;
    d["source"] = p.source;
    d["ipd"] = p.ipd;
    d["size"] = py::make_tuple(p.eye_width, p.eye_height);
    py::list angles, areas;
    for (const api::EyeOptics& eye : p.eyes) {
        for (double a : {eye.fov.left, eye.fov.right, eye.fov.up, eye.fov.down}) angles.append(a);
        py::list area;
        for (const std::array<double, 2>& c : eye.visible_area) area.append(py::make_tuple(c[0], c[1]));
        areas.append(area);
    }
    d["fov_angles"] = py::tuple(angles);
    d["visible_area"] = py::tuple(areas);
    py::object poses = py::none();
    if (p.eye_poses) {
        py::list both;
        for (const api::EyePose& e : *p.eye_poses)
            both.append(
                py::make_tuple(py::make_tuple(e.position[0], e.position[1], e.position[2]),
                               py::make_tuple(e.orientation[0], e.orientation[1], e.orientation[2], e.orientation[3])));
        poses = py::tuple(both);
    }
    d["eye_poses"] = poses;
    return d;
}

// Two poses, the left and the right hand, each as `pose` (--hands).
std::array<api::Pose, 2> hands_of(py::handle value, double limit = 1e7) {
    const char* expected = "hands: expected two poses, the left and the right hand";
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value)) raise(PyExc_TypeError, expected);
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() != 2) raise(PyExc_ValueError, std::string(expected) + ", got " + std::to_string(seq.size()));
    return {pose_of(seq[0], limit, "hands[0]"), pose_of(seq[1], limit, "hands[1]")};
}

// One frame's view.
api::View view_of(const ViewBase& base, py::handle pose, py::handle room, py::handle hands, double time, int max_depth,
                  py::handle light_depth, py::handle exposure = py::none()) {
    api::View v;
    if (!light_depth.is_none()) v.light_depth = integer_of(light_depth, "light_depth");
    if (!exposure.is_none()) v.exposure = real_of(exposure, "exposure");
    if (!hands.is_none()) v.hands = hands_of(hands);
    if (!pose.is_none()) v.pose = pose_of(pose, 1e7, "pose");
    if (!room.is_none()) v.room = text_of(room, "room", "a room id (str)");
    std::tie(v.width, v.height) = base.size;
    v.samples = base.samples;
    v.max_portal_passes = base.max_portal_passes;
    v.ipd = base.ipd;
    v.fov_deg = base.fov;
    v.eye_optics = base.eye_optics;
    v.eye_poses = base.eye_poses;
    v.time = time;
    v.max_depth = max_depth;
    return v;
}

py::dict trace_frame(const api::Layout& layout, const api::View& view, int threads) {
    api::Expected<api::Frame> frame = [&] {
        py::gil_scoped_release unlocked;
        return api::trace(layout, view, threads);
    }();
    return frame_dict(value_or_raise(std::move(frame)), false);
}

// A headless rasteriser, drawing in the GL context that the renderers of
// its thread share (the context is current there), until closed: close()
// (or leaving a `with` block) frees its GL objects at once, as deleting the
// last reference does.
class PyRenderer {
public:
    PyRenderer(const api::Layout& layout, ViewBase base, const std::string& backend, const api::RenderOptions& options)
        : layout_(layout),
          renderer_(value_or_raise(api::Renderer::headless(layout, backend_of(backend)))),
          gl_renderer_(renderer_->gl_renderer()),
          base_(base),
          options_(options),
          thread_(std::this_thread::get_id()) {}

    py::dict render(py::handle pose, py::handle room, py::handle hands, double time, int max_depth,
                    py::handle light_depth, py::handle exposure) {
        const api::View view = view_of(base_, pose, room, hands, time, max_depth, light_depth, exposure);
        on_its_thread("draws");
        if (!renderer_) raise(PyExc_ValueError, "render: the renderer is closed");
        api::Expected<api::Frame> frame = [&] {
            py::gil_scoped_release unlocked;
            return renderer_->render(view, options_);
        }();
        return frame_dict(value_or_raise(std::move(frame)), true);
    }

    py::dict trace(py::handle pose, py::handle room, py::handle hands, double time, int max_depth, int threads,
                   py::handle light_depth, py::handle exposure) {
        return trace_frame(layout_, view_of(base_, pose, room, hands, time, max_depth, light_depth, exposure), threads);
    }

    // Frees the GL objects now, in the context they were made in; again:
    // nothing.
    void close() {
        if (!renderer_) return;
        on_its_thread("is closed");
        renderer_.reset();
    }

    const api::Layout& layout() const { return layout_; }
    ViewBase base() const { return base_; }
    const std::string& gl_renderer() const { return gl_renderer_; }
    bool closed() const { return !renderer_; }

private:
    api::Layout layout_;
    std::optional<api::Renderer> renderer_;
    std::string gl_renderer_;
    ViewBase base_;
    api::RenderOptions options_;
    std::thread::id thread_;

    void on_its_thread(const char* what) const {
        if (std::this_thread::get_id() != thread_)
            raise(PyExc_RuntimeError, std::string("a Renderer ") + what + " only on the thread that made it");
    }
};

py::dict step_dict(std::size_t frame, const api::WalkStep& s) {
    py::dict d;
    d["frame"] = frame;
    d["room"] = s.room;
    d["teleports"] = py::cast(s.teleports);
    // + 0.0: -0 becomes 0, as `walk` writes it.
    d["position"] = py::make_tuple(s.position[0] + 0.0, s.position[1] + 0.0, s.position[2] + 0.0).cast<py::list>();
    d["forward"] = py::make_tuple(s.forward[0] + 0.0, s.forward[1] + 0.0, s.forward[2] + 0.0).cast<py::list>();
    if (s.hands) d["hands"] = py::make_tuple((*s.hands)[0].room, (*s.hands)[1].room).cast<py::list>();
    if (!s.props.empty()) {
        py::dict props;  // insertion order: the layout's, as `walk` prints it
        for (const auto& [id, room] : s.props) props[py::str(id)] = room;
        d["props"] = props;
    }
    if (!s.changes.empty()) d["changes"] = py::cast(s.changes);  // as `walk` prints it: only where made
    return d;
}

// The view options of the changes' seen test (layout-format.md, "Changes
// while walking"): render's view options that place the eyes, with their
// defaults; the head is the walk's.
api::View seen_view_of(py::handle size, py::handle ipd, py::handle fov, py::handle fov_angles, py::handle visible_area,
                       py::handle hmd, py::handle eye_poses, int max_depth) {
    const ViewBase base = base_of(size, 1, ipd, fov, fov_angles, visible_area, hmd, eye_poses);
    return view_of(base, py::none(), py::none(), py::none(), 0.0, max_depth, py::none());
}

py::list change_states(const std::vector<api::ChangeState>& states) {
    py::list out;
    for (const api::ChangeState& c : states) {
        py::dict d;
        d["id"] = c.id;
        d["armed"] = c.armed;
        d["made_frame"] = c.made_frame < 0 ? py::object(py::none()) : py::object(py::int_(c.made_frame));
        out.append(d);
    }
    return out;
}

// A path file's line: 6 numbers (the head) or 18 (the head, then the left
// and the right hand), each within ±1e6 as the file's.
api::PathLine line_of(py::handle value, const char* what) {
    if (!py::isinstance<py::str>(value) && py::isinstance<py::sequence>(value) && py::len(value) == 18) {
        const auto seq = py::reinterpret_borrow<py::sequence>(value);
        py::tuple part[3];
        for (int k = 0; k < 3; ++k) part[k] = seq[py::slice(6 * k, 6 * k + 6, 1)];
        return {pose_of(part[0], 1e6, what),
                std::array<api::Pose, 2>{pose_of(part[1], 1e6, what), pose_of(part[2], 1e6, what)}};
    }
    if (!py::isinstance<py::str>(value) && py::isinstance<py::sequence>(value) && py::len(value) != 6)
        raise(PyExc_ValueError, std::string(what) +
                                    ": expected 6 numbers (x, y, z, yaw, pitch, roll) or 18 (the head, then the "
                                    "left and the right hand), got " +
                                    std::to_string(py::len(value)));
    return {pose_of(value, 1e6, what), std::nullopt};
}

// The walker, one physical pose at a time; `pose` is the virtual head after
// the last step, `hands` the virtual hands (with a step that had hands), to
// render that frame.
class PyWalker {
public:
    PyWalker(const api::Layout& layout, const api::View& seen)
        : walker_(value_or_raise(api::Walker::make(layout, seen))), pose_(layout.start()), room_(layout.start_room()) {}

    py::dict step(py::handle physical, py::handle hands) {
        api::PathLine line = line_of(physical, "pose");
        if (!hands.is_none()) {
            if (line.hands) raise(PyExc_ValueError, "hands: given twice (the pose holds 18 numbers)");
            line.hands = hands_of(hands, 1e6);
        }
        const api::WalkStep s = line.hands ? walker_.step(line.head, *line.hands) : walker_.step(line.head);
        pose_ = s.virtual_pose;
        room_ = s.room;
        hands_ = s.hands;
        return step_dict(frames_++, s);
    }
    py::tuple pose() const { return tuple_of(pose_); }
    const std::string& room() const { return room_; }
    py::object hands() const {
        if (!hands_) return py::none();
        return py::make_tuple(tuple_of((*hands_)[0].virtual_pose), tuple_of((*hands_)[1].virtual_pose));
    }
    py::object hand_rooms() const {
        if (!hands_) return py::none();
        return py::make_tuple((*hands_)[0].room, (*hands_)[1].room);
    }
    api::Layout layout() const { return walker_.layout(); }
    py::list changes() const { return change_states(walker_.changes()); }

private:
    api::Walker walker_;
    api::Pose pose_;
    std::string room_;
    std::optional<std::array<api::WalkHand, 2>> hands_;
    std::size_t frames_ = 0;
};

std::vector<api::PathLine> lines_of(py::handle poses, double fps) {
    if (!(fps > 0 && std::isfinite(fps))) raise(PyExc_ValueError, "fps must be a finite number above 0");
    if (py::isinstance<py::str>(poses) || !py::isinstance<py::iterable>(poses))
        raise(PyExc_TypeError, "poses: expected a list of poses");
    std::vector<api::PathLine> lines;
    for (py::handle p : py::reinterpret_borrow<py::iterable>(poses)) lines.push_back(line_of(p, "poses"));
    return lines;
}

py::list walk(const api::Layout& layout, py::handle poses, double fps, const api::View& seen) {
    const std::vector<api::WalkStep> steps = value_or_raise(api::walk(layout, lines_of(poses, fps), fps, seen));
    py::list out;
    for (std::size_t k = 0; k < steps.size(); ++k) out.append(step_dict(k, steps[k]));
    return out;
}

api::Layout paired_at(const api::Layout& layout, py::handle poses, long long frame, double fps, const api::View& seen) {
    const std::vector<api::PathLine> lines = lines_of(poses, fps);
    if (frame < 0 || static_cast<unsigned long long>(frame) >= lines.size())
        raise(PyExc_IndexError, "frame " + std::to_string(frame) + ": the walk has " + std::to_string(lines.size()) +
                                    " poses (frames 0.." + std::to_string(static_cast<long long>(lines.size()) - 1) +
                                    ")");
    return value_or_raise(api::paired_at(layout, lines, static_cast<std::size_t>(frame), fps, seen));
}

// A path file's lines: 6-tuples, or with hands=True, each line as written
// (6 or 18 numbers).
py::list read_path(py::handle path, bool hands) {
    const std::string name = py::module_::import("os").attr("fspath")(path).cast<std::string>();
    if (!hands) return tuples_of(value_or_raise(api::read_path(name)));
    py::list out;
    for (const api::PathLine& line : value_or_raise(api::read_path_lines(name))) {
        py::tuple t = tuple_of(line.head);
        if (line.hands) t = t + tuple_of((*line.hands)[0]) + tuple_of((*line.hands)[1]);
        out.append(t);
    }
    return out;
}

// play_area: (width, depth) of a rectangle centred on the origin, or a
// polygon [(x, z), ...].
std::string generate(py::handle play_area, int rooms, long long seed, std::optional<double> max_overlap) {
    if (seed < 0 || seed > 2'000'000'000) raise(PyExc_ValueError, "seed must be 0..2000000000");
    api::GenerateRequest request;
    const char* expected = "play_area: expected (width, depth) or a polygon [(x, z), ...]";
    if (py::isinstance<py::str>(play_area) || !py::isinstance<py::sequence>(play_area))
        raise(PyExc_TypeError, std::string(expected) + ", got " + type_name(play_area));
    const auto area = play_area.cast<std::vector<py::object>>();
    if (area.size() == 2 && !py::isinstance<py::sequence>(area[0])) {
        request.width = real_of(area[0], "play_area: width");
        request.depth = real_of(area[1], "play_area: depth");
    } else {
        for (const py::object& corner : area) {
            const std::vector<double> c = numbers_of(corner, "play_area", "corners of 2 numbers (x, z)");
            if (c.size() != 2) raise(PyExc_ValueError, "play_area: expected corners of 2 numbers (x, z)");
            request.play_area.push_back({c[0], c[1]});
        }
    }
    request.rooms = rooms;
    request.seed = static_cast<std::uint64_t>(seed);
    request.max_overlap = max_overlap;
    return value_or_raise(api::generate(request));
}

void bind_layout(py::module_& m) {
    py::class_<api::Layout>(m, "Layout", "A loaded, valid layout (impossible.load)")
        .def_property_readonly("source", &api::Layout::source)
        .def_property_readonly("name", &api::Layout::name)
        .def_property_readonly("rooms", &api::Layout::room_ids)
        .def_property_readonly("portals", &api::Layout::portal_ids)
        .def_property_readonly("start_room", &api::Layout::start_room)
        .def_property_readonly("start", [](const api::Layout& l) { return tuple_of(l.start()); })
        .def_property_readonly("warnings", &api::Layout::warnings)
        .def(
            "validate", [](const api::Layout& l) { return py::module_::import("json").attr("loads")(l.report_json()); },
            "The designer's report as a dict (`impossible validate --json`)")
        .def("report", &api::Layout::report_text, "The report as `impossible validate` prints it")
        .def("__repr__", [](const api::Layout& l) { return "<impossible.Layout " + l.source() + ">"; });
    m.def(
        "load", [](py::handle path) { return value_or_raise(api::Layout::load(path_string(path))); }, py::arg("path"),
        "Reads and checks a layout file; impossible.Error (FILE:LINE:COLUMN: message) if it is bad");
    m.def(
        "parse",
        [](const std::string& text, const std::string& name, const std::string& base_dir) {
            return value_or_raise(api::Layout::parse(text, name, base_dir));
        },
        py::arg("text"), py::arg("name") = "<string>", py::arg("base_dir") = ".", "A layout from its JSON text");
    m.def("builtin", &api::Layout::builtin, "The built-in default layout (what `impossible render` draws)");
}

void bind_renderer(py::module_& m) {
    py::class_<PyRenderer>(m, "Renderer", "The OpenGL rasteriser for one layout, in its thread's headless context")
        .def(py::init([](const api::Layout& layout, py::handle size, int samples, const std::string& backend,
                         py::handle ipd, py::handle fov, py::handle fov_angles, py::handle visible_area, py::handle hmd,
                         int max_portal_passes, const std::string& stereo, const std::string& clip,
                         const std::string& depth, const std::string& technique, int texture_from_level,
                         double texture_scale, bool shadows, int shadow_size, bool occlusion_test, bool cull,
                         py::handle eye_poses) {
                 ViewBase base = base_of(size, samples, ipd, fov, fov_angles, visible_area, hmd, eye_poses);
                 base.max_portal_passes = max_portal_passes;
                 return new PyRenderer(layout, base, backend,
                                       render_options_of(stereo, clip, depth, technique, texture_from_level,
                                                         texture_scale, shadows, shadow_size, occlusion_test, cull));
             }),
             py::arg("layout"), py::arg("size") = py::none(), py::arg("samples") = 1, py::arg("backend") = "egl",
             py::arg("ipd") = py::none(), py::arg("fov") = py::none(), py::arg("fov_angles") = py::none(),
             py::arg("visible_area") = py::none(), py::arg("hmd") = py::none(), py::arg("max_portal_passes") = 10'000,
             py::arg("stereo") = "clip-shift", py::arg("clip") = "clip-distance", py::arg("depth") = "reversed-z",
             py::arg("technique") = "stencil", py::arg("texture_from_level") = 0, py::arg("texture_scale") = 1.0,
             py::arg("shadows") = true, py::arg("shadow_size") = 512, py::arg("occlusion_test") = false,
             py::arg("cull") = true, py::arg("eye_poses") = py::none())
        .def("render", &PyRenderer::render, py::arg("pose") = py::none(), py::arg("room") = py::none(),
             py::arg("hands") = py::none(), py::arg("time") = 0.0, py::arg("max_depth") = 8,
             py::arg("light_depth") = py::none(), py::arg("exposure") = py::none())
        .def("trace", &PyRenderer::trace, py::arg("pose") = py::none(), py::arg("room") = py::none(),
             py::arg("hands") = py::none(), py::arg("time") = 0.0, py::arg("max_depth") = 8, py::arg("threads") = 0,
             py::arg("light_depth") = py::none(), py::arg("exposure") = py::none())
        .def("close", &PyRenderer::close, "Frees its GL objects now; render() raises ValueError after")
        .def("__enter__", [](py::object self) { return self; })
        .def("__exit__", [](PyRenderer& r, const py::args&) { r.close(); })
        .def_property_readonly("closed", &PyRenderer::closed)
        .def_property_readonly("layout", &PyRenderer::layout)
        .def_property_readonly("size", [](const PyRenderer& r) { return r.base().size; })
        .def_property_readonly("gl_renderer", &PyRenderer::gl_renderer);
    m.def(
        "trace",
        [](const api::Layout& layout, py::handle size, int samples, py::handle pose, py::handle room, py::handle hands,
           double time, int max_depth, int threads, py::handle light_depth, py::handle ipd, py::handle fov,
           py::handle fov_angles, py::handle visible_area, py::handle hmd, py::handle eye_poses, py::handle exposure) {
            const ViewBase base = base_of(size, samples, ipd, fov, fov_angles, visible_area, hmd, eye_poses);
            return trace_frame(layout, view_of(base, pose, room, hands, time, max_depth, light_depth, exposure),
                               threads);
        },
        py::arg("layout"), py::arg("size") = py::none(), py::arg("samples") = 1, py::arg("pose") = py::none(),
        py::arg("room") = py::none(), py::arg("hands") = py::none(), py::arg("time") = 0.0, py::arg("max_depth") = 8,
        py::arg("threads") = 0, py::arg("light_depth") = py::none(), py::arg("ipd") = py::none(),
        py::arg("fov") = py::none(), py::arg("fov_angles") = py::none(), py::arg("visible_area") = py::none(),
        py::arg("hmd") = py::none(), py::arg("eye_poses") = py::none(), py::arg("exposure") = py::none(),
        "The reference ray tracer (`impossible trace`); no GL context needed");
    m.def(
        "load_hmd_profile",
        [](py::handle path) { return profile_dict(value_or_raise(api::load_hmd_profile(path_string(path)))); },
        py::arg("path"),
        "A headset profile (`--hmd`) as a dict: name, source, ipd, size, fov_angles (8), visible_area (left, right),\n"
        "eye_poses (None, or each eye's (position, orientation))");
}

void bind_tools(py::module_& m) {
    py::class_<PyWalker>(m, "Walker", "Physical head poses to the virtual head, one at a time")
        .def(py::init([](const api::Layout& layout, py::handle size, py::handle ipd, py::handle fov,
                         py::handle fov_angles, py::handle visible_area, py::handle hmd, py::handle eye_poses,
                         int max_depth) {
                 return new PyWalker(layout,
                                     seen_view_of(size, ipd, fov, fov_angles, visible_area, hmd, eye_poses, max_depth));
             }),
             py::arg("layout"), py::kw_only(), py::arg("size") = py::none(), py::arg("ipd") = py::none(),
             py::arg("fov") = py::none(), py::arg("fov_angles") = py::none(), py::arg("visible_area") = py::none(),
             py::arg("hmd") = py::none(), py::arg("eye_poses") = py::none(), py::arg("max_depth") = 8)
        .def("step", &PyWalker::step, py::arg("pose"), py::arg("hands") = py::none())
        .def_property_readonly("pose", &PyWalker::pose)
        .def_property_readonly("room", &PyWalker::room)
        .def_property_readonly("hands", &PyWalker::hands)
        .def_property_readonly("hand_rooms", &PyWalker::hand_rooms)
        .def_property_readonly("layout", &PyWalker::layout,
                               "The layout with the pairing in force after the last step (the changes made)")
        .def_property_readonly("changes", &PyWalker::changes,
                               "Each of the layout's changes: {'id', 'armed', 'made_frame' (None: not yet)}");
    m.def(
        "walk",
        [](const api::Layout& layout, py::handle poses, double fps, py::handle size, py::handle ipd, py::handle fov,
           py::handle fov_angles, py::handle visible_area, py::handle hmd, py::handle eye_poses, int max_depth) {
            return walk(layout, poses, fps,
                        seen_view_of(size, ipd, fov, fov_angles, visible_area, hmd, eye_poses, max_depth));
        },
        py::arg("layout"), py::arg("poses"), py::arg("fps") = 90.0, py::kw_only(), py::arg("size") = py::none(),
        py::arg("ipd") = py::none(), py::arg("fov") = py::none(), py::arg("fov_angles") = py::none(),
        py::arg("visible_area") = py::none(), py::arg("hmd") = py::none(), py::arg("eye_poses") = py::none(),
        py::arg("max_depth") = 8, "Every frame of a walk as `impossible walk` prints it");
    m.def(
        "paired_at",
        [](const api::Layout& layout, py::handle poses, long long frame, double fps, py::handle size, py::handle ipd,
           py::handle fov, py::handle fov_angles, py::handle visible_area, py::handle hmd, py::handle eye_poses,
           int max_depth) {
            return paired_at(layout, poses, frame, fps,
                             seen_view_of(size, ipd, fov, fov_angles, visible_area, hmd, eye_poses, max_depth));
        },
        py::arg("layout"), py::arg("poses"), py::arg("frame"), py::arg("fps") = 90.0, py::kw_only(),
        py::arg("size") = py::none(), py::arg("ipd") = py::none(), py::arg("fov") = py::none(),
        py::arg("fov_angles") = py::none(), py::arg("visible_area") = py::none(), py::arg("hmd") = py::none(),
        py::arg("eye_poses") = py::none(), py::arg("max_depth") = 8,
        "The layout with the pairing in force at line `frame` of a walk (`render --path FILE --frame K`)");
    m.def("read_path", &read_path, py::arg("path"), py::arg("hands") = false,
          "The poses of a path file; with hands=True each line as written, 6 or 18 numbers");
    m.def("generate", &generate, py::arg("play_area"), py::arg("rooms"), py::arg("seed"),
          py::arg("max_overlap") = py::none(), "A random valid layout's JSON text (`impossible generate`)");
    m.def(
        "plan",
        [](const api::Layout& layout, py::handle path) {
            return value_or_raise(
                api::plan_svg(layout, path.is_none() ? std::vector<api::Pose>{} : poses_of(path, "path")));
        },
        py::arg("layout"), py::arg("path") = py::none(), "The SVG of `impossible plan`");
    m.def(
        "tour",
        [](const api::Layout& layout, double step, double head_height) {
            return tuples_of(value_or_raise(api::tour(layout, {step, head_height})));
        },
        py::arg("layout"), py::arg("step") = 0.05, py::arg("head_height") = 1.6,
        "A walk through every reachable room (`impossible tour`), as physical poses");
}

}  // namespace

PYBIND11_MODULE(impossible, m) {
    m.doc() = "impossible: impossible spaces (portal renderer, ray tracer, walker, designer's tools)";
    m.attr("__version__") = api::version();
    py::register_exception<Failure>(m, "Error", PyExc_ValueError);
    bind_layout(m);
    bind_renderer(m);
    bind_tools(m);
}
