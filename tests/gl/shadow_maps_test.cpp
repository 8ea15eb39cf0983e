// Cube shadow maps (render/lights/shadow_maps.hpp): what the maps hold, read back
// through shaders/shadow_lookup.frag.glsl's light_visible in a compute
// shader, for light images made by hand (so that these tests depend on the
// maps alone, not on the images' enumeration).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "base/embedded.hpp"
#include "gl/context.hpp"
#include "gl/shader.hpp"
#include "render/lights/shadow_maps.hpp"
#include "render/programs/gpu_scene.hpp"
#include "render/programs/scene_program.hpp"
#include "scene/scene.hpp"
#include "walk/objects.hpp"

#include "gl_fixture.hpp"

namespace impossible {
namespace {

// Reads, for light image g, the stored distance along each direction and
// light_visible(g, direction, d).
const char* const kShadowProbeSource = R"(
layout(local_size_x = 1) in;
// Per query two vec4s: p - L' and d; the cosine of incidence (0: none).
layout(std430, binding = 7) readonly buffer ShadowProbeQueries { vec4 q[]; };
layout(std430, binding = 8) writeonly buffer ShadowProbeResults { vec2 r[]; };
uniform int u_image;
void main() {
    uint i = gl_GlobalInvocationID.x;
    vec4 v = q[2 * i];
    float c = q[2 * i + 1].x;
    int layer = u_image < shadow_layer.length() ? shadow_layer[u_image] : -1;
    float stored = layer < 0 ? -1.0 : textureLod(u_shadow_maps, vec4(v.xyz, float(layer)), 0.0).r;
    r[i] = vec2(stored, c > 0.0 ? light_visible(u_image, v.xyz, v.w, c) : light_visible(u_image, v.xyz, v.w));
}
)";

struct ShadowProbeResult {
    float stored = 0.0f;   // the map's distance along the direction; -1: no map
    float visible = 0.0f;  // light_visible
};

// A scene on the GPU, its shadow maps and the probe.
struct ShadowRig {
    layout::Layout layout;
    scene::Scene scene;
    gl::Context context;
    render::GpuScene gpu;
    render::ShadowMaps maps;
    gl::Program probe;
    std::vector<walk::ObjectInstance> instances;
    std::vector<int> instance_mesh;

    explicit ShadowRig(const char* text) : ShadowRig(testing::layout_from_text(text)) {}
    explicit ShadowRig(layout::Layout l)
        : layout(std::move(l)),
          scene(scene::build_scene(layout)),
          context(std::move(gl::create_context(gl::Backend::Egl).value())),
          gpu(render::upload_scene(scene)) {
        const std::string lookup(embedded::find("shaders/shadow_lookup.frag.glsl"));
        probe =
            gl::build_program({{GL_COMPUTE_SHADER, "shadow_probe", lookup + kShadowProbeSource}}, "#define LIGHTS\n")
                .value();
    }

    // Places the dynamic objects at `time` (props only; no hands).
    void place(double time) {
        math::View view;
        view.time = time;
        instances = walk::place_objects(scene.object_set, view);
        instance_mesh.clear();
        for (const walk::ObjectInstance& inst : instances)
            for (size_t i = 0; i < scene.object_set.props.size(); ++i)
                if (scene.object_set.props[i].room == inst.listed_room && scene.object_set.props[i].index == inst.index)
                    instance_mesh.push_back(static_cast<int>(i));
    }

    int update(const std::vector<lights::RoomLights>& rooms, int size = 256) {
        render::ShadowSources s{.gpu = &gpu,
                                .objects = &scene.objects,
                                .origins = &scene.origins,
                                .object_meshes = &scene.object_meshes,
                                .instances = &instances,
                                .instance_mesh = &instance_mesh};
        render::FrameDesc frame;
        frame.shadow_map_size = size;
        Result<int> drawn = render::update_shadow_maps(maps, context.state(), s, rooms, frame);
        EXPECT_TRUE(drawn) << drawn.error();
        return drawn ? *drawn : -1;
    }

