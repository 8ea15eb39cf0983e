// A model as the asset importer reads it from glTF 2.0 and the renderers
// draw it: triangles in the model's own coordinates, the materials they use
// and the textures those use (decoded once, shared).
#pragma once

#include <array>
#include <memory>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/pixels.hpp"

namespace impossible::assets {

// How a texture is read (glTF 2.0 "samplers"; the codes are glTF's, which are
// OpenGL's). Texture coordinates (0, 0) are the image's top-left corner.
namespace sampler_code {
inline constexpr int kNearest = 9728;
inline constexpr int kLinear = 9729;
inline constexpr int kNearestMipmapNearest = 9984;
inline constexpr int kLinearMipmapNearest = 9985;
inline constexpr int kNearestMipmapLinear = 9986;
inline constexpr int kLinearMipmapLinear = 9987;
inline constexpr int kClampToEdge = 33071;
inline constexpr int kMirroredRepeat = 33648;
inline constexpr int kRepeat = 10497;
}  // namespace sampler_code

struct Sampler {
    int mag_filter = sampler_code::kLinear;              // kNearest or kLinear
    int min_filter = sampler_code::kLinearMipmapLinear;  // any of the six filters
    int wrap_s = sampler_code::kRepeat;
    int wrap_t = sampler_code::kRepeat;
};

struct Texture {
    std::shared_ptr<const image::Pixels> image;  // RGBA; never null in a loaded model
    Sampler sampler;
};

// glTF alphaMode as the renderers draw it. The loader reads BLEND as Mask
// with the cutoff 0.5 and marks the material `blend` (layout-format.md,
// "glTF props": a prop's "blend" may make it Opaque instead).
enum class AlphaMode { Opaque, Mask };

// A glTF material as the renderers use it: the colour at a point of a
// triangle is base_color.rgb · COLOR_0.rgb · texel.rgb, its alpha
// base_color.a · COLOR_0.a · texel.a (the texel is white without a texture).
struct Material {
    glm::dvec4 base_color{0.8, 0.8, 0.8, 1.0};  // baseColorFactor
    int texture = -1;                           // into the model's textures; -1: none
    bool double_sided = false;                  // both sides visible, the back's normal reversed
    AlphaMode alpha_mode = AlphaMode::Opaque;
    double alpha_cutoff = 0.5;  // Mask: alpha below this is not drawn
    bool blend = false;         // the file says alphaMode BLEND (read as Mask at 0.5)
    std::string name;           // "material 2 (\"Glass\")", for warnings
};

// A triangle of a glTF model, in the model's own coordinates (before the
// prop's scale, yaw and position).
struct ModelTriangle {
    std::array<glm::dvec3, 3> position;
    std::array<glm::dvec3, 3> normal;  // unit
    glm::dvec3 color{0.8};             // the material's base colour factor (rgb), as in Material
    std::array<glm::dvec4, 3> vertex_color{glm::dvec4(1.0), glm::dvec4(1.0), glm::dvec4(1.0)};  // COLOR_0
    std::array<glm::dvec2, 3> uv{};  // the material texture's texCoord set; (0, 0) without
    int material = -1;               // into the model's materials; -1: the default (grey, opaque, one-sided)
};

// A light of glTF's KHR_lights_punctual extension (point or spot), placed by
// its node: in the model's own coordinates, like ModelTriangle. Directional
// lights are not kept (layout-format.md, "Lights", has none).
struct ModelLight {
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // a spot's axis (the node's -Z), unit
    glm::dvec3 color{1.0};
    double intensity = 1.0;  // candela
    double range = 0.0;      // 0: no limit
    bool spot = false;
    double inner_cone_rad = 0.0;                 // glTF's innerConeAngle, radians
    double outer_cone_rad = 0.7853981633974483;  // glTF's outerConeAngle (default pi/4)
    // Names it in warnings: "light \"Point.002\" (light 1, node 4 \"Bulb\")".
    std::string name;
};

}  // namespace impossible::assets
