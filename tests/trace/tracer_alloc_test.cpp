// trace_ray allocates nothing: this program's operator new counts the
// allocations made on each thread, and rays through a model (its tree, with
// textured, masked and double-sided triangles), textured room faces, a prop
// box, a mirror, a door and a window make none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace {
thread_local long t_allocations = 0;
}  // namespace

// Every form that a plain operator delete may free is replaced, so that
// allocation and release always pair malloc with free (the standard library's
// temporary buffers use the nothrow form; AddressSanitizer checks the pairs).
void* operator new(std::size_t size) {
    ++t_allocations;
    if (void* p = std::malloc(size > 0 ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    ++t_allocations;
    return std::malloc(size > 0 ? size : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace impossible::trace {
namespace {

TEST(TracerAlloc, TraceRayAllocatesNothing) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(test::make_room("a", {-3, 0, -4}, {3, 3, 3}));
    l.rooms.push_back(test::make_room("b", {10, 0, -4}, {16, 3, 3}));
    layout::GltfProp model;
    model.position = {0.0, 1.0, -2.0};
    const double pi = std::acos(-1.0);
    // Materials: textured and masked (linear), double-sided (nearest).
    auto image = std::make_shared<image::Pixels>();
    image->width = 2;
    image->height = 2;
    image->data = {255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 255, 255, 255, 255, 255};
    model.textures.push_back({image, assets::Sampler{}});
    model.textures.push_back({image, assets::Sampler{assets::sampler_code::kNearest}});
    model.materials.resize(2);
    model.materials[0].texture = 0;
    model.materials[0].alpha_mode = assets::AlphaMode::Mask;
    model.materials[1].texture = 1;
    model.materials[1].double_sided = true;
    for (int i = 0; i < 40; ++i) {  // a fan of triangles facing +z
        const double a0 = 2.0 * pi * i / 40, a1 = 2.0 * pi * (i + 1) / 40;
        assets::ModelTriangle t;
        t.position = {dvec3(0.0), dvec3(std::cos(a0), std::sin(a0), 0.0), dvec3(std::cos(a1), std::sin(a1), 0.0)};
        t.normal = {dvec3(0, 0, 1), dvec3(0, 0, 1), dvec3(0, 0, 1)};
        t.uv = {glm::dvec2(0.5), glm::dvec2(std::cos(a0), std::sin(a0)), glm::dvec2(std::cos(a1), std::sin(a1))};
        t.material = i % 3 - 1;  // none, masked, double-sided
        model.triangles.push_back(t);
    }
    l.rooms[0].props.push_back(model);
    layout::BoxProp box;
    box.min = {1.0, 0.0, -1.0};
    box.max = {1.5, 1.0, -0.5};
    l.rooms[0].props.push_back(box);
    for (auto& face : l.rooms[0].face_texture) face = image;
    l.portals.push_back(test::make_mirror("mirror", 0, {0.0, 1.5, -4.0}, {0.0, 0.0, 1.0}, 5.0, 2.6));
    test::add_pair(l, test::make_window("w", 0, {-3.0, 1.5, 0.0}, {1, 0, 0}, 2.0, 2.0, {0.9, 0.9, 1.0}, 0.3),
                   test::make_window("w2", 1, {16.0, 1.5, 0.0}, {-1, 0, 0}, 2.0, 2.0, {0.9, 0.9, 1.0}, 0.3));
    test::add_pair(l, test::make_portal("d", 0, {0.0, 1.0, 3.0}, {0, 0, -1}),
                   test::make_portal("d2", 1, {13.0, 1.0, 3.0}, {0, 0, -1}));
    l.start.room = 0;
    const Scene scene = prepare_scene(l).value();
    ASSERT_FALSE(scene.rooms[0].bvh.nodes.empty());

    const dvec3 eye(0.5, 1.5, 1.0);
    int hits_model = 0;
    const long before = t_allocations;
    for (int i = 0; i < 60; ++i) {
        for (int j = 0; j < 30; ++j) {
            const double yaw = 2.0 * pi * i / 60, pitch = 0.9 * (j - 15) / 15.0;
            const dvec3 dir(std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw));
            const TraceHit hit = trace_ray(scene, eye, dir, 0, 8);
            if (hit.id == 1 && hit.normal == dvec3(0, 0, 1) && std::abs(hit.point.z + 2.0) < 1e-9) ++hits_model;
        }
    }
    EXPECT_EQ(t_allocations - before, 0);
    EXPECT_GT(hits_model, 0);
}

}  // namespace
}  // namespace impossible::trace
