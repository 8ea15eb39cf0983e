#include "render/lights/light_buffers.hpp"

#include <cassert>
#include <cmath>

#include "lights/lit_region.hpp"
#include "math/portal.hpp"
#include "render/programs/scene_program.hpp"

namespace impossible::render {
namespace {

void push4(std::vector<float>& out, const glm::dvec3& v, double w) {
    out.insert(out.end(),
               {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)});
}

// A portal rectangle in the lit room's coordinates less its origin: centre
// (w: `w`), normal, and right and up over the half extents.
void push_rect(std::vector<float>& out, const math::PortalRect& rect, const glm::dvec3& origin, double w) {
    push4(out, rect.center - origin, w);
    push4(out, rect.normal, 0.0);
    push4(out, glm::cross(rect.up, rect.normal) / (0.5 * rect.width), 0.0);
    push4(out, rect.up / (0.5 * rect.height), 0.0);
}

// The image's one aperture as light_aperture_open reads it (image vec4s 3 to
// 5): its plane (normal n, k = n · (c - L')), the right axis over the half
// width r' with a = r' · (L' - c), b = u' · (L' - c) for the up axis over the
// half height u', and width / height, from which u' = (n × r') · w / h.
void push_aperture(PackedLights& out, const lights::LightImage& image, const glm::dvec3& origin) {
    const math::PortalRect& rect = image.apertures.front().rect;
    const glm::dvec3 l = image.position - origin, c = rect.center - origin;
    const glm::dvec3 right = glm::cross(rect.up, rect.normal) / (0.5 * rect.width);
    const glm::dvec3 up = rect.up / (0.5 * rect.height);
    float* at = &out.images[out.images.size() - 3 * 4];
    at[2] = static_cast<float>(glm::dot(rect.normal, c - l));
    at[3] = static_cast<float>(glm::dot(right, l - c));
    for (int i = 0; i < 3; ++i) {
        at[4 + i] = static_cast<float>(rect.normal[i]);
        at[8 + i] = static_cast<float>(right[i]);
    }
    at[7] = static_cast<float>(glm::dot(up, l - c));
    at[11] = static_cast<float>(rect.width / rect.height);
}

void push_image(PackedLights& out, const lights::LightImage& image, const layout::Light& light,
                const glm::dvec3& origin, bool one_aperture) {
    const auto rect_index = [&out] { return static_cast<double>(out.rects.size() / (4 * kLightRectVec4s)); };
    push4(out.images, image.position - origin, light.range > 0.0 ? light.range : 0.0);
    const glm::dvec3 radiance = light.color * light.intensity * image.factor;
    const double pi = 3.14159265358979323846;
    double cos_outer = 2.0, inverse_band = 0.0;
    if (light.spot) {
        cos_outer = std::cos(light.spot->outer_deg * pi / 180.0);
        inverse_band = 1.0 / (std::cos(light.spot->inner_deg * pi / 180.0) - cos_outer);
    }
    push4(out.images, radiance, cos_outer);
    push4(out.images, image.spot_direction, inverse_band);
    // The path's rectangles leg by leg: leg j's blockers, then aperture j.
    const double first = rect_index();
    for (size_t leg = 0; leg <= image.apertures.size(); ++leg) {
        for (const lights::Blocker& b : image.blockers)
            if (static_cast<size_t>(b.leg) == leg) push_rect(out.rects, b.rect, origin, 1.0);
        if (leg < image.apertures.size()) push_rect(out.rects, image.apertures[leg].rect, origin, 0.0);
    }
    const double count = rect_index() - first;
    out.images.insert(out.images.end(), {static_cast<float>(first), static_cast<float>(count), 0.0f, 0.0f});
    out.images.insert(out.images.end(), 8, 0.0f);
    if (one_aperture) push_aperture(out, image, origin);
}

// Whether every path image of `room` (those from `direct` on) passes one
// aperture and meets no blocker (kLightsSingleAperture).
bool one_aperture_each(const lights::RoomLights& room, int direct) {
    for (size_t i = static_cast<size_t>(direct); i < room.images.size(); ++i)
        if (room.images[i].apertures.size() != 1 || !room.images[i].blockers.empty()) return false;
    return true;
}

// A room's own lights seen directly come first (images come by path length):
// its images before the first with an aperture.
int direct_images(const lights::RoomLights& room) {
    int direct = 0;
    while (static_cast<size_t>(direct) < room.images.size() &&
           room.images[static_cast<size_t>(direct)].apertures.empty())
        ++direct;
    return direct;
}

// The lit regions of `room`'s images from `direct` on; nullopt if one may
// light the whole room.
std::optional<std::vector<std::array<glm::dvec3, 8>>> path_regions(const lights::RoomLights& room, int direct,
                                                                   const layout::Room& bounds) {
    std::vector<std::array<glm::dvec3, 8>> out;
    for (size_t i = static_cast<size_t>(direct); i < room.images.size(); ++i) {
        const lights::LitRegion region = lights::lit_region(room.images[i], bounds.min, bounds.max);
        if (region.kind == lights::LitRegion::Kind::Everywhere) return std::nullopt;
        if (region.kind == lights::LitRegion::Kind::Pyramid) out.push_back(region.corners);
    }
    return out;
}

// A buffer of `data`, at least one vec4 (a buffer's storage cannot be
// empty); for a uniform block, all of the block's kLightUboVec4s.
gl::Buffer upload_floats(std::vector<float> data, bool ubo) {
    if (data.empty()) data.assign(4, 0.0f);
    if (ubo) data.resize(4 * static_cast<size_t>(kLightUboVec4s), 0.0f);
    gl::Buffer buffer = gl::create_buffer();
    glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), 0);
    return buffer;
}

}  // namespace

