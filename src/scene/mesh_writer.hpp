// Appends vertices and triangles to a Scene: the building block shared by the
// parts of build_scene (room faces, props, portal boxes).
//
// Positions arrive as float already (vertices that several surfaces share must
// be bitwise equal, so callers convert them once, with local()); normals and
// colours are computed in double and converted here.
#pragma once

#include <cassert>
#include <cstdint>
#include <limits>
#include <optional>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"
#include "shading/shading.hpp"

namespace impossible::scene {

// How a room face's vertices get texture coordinates: shading.hpp's
// room_texture_uv, less a whole number of tiles (`shift`, from the cell's
// origin) so that they stay small, and exact in float, far from the origin.
struct FaceUv {
    layout::Face face = layout::Face::Floor;
    double size = 1.0;
    glm::dvec2 shift{0.0};
};

struct MeshWriter {
    Scene& scene;
    glm::dvec3 origin{0.0};           // the current cell's CellOrigin::origin
    std::optional<FaceUv> face_uv{};  // set while a textured room face is written

    // A layout coordinate on `axis`, or a layout point, as a vertex coordinate.
    float local(double v, int axis) const { return static_cast<float>(v - origin[axis]); }
    glm::vec3 local(const glm::dvec3& p) const { return glm::vec3(p - origin); }
    // A vertex coordinate back in layout coordinates (exact).
    double world(float v, int axis) const { return static_cast<double>(v) + origin[axis]; }

    std::uint32_t vertex(const glm::vec3& position, const glm::dvec3& normal, const glm::dvec3& color, double checker) {
        glm::dvec2 uv(0.0);
        if (face_uv) {
            const glm::dvec3 p(world(position.x, 0), world(position.y, 1), world(position.z, 2));
            uv = shading::room_texture_uv(face_uv->face, p, face_uv->size) - face_uv->shift;
        }
        return vertex(position, normal, color, checker, uv, 1.0);
    }

    std::uint32_t vertex(const glm::vec3& position, const glm::dvec3& normal, const glm::dvec3& color, double checker,
                         const glm::dvec2& uv, double alpha) {
        assert(scene.vertices.size() < std::numeric_limits<std::uint32_t>::max());
        scene.vertices.push_back(Vertex{position, glm::vec3(normal), glm::vec3(color), static_cast<float>(checker),
                                        glm::vec2(uv), static_cast<float>(alpha)});
        return static_cast<std::uint32_t>(scene.vertices.size() - 1);
    }

    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        scene.indices.insert(scene.indices.end(), {a, b, c});
    }

    std::uint32_t index_count() const {
        assert(scene.indices.size() <= std::numeric_limits<std::uint32_t>::max());
        return static_cast<std::uint32_t>(scene.indices.size());
    }

    // The indices written since `first` (an earlier index_count()).
    IndexRange range_since(std::uint32_t first) const { return {first, index_count() - first}; }

    // The index of an image with a sampler in Scene::textures, added when new.
    int texture(const std::shared_ptr<const image::Pixels>& image, const assets::Sampler& sampler) {
        const auto same = [](const assets::Sampler& a, const assets::Sampler& b) {
            return a.mag_filter == b.mag_filter && a.min_filter == b.min_filter && a.wrap_s == b.wrap_s &&
                   a.wrap_t == b.wrap_t;
        };
        for (std::size_t i = 0; i < scene.textures.size(); ++i)
            if (scene.textures[i].image == image && same(scene.textures[i].sampler, sampler))
                return static_cast<int>(i);
        scene.textures.push_back({image, sampler});
        return static_cast<int>(scene.textures.size() - 1);
    }
};

// Appends a batch to a cell's list, merged into the last one when it follows
// it with the same state; empty ranges are dropped.
inline void add_batch(std::vector<DrawBatch>& batches, const DrawBatch& batch) {
    if (batch.range.count == 0) return;
    if (!batches.empty()) {
        DrawBatch& last = batches.back();
        if (last.same_state(batch) && last.range.first + last.range.count == batch.range.first) {
            last.range.count += batch.range.count;
            return;
        }
    }
    batches.push_back(batch);
}

// The in-plane axes (a, b) of a plane with normal ±e_axis, ordered so that
// e_a × e_b is the normal: a rectangle walked (a0,b0) → (a1,b0) → (a1,b1) →
// (a0,b1) is then counter-clockwise seen from the normal's side.
struct PlaneAxes {
    int a = 0;
    int b = 0;
};

inline PlaneAxes plane_axes(int axis, bool positive) {
    const int next = (axis + 1) % 3;  // cyclic: x → (y, z), y → (z, x), z → (x, y)
    const int last = (axis + 2) % 3;
    return positive ? PlaneAxes{next, last} : PlaneAxes{last, next};
}

// A point of that plane from its in-plane coordinates, in float.
inline glm::vec3 plane_point(int axis, float plane, PlaneAxes in, float a, float b) {
    glm::vec3 p(0.0f);
    p[axis] = plane;
    p[in.a] = a;
    p[in.b] = b;
    return p;
}

}  // namespace impossible::scene