    // Light image g's map along each (p - L') direction, with d = |p - L'|,
    // and the cosine of incidence for the four-argument light_visible (none:
    // the three-argument one).
    std::vector<ShadowProbeResult> probe_at(int g, const std::vector<glm::dvec3>& offsets,
                                            const std::vector<double>& cosines = {}) {
        std::vector<float> queries;
        for (size_t k = 0; k < offsets.size(); ++k) {
            const glm::dvec3& v = offsets[k];
            const float c = k < cosines.size() ? float(cosines[k]) : 0.0f;
            queries.insert(queries.end(), {float(v.x), float(v.y), float(v.z), float(glm::length(v)), c, 0, 0, 0});
        }
        gl::Buffer in = gl::create_buffer(), out = gl::create_buffer();
        glNamedBufferData(in.get(), static_cast<GLsizeiptr>(queries.size() * sizeof(float)), queries.data(),
                          GL_STATIC_DRAW);
        glNamedBufferData(out.get(), static_cast<GLsizeiptr>(offsets.size() * 2 * sizeof(float)), nullptr,
                          GL_STATIC_READ);
        render::bind_shadow_maps(maps, context.state());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, in.get());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, out.get());
        context.state().program(probe.get());
        glProgramUniform1i(probe.get(), glGetUniformLocation(probe.get(), "u_image"), g);
        glDispatchCompute(static_cast<GLuint>(offsets.size()), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<ShadowProbeResult> results(offsets.size());
        glGetNamedBufferSubData(out.get(), 0, static_cast<GLsizeiptr>(results.size() * sizeof(ShadowProbeResult)),
                                results.data());
        context.state().release_bindings();
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return results;
    }
};

// A light of room `room` seen directly (no portals).
lights::LightImage shadow_direct_image(int room, const glm::dvec3& position) {
    lights::LightImage image;
    image.light_room = room;
    image.light = 0;
    image.position = position;
    image.rooms = {room};
    image.to_room = {math::dmat4(1.0)};
    return image;
}

// The distance along the unit direction `w` from `o` to the box, or +inf (a
// map holds a box prop's side facing the light: render/lights/shadow_maps.cpp).
double shadow_box_distance(const glm::dvec3& o, const glm::dvec3& w, const glm::dvec3& lo, const glm::dvec3& hi) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        const double ta = (lo[a] - o[a]) / w[a], tb = (hi[a] - o[a]) / w[a];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    return t0 <= t1 ? t0 : std::numeric_limits<double>::infinity();
}

const char* const kShadowBoxRoom = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [2, 1.6, 2] },
  "rooms": [ { "id": "a", "min": [-3, 0, -3], "max": [3, 3, 3],
    "props": [ { "box": { "min": [-0.5, 1.0, -0.4], "max": [0.6, 1.2, 0.5] } } ] } ] })";

TEST(ShadowMaps, ABoxsDistanceInTheMapMatchesTheCpusWithinATexel) {
    ShadowRig rig(kShadowBoxRoom);
    const glm::dvec3 light(0.1, 2.5, -0.2);
    const glm::dvec3 lo(-0.5, 1.0, -0.4), hi(0.6, 1.2, 0.5);
    lights::RoomLights room;
    room.images.push_back(shadow_direct_image(0, light));
    const int size = 256;
    EXPECT_EQ(rig.update({room}, size), 1);
    std::vector<glm::dvec3> offsets;
    for (int i = -4; i <= 4; ++i)
        for (int j = -4; j <= 4; ++j) offsets.push_back(glm::dvec3(0.17 * i, -2.5, 0.15 * j));  // to the floor
    offsets.push_back({2.0, 0.1, 0.3});                                                         // misses the box
    const std::vector<ShadowProbeResult> r = rig.probe_at(0, offsets);
    int under = 0;
    for (size_t k = 0; k < offsets.size(); ++k) {
        const double d = glm::length(offsets[k]);
        const double cpu = shadow_box_distance(light, offsets[k] / d, lo, hi);
        if (std::isinf(cpu)) {
            EXPECT_EQ(r[k].stored, render::kNoShadowOccluder) << k;
            EXPECT_EQ(r[k].visible, 1.0f) << k;
            continue;
        }
        // The texel's direction is within half a texel (1 / size at a face's
        // centre) of the query's; the top face is within 45° of head-on.
        EXPECT_NEAR(r[k].stored, cpu, 2.0 * cpu / size) << k;
        EXPECT_EQ(r[k].visible, 0.0f) << k;  // the floor point under the box
        ++under;
    }
    EXPECT_GT(under, 20);
    // Points on the box's lit top face are not shadowed by the face itself.
    const std::vector<ShadowProbeResult> top =
        rig.probe_at(0, {glm::dvec3(0.0, 1.2, 0.0) - light, glm::dvec3(0.5, 1.2, 0.4) - light});
    for (const ShadowProbeResult& t : top) EXPECT_EQ(t.visible, 1.0f);
}

