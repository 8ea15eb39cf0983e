#include "trace/bvh.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace impossible::trace {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Padding, relative to the largest coordinate magnitude. A triangle's box is
// padded by kPad · max|coordinate of its vertices|, and each ray widens
// every box it tests by kPad · max|coordinate of its origin|. hit_triangle
// reports t and (u, v) from a 3×3 solve whose residual, the distance from
// origin + t · dir to the barycentric point (which lies in the triangle's
// box), is a few ulps of those magnitudes times the system's condition; and
// the slab test's own roundings are ulps of the same magnitudes. The padding
// is 10^7 ulps, so a hit the scan reports lies inside the widened box, at a
// parameter no smaller than the box's computed entry t: the tree skips no
// hit the scan would keep. It costs nothing measurable: 1 nm at 1 m.
constexpr double kPad = 1e-9;

// Bins per axis of the surface-area heuristic.
constexpr int kBins = 16;

double max_abs(const dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

struct Box {
    dvec3 lo{kInf};
    dvec3 hi{-kInf};

    void grow(const dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    // Half the surface area (the heuristic needs only ratios).
    double half_area() const {
        const dvec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

struct Item {
    Box box;       // padded
    dvec3 centre;  // of the box
};

Item padded(Item item) {
    const double pad = kPad * std::max(max_abs(item.box.lo), max_abs(item.box.hi));
    item.box.lo -= pad;
    item.box.hi += pad;
    item.centre = 0.5 * (item.box.lo + item.box.hi);
    return item;
}

Item item_of(const PropTriangle& t) {
    Item item;
    for (const dvec3& p : t.position) item.box.grow(p);
    return padded(item);
}

// A prop box's hit (hit_prop_box) lies on its surface, inside its padded
// bounds, as a triangle's lies in its own.
Item item_of(const PropBox& b) {
    Item item;
    item.box.grow(b.min);
    item.box.grow(b.max);
    return padded(item);
}

// Whether hit_triangle's t can stray far from the triangle (a needle or a
// sliver: twice its area below kSliver times its longest edge squared, the
// sine of its smallest angle below about kSliver). Its solve is then too
// ill-conditioned for any padding, and the tree leaves it out: it is tested
// on every ray, as the scan tests it. Zero-area triangles, which no ray
// hits, are slivers too. A model has few if any (the loader drops zero-area
// triangles).
constexpr double kSliver = 1e-6;

bool is_sliver(const PropTriangle& t) {
    const dvec3 e1 = t.position[1] - t.position[0], e2 = t.position[2] - t.position[0];
    const dvec3 e3 = t.position[2] - t.position[1];
    const double longest = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
    return !(glm::length(glm::cross(e1, e2)) > kSliver * longest);
}

class Builder {
public:
    Builder(const std::vector<Item>& items, Bvh& bvh) : items_(items), bvh_(bvh) {}

    // Builds the subtree over order[begin, end) at `depth`; returns its index.
    int build(int begin, int end, int depth) {
        const int index = static_cast<int>(bvh_.nodes.size());
        bvh_.nodes.emplace_back();
        Box bounds, centres;
        for (int i = begin; i < end; ++i) {
            const Item& item = items_[bvh_.order[i]];
            bounds.grow(item.box);
            centres.grow(item.centre);
        }
        bvh_.nodes[index].lo = bounds.lo;
        bvh_.nodes[index].hi = bounds.hi;
        const int count = end - begin;
        if (count <= kBvhLeafSize || depth >= kBvhMaxDepth) {
            bvh_.nodes[index].first = begin;
            bvh_.nodes[index].count = count;
            return index;
        }
        const int mid = split(begin, end, centres);
        build(begin, mid, depth + 1);
        const int second = build(mid, end, depth + 1);
        bvh_.nodes[index].first = second;
        return index;
    }

private:
    // The bin of a centre coordinate on an axis where the centres span
    // [lo, lo + extent], extent > 0: the lowest centre goes to the first bin,
    // the highest to the last.
    static int bin_of(double c, double lo, double scale) {
        return std::clamp(static_cast<int>((c - lo) * scale), 0, kBins - 1);
    }

    // Reorders order[begin, end) into two non-empty runs and returns where
    // the second starts: the binned split of least surface-area cost, ties
    // to the lower axis and plane; the middle of the list when all the
    // centres coincide. Both keep the order within each run.
    int split(int begin, int end, const Box& centres) {
        double best_cost = kInf;
        int best_axis = -1, best_plane = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = centres.hi[axis] - centres.lo[axis];
            if (!(extent > 0.0)) continue;
            const double scale = kBins / extent;
            std::array<Box, kBins> boxes;
            std::array<int, kBins> counts{};
            for (int i = begin; i < end; ++i) {
                const Item& item = items_[bvh_.order[i]];
                const int b = bin_of(item.centre[axis], centres.lo[axis], scale);
                boxes[b].grow(item.box);
                ++counts[b];
            }
            // right[k]: the bins k.. together.
            std::array<double, kBins> right_area{};
            std::array<int, kBins> right_count{};
            Box right;
            int n = 0;
            for (int k = kBins - 1; k > 0; --k) {
                right.grow(boxes[k]);
                n += counts[k];
                right_area[k] = n > 0 ? right.half_area() : 0.0;
                right_count[k] = n;
            }
            Box left;
            int m = 0;
            for (int k = 1; k < kBins; ++k) {
                left.grow(boxes[k - 1]);
                m += counts[k - 1];
                if (m == 0 || right_count[k] == 0) continue;
                const double cost = left.half_area() * m + right_area[k] * right_count[k];
                if (cost < best_cost) {
                    best_cost = cost;
                    best_axis = axis;
                    best_plane = k;
                }
            }
        }
        auto first = bvh_.order.begin() + begin, last = bvh_.order.begin() + end;
        if (best_axis < 0) return begin + (end - begin) / 2;
        const double lo = centres.lo[best_axis];
        const double scale = kBins / (centres.hi[best_axis] - lo);
        const auto mid = std::stable_partition(
            first, last, [&](int t) { return bin_of(items_[t].centre[best_axis], lo, scale) < best_plane; });
        return static_cast<int>(mid - bvh_.order.begin());
    }

    const std::vector<Item>& items_;
    Bvh& bvh_;
};

// The slab test against a node's box widened by `pad`: whether the ray meets
// it at some t ≥ 0 (within the roundings the padding covers), and where it
// enters (`t_enter`, possibly negative). An axis along which the ray does not
// move (1 / dir is infinite: dir is zero or subnormal there) is tested on the
// origin alone, so no 0 · ∞ ever makes a NaN.
struct RaySlabs {
    dvec3 origin;
    dvec3 inv;
    std::array<bool, 3> parallel;
    double pad;

    RaySlabs(const dvec3& o, const dvec3& dir) : origin(o), inv(1.0 / dir), pad(kPad * max_abs(o)) {
        for (int a = 0; a < 3; ++a) parallel[a] = std::isinf(inv[a]);
    }

    bool enters(const BvhNode& node, double& t_enter) const {
        double t_near = -kInf, t_far = kInf;
        for (int a = 0; a < 3; ++a) {
            const double lo = node.lo[a] - pad, hi = node.hi[a] + pad;
            if (parallel[a]) {
                if (origin[a] < lo || origin[a] > hi) return false;
                continue;
            }
            double t0 = (lo - origin[a]) * inv[a];
            double t1 = (hi - origin[a]) * inv[a];
            if (t0 > t1) std::swap(t0, t1);
            t_near = std::max(t_near, t0);
            t_far = std::min(t_far, t1);
        }
        t_enter = t_near;
        return t_near <= t_far && t_far >= 0.0;
    }
};

// Calls consider(index) for every item in a leaf the ray enters at a t no
// greater than best_t, which consider lowers as it finds hits: the nearer
// child first. A node is skipped only when the ray enters it beyond best_t:
// one it enters at best_t may still hold an item that ties with the best one
// and comes before it in the list. Allocates nothing.
template <class Consider>
void visit(const Bvh& bvh, const dvec3& origin, const dvec3& dir, const double& best_t, Consider&& consider) {
    const RaySlabs ray(origin, dir);
    double t_enter = 0.0;
    if (!ray.enters(bvh.nodes[0], t_enter) || t_enter > best_t) return;

    // Nodes still to visit, with their entry t. A node is pushed only while
    // its sibling is visited, at most one per level (depth ≤ kBvhMaxDepth).
    struct Pending {
        int node;
        double t;
    };
    std::array<Pending, kBvhMaxDepth + 1> stack;
    int pending = 0;
    int node = 0;
    for (;;) {
        const BvhNode& n = bvh.nodes[node];
        if (n.count > 0) {
            for (int k = n.first; k < n.first + n.count; ++k) consider(bvh.order[k]);
        } else {
            int a = node + 1, b = n.first;
            double ta = 0.0, tb = 0.0;
            const bool hit_a = ray.enters(bvh.nodes[a], ta) && ta <= best_t;
            const bool hit_b = ray.enters(bvh.nodes[b], tb) && tb <= best_t;
            if (hit_a && hit_b) {
                if (tb < ta) {  // the nearer first; equal: the first child
                    std::swap(a, b);
                    std::swap(ta, tb);
                }
                assert(pending < static_cast<int>(stack.size()));
                stack[pending++] = {b, tb};
                node = a;
                continue;
            }
            if (hit_a || hit_b) {
                node = hit_a ? a : b;
                continue;
            }
        }
        for (;;) {
            if (pending == 0) return;
            const Pending next = stack[--pending];
            if (next.t <= best_t) {
                node = next.node;
                break;
            }
        }
    }
}

// Keeps `hit` of item `index` if it is nearer than the best so far: the
// smallest t, and at equal t the lower index (the first the scan meets); a
// tie with the limit the search started from (best.index < 0) loses.
// `Best` is TriangleHit or BoxHit.
template <class Best>
void keep_nearer(Best& best, double& best_t, const std::optional<SurfaceHit>& hit, int index) {
    if (hit && (hit->t < best_t || (hit->t == best_t && best.index >= 0 && index < best.index))) {
        best_t = hit->t;
        best.hit = hit;
        best.index = index;
    }
}

// Builds the tree over bvh.order (the items not left out), if any.
void build_over(const std::vector<Item>& items, Bvh& bvh) {
    if (bvh.order.empty()) return;
    bvh.nodes.reserve(bvh.order.size());
    Builder(items, bvh).build(0, static_cast<int>(bvh.order.size()), 0);
}

}  // namespace

TriangleHit nearest_triangle_scan(const std::vector<PropTriangle>& triangles, std::span<const PropMaterial> materials,
                                  const dvec3& origin, const dvec3& dir, const ClipPlane& clip, double t_limit) {
    TriangleHit best;
    double best_t = t_limit;
    const int n = static_cast<int>(triangles.size());
    for (int i = 0; i < n; ++i) keep_nearer(best, best_t, hit_triangle(triangles[i], materials, origin, dir, clip), i);
    return best;
}

Bvh build_bvh(const std::vector<PropTriangle>& triangles) {
    Bvh bvh;
    std::vector<Item> items;
    items.reserve(triangles.size());
    for (int i = 0; i < static_cast<int>(triangles.size()); ++i) {
        items.push_back(item_of(triangles[i]));
        (is_sliver(triangles[i]) ? bvh.slivers : bvh.order).push_back(i);
    }
    build_over(items, bvh);
    return bvh;
}

TriangleHit nearest_triangle(const Bvh& bvh, const std::vector<PropTriangle>& triangles,
                             std::span<const PropMaterial> materials, const dvec3& origin, const dvec3& dir,
                             const ClipPlane& clip, double t_limit) {
    TriangleHit best;
    double best_t = t_limit;
    auto consider = [&](int index) {
        keep_nearer(best, best_t, hit_triangle(triangles[index], materials, origin, dir, clip), index);
    };
    for (int index : bvh.slivers) consider(index);
    if (bvh.nodes.empty()) return best;
    visit(bvh, origin, dir, best_t, consider);
    return best;
}

BoxHit nearest_box_scan(const std::vector<PropBox>& boxes, const dvec3& origin, const dvec3& dir, const ClipPlane& clip,
                        double t_limit) {
    BoxHit best;
    double best_t = t_limit;
    const int n = static_cast<int>(boxes.size());
    for (int i = 0; i < n; ++i) keep_nearer(best, best_t, hit_prop_box(boxes[i], origin, dir, clip), i);
    return best;
}

Bvh build_box_bvh(const std::vector<PropBox>& boxes) {
    Bvh bvh;
    std::vector<Item> items;
    items.reserve(boxes.size());
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        items.push_back(item_of(boxes[i]));
        bvh.order.push_back(i);
    }
    build_over(items, bvh);
    return bvh;
}

BoxHit nearest_box(const Bvh& bvh, const std::vector<PropBox>& boxes, const dvec3& origin, const dvec3& dir,
                   const ClipPlane& clip, double t_limit) {
    BoxHit best;
    double best_t = t_limit;
    if (bvh.nodes.empty()) return best;
    visit(bvh, origin, dir, best_t,
          [&](int index) { keep_nearer(best, best_t, hit_prop_box(boxes[index], origin, dir, clip), index); });
    return best;
}

}  // namespace impossible::trace