PackedLights pack_light_images(const std::vector<lights::RoomLights>& rooms, const layout::Layout& layout,
                               const std::vector<scene::CellOrigin>& origins) {
    PackedLights out;
    for (size_t c = 0; c < rooms.size(); ++c) {
        const glm::dvec3 origin = origins[c].origin;
        const int direct = direct_images(rooms[c]);
        const bool one_aperture = one_aperture_each(rooms[c], direct);
        for (size_t i = 0; i < rooms[c].images.size(); ++i) {
            const lights::LightImage& image = rooms[c].images[i];
            const layout::Room& room = layout.rooms[static_cast<size_t>(image.light_room)];
            push_image(out, image, room.lights[static_cast<size_t>(image.light)], origin,
                       one_aperture && static_cast<int>(i) >= direct);
        }
    }
    return out;
}

LightBuffers upload_light_images(const std::vector<lights::RoomLights>& rooms, const layout::Layout& layout,
                                 const std::vector<scene::CellOrigin>& origins, int depth) {
    LightBuffers out;
    out.depth = depth;
    for (size_t c = 0; c < rooms.size(); ++c) {
        out.first.push_back(out.total);
        out.count.push_back(static_cast<int>(rooms[c].images.size()));
        const int direct = direct_images(rooms[c]);
        bool blockers = false;
        for (int i = 0; i < direct; ++i)
            blockers = blockers || !rooms[c].images[static_cast<size_t>(i)].blockers.empty();
        out.direct.push_back(direct);
        out.direct_blockers.push_back(blockers);
        bool plain = true;
        for (const lights::LightImage& image : rooms[c].images) {
            const layout::Light& light =
                layout.rooms[static_cast<size_t>(image.light_room)].lights[static_cast<size_t>(image.light)];
            plain = plain && !light.spot && !(light.range > 0.0);
        }
        out.plain_points.push_back(plain);
        out.single_apertures.push_back(one_aperture_each(rooms[c], direct));
        out.path_regions.push_back(path_regions(rooms[c], direct, layout.rooms[c]));
        out.ambient.emplace_back(rooms[c].ambient);
        out.origins.push_back(origins[c].origin);
        out.total += out.count.back();
    }
    out.rooms = rooms;
    PackedLights packed = pack_light_images(rooms, layout, origins);
    const auto fits = [](const std::vector<float>& v) { return v.size() <= 4 * static_cast<size_t>(kLightUboVec4s); };
    GLint block_bytes = 0;
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &block_bytes);
    out.ubo = fits(packed.images) && fits(packed.rects) && block_bytes >= 16 * kLightUboVec4s;
    out.packed_images = packed.images;
    out.images = upload_floats(std::move(packed.images), out.ubo);
    out.rects = upload_floats(std::move(packed.rects), out.ubo);
    return out;
}