// Room a's door a_n (in its wall) leads to b_s, standing free in the middle
// of room b: what a sees through the door is b's part in front of b_s
// (z < 0); b's part behind b_s maps into room a's own space. Prop "front" is
// in front of b_s, prop "behind" behind it.
const char* const kShadowDoorRooms = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [2, 1.6, 2] },
  "rooms": [
    { "id": "a", "min": [-3, 0, -3], "max": [3, 3, 3] },
    { "id": "b", "min": [10, 0, -3], "max": [16, 3, 3], "props": [
      { "id": "front", "box": { "min": [13.1, 2.0, -1.1], "max": [13.3, 2.2, -0.9] } },
      { "id": "behind", "box": { "min": [12.8, 0.5, 0.8], "max": [13.2, 0.8, 1.2] } } ] } ],
  "portals": [
    { "id": "a_n", "room": "a", "center": [0, 1.1, -3], "normal": [0, 0, 1], "width": 1.2, "height": 2.2,
      "target": "b_s" },
    { "id": "b_s", "room": "b", "center": [13, 1.1, 0], "normal": [0, 0, -1], "width": 1.2, "height": 2.2,
      "target": "a_n" } ] })";

// Light (13, 2.6, -2) of room b, as room a sees it through a_n.
std::vector<lights::RoomLights> shadow_door_lights(const ShadowRig& rig) {
    const math::dmat4 m = rig.scene.links.transfer[0];  // a's coordinates -> b's
    lights::LightImage image;
    image.light_room = 1;
    image.light = 0;
    image.position = glm::dvec3(glm::inverse(m) * glm::dvec4(13.0, 2.6, -2.0, 1.0));
    image.rooms = {0, 1};
    image.to_room = {math::dmat4(1.0), m};
    lights::Aperture door;
    door.rect = rig.layout.portals[0].rect;
    door.portal = 0;
    image.apertures = {door};
    lights::RoomLights a, b;
    a.images.push_back(image);
    return {a, b};
}

TEST(ShadowMaps, APropBeyondADoorShadowsAPointOfTheLitRoomThroughIt) {
    ShadowRig rig(kShadowDoorRooms);
    const glm::dvec4 door_in_b = rig.scene.links.transfer[0] * glm::dvec4(0.0, 1.1, -3.0, 1.0);
    ASSERT_NEAR(glm::distance(glm::dvec3(door_in_b), glm::dvec3(13.0, 1.1, 0.0)), 0.0, 1e-12);
    const std::vector<lights::RoomLights> rooms = shadow_door_lights(rig);
    const glm::dvec3 lprime = rooms[0].images[0].position;  // (0, 2.6, -5)
    EXPECT_EQ(rig.update(rooms), 1);
    // (0.8, 0.6, -1) is behind "front" (centre (0.2, 2.1, -4) in a's
    // coordinates) through the door; (-0.8, 0.6, -1) is not.
    const std::vector<ShadowProbeResult> r =
        rig.probe_at(0, {glm::dvec3(0.8, 0.6, -1.0) - lprime, glm::dvec3(-0.8, 0.6, -1.0) - lprime});
    EXPECT_EQ(r[0].visible, 0.0f);
    const glm::dvec3 w = glm::normalize(glm::dvec3(0.8, 0.6, -1.0) - lprime);
    const double cpu = shadow_box_distance(lprime, w, {0.1, 2.0, -4.1}, {0.3, 2.2, -3.9});  // "front" in a's
    EXPECT_NEAR(r[0].stored, cpu, 2.0 * cpu / 256);
    EXPECT_EQ(r[1].visible, 1.0f);
}

TEST(ShadowMaps, APropOutsideItsLegsSlabCastsNoShadow) {
    ShadowRig rig(kShadowDoorRooms);
    const std::vector<lights::RoomLights> rooms = shadow_door_lights(rig);
    const glm::dvec3 lprime = rooms[0].images[0].position;
    EXPECT_EQ(rig.update(rooms), 1);
    // The segment from L' to (0, 0, -1) meets "behind" mapped into a's
    // coordinates (x ±0.2, y 0.5..0.8, z -2.2..-1.8) at z = -2, in a's own
    // space: the last leg runs behind the door only, so it casts nothing.
    const std::vector<ShadowProbeResult> r = rig.probe_at(0, {glm::dvec3(0.0, 0.0, -1.0) - lprime});
    EXPECT_EQ(r[0].visible, 1.0f);
    EXPECT_EQ(r[0].stored, render::kNoShadowOccluder);
}

const char* const kShadowMovingRoom = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [2, 1.6, 2] },
  "rooms": [ { "id": "a", "min": [-3, 0, -3], "max": [3, 3, 3], "props": [
    { "box": { "min": [-2.5, 0, -2.5], "max": [-2, 0.5, -2] } },
    { "id": "slider", "box": { "min": [-0.3, 1.0, -0.3], "max": [0.3, 1.2, 0.3] },
      "motion": { "path": [[0, 0, 0, 0], [2, 1, 0, 0]], "loop": true } } ] } ] })";

