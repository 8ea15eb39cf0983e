// The gallery's four models (gallery_assets.hpp) as glTF 2.0 binaries: one
// mesh of one primitive each, 16-bit indices, POSITION (with min and max)
// and NORMAL, and the attributes and material that the model shows.
#include "gallery_assets.hpp"
#include "glb_container.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>

namespace impossible::tools::gallery {

namespace {

using Vec2 = std::array<float, 2>;
using Vec3 = std::array<float, 3>;
using Vec4 = std::array<float, 4>;

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
float dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Vertex {
    Vec3 position;
    Vec3 normal;
    Vec2 uv{};
    Vec4 color{1, 1, 1, 1};
};

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint16_t> indices;

    std::uint16_t add(const Vertex& v) {
        vertices.push_back(v);
        return static_cast<std::uint16_t>(vertices.size() - 1);
    }
    // A triangle whose front (counter-clockwise) side faces `outward`.
    void triangle(std::uint16_t a, std::uint16_t b, std::uint16_t c, const Vec3& outward) {
        const Vec3& pa = vertices[a].position;
        const Vec3 n = cross(sub(vertices[b].position, pa), sub(vertices[c].position, pa));
        if (dot(n, outward) < 0) std::swap(b, c);
        indices.insert(indices.end(), {a, b, c});
    }
};

// A rectangle centred on `centre`, facing along right × up, with the whole
// texture on it: (0, 0), the image's top-left corner, at the top left as seen
// from the front.
void add_quad(Mesh& mesh, const Vec3& centre, const Vec3& right, const Vec3& up, float half_width, float half_height) {
    const Vec3 normal = cross(right, up);
    std::array<std::uint16_t, 4> corner{};
    const std::array<std::array<float, 2>, 4> at = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    for (std::size_t k = 0; k < 4; ++k) {
        Vertex v;
        for (std::size_t i = 0; i < 3; ++i) {
            v.position[i] = centre[i] + at[k][0] * half_width * right[i] + at[k][1] * half_height * up[i];
        }
        v.normal = normal;
        v.uv = {(at[k][0] + 1) / 2, (1 - at[k][1]) / 2};
        corner[k] = mesh.add(v);
    }
    mesh.triangle(corner[0], corner[1], corner[2], normal);
    mesh.triangle(corner[0], corner[2], corner[3], normal);
}

// cos and sin of step / steps of a full turn, rounded to float, with the
// rounding errors of cos(π/2), sin(π) and the like made exact zeros.
Vec2 circle(int step, int steps) {
    const double angle = 2.0 * 3.14159265358979323846 * step / steps;
    const auto tidy = [](double v) { return static_cast<float>(std::fabs(v) < 1e-12 ? 0.0 : v); };
    return {tidy(std::cos(angle)), tidy(std::sin(angle))};
}

// A fully saturated colour of hue step / steps (red, yellow, green, cyan,
// blue, magenta, back to red), piecewise linear.
Vec4 hue(int step, int steps) {
    const float h = 6.0f * static_cast<float>(step % steps) / static_cast<float>(steps);
    const auto channel = [h](float centre) {
        float d = std::fabs(h - centre);
        d = std::min(d, 6.0f - d);
        return std::clamp(2.0f - d, 0.0f, 1.0f);
    };
    return {channel(0.0f), channel(2.0f), channel(4.0f), 1.0f};
}

// Appends the values and pads with zeros to a multiple of 4 bytes, so that
// the next view starts aligned; returns the values' length in bytes.
template <class T>
std::size_t append_bytes(std::vector<unsigned char>& out, const T* values, std::size_t count) {
    const std::size_t begin = out.size();
    out.resize(begin + count * sizeof(T));
    std::memcpy(out.data() + begin, values, count * sizeof(T));
    while (out.size() % 4 != 0) out.push_back(0);
    return count * sizeof(T);
}

std::string floats(const float* values, std::size_t count) {
    std::string out = "[";
    for (std::size_t i = 0; i < count; ++i) out += (i > 0 ? "," : "") + json_number(values[i]);
    return out + "]";
}

struct Parts {
    bool uv = false;
    bool color = false;
    std::string material;            // a glTF material object
    std::vector<unsigned char> png;  // a base colour texture's image, if any
    std::string sampler;             // its glTF sampler object
};

// The binary buffer of a .glb being written, with its buffer views and
// accessors as glTF JSON (comma-separated objects).
struct GlbBuffers {
    std::vector<unsigned char> bin;
    std::string views;
    std::string accessors;
    int view_count = 0;
    int accessor_count = 0;

