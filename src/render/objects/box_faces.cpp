#include "render/objects/box_faces.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace impossible::render {

double min_pixels_per_radian(const EyeView& eye, int width, int height) {
    const math::dmat4& m = eye.view_proj;
    const auto row = [&](int i) { return math::dvec3(m[0][i], m[1][i], m[2][i]); };
    const math::dvec3 w = row(3);
    const double w_norm = glm::length(w);
    if (!(w_norm > 0.0)) return 0.0;
    const math::dvec3 axis = w / w_norm;
    // Across the image, x_ndc = (r0 · u) / (w · u) for a direction u from the
    // eye: at the centre it turns by |r0 less its part along w| / |w| per
    // radian, and nowhere by less (the gnomonic projection only stretches).
    const auto density = [&](const math::dvec3& r, int pixels) {
        return glm::length(r - glm::dot(r, axis) * axis) / w_norm * 0.5 * pixels;
    };
    const double f = std::min(density(row(0), width), density(row(1), height));
    return std::isfinite(f) ? f : 0.0;
}

BoxFaceView box_face_view(const LevelView& view, int width, int height, int samples) {
    BoxFaceView bf;
    bf.width = width;
    bf.height = height;
    bf.samples = samples;
    for (std::size_t e = 0; e < 2; ++e) {
        const EyeView& ev = view.eyes[e];
        bf.pixels_per_radian[e] = min_pixels_per_radian(ev, width, height);
        bf.reach[e] = ev.active && !ev.rect.empty() ? intersect(widened(ev.rect, 2.0, width, height), NdcRect{})
                                                    : NdcRect::none();
    }
    return bf;
}

namespace {

// The faces of `faces` that the eye does not see from behind (box_front_faces).
unsigned bf_not_behind(const glm::dvec3& lo, const glm::dvec3& hi, const math::dvec3& p, double pixels_per_radian,
                       unsigned faces) {
    const glm::dvec3 extent = hi - lo;
    double far2 = 0.0;  // the farthest corner's squared distance
    for (int a = 0; a < 3; ++a) far2 += std::max((p[a] - lo[a]) * (p[a] - lo[a]), (p[a] - hi[a]) * (p[a] - hi[a]));
    unsigned out = 0;
    for (int a = 0; a < 3; ++a) {
        // The face's shorter side: its image is at least 0.7 · h · side /
        // far² radians thick for an eye h behind its plane.
        const double side = std::min(extent[(a + 1) % 3], extent[(a + 2) % 3]);
        for (const int positive : {0, 1}) {
            const unsigned bit = 1u << (2 * a + positive);
            if ((faces & bit) == 0) continue;
            const double plane = positive ? hi[a] : lo[a];
            const double behind = positive ? plane - p[a] : p[a] - plane;
            const double floor = kBackFaceMinDistance + 1e-6 * (std::abs(p[a]) + std::abs(plane));
            const bool back =
                behind > floor && 0.7 * behind * side * pixels_per_radian >= kBackFaceMinThicknessPx * far2;
            if (!back) out |= bit;
        }
    }
    return out;
}

// The faces lying in the eye's clip plane (every corner within the tracer's
// tolerance of it): "What a pixel shows" keeps only what lies strictly in
// front of the plane, so none of their fragments belongs in the image, but a
// clip distance of 0 give or take float rounding would keep some (a box
// standing on a floor seen from below through a trapdoor in it).
unsigned bf_in_plane(const glm::dvec3& lo, const glm::dvec3& hi, const math::dvec4& plane) {
    const glm::dvec3 n(plane.x, plane.y, plane.z);
    if (n == glm::dvec3(0.0)) return 0;  // no clip plane
    unsigned out = 0;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (const int positive : {0, 1}) {
            glm::dvec3 corner = lo;
            corner[a] = positive ? hi[a] : lo[a];
            bool in_plane = true;
            for (int k = 0; k < 4 && in_plane; ++k) {
                corner[b] = (k & 1) ? hi[b] : lo[b];
                corner[c] = (k & 2) ? hi[c] : lo[c];
                const double d = glm::dot(n, corner) + plane.w;
                in_plane = std::abs(d) <= 1e-9 * (1.0 + std::abs(plane.w) + glm::length(corner));
            }
            if (in_plane) out |= 1u << (2 * a + positive);
        }
    }
    return out;
}