TEST(ShadowMaps, AStaticLayoutDrawsItsMapsOnceAndAMovingPropRedrawsThem) {
    {
        ShadowRig rig(kShadowBoxRoom);
        lights::RoomLights room;
        room.images.push_back(shadow_direct_image(0, {0.0, 2.5, 0.0}));
        EXPECT_EQ(rig.update({room}), 1);
        EXPECT_EQ(rig.update({room}), 0);
        EXPECT_EQ(rig.update({room}, 128), 1);  // another size
        room.images[0].position.x = 0.5;        // the light's image moved (another light depth, say)
        EXPECT_EQ(rig.update({room}, 128), 1);
        EXPECT_EQ(rig.update({room}, 128), 0);
    }
    ShadowRig rig(kShadowMovingRoom);
    ASSERT_EQ(rig.scene.object_set.props.size(), 1u);
    lights::RoomLights room;
    room.images.push_back(shadow_direct_image(0, {0.0, 2.5, 0.0}));
    rig.place(0.0);
    ASSERT_EQ(rig.instances.size(), 1u);
    EXPECT_EQ(rig.update({room}), 1);
    const glm::dvec3 down(0.0, -2.5, 0.0);
    EXPECT_EQ(rig.probe_at(0, {down})[0].visible, 0.0f);  // under the prop at x = 0
    rig.place(0.0);
    EXPECT_EQ(rig.update({room}), 0);
    rig.place(1.0);  // moved by 0.5 along x
    EXPECT_EQ(rig.update({room}), 1);
    EXPECT_EQ(rig.probe_at(0, {down})[0].visible, 1.0f);
    EXPECT_EQ(rig.probe_at(0, {glm::dvec3(0.5, -2.5, 0.0)})[0].visible, 0.0f);
}

// A long slab lit at grazing incidence: with the cosine of incidence the
// bias grows with the slope, so that the slab's top is not shadowed by
// itself at 80° and more; the floor under it stays shadowed.
TEST(ShadowMaps, AFaceLitAtGrazingIncidenceIsNotShadowedByItself) {
    ShadowRig rig(R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "a", "position": [2, 1.6, 2] },
      "rooms": [ { "id": "a", "min": [-3, 0, -3], "max": [3, 3, 3],
        "props": [ { "box": { "min": [-2.5, 1.0, -0.5], "max": [2.5, 1.2, 0.5] } } ] } ] })");
    const glm::dvec3 light(0.0, 1.35, 0.0);
    lights::RoomLights room;
    room.images.push_back(shadow_direct_image(0, light));
    for (const int size : {128, 512}) {
        EXPECT_EQ(rig.update({room}, size), 1);
        std::vector<glm::dvec3> offsets;
        std::vector<double> cosines;
        for (int k = 0; k <= 40; ++k) {  // x = 0.8 .. 2.4, z = -0.4 .. 0.4: incidence 79° to 86°
            const glm::dvec3 p(0.8 + 0.04 * k, 1.2, -0.4 + 0.02 * k);
            offsets.push_back(p - light);
            cosines.push_back(glm::normalize(light - p).y);
        }
        const glm::dvec3 floor(1.0, 0.0, 0.1);
        offsets.push_back(floor - light);
        cosines.push_back(glm::normalize(light - floor).y);
        const std::vector<ShadowProbeResult> r = rig.probe_at(0, offsets, cosines);
        for (size_t k = 0; k + 1 < r.size(); ++k) EXPECT_EQ(r[k].visible, 1.0f) << size << " point " << k;
        EXPECT_EQ(r.back().visible, 0.0f) << size;
    }
}

