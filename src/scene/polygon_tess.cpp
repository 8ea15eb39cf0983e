#include "scene/polygon_tess.hpp"

#include <GL/glu.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>

#include "math/polygon.hpp"

namespace impossible::scene {

namespace {

// What the callbacks fill (GLU passes it back as polygon data).
struct TessState {
    Tessellation out;
    std::vector<int> corners;  // vertex indices as GLU emits them, three per triangle
    bool failed = false;
};

// A vertex's index travels through GLU as its pointer value, plus one (so
// that index 0 is not a null pointer).
void* tess_tag(int index) { return reinterpret_cast<void*>(static_cast<std::intptr_t>(index) + 1); }
int tess_index(void* tag) { return static_cast<int>(reinterpret_cast<std::intptr_t>(tag) - 1); }

void GLAPIENTRY tess_begin(GLenum, void*) {}
void GLAPIENTRY tess_edge_flag(GLboolean, void*) {}  // its presence makes GLU emit GL_TRIANGLES only
void GLAPIENTRY tess_vertex(void* tag, void* state) {
    static_cast<TessState*>(state)->corners.push_back(tess_index(tag));
}
void GLAPIENTRY tess_end(void*) {}
void GLAPIENTRY tess_error(GLenum, void* state) { static_cast<TessState*>(state)->failed = true; }
void GLAPIENTRY tess_combine(GLdouble coords[3], void* [4], GLfloat[4], void** out, void* state) {
    TessState& s = *static_cast<TessState*>(state);
    s.out.points.push_back({coords[0], coords[1]});
    s.out.added += 1;
    *out = tess_tag(static_cast<int>(s.out.points.size()) - 1);
}

double tess_twice_area(const std::vector<glm::dvec2>& p, const std::array<int, 3>& t) {
    const glm::dvec2 a = p[static_cast<std::size_t>(t[0])];
    const glm::dvec2 b = p[static_cast<std::size_t>(t[1])];
    const glm::dvec2 c = p[static_cast<std::size_t>(t[2])];
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A sliver: a triangle whose corners lie on one line, to rounding (GLU
// joins three collinear points of an edge so). Its corner between the
// other two (opposite its longest edge), or -1 for a proper triangle.
int tess_sliver_middle(const std::vector<glm::dvec2>& p, const std::array<int, 3>& t) {
    double longest = 0.0;
    int middle = -1;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 e = p[static_cast<std::size_t>(t[(k + 2) % 3])] - p[static_cast<std::size_t>(t[(k + 1) % 3])];
        if (glm::dot(e, e) > longest) {
            longest = glm::dot(e, e);
            middle = k;
        }
    }
    return std::abs(tess_twice_area(p, t)) <= 1e-12 * longest ? middle : -1;
}

// Removes each sliver (a, m, b) with m between a and b by splitting the
// triangle across its edge a–b at m: (b, a, x) becomes (b, m, x) and
// (m, a, x). The outline's points on that edge then meet proper triangles
// only. A sliver left in place would hold the mesh together in exact
// arithmetic, but a rasteriser snaps vertices to its sub-pixel grid, which
// can turn it to face away and open a crack (a fuzzed turned room showed one
// pixel of nothing at the ceiling's edge). A sliver whose long edge has no
// neighbour is kept.
void remove_slivers(const std::vector<glm::dvec2>& p, std::vector<std::array<int, 3>>& tris) {
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t s = 0; s < tris.size() && !changed; ++s) {
            const int k = tess_sliver_middle(p, tris[s]);
            if (k < 0) continue;
            const int m = tris[s][static_cast<std::size_t>(k)];
            const int a = tris[s][static_cast<std::size_t>((k + 1) % 3)];
            const int b = tris[s][static_cast<std::size_t>((k + 2) % 3)];
            for (std::size_t n = 0; n < tris.size() && !changed; ++n) {
                for (std::size_t j = 0; j < 3 && n != s; ++j) {
                    if (tris[n][j] != b || tris[n][(j + 1) % 3] != a) continue;
                    const int x = tris[n][(j + 2) % 3];
                    tris[n] = {b, m, x};
                    tris[s] = {m, a, x};
                    changed = true;
                    break;
                }
            }
        }
    }
}

struct TessDeleter {
    void operator()(GLUtesselator* t) const { gluDeleteTess(t); }
};

void tess_callbacks(GLUtesselator* t) {
    const auto cb = [](auto f) { return reinterpret_cast<_GLUfuncptr>(f); };
    gluTessCallback(t, GLU_TESS_BEGIN_DATA, cb(&tess_begin));
    gluTessCallback(t, GLU_TESS_EDGE_FLAG_DATA, cb(&tess_edge_flag));
    gluTessCallback(t, GLU_TESS_VERTEX_DATA, cb(&tess_vertex));
    gluTessCallback(t, GLU_TESS_END_DATA, cb(&tess_end));
    gluTessCallback(t, GLU_TESS_ERROR_DATA, cb(&tess_error));
    gluTessCallback(t, GLU_TESS_COMBINE_DATA, cb(&tess_combine));
    gluTessProperty(t, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
    gluTessNormal(t, 0.0, 0.0, 1.0);
}

}  // namespace

Tessellation tessellate(const std::vector<std::vector<glm::dvec2>>& contours) {
    TessState state;
    std::vector<std::array<GLdouble, 3>> coords;  // GLU keeps pointers to these until the end
    for (const auto& contour : contours) {
        for (const glm::dvec2& p : contour) {
            state.out.points.push_back(p);
            coords.push_back({p.x, p.y, 0.0});
        }
    }
    const std::unique_ptr<GLUtesselator, TessDeleter> tess(gluNewTess());
    if (!tess) return {};
    tess_callbacks(tess.get());
    gluTessBeginPolygon(tess.get(), &state);
    // The outline counter-clockwise (winding +1 inside), the holes clockwise
    // (-1): the positive region is inside the outline and outside every hole,
    // even where a hole pokes out of the outline or holes overlap.
    int first = 0;
    for (std::size_t c = 0; c < contours.size(); ++c) {
        const auto& contour = contours[c];
        const bool reverse = (math::signed_area(contour) > 0.0) != (c == 0);
        const auto n = static_cast<int>(contour.size());
        gluTessBeginContour(tess.get());
        for (int k = 0; k < n; ++k) {
            const int index = first + (reverse ? n - 1 - k : k);
            gluTessVertex(tess.get(), coords[static_cast<std::size_t>(index)].data(), tess_tag(index));
        }
        gluTessEndContour(tess.get());
        first += n;
    }
    gluTessEndPolygon(tess.get());
    if (state.failed || state.corners.size() % 3 != 0) return {};

    for (std::size_t k = 0; k + 2 < state.corners.size(); k += 3) {
        std::array<int, 3> t = {state.corners[k], state.corners[k + 1], state.corners[k + 2]};
        // GLU emits counter-clockwise triangles about the normal (a sliver's
        // rounding may say otherwise: it is left as it is, and removed).
        if (tess_sliver_middle(state.out.points, t) < 0 && tess_twice_area(state.out.points, t) < 0.0)
            std::swap(t[1], t[2]);
        state.out.triangles.push_back(t);
    }
    remove_slivers(state.out.points, state.out.triangles);
    return std::move(state.out);
}

}  // namespace impossible::scene
