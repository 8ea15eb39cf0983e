#include "render/lights/shadow_maps.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/shader.hpp"
#include "math/projection.hpp"
#include "render/lights/shadow_regions.hpp"
#include "render/objects/frame_objects.hpp"
#include "render/programs/scene_program.hpp"
#include "render/scene_data.hpp"

namespace impossible::render {
namespace {

// What a light image's map is drawn from: its legs (room, C -> room) and
// slab planes, and the dynamic objects placed in those rooms.
struct ShadowLeg {
    int room = -1;
    math::dmat4 from_room{1.0};  // the leg's room's coordinates -> L'-relative ones of C
    std::array<math::dvec4, 2> slab{math::dvec4(0.0, 0.0, 0.0, 1.0), math::dvec4(0.0, 0.0, 0.0, 1.0)};
};

// Keep d >= 0 in front of (front = true) or behind an aperture, as a plane
// in L'-relative coordinates.
math::dvec4 shadow_aperture_plane(const lights::Aperture& a, const math::dvec3& lprime, bool front) {
    const math::dvec3 n = front ? a.rect.normal : -a.rect.normal;
    return {n, glm::dot(n, lprime - a.rect.center)};
}

std::vector<ShadowLeg> shadow_legs_of(const lights::LightImage& image) {
    std::vector<ShadowLeg> legs(image.rooms.size());
    const math::dmat4 to_relative = glm::translate(math::dmat4(1.0), -image.position);
    for (size_t i = 0; i < legs.size(); ++i) {
        legs[i].room = image.rooms[i];
        legs[i].from_room = to_relative * glm::inverse(image.to_room[i]);
        if (i < image.apertures.size())
            legs[i].slab[0] = shadow_aperture_plane(image.apertures[i], image.position, true);
        if (i > 0) legs[i].slab[1] = shadow_aperture_plane(image.apertures[i - 1], image.position, false);
    }
    return legs;
}

// Per room, the frame's instances drawn in it.
std::vector<std::vector<int>> shadow_instances_by_room(const ShadowSources& s) {
    std::vector<std::vector<int>> by_room(s.objects->size());
    for (size_t i = 0; i < s.instances->size(); ++i) {
        const int cell = (*s.instances)[i].cell;
        if (links::valid_index(cell, by_room.size())) by_room[static_cast<size_t>(cell)].push_back(static_cast<int>(i));
    }
    return by_room;
}

bool shadow_has_occluders(const ShadowSources& s, const std::vector<std::vector<int>>& by_room,
                          const lights::LightImage& image) {
    for (const int room : image.rooms) {
        const auto r = static_cast<size_t>(room);
        if (!(*s.objects)[r].batches.empty() || !by_room[r].empty()) return true;
    }
    return false;
}

void shadow_key_push(std::vector<double>& key, const math::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) key.push_back(m[c][r]);
}

// Everything a map depends on: equal keys, equal maps.
std::vector<double> shadow_key_of(const ShadowSources& s, const std::vector<std::vector<int>>& by_room,
                                  const lights::LightImage& image, int size) {
    std::vector<double> key = {double(size), image.position.x, image.position.y, image.position.z};
    for (size_t i = 0; i < image.rooms.size(); ++i) {
        key.push_back(image.rooms[i]);
        shadow_key_push(key, image.to_room[i]);
        for (const int k : by_room[static_cast<size_t>(image.rooms[i])]) {
            const walk::ObjectInstance& inst = (*s.instances)[static_cast<size_t>(k)];
            key.push_back((*s.instance_mesh)[static_cast<size_t>(k)]);
            shadow_key_push(key, inst.to_cell);
            key.push_back(inst.cut_count);
            for (int c = 0; c < inst.cut_count; ++c)
                for (int j = 0; j < 4; ++j) key.push_back(inst.cuts[static_cast<size_t>(c)].plane[j]);
        }
    }
    for (const lights::Aperture& a : image.apertures) {
        key.insert(key.end(), {a.rect.center.x, a.rect.center.y, a.rect.center.z});
        key.insert(key.end(), {a.rect.normal.x, a.rect.normal.y, a.rect.normal.z});
    }
    return key;
}

Result<void> ensure_shadow_program(ShadowMaps& m) {
    if (m.program) return {};
    std::vector<gl::ShaderSource> stages = {embedded_shader(GL_VERTEX_SHADER, "shaders/shadow_map.vert.glsl"),
                                            embedded_shader(GL_FRAGMENT_SHADER, "shaders/shadow_map.frag.glsl")};
    Result<gl::Program> built = gl::build_program(stages, "");
    if (!built) return Error{built.error()};
    m.program = std::move(*built);
    gl::UniformLocations u(m.program.get(), gl::program_name(stages));
    m.model = u.required("u_model");
    m.face_proj = u.required("u_face_proj");
    m.planes = u.required("u_planes");
    m.textured = u.required("u_textured");
    m.alpha_cutoff = u.required("u_alpha_cutoff");
    return u.check();
}

// Storage for `count` maps of `size`² texels per face; false if kept.
bool ensure_shadow_storage(ShadowMaps& m, gl::StateCache& state, int size, int count) {
    if (m.maps && m.size == size && m.capacity >= count) return false;
    state.deleting_texture(m.maps.get());
    state.deleting_texture(m.depth.get());
    m.maps = gl::create_texture(GL_TEXTURE_CUBE_MAP_ARRAY);
    glTextureStorage3D(m.maps.get(), 1, GL_R32F, size, size, 6 * count);
    glTextureParameteri(m.maps.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(m.maps.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m.depth = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(m.depth.get(), 1, GL_DEPTH_COMPONENT32F, size, size);
    if (!m.framebuffer) m.framebuffer = gl::create_framebuffer();
    glNamedFramebufferTexture(m.framebuffer.get(), GL_DEPTH_ATTACHMENT, m.depth.get(), 0);
    glNamedFramebufferDrawBuffer(m.framebuffer.get(), GL_COLOR_ATTACHMENT0);
    m.size = size;
    m.capacity = count;
    m.keys.assign(static_cast<size_t>(count), {});
    return true;
}

// The GL cube map faces' views (+X, -X, +Y, -Y, +Z, -Z), looking from L'.
math::dmat4 shadow_face_view(int face) {
    static const math::dvec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const math::dvec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return glm::lookAt(math::dvec3(0.0), dirs[face], ups[face]);
}

void set_shadow_planes(const ShadowMaps& m, const ShadowLeg& leg, const walk::ObjectInstance* inst) {
    float planes[4][4];
    for (int k = 0; k < 4; ++k) {
        math::dvec4 p(0.0, 0.0, 0.0, 1.0);
        if (k < 2)
            p = leg.slab[static_cast<size_t>(k)];
        else if (inst && k - 2 < inst->cut_count)  // the room's plane, into L'-relative coordinates
            p = glm::transpose(glm::inverse(leg.from_room)) * inst->cuts[static_cast<size_t>(k - 2)].plane;
        for (int c = 0; c < 4; ++c) planes[k][c] = static_cast<float>(p[c]);
    }
    glProgramUniform4fv(m.program.get(), m.planes, 4, &planes[0][0]);
}

void draw_shadow_batches(const ShadowMaps& m, gl::StateCache& state, const ShadowSources& s,
                         std::span<const scene::DrawBatch> batches, const math::dmat4& model) {
    const glm::mat4 model_f(model);
    const GLuint p = m.program.get();
    glProgramUniformMatrix4fv(p, m.model, 1, GL_FALSE, &model_f[0][0]);
    for (const scene::DrawBatch& b : batches) {
        if (b.range.count == 0) continue;
        glProgramUniform1i(p, m.textured, b.texture >= 0 ? 1 : 0);
        glProgramUniform1f(p, m.alpha_cutoff, b.alpha_cutoff);
        if (b.texture >= 0) state.texture(kSceneTextureUnit, s.gpu->textures[static_cast<size_t>(b.texture)].get());
        const auto offset = static_cast<std::uintptr_t>(b.range.first) * sizeof(std::uint32_t);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(b.range.count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(offset));
    }
}

// Which sides of a prop a map holds. A shadow ray meets only the front faces
// of surfaces, seen from the point it starts at (layout-format.md,
// "Lights"): of a model's triangles, those turned away from the light. Seen
// from L' they wind clockwise (anticlockwise in a leg mirrored an odd number
// of times), and the others are culled; a double-sided material's back is a
// triangle of its own (scene/box_mesh.cpp), so it blocks from either side. A
// box prop is closed, so any ray through it meets one face of each side: it
// is drawn whole, and the map holds its side facing the light, whose
// distance leaves no gap where the box stands on the floor (its far side
// would: a floor point just past the far side's foot is within the lookup's
// bias of it, and was lit in mirror_lamp's stool shadow).
gl::PassState shadow_pass_state(bool box, bool mirrored) {
    gl::PassState p;
    p.depth_test = true;
    p.depth_write = true;
    p.depth_func = GL_GREATER;  // reversed-Z
    p.write_ids = false;
    p.cull_back_faces = !box;
    p.front_clockwise = !mirrored;
    p.clip_distances = 4;
    return p;
}

// A leg's props: the room's static ones, then the instances placed in it.
void draw_shadow_leg(const ShadowMaps& m, gl::StateCache& state, const ShadowSources& s,
                     const std::vector<int>& instances, const ShadowLeg& leg) {
    const auto room = static_cast<size_t>(leg.room);
    const bool mirrored = glm::determinant(math::dmat3(leg.from_room)) < 0.0;
    set_shadow_planes(m, leg, nullptr);
    const scene::CellObjects& objects = (*s.objects)[room];
    const math::dmat4 room_model = leg.from_room * glm::translate(math::dmat4(1.0), (*s.origins)[room].origin);
    for (const scene::CellObject& object : objects.objects) {
        state.apply(shadow_pass_state(object.box_vertex >= 0, mirrored), 0);
        draw_shadow_batches(
            m, state, s,
            std::span<const scene::DrawBatch>(objects.batches).subspan(object.first_batch, object.batch_count),
            room_model);
    }
    for (const int k : instances) {
        const walk::ObjectInstance& inst = (*s.instances)[static_cast<size_t>(k)];
        const scene::ObjectMesh& mesh =
            (*s.object_meshes)[static_cast<size_t>((*s.instance_mesh)[static_cast<size_t>(k)])];
        set_shadow_planes(m, leg, &inst);
        state.apply(shadow_pass_state(mesh.box, mirrored), 0);
        draw_shadow_batches(m, state, s, mesh.batches,
                            leg.from_room * inst.to_cell * glm::translate(math::dmat4(1.0), mesh.origin));
    }
}

void draw_shadow_map(const ShadowMaps& m, gl::StateCache& state, const ShadowSources& s,
                     const std::vector<std::vector<int>>& by_room, const lights::LightImage& image, int layer) {
    const std::vector<ShadowLeg> legs = shadow_legs_of(image);
    math::Frustum f;
    f.fov_y_deg = 90.0;
    f.aspect = 1.0;
    f.near = kShadowNear;
    const math::dmat4 projection = math::perspective_reversed_z(f);
    const GLuint fb = m.framebuffer.get();
    const GLfloat none[4] = {kNoShadowOccluder, 0.0f, 0.0f, 0.0f};
    const GLfloat far_depth = 0.0f;
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTextureLayer(fb, GL_COLOR_ATTACHMENT0, m.maps.get(), 0, 6 * layer + face);
        glClearNamedFramebufferfv(fb, GL_COLOR, 0, none);
        glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
        const glm::mat4 face_proj(projection * shadow_face_view(face));
        glProgramUniformMatrix4fv(m.program.get(), m.face_proj, 1, GL_FALSE, &face_proj[0][0]);
        for (const ShadowLeg& leg : legs) draw_shadow_leg(m, state, s, by_room[static_cast<size_t>(leg.room)], leg);
    }
}

void upload_shadow_layers(ShadowMaps& m) {
    std::vector<std::int32_t> data(m.layer.size() + 2);
    const float header[2] = {m.size > 0 ? 2.0f / static_cast<float>(m.size) : 0.0f,
                             static_cast<float>(kShadowBiasTexels)};
    std::memcpy(data.data(), header, sizeof header);
    for (size_t g = 0; g < m.layer.size(); ++g) data[g + 2] = m.layer[g];
    if (!m.layers) m.layers = gl::create_buffer();
    glNamedBufferData(m.layers.get(), static_cast<GLsizeiptr>(data.size() * sizeof(std::int32_t)), data.data(),
                      GL_DYNAMIC_DRAW);
}

}  // namespace

int shadow_map_size_for(int requested, std::size_t maps) {
    int size = requested;
    while (size > kMinShadowMapSize &&
           maps * 6 * static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4 > kMaxShadowMapBytes)
        size /= 2;
    return size;
}

Result<int> update_shadow_maps(ShadowMaps& m, gl::StateCache& state, const ShadowSources& s,
                               const std::vector<lights::RoomLights>& rooms, const FrameDesc& frame) {
    std::vector<const lights::LightImage*> images;
    for (const lights::RoomLights& room : rooms)
        for (const lights::LightImage& image : room.images) images.push_back(&image);
    m.layer.assign(images.size(), -1);
    const bool on = frame.shadows && frame.shadow_map_size > 0;
    const std::vector<std::vector<int>> by_room = on ? shadow_instances_by_room(s) : std::vector<std::vector<int>>{};
    if (m.max_maps == 0) {
        GLint layers = 0;
        glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
        m.max_maps = std::max(1, static_cast<int>(layers) / 6);
    }
    int count = 0;
    if (on)
        for (size_t g = 0; g < images.size() && count < m.max_maps; ++g)
            if (shadow_has_occluders(s, by_room, *images[g])) m.layer[g] = count++;
    int drawn = 0;
    if (count > 0) {
        if (Result<void> made = ensure_shadow_program(m); !made) return Error{made.error()};
        const int size = shadow_map_size_for(frame.shadow_map_size, static_cast<std::size_t>(count));
        ensure_shadow_storage(m, state, size, count);
        state.apply(shadow_pass_state(true, false), 0);  // the clears obey its write masks; each prop sets its sides
        state.no_scissor();
        state.viewport({0, 0, size, size});
        state.clip_control(GL_ZERO_TO_ONE);
        state.draw_framebuffer(m.framebuffer.get());
        state.program(m.program.get());
        state.vertex_array(s.gpu->vao.get());
        for (size_t g = 0; g < images.size(); ++g) {
            const int layer = m.layer[g];
            if (layer < 0) continue;
            std::vector<double> key = shadow_key_of(s, by_room, *images[g], size);
            key.push_back(static_cast<double>(g));
            if (m.keys[static_cast<size_t>(layer)] == key) continue;
            draw_shadow_map(m, state, s, by_room, *images[g], layer);
            m.keys[static_cast<size_t>(layer)] = std::move(key);
            ++drawn;
        }
    }
    upload_shadow_layers(m);
    return drawn;
}

void bind_shadow_maps(const ShadowMaps& m, gl::StateCache& state) {
    state.texture(kShadowMapTextureUnit, m.maps.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowLayerBinding, m.layers.get());
}

void unbind_shadow_maps() { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowLayerBinding, 0); }

Result<void> prepare_shadow_maps(ShadowMaps& maps, gl::StateCache& state, const SceneData& r,
                                 const FrameObjects& objects, const std::vector<lights::RoomLights>& rooms,
                                 const FrameDesc& frame, FrameStats& stats) {
    const ShadowSources sources = shadow_sources(r, objects);
    Result<int> drawn = update_shadow_maps(maps, state, sources, rooms, frame);
    if (!drawn) return Error{drawn.error()};
    stats.shadow_maps_drawn = *drawn;
    bind_shadow_maps(maps, state);
    return {};
}

}  // namespace impossible::render