// The faces of `faces` whose corners' image, within `reach`, holds a pixel
// centre; all of them when a corner is not in front of the eye.
unsigned bf_with_pixels(const glm::dvec3& lo, const glm::dvec3& hi, const EyeView& ev, const NdcRect& reach, int width,
                        int height, unsigned faces) {
    double x[8], y[8];
    for (int k = 0; k < 8; ++k) {
        const math::dvec3 c((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const math::dvec4 clip = ev.view_proj * math::dvec4(c, 1.0);
        if (!(clip.w > 1e-6)) return faces;
        x[k] = clip.x / clip.w;
        y[k] = clip.y / clip.w;
    }
    unsigned out = 0;
    for (int f = 0; f < 6; ++f) {
        if ((faces & (1u << f)) == 0) continue;
        const int axis = f / 2, side = f % 2;
        NdcRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
        for (int k = 0; k < 8; ++k) {
            if (((k >> axis) & 1) != side) continue;
            r = {std::min(r.x0, x[k]), std::min(r.y0, y[k]), std::max(r.x1, x[k]), std::max(r.y1, y[k])};
        }
        if (covers_pixel_centre(intersect(r, reach), width, height, 1)) out |= 1u << f;
    }
    return out;
}

}  // namespace

unsigned box_front_faces(const glm::dvec3& lo, const glm::dvec3& hi, const LevelView& view, const BoxFaceView& bf) {
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    unsigned seen = 0;
    int eyes = 0;
    for (std::size_t e = 0; e < 2; ++e) {
        const EyeView& ev = view.eyes[e];
        if (!ev.active || ev.rect.empty()) continue;
        ++eyes;
        const math::dvec3& p = ev.eye.position;
        unsigned faces = bf_not_behind(lo, hi, p, bf.pixels_per_radian[e], kAllBoxFaces);
        // A box that may look small: are its faces' images between pixel centres?
        const double d = glm::length(p - centre);
        const bool small = d > 2.0 * radius && 2.0 * radius / (d - radius) * bf.pixels_per_radian[e] < kSmallBoxPx;
        if (faces != 0 && bf.samples == 1 && small)
            faces = bf_with_pixels(lo, hi, ev, bf.reach[e], bf.width, bf.height, faces);
        seen |= faces;
    }
    return eyes == 0 ? kAllBoxFaces : seen;
}

unsigned faces_in_clip_planes(const glm::dvec3& box_min, const glm::dvec3& box_max, const LevelView& view) {
    unsigned out = kAllBoxFaces;
    int eyes = 0;
    for (const EyeView& ev : view.eyes) {
        if (!ev.active || ev.rect.empty()) continue;
        ++eyes;
        out &= bf_in_plane(box_min, box_max, ev.exit_plane);
    }
    return eyes == 0 ? 0u : out;
}

void append_box_faces(std::uint32_t first_vertex, unsigned faces, std::vector<std::uint32_t>& out) {
    for (std::uint32_t f = 0; f < 6; ++f) {
        if ((faces & (1u << f)) == 0) continue;
        const std::uint32_t v = first_vertex + 4 * f;  // v00, v10, v11, v01
        out.insert(out.end(), {v, v + 1, v + 2, v, v + 2, v + 3});
    }
}

std::uint32_t upload_faces(FaceStream& stream, GLuint buffer) {
    const std::size_t n = stream.pending.size();
    if (stream.used + n > stream.capacity) {
        // Re-specifying the store orphans the old one: draws already made
        // keep theirs.
        stream.capacity = std::max({2 * stream.capacity, stream.used + n, std::size_t{1} << 16});
        glNamedBufferData(buffer, static_cast<GLsizeiptr>(stream.capacity * sizeof(std::uint32_t)), nullptr,
                          GL_STREAM_DRAW);
        stream.used = 0;
    }
    const auto first = static_cast<std::uint32_t>(stream.used);
    if (n > 0)
        glNamedBufferSubData(buffer, static_cast<GLintptr>(stream.used * sizeof(std::uint32_t)),
                             static_cast<GLsizeiptr>(n * sizeof(std::uint32_t)), stream.pending.data());
    stream.used += n;
    stream.pending.clear();
    return first;
}

}  // namespace impossible::render