    // Appends the values as a new buffer view; returns its index.
    template <class T>
    int add_view(const T* values, std::size_t count, int target) {
        const std::size_t offset = bin.size();
        const std::size_t length = append_bytes(bin, values, count);
        if (!views.empty()) views += ",";
        views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) + ",\"byteLength\":" + std::to_string(length);
        if (target != 0) views += ",\"target\":" + std::to_string(target);
        views += "}";
        return view_count++;
    }

    // A float attribute of the mesh's vertices, `width` components of
    // `member`: a view and an accessor (with `bounds`, JSON to add to it).
    template <class Member>
    int add_attribute(const Mesh& mesh, std::size_t width, const char* type, Member member, const std::string& bounds) {
        std::vector<float> values;
        for (const Vertex& v : mesh.vertices) {
            const auto& field = v.*member;
            values.insert(values.end(), field.begin(), field.begin() + static_cast<std::ptrdiff_t>(width));
        }
        const int view = add_view(values.data(), values.size(), 34962);
        if (!accessors.empty()) accessors += ",";
        accessors += "{\"bufferView\":" + std::to_string(view) +
                     ",\"componentType\":5126,\"count\":" + std::to_string(mesh.vertices.size()) + ",\"type\":\"" +
                     type + "\"" + bounds + "}";
        return accessor_count++;
    }
};

// The positions' "min" and "max", as JSON to add to their accessor.
std::string position_bounds(const Mesh& mesh) {
    Vec3 lo = mesh.vertices.front().position;
    Vec3 hi = lo;
    for (const Vertex& v : mesh.vertices) {
        for (std::size_t i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], v.position[i]);
            hi[i] = std::max(hi[i], v.position[i]);
        }
    }
    return ",\"min\":" + floats(lo.data(), 3) + ",\"max\":" + floats(hi.data(), 3);
}

// The primitive's attributes (POSITION, NORMAL, [TEXCOORD_0], [COLOR_0]),
// written to the buffers; returns the JSON of its "attributes" object's members.
std::string add_attributes(GlbBuffers& buffers, const Mesh& mesh, const Parts& parts) {
    std::string attributes = "\"POSITION\":" + std::to_string(buffers.add_attribute(mesh, 3, "VEC3", &Vertex::position,
                                                                                    position_bounds(mesh)));
    attributes += ",\"NORMAL\":" + std::to_string(buffers.add_attribute(mesh, 3, "VEC3", &Vertex::normal, ""));
    if (parts.uv) {
        attributes += ",\"TEXCOORD_0\":" + std::to_string(buffers.add_attribute(mesh, 2, "VEC2", &Vertex::uv, ""));
    }
    if (parts.color) {
        attributes += ",\"COLOR_0\":" + std::to_string(buffers.add_attribute(mesh, 4, "VEC4", &Vertex::color, ""));
    }
    return attributes;
}

// The model as a .glb: buffer views for positions, normals, [uv], [colours],
// indices and [the PNG], in that order, each with one accessor but the PNG.
std::vector<unsigned char> glb_of_mesh(const std::string& name, const Mesh& mesh, const Parts& parts) {
    GlbBuffers buffers;
    const std::string attributes = add_attributes(buffers, mesh, parts);

    const int index_view = buffers.add_view(mesh.indices.data(), mesh.indices.size(), 34963);
    const int index_accessor = buffers.accessor_count++;
    buffers.accessors += ",{\"bufferView\":" + std::to_string(index_view) +
                         ",\"componentType\":5123,\"count\":" + std::to_string(mesh.indices.size()) +
                         ",\"type\":\"SCALAR\"}";

    std::string textures;
    if (!parts.png.empty()) {
        const int image_view = buffers.add_view(parts.png.data(), parts.png.size(), 0);
        textures =
            ",\"textures\":[{\"sampler\":0,\"source\":0}],"
            "\"images\":[{\"bufferView\":" +
            std::to_string(image_view) +
            ",\"mimeType\":\"image/png\"}],"
            "\"samplers\":[" +
            parts.sampler + "]";
    }
    std::string json =
        "{\"asset\":{\"version\":\"2.0\",\"generator\":\"impossible tools/make_gallery_assets\"},"
        "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
        "\"nodes\":[{\"name\":\"" +
        name +
        "\",\"mesh\":0}],"
        "\"meshes\":[{\"name\":\"" +
        name + "\",\"primitives\":[{\"attributes\":{" + attributes + "},\"indices\":" + std::to_string(index_accessor) +
        ",\"material\":0}]}],"
        "\"materials\":[" +
        parts.material + "]" + textures +
        ","
        "\"accessors\":[" +
        buffers.accessors +
        "],"
        "\"bufferViews\":[" +
        buffers.views +
        "],"
        "\"buffers\":[{\"byteLength\":" +
        std::to_string(buffers.bin.size()) + "}]}";
    while (json.size() % 4 != 0) json += ' ';
    return glb_of(json, buffers.bin);
}

}  // namespace

