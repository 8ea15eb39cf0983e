// The node walk of a glTF model: each node's transform, checked, and the
// instances of meshes in the default scene's tree.
#include <algorithm>
#include <cmath>

#include "assets/gltf_import.hpp"

namespace impossible::assets {

namespace {

bool all_finite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// Translations are coordinates (|t| <= 100 km) and scale factors are bounded
// like a prop's scale (|s| <= 1e6). `who` is "has node N".
Result<void> check_node_scale(const std::string& who, double v, const char* field) {
    if (std::abs(v) > limits::kMaxScale) {
        return Error{who + " whose " + field + " holds " + format_number(v) + ", beyond the scale limit of " +
                     format_number(limits::kMaxScale)};
    }
    return {};
}

Result<void> check_node_translation(const std::string& who, double v, const char* field) {
    if (std::abs(v) > limits::kMaxCoordinate) {
        return Error{who + " whose " + field + " holds " + format_number(v) + ", " + beyond_coordinate_limit()};
    }
    return {};
}

// A node's `matrix` (16 numbers, column-major), checked.
Result<glm::dmat4> matrix_transform(const tinygltf::Node& node, const std::string& who) {
    if (node.matrix.size() != 16) {
        return Error{who + " whose matrix does not have 16 numbers"};
    }
    glm::dmat4 m(1.0);
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node.matrix[static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            if (Result<void> ok = check_node_scale(who, m[c][r], "matrix"); !ok) return ok;
        }
        if (Result<void> ok = check_node_translation(who, m[3][c], "matrix translation"); !ok) return ok;
    }
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) {
        return Error{who + " whose matrix is not affine (its last row must be 0, 0, 0, 1)"};
    }
    return m;
}

// The rotation matrix of a node's `rotation` (x, y, z, w), normalized.
Result<glm::dmat4> rotation_transform(const std::vector<double>& q, const std::string& who) {
    double x = q[0], y = q[1], z = q[2], w = q[3];
    const double length = std::sqrt(x * x + y * y + z * z + w * w);
    if (!(length > 1e-12) || !std::isfinite(length)) {
        return Error{who + " whose rotation is not a unit quaternion"};
    }
    x /= length, y /= length, z /= length, w /= length;
    glm::dmat4 r(1.0);
    // Columns of the rotation matrix of the quaternion (x, y, z, w).
    r[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y), 0);
    r[1] = glm::dvec4(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x), 0);
    r[2] = glm::dvec4(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y), 0);
    return r;
}

// translation · rotation · scale, each optional, checked.
Result<glm::dmat4> trs_transform(const tinygltf::Node& node, const std::string& who) {
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) || (!node.scale.empty() && node.scale.size() != 3)) {
        return Error{who + " whose translation, rotation or scale has the wrong number of values"};
    }
    for (double v : node.translation) {
        if (Result<void> ok = check_node_translation(who, v, "translation"); !ok) return ok;
    }
    for (double v : node.scale) {
        if (Result<void> ok = check_node_scale(who, v, "scale"); !ok) return ok;
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) {
        t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (!node.rotation.empty()) {
        const Result<glm::dmat4> rotation = rotation_transform(node.rotation, who);
        if (!rotation) return rotation;
        r = *rotation;
    }
    if (!node.scale.empty()) {
        s[0][0] = node.scale[0], s[1][1] = node.scale[1], s[2][2] = node.scale[2];
    }
    return t * r * s;
}

// The node's local transform: its matrix, or translation · rotation · scale.
// Bounded (see check_node_scale), so a finite but absurd node (a matrix of
// 1e300) is an error naming it rather than triangles that overflow.
Result<glm::dmat4> local_transform(const tinygltf::Node& node, int index) {
    const std::string who = "has node " + std::to_string(index);
    if (!all_finite(node.matrix) || !all_finite(node.translation) || !all_finite(node.rotation) ||
        !all_finite(node.scale)) {
        return Error{who + " with a non-finite transform"};
    }
    if (!node.matrix.empty()) return matrix_transform(node, who);
    return trs_transform(node, who);
}

// The default scene's root nodes; every node that is no child when the
// file has no scene.
Result<std::vector<int>> scene_roots(const tinygltf::Model& model) {
    if (!model.scenes.empty()) {
        int scene = model.defaultScene < 0 ? 0 : model.defaultScene;
        if (static_cast<std::size_t>(scene) >= model.scenes.size()) {
            return Error{"names default scene " + std::to_string(scene) + ", which does not exist"};
        }
        return model.scenes[static_cast<std::size_t>(scene)].nodes;
    }
    const std::size_t node_count = model.nodes.size();
    std::vector<bool> is_child(node_count, false);
    for (const tinygltf::Node& node : model.nodes) {
        for (int c : node.children) {
            if (c >= 0 && static_cast<std::size_t>(c) < node_count) is_child[static_cast<std::size_t>(c)] = true;
        }
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < node_count; ++i) {
        if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
}

}  // namespace

Result<std::vector<MeshInstance>> collect_instances(const tinygltf::Model& model, std::vector<LightInstance>& lights) {
    std::vector<MeshInstance> out;
    const std::size_t node_count = model.nodes.size();
    const Result<std::vector<int>> roots = scene_roots(model);
    if (!roots) return roots;
    struct Item {
        int node;
        glm::dmat4 parent;
        std::size_t depth;
    };
    std::vector<Item> stack;
    for (auto it = roots->rbegin(); it != roots->rend(); ++it) stack.push_back({*it, glm::dmat4(1.0), 1});
    std::vector<bool> visited(node_count, false);
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || static_cast<std::size_t>(item.node) >= node_count) {
            return Error{"refers to node " + std::to_string(item.node) + ", which does not exist"};
        }
        const auto index = static_cast<std::size_t>(item.node);
        if (visited[index]) {
            return Error{"reaches node " + std::to_string(item.node) + " twice (its nodes must form a tree)"};
        }
        visited[index] = true;
        if (item.depth > limits::kMaxNodeDepth) {
            return Error{"has nodes nested deeper than " + std::to_string(limits::kMaxNodeDepth) + " levels"};
        }
        const tinygltf::Node& node = model.nodes[index];
        const Result<glm::dmat4> local = local_transform(node, item.node);
        if (!local) return local;
        const glm::dmat4 world = item.parent * *local;
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= model.meshes.size()) {
                return Error{"refers to mesh " + std::to_string(node.mesh) + ", which does not exist"};
            }
            out.push_back({item.node, node.mesh, world});
        }
        if (const auto ext = node.extensions.find("KHR_lights_punctual"); ext != node.extensions.end()) {
            if (ext->second.IsObject() && ext->second.Has("light")) {
                lights.push_back({item.node, &ext->second.Get("light"), world});
            }
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) {
            stack.push_back({*c, world, item.depth + 1});
        }
    }
    return out;
}

}  // namespace impossible::assets
