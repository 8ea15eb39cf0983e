// Limits on what the asset importer reads (glTF models, PNG and JPEG
// images), where glTF and the layout format are silent. They keep absurd
// input from reaching the renderer, and are documented for users in
// docs/layout-limits.md; keep the two in step. The layout's own limits
// (layout/limits.hpp) include these.
#pragma once

#include <cstddef>

namespace impossible::assets::limits {

// Renderers draw in single precision, so a coordinate (of a layout or of a
// model's vertex, in metres) beyond 100 km would lose millimetres.
inline constexpr double kMaxCoordinate = 1e5;

// A glTF prop's scale factor.
inline constexpr double kMinScale = 1e-6;
inline constexpr double kMaxScale = 1e6;

// glTF models.
inline constexpr std::size_t kMaxModelBytes = 256u << 20;  // 256 MiB
inline constexpr std::size_t kMaxModelTriangles = 1'000'000;
inline constexpr std::size_t kMaxLayoutTriangles = 2'000'000;  // all props of a layout together
inline constexpr std::size_t kMaxNodeDepth = 64;
// KHR_lights_punctual: the point and spot lights a model's nodes place, and
// a light's intensity (candela; a layout's lights have the same bound).
inline constexpr std::size_t kMaxModelLights = 1'000;
inline constexpr double kMaxLightIntensity = 1e9;
// A model's JSON (a .gltf file, a .glb's JSON chunk), checked before tinygltf
// parses it: tinygltf copies `extras` and `extensions` recursively, so deep
// nesting overflows the stack, and every value costs it about 100 bytes. A
// glTF document needs about 8 levels; its bulk data lives in buffers.
inline constexpr std::size_t kMaxModelJsonDepth = 64;
inline constexpr std::size_t kMaxModelJsonValues = 1'000'000;

// Images: glTF textures and room face textures (PNG or JPEG), decoded to
// 8-bit RGBA (4 bytes a texel). A side of 8192 pixels is what GL guarantees
// at least for a texture side on current hardware; the texel budgets bound
// the decoded memory (64 Mi texels = 256 MiB) per model and for the whole
// layout, each distinct image (by file, or by model and image index) counted
// once. A room texture file is read up to kMaxImageFileBytes.
inline constexpr int kMaxImageSide = 8192;
inline constexpr std::size_t kMaxModelTexels = std::size_t{64} << 20;
inline constexpr std::size_t kMaxLayoutTexels = std::size_t{128} << 20;
inline constexpr std::size_t kMaxImageFileBytes = 64u << 20;  // 64 MiB

}  // namespace impossible::assets::limits