// A 0.6 m wooden crate: a cube with the whole crate_side texture on each
// face, upright on the four sides; the image's top towards -z on the top
// face and towards +z on the bottom. Linear filters, repeat.
std::vector<unsigned char> crate_glb() {
    Mesh mesh;
    const float h = 0.3f;
    const std::array<std::pair<Vec3, Vec3>, 6> faces = {{
        {{0, 0, 1}, {0, 1, 0}},
        {{0, 0, -1}, {0, 1, 0}},
        {{1, 0, 0}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 1, 0}},
        {{0, 1, 0}, {0, 0, -1}},
        {{0, -1, 0}, {0, 0, 1}},
    }};
    for (const auto& [normal, up] : faces) {
        const Vec3 centre = {h * normal[0], h + h * normal[1], h * normal[2]};
        add_quad(mesh, centre, cross(up, normal), up, h, h);
    }
    Parts parts;
    parts.uv = true;
    parts.png = png_of(crate_side());
    parts.sampler = "{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}";
    parts.material =
        "{\"name\":\"crate wood\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,1],"
        "\"baseColorTexture\":{\"index\":0},\"metallicFactor\":0,\"roughnessFactor\":0.9}}";
    return glb_of_mesh("crate", mesh, parts);
}

// A drum 0.9 m high and 0.3 m in radius whose colours come from COLOR_0
// alone (baseColorFactor white, no texture): its side runs once round the
// hue circle, dark at the foot and full at the top, with smooth normals; its
// top is a colour wheel, white at the centre; its underside dark grey.
// 24 segments, 96 triangles.
std::vector<unsigned char> vertex_colours_glb() {
    constexpr int kSegments = 24;
    const float radius = 0.3f;
    const float height = 0.9f;
    Mesh mesh;
    const auto dark = [](Vec4 c) { return Vec4{0.3f * c[0], 0.3f * c[1], 0.3f * c[2], 1.0f}; };
    const std::uint16_t top_centre = mesh.add({{0, height, 0}, {0, 1, 0}, {}, {1, 1, 1, 1}});
    const std::uint16_t bottom_centre = mesh.add({{0, 0, 0}, {0, -1, 0}, {}, {0.2f, 0.2f, 0.2f, 1}});
    for (int k = 0; k < kSegments; ++k) {
        const Vec2 c0 = circle(k, kSegments);
        const Vec2 c1 = circle(k + 1, kSegments);
        const Vec4 h0 = hue(k, kSegments);
        const Vec4 h1 = hue(k + 1, kSegments);
        const Vec3 n0 = {c0[0], 0, c0[1]};
        const Vec3 n1 = {c1[0], 0, c1[1]};
        const Vec3 outward = {c0[0] + c1[0], 0, c0[1] + c1[1]};
        const std::uint16_t a = mesh.add({{radius * c0[0], 0, radius * c0[1]}, n0, {}, dark(h0)});
        const std::uint16_t b = mesh.add({{radius * c1[0], 0, radius * c1[1]}, n1, {}, dark(h1)});
        const std::uint16_t c = mesh.add({{radius * c1[0], height, radius * c1[1]}, n1, {}, h1});
        const std::uint16_t d = mesh.add({{radius * c0[0], height, radius * c0[1]}, n0, {}, h0});
        mesh.triangle(a, b, c, outward);
        mesh.triangle(a, c, d, outward);
        const std::uint16_t t0 = mesh.add({{radius * c0[0], height, radius * c0[1]}, {0, 1, 0}, {}, h0});
        const std::uint16_t t1 = mesh.add({{radius * c1[0], height, radius * c1[1]}, {0, 1, 0}, {}, h1});
        mesh.triangle(top_centre, t0, t1, {0, 1, 0});
        const std::uint16_t b0 = mesh.add({{radius * c0[0], 0, radius * c0[1]}, {0, -1, 0}, {}, {0.2f, 0.2f, 0.2f, 1}});
        const std::uint16_t b1 = mesh.add({{radius * c1[0], 0, radius * c1[1]}, {0, -1, 0}, {}, {0.2f, 0.2f, 0.2f, 1}});
        mesh.triangle(bottom_centre, b0, b1, {0, -1, 0});
    }
    Parts parts;
    parts.color = true;
    parts.material =
        "{\"name\":\"vertex colours\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,1],"
        "\"metallicFactor\":0,\"roughnessFactor\":1}}";
    return glb_of_mesh("colour drum", mesh, parts);
}

