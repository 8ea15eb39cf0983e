// Triangle soups for the bounding-volume hierarchy's tests (bvh_test.cpp,
// bvh_tree_test.cpp).
#pragma once

#include <algorithm>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "trace/bvh.hpp"
#include "trace/trace_test_util.hpp"

namespace impossible::trace::test {

// A triangle with its flat normal at every corner (+y when it has no area).
inline PropTriangle triangle(dvec3 a, dvec3 b, dvec3 c) {
    PropTriangle t;
    t.position = {a, b, c};
    const dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    const dvec3 unit = len > 0.0 ? n / len : dvec3(0.0, 1.0, 0.0);
    t.normal = {unit, unit, unit};
    return t;
}

// A flat grid of squares on integer multiples of `step` (exact in binary),
// in the plane p[axis] = coord, two triangles a square, facing +axis or
// -axis: shared edges and vertices, and rays down the axis meet several
// triangles at exactly the same t.
inline void add_grid(std::vector<PropTriangle>& out, int axis, double coord, double sign, int cells, double step) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    auto at = [&](int i, int j) {
        dvec3 p(0.0);
        p[axis] = coord;
        p[b] = (i - cells / 2) * step;
        p[c] = (j - cells / 2) * step;
        return p;
    };
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            const dvec3 p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
            if (sign > 0.0) {  // (b, c) counter-clockwise seen from +axis
                out.push_back(triangle(p00, p10, p11));
                out.push_back(triangle(p00, p11, p01));
            } else {
                out.push_back(triangle(p00, p11, p10));
                out.push_back(triangle(p00, p01, p11));
            }
        }
    }
}

// A soup of every kind of trouble: random triangles of all sizes, flat
// axis-aligned grids facing both ways (coplanar, shared edges and
// vertices), exact duplicates scattered through the list, zero-area
// (collinear or coincident vertices) and needle triangles, and a far-off
// cluster; then shuffled, so that duplicates land in both orders.
inline std::vector<PropTriangle> adversarial_soup(std::mt19937_64& rng, dvec3 offset, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto point = [&] { return offset + scale * dvec3(u(rng), u(rng), u(rng)); };
    std::vector<PropTriangle> soup;
    for (int k = 0; k < 200; ++k) {  // random, large
        soup.push_back(triangle(point(), point(), point()));
    }
    for (int k = 0; k < 200; ++k) {  // random, small
        const dvec3 c = point();
        const double s = 0.05 * scale;
        soup.push_back(triangle(c + s * dvec3(u(rng), u(rng), u(rng)), c + s * dvec3(u(rng), u(rng), u(rng)),
                                c + s * dvec3(u(rng), u(rng), u(rng))));
    }
    std::vector<PropTriangle> grids;
    add_grid(grids, 1, 0.0, 1.0, 8, 0.25);    // y = 0, facing up
    add_grid(grids, 1, 0.0, -1.0, 8, 0.25);   // the same plane, facing down
    add_grid(grids, 0, 0.5, 1.0, 6, 0.25);    // x = 0.5, facing +x
    add_grid(grids, 2, -0.75, -1.0, 6, 0.5);  // z = -0.75, facing -z
    add_grid(grids, 1, 0.0, 1.0, 4, 0.5);     // y = 0 again, coarser: overlapping coplanar triangles
    for (PropTriangle& t : grids) {
        for (dvec3& p : t.position) p = offset + scale * p;
        soup.push_back(t);
    }
    const size_t before = soup.size();
    for (int k = 0; k < 150; ++k) soup.push_back(soup[rng() % before]);  // duplicates
    for (int k = 0; k < 40; ++k) {                                       // degenerate
        const dvec3 a = point(), b = point();
        soup.push_back(triangle(a, b, 0.5 * (a + b)));                                         // collinear
        soup.push_back(triangle(a, a, b));                                                     // two vertices the same
        soup.push_back(triangle(a, a, a));                                                     // a point
        soup.push_back(triangle(a, b, a + 1e-12 * (b - a) + dvec3(0.0, 1e-13 * scale, 0.0)));  // a needle
    }
    std::shuffle(soup.begin(), soup.end(), rng);
    return soup;
}

}  // namespace impossible::trace::test
