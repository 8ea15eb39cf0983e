// Bounds-checked access to glTF accessor data (tinygltf does not check that
// an accessor's elements lie inside its buffer). An accessor without a
// bufferView reads as zeros, and a sparse accessor has its substitutions
// applied (glTF 2.0, "Sparse Accessors"); both are copied into the view.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "base/result.hpp"

namespace tinygltf {
class Model;
}

namespace impossible::assets {

struct AccessorView {
    const unsigned char* data = nullptr;  // the first element, in the model's buffer; or
    std::vector<unsigned char> owned;     // the elements, when copied (zeros, sparse)
    std::size_t stride = 0;               // bytes between elements
    std::size_t count = 0;
    int component_type = 0;  // TINYGLTF_COMPONENT_TYPE_*

    const unsigned char* bytes() const { return owned.empty() ? data : owned.data(); }

    glm::dvec3 vec3(std::size_t i) const;      // FLOAT VEC3
    std::uint32_t index(std::size_t i) const;  // UNSIGNED_BYTE/SHORT/INT SCALAR
    // Component c of element i: a FLOAT as it is, an UNSIGNED_BYTE or
    // UNSIGNED_SHORT normalized to 0..1 (glTF 2.0, "Accessor Data Types").
    double normalized(std::size_t i, std::size_t c) const;
};

// Checks accessor `index` (`what` names it in errors: "POSITION") against
// the wanted type (TINYGLTF_TYPE_*) and component types, and that every
// element (and every sparse index and value) lies inside its buffer view and
// buffer. Copied accessors hold at most `max_copied` elements.
Result<AccessorView> accessor_view(const tinygltf::Model& model, int index, int type,
                                   std::initializer_list<int> component_types, const char* what,
                                   std::size_t max_copied);

}  // namespace impossible::assets
