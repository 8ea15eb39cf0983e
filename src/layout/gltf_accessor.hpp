// Bounds-checked access to glTF accessor data (tinygltf does not check that
// an accessor's elements lie inside its buffer).
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

#include <glm/vec3.hpp>

#include "base/result.hpp"

namespace tinygltf {
class Model;
}

namespace impossible::layout::detail {

struct AccessorView {
    const unsigned char* data = nullptr;  // the first element
    std::size_t stride = 0;               // bytes between elements
    std::size_t count = 0;
    int component_type = 0;  // TINYGLTF_COMPONENT_TYPE_*

    glm::dvec3 vec3(std::size_t i) const;      // FLOAT VEC3
    std::uint32_t index(std::size_t i) const;  // UNSIGNED_BYTE/SHORT/INT SCALAR
};

// Checks accessor `index` (`what` names it in errors: "POSITION") against
// the wanted type (TINYGLTF_TYPE_*) and component types, and that every
// element lies inside its buffer view and buffer.
Result<AccessorView> accessor_view(const tinygltf::Model& model, int index, int type,
                                   std::initializer_list<int> component_types, const char* what);

}  // namespace impossible::layout::detail