// Half a cylinder, 1.2 m high and 0.6 m in radius, curved round the model's
// back (z <= 0) and open towards +z: a thin screen of one layer of triangles
// whose front faces look outwards (normals away from the axis). From +z one
// sees its inside, the back faces, which `doubleSided` makes visible.
// 16 segments × 4 rows, 128 triangles.
std::vector<unsigned char> double_sided_glb() {
    constexpr int kSegments = 16;
    constexpr int kRows = 4;
    const float radius = 0.6f;
    const float height = 1.2f;
    Mesh mesh;
    for (int row = 0; row <= kRows; ++row) {
        for (int k = 0; k <= kSegments; ++k) {
            const Vec2 c = circle(kSegments + k, 2 * kSegments);  // from angle π to 2π: z <= 0
            const float y = height * static_cast<float>(row) / kRows;
            mesh.add({{radius * c[0], y, radius * c[1]}, {c[0], 0, c[1]}, {}, {1, 1, 1, 1}});
        }
    }
    for (int row = 0; row < kRows; ++row) {
        for (int k = 0; k < kSegments; ++k) {
            const auto at = [&](int r, int s) { return static_cast<std::uint16_t>(r * (kSegments + 1) + s); };
            const Vec2 c = circle(2 * kSegments + 2 * k + 1, 4 * kSegments);  // the segment's middle
            const Vec3 outward = {c[0], 0, c[1]};
            mesh.triangle(at(row, k), at(row, k + 1), at(row + 1, k + 1), outward);
            mesh.triangle(at(row, k), at(row + 1, k + 1), at(row + 1, k), outward);
        }
    }
    Parts parts;
    parts.material =
        "{\"name\":\"two-sided screen\",\"doubleSided\":true,\"pbrMetallicRoughness\":{"
        "\"baseColorFactor\":[0.95,0.62,0.22,1],\"metallicFactor\":0,\"roughnessFactor\":1}}";
    return glb_of_mesh("screen", mesh, parts);
}

// A plant of three crossed quads, 1.0 m wide and 1.2 m high, 60° apart
// about the vertical axis, each with the whole plant_leaves image on it:
// alphaMode MASK with cutoff 0.5 cuts away everything around the leaves,
// doubleSided shows each quad from both sides. The sampler is nearest for
// both filters (no mipmaps) and clamps to the edge, so that what is cut is
// exactly the texels whose alpha is 0, the same in every renderer.
std::vector<unsigned char> cutout_glb() {
    Mesh mesh;
    const float s = 0.866025403784438647f;  // sin 60°
    for (const Vec3& right : {Vec3{1, 0, 0}, Vec3{0.5f, 0, -s}, Vec3{-0.5f, 0, -s}}) {
        add_quad(mesh, {0, 0.6f, 0}, right, {0, 1, 0}, 0.5f, 0.6f);
    }
    Parts parts;
    parts.uv = true;
    parts.png = png_of(plant_leaves());
    parts.sampler = "{\"magFilter\":9728,\"minFilter\":9728,\"wrapS\":33071,\"wrapT\":33071}";
    parts.material =
        "{\"name\":\"leaves\",\"alphaMode\":\"MASK\",\"alphaCutoff\":0.5,\"doubleSided\":true,"
        "\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,1],\"baseColorTexture\":{\"index\":0},"
        "\"metallicFactor\":0,\"roughnessFactor\":1}}";
    return glb_of_mesh("plant", mesh, parts);
}

std::vector<File> gallery_files() {
    return {
        {"brick.png", png_of(brick_wall())},
        {"tiles.png", png_of(floor_tiles())},
        {"wood.png", png_of(wood_planks())},
        {"mural.png", png_of(mural())},
        {"crate.glb", crate_glb()},
        {"vertex_colours.glb", vertex_colours_glb()},
        {"double_sided.glb", double_sided_glb()},
        {"cutout.glb", cutout_glb()},
    };
}

}  // namespace impossible::tools::gallery