unsigned light_loop_flags(const LightBuffers& buffers, int room) {
    const auto c = static_cast<size_t>(room);
    if (buffers.count[c] == 0) return 0u;
    const unsigned plain = buffers.plain_points[c] ? kLightsPlainPoints : 0u;
    // The one-aperture bit only for a room with path images (their loop's).
    const unsigned single = buffers.single_apertures[c] ? kLightsSingleAperture : 0u;
    if (buffers.direct[c] == 0) return kLightsNoDirect | plain | single;
    const unsigned blockers = buffers.direct_blockers[c] ? kLightsDirectBlockers : 0u;
    if (buffers.direct[c] == buffers.count[c]) return kLightsNoPaths | blockers | plain;
    return blockers | plain | single;
}

unsigned direct_loop_flags(const LightBuffers& buffers, int room) {
    return (light_loop_flags(buffers, room) | kLightsNoPaths) & ~kLightsSingleAperture;
}

std::uint64_t light_loops_needed(const LightBuffers& buffers, bool shadows, bool split) {
    std::uint64_t needed = 0u;
    const auto bit = [](unsigned flags) { return std::uint64_t{1} << light_loop_index(flags); };
    for (size_t c = 0; c < buffers.count.size(); ++c) {
        if (buffers.count[c] == 0) continue;
        const int room = static_cast<int>(c);
        const unsigned loops = light_loop_flags(buffers, room);
        std::vector<unsigned> kinds = {loops};
        // A room with both kinds draws without its paths outside their lit
        // regions (render/objects/object_draw.cpp).
        if (split && (loops & (kLightsNoDirect | kLightsNoPaths)) == 0u)
            kinds.push_back(direct_loop_flags(buffers, room));
        for (const unsigned k : kinds) {
            // Split, the parts outside the props' shadows (and every part,
            // without maps) skip the lookups; the rest, or every draw when
            // not split, has them.
            if (shadows || !split) needed |= bit(k);
            if (split) needed |= bit(k | kLightsNoShadows);
        }
    }
    return needed;
}

void bind_light_buffers(const LightBuffers* buffers) {
    const GLenum target = buffers && buffers->ubo ? GL_UNIFORM_BUFFER : GL_SHADER_STORAGE_BUFFER;
    if (!buffers)
        for (const GLenum t : {GL_UNIFORM_BUFFER, GL_SHADER_STORAGE_BUFFER}) {
            glBindBufferBase(t, kLightImagesBinding, 0);
            glBindBufferBase(t, kLightRectsBinding, 0);
        }
    else {
        glBindBufferBase(target, kLightImagesBinding, buffers->images.get());
        glBindBufferBase(target, kLightRectsBinding, buffers->rects.get());
    }
}

void set_light_uniforms(const LightBuffers& buffers, const SceneProgram& program, int room,
                        const glm::mat4& to_light_space) {
    if (program.light_ambient < 0) return;  // not a LIGHTS variant
    const auto c = static_cast<size_t>(room);
    const GLuint p = program.program.get();
    const glm::vec3 origin(buffers.origins[c]);
    glProgramUniformMatrix4fv(p, program.to_light_space, 1, GL_FALSE, &to_light_space[0][0]);
    glProgramUniform1i(p, program.light_first, buffers.first[c]);
    glProgramUniform1i(p, program.light_count, buffers.count[c]);
    glProgramUniform1i(p, program.light_direct, buffers.direct[c]);
    glProgramUniform3fv(p, program.light_ambient, 1, &buffers.ambient[c][0]);
    glProgramUniform3fv(p, program.light_origin, 1, &origin[0]);
}

}  // namespace impossible::render