// A glTF quad (x -1.5..1.5, y 0.5..2.5 at z = -1.5, facing +z, double-sided
// so that it blocks the light in front of it) textured 2×2 with alpha 1, 0
// (top right), 1, 0.5 (bottom right) and cutoff 0.6: light passes its cut-out
// quadrants.
TEST(ShadowMaps, AlphaCutOutsLetLightThrough) {
    layout::Layout l = testing::layout_from_text(kShadowBoxRoom);
    l.rooms[0].props.clear();
    layout::GltfProp prop;
    prop.path = prop.resolved_path = "<quad>";
    const glm::dvec3 bl(-1.5, 0.5, -1.5), br(1.5, 0.5, -1.5), tr(1.5, 2.5, -1.5), tl(-1.5, 2.5, -1.5);
    const auto tri = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec2 ua, glm::dvec2 ub, glm::dvec2 uc) {
        assets::ModelTriangle t;
        t.position = {a, b, c};
        t.normal = {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)};
        t.uv = {ua, ub, uc};
        t.color = glm::dvec3(1.0);
        t.material = 0;
        prop.triangles.push_back(t);
    };
    tri(bl, br, tr, {0, 1}, {1, 1}, {1, 0});
    tri(bl, tr, tl, {0, 1}, {1, 0}, {0, 0});
    auto image = std::make_shared<image::Pixels>();
    image->width = image->height = 2;
    image->data = {255, 255, 255, 255, 255, 255, 255, 0, 255, 255, 255, 255, 255, 255, 255, 128};
    assets::Texture texture;
    texture.image = image;
    texture.sampler.mag_filter = assets::sampler_code::kNearest;
    texture.sampler.min_filter = assets::sampler_code::kNearest;
    prop.textures.push_back(texture);
    assets::Material m;
    m.texture = 0;
    m.alpha_mode = assets::AlphaMode::Mask;
    m.alpha_cutoff = 0.6;
    m.double_sided = true;
    prop.materials.push_back(m);
    l.rooms[0].props.push_back(prop);
    ShadowRig rig(l);
    const glm::dvec3 light(0.0, 1.5, 1.0);
    lights::RoomLights room;
    room.images.push_back(shadow_direct_image(0, light));
    EXPECT_EQ(rig.update({room}), 1);
    // Behind each quadrant's centre, on the wall at z = -3.
    const glm::dvec3 centres[4] = {{-0.75, 2.0, -1.5}, {0.75, 2.0, -1.5}, {-0.75, 1.0, -1.5}, {0.75, 1.0, -1.5}};
    std::vector<glm::dvec3> offsets;
    for (const glm::dvec3& c : centres) offsets.push_back(2.0 * (c - light));
    const std::vector<ShadowProbeResult> r = rig.probe_at(0, offsets);
    const float quad = static_cast<float>(glm::length(centres[0] - light));
    EXPECT_NEAR(r[0].stored, quad, 0.02f);
    EXPECT_EQ(r[0].visible, 0.0f);
    EXPECT_EQ(r[1].stored, render::kNoShadowOccluder);  // alpha 0
    EXPECT_EQ(r[1].visible, 1.0f);
    EXPECT_NEAR(r[2].stored, quad, 0.02f);
    EXPECT_EQ(r[3].stored, render::kNoShadowOccluder);  // alpha 0.5 < 0.6
}

// More images with props than a cube map array holds (GL_MAX_ARRAY_TEXTURE_LAYERS
// / 6): the first ones get maps, the rest none (lit through props), and GL
// reports no error.
TEST(ShadowMaps, ImagesPastTheArraysLayersHaveNoMap) {
    ShadowRig rig(kShadowBoxRoom);
    GLint layers = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
    const int max_maps = layers / 6;
    lights::RoomLights room;
    for (int k = 0; k < max_maps + 5; ++k) room.images.push_back(shadow_direct_image(0, {0.001 * k, 2.5, 0.0}));
    EXPECT_EQ(rig.update({room}, 16), max_maps);
    EXPECT_EQ(rig.maps.capacity, max_maps);
    EXPECT_EQ(rig.maps.layer[static_cast<size_t>(max_maps - 1)], max_maps - 1);
    EXPECT_EQ(rig.maps.layer[static_cast<size_t>(max_maps)], -1);
    const glm::dvec3 down(0.0, -2.5, 0.0);
    EXPECT_EQ(rig.probe_at(max_maps - 1, {down})[0].visible, 0.0f);
    EXPECT_EQ(rig.probe_at(max_maps, {down})[0].visible, 1.0f);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ShadowMaps, TheMapsMemoryIsCappedByLoweringTheSize) {
    EXPECT_EQ(render::shadow_map_size_for(512, 1), 512);
    EXPECT_EQ(render::shadow_map_size_for(4096, 1), 2048);  // 6 · 4096² · 4 bytes = 384 MiB
    EXPECT_EQ(render::shadow_map_size_for(512, 100), 256);
    EXPECT_EQ(render::shadow_map_size_for(512, 100000), render::kMinShadowMapSize);
    for (const std::size_t maps : {1u, 7u, 42u, 170u})
        EXPECT_LE(maps * 6 * std::size_t(render::shadow_map_size_for(1024, maps)) *
                      std::size_t(render::shadow_map_size_for(1024, maps)) * 4,
                  render::kMaxShadowMapBytes);
}

}  // namespace
}  // namespace impossible
