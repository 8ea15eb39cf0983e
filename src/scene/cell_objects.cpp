#include "scene/cell_objects.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>
#include <variant>

#include <glm/common.hpp>

#include "scene/mesh_writer.hpp"

namespace impossible::scene {

void bound_object(const Scene& scene, std::uint32_t first_vertex, const glm::dvec3& origin, CellObject& object) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::size_t v = first_vertex; v < scene.vertices.size(); ++v) {
        const glm::dvec3 p = glm::dvec3(scene.vertices[v].position) + origin;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 pad = 1e-6 + 1e-9 * glm::max(glm::abs(lo), glm::abs(hi));
    object.lo = lo - pad;
    object.hi = hi + pad;
}

namespace {

struct TreeBuilder {
    CellObjects& cell;

    void build(int first, int count) {
        const auto node_index = static_cast<std::size_t>(cell.nodes.size());
        cell.nodes.push_back({});
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        glm::dvec3 clo = lo, chi = hi;  // of the centres
        for (int i = first; i < first + count; ++i) {
            const CellObject& o = cell.objects[static_cast<std::size_t>(cell.order[static_cast<std::size_t>(i)])];
            lo = glm::min(lo, o.lo);
            hi = glm::max(hi, o.hi);
            const glm::dvec3 c = 0.5 * (o.lo + o.hi);
            clo = glm::min(clo, c);
            chi = glm::max(chi, c);
        }
        cell.nodes[node_index].lo = lo;
        cell.nodes[node_index].hi = hi;
        if (count <= kCullLeafSize) {
            cell.nodes[node_index].first = first;
            cell.nodes[node_index].count = count;
            return;
        }
        const glm::dvec3 extent = chi - clo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
        const auto begin = cell.order.begin() + first;
        const int half = count / 2;
        // Ties by index, so the tree does not depend on the sort's whims.
        std::nth_element(begin, begin + half, begin + count, [&](int a, int b) {
            const double ca =
                cell.objects[static_cast<std::size_t>(a)].lo[axis] + cell.objects[static_cast<std::size_t>(a)].hi[axis];
            const double cb =
                cell.objects[static_cast<std::size_t>(b)].lo[axis] + cell.objects[static_cast<std::size_t>(b)].hi[axis];
            return ca < cb || (ca == cb && a < b);
        });
        build(first, half);
        cell.nodes[node_index].first = static_cast<int>(cell.nodes.size());
        cell.nodes[node_index].count = 0;
        build(first + half, count - half);
    }
};

}  // namespace

void build_cull_tree(CellObjects& cell) {
    cell.nodes.clear();
    cell.order.resize(cell.objects.size());
    std::iota(cell.order.begin(), cell.order.end(), 0);
    if (cell.objects.empty()) return;
    TreeBuilder{cell}.build(0, static_cast<int>(cell.objects.size()));
}

std::vector<std::pair<glm::dvec3, glm::dvec3>> occluders_of(const layout::Room& room, const std::vector<bool>& skip) {
    struct Candidate {
        double area;
        std::size_t index;
        glm::dvec3 lo, hi;
    };
    std::vector<Candidate> found;
    for (std::size_t i = 0; i < room.props.size(); ++i) {
        const auto* box = std::get_if<layout::BoxProp>(&room.props[i]);
        if (box == nullptr) continue;  // a model need not be convex
        if (i < skip.size() && skip[i]) continue;
        const glm::dvec3 e = box->max - box->min;
        const double area = std::max({e.x * e.y, e.y * e.z, e.x * e.z});
        if (area < kMinOccluderArea) continue;
        const glm::dvec3 pad = 1e-6 + 1e-9 * glm::max(glm::abs(box->min), glm::abs(box->max));
        found.push_back({area, i, box->min + pad, box->max - pad});
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const Candidate& a, const Candidate& b) { return a.area > b.area; });
    if (found.size() > kMaxOccluders) found.resize(kMaxOccluders);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> out;
    for (const Candidate& c : found) out.emplace_back(c.lo, c.hi);
    return out;
}

std::vector<DrawBatch> finish_cell(Scene& scene, CellObjects& cell) {
    build_cull_tree(cell);
    std::vector<DrawBatch> merged;
    if (cell.objects.empty()) {
        for (const DrawBatch& b : cell.surfaces) add_batch(merged, b);
        return merged;
    }
    // The cell's indices, surfaces then objects as written, become objects
    // in leaf order then surfaces.
    const std::uint32_t begin =
        cell.surfaces.empty() ? cell.batches.front().range.first : cell.surfaces.front().range.first;
    std::vector<std::uint32_t> moved;
    moved.reserve(scene.indices.size() - begin);
    const auto move = [&](DrawBatch batch) {
        const auto from = scene.indices.begin() + batch.range.first;
        batch.range.first = begin + static_cast<std::uint32_t>(moved.size());
        moved.insert(moved.end(), from, from + batch.range.count);
        add_batch(merged, batch);
        return batch;
    };
    std::vector<CellObject> objects;
    std::vector<DrawBatch> batches;
    objects.reserve(cell.objects.size());
    batches.reserve(cell.batches.size());
    for (const int o : cell.order) {
        CellObject object = cell.objects[static_cast<std::size_t>(o)];
        const auto first_batch = static_cast<std::uint32_t>(batches.size());
        for (std::uint32_t b = object.first_batch; b < object.first_batch + object.batch_count; ++b)
            batches.push_back(move(cell.batches[b]));
        object.first_batch = first_batch;
        objects.push_back(object);
    }
    for (DrawBatch& b : cell.surfaces) b = move(b);
    assert(begin + moved.size() == scene.indices.size());
    std::copy(moved.begin(), moved.end(), scene.indices.begin() + begin);
    cell.objects = std::move(objects);
    cell.batches = std::move(batches);
    std::iota(cell.order.begin(), cell.order.end(), 0);
    return merged;
}

}  // namespace impossible::scene
