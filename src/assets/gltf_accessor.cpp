#include "assets/gltf_accessor.hpp"

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>

namespace impossible::assets {

namespace {

std::size_t component_size(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

std::size_t component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        default: return 0;
    }
}

const char* type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        default: return "a matrix type";
    }
}

}  // namespace

glm::dvec3 AccessorView::vec3(std::size_t i) const {
    float f[3];
    std::memcpy(f, bytes() + i * stride, sizeof f);  // little-endian, as glTF
    return {f[0], f[1], f[2]};
}

std::uint32_t AccessorView::index(std::size_t i) const {
    const unsigned char* p = bytes() + i * stride;
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
        default: {
            std::uint32_t v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
    }
}

double AccessorView::normalized(std::size_t i, std::size_t c) const {
    const unsigned char* p = bytes() + i * stride;
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[c] / 255.0;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p + 2 * c, sizeof v);
            return v / 65535.0;
        }
        default: {
            float f;
            std::memcpy(&f, p + 4 * c, sizeof f);
            return f;
        }
    }
}

namespace {

// The `count` elements of `element` bytes, `stride` apart, from `byte_offset`
// into buffer view `view_index`: their first byte, or why they do not fit.
// `stride` 0 takes the view's byteStride (or `element`).
Result<const unsigned char*> view_elements(const tinygltf::Model& model, int view_index, std::size_t byte_offset,
                                           std::size_t count, std::size_t element, std::size_t& stride,
                                           const std::string& name) {
    if (view_index < 0 || static_cast<std::size_t>(view_index) >= model.bufferViews.size()) {
        return Error{name + " refers to bufferView " + std::to_string(view_index) +
                     ", which does not exist (the model has " + std::to_string(model.bufferViews.size()) + ")"};
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(view_index)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
        return Error{name + ": its bufferView " + std::to_string(view_index) + " names buffer " +
                     std::to_string(view.buffer) + ", which does not exist"};
    }
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (stride == 0) stride = view.byteStride == 0 ? element : view.byteStride;
    if (stride < element) {
        return Error{name + ": byte stride " + std::to_string(stride) + " is smaller than an element"};
    }
    if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength) {
        return Error{name + ": its bufferView " + std::to_string(view_index) + " reaches past the end of its buffer"};
    }
    if (count == 0) return buffer.data() + view.byteOffset;
    // byte_offset + stride * (count - 1) + element <= view.byteLength, without overflow.
    const bool fits = byte_offset <= view.byteLength && element <= view.byteLength - byte_offset &&
                      count - 1 <= (view.byteLength - byte_offset - element) / stride;
    if (!fits) {
        return Error{name + " reaches past the end of its bufferView " + std::to_string(view_index)};
    }
    return buffer.data() + view.byteOffset + byte_offset;
}

// Accessor `index`, which must exist and have the wanted type and one of
// the component types. `name` is "POSITION accessor 3".
Result<const tinygltf::Accessor*> checked_accessor(const tinygltf::Model& model, int index, int type,
                                                   std::initializer_list<int> component_types,
                                                   const std::string& name) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        return Error{name + " does not exist"};
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.type != type) {
        return Error{name + " must be " + type_name(type) + ", not " + type_name(accessor.type)};
    }
    if (std::find(component_types.begin(), component_types.end(), accessor.componentType) == component_types.end()) {
        return Error{name + " has the unsupported component type " + std::to_string(accessor.componentType)};
    }
    return &accessor;
}

// Copies the accessor's dense elements (zeros without a bufferView) into
// out.owned, tightly packed.
Result<void> copy_dense_elements(const tinygltf::Model& model, const tinygltf::Accessor& accessor, std::size_t element,
                                 const std::string& name, AccessorView& out) {
    out.stride = element;
    out.owned.assign(std::max<std::size_t>(1, accessor.count * element), 0);
    if (accessor.bufferView >= 0 && accessor.count > 0) {
        std::size_t stride = 0;
        Result<const unsigned char*> first =
            view_elements(model, accessor.bufferView, accessor.byteOffset, accessor.count, element, stride, name);
        if (!first) return first;
        for (std::size_t i = 0; i < accessor.count; ++i) {
            std::memcpy(out.owned.data() + i * element, *first + i * stride, element);
        }
    }
    return {};
}

// Applies a sparse accessor's substitutions to the elements in out.owned.
Result<void> apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor, std::size_t element,
                          const std::string& name, AccessorView& out) {
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > accessor.count) {
        return Error{name + " has a sparse count of " + std::to_string(sparse.count) + "; it must be 1 to " +
                     std::to_string(accessor.count)};
    }
    const auto substitutions = static_cast<std::size_t>(sparse.count);
    AccessorView indices;
    indices.component_type = sparse.indices.componentType;
    indices.stride = component_size(sparse.indices.componentType);
    if (sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        return Error{name + "'s sparse indices have the unsupported component type " +
                     std::to_string(sparse.indices.componentType)};
    }
    Result<const unsigned char*> index_data =
        view_elements(model, sparse.indices.bufferView, static_cast<std::size_t>(sparse.indices.byteOffset),
                      substitutions, indices.stride, indices.stride, name + "'s sparse indices");
    if (!index_data) return index_data;
    indices.data = *index_data;
    std::size_t value_stride = element;  // sparse values are tightly packed
    Result<const unsigned char*> values =
        view_elements(model, sparse.values.bufferView, static_cast<std::size_t>(sparse.values.byteOffset),
                      substitutions, element, value_stride, name + "'s sparse values");
    if (!values) return values;
    std::size_t previous = 0;
    for (std::size_t i = 0; i < substitutions; ++i) {
        const std::size_t at = indices.index(i);
        if (at >= accessor.count || (i > 0 && at <= previous)) {
            return Error{name + "'s sparse index " + std::to_string(at) + " (number " + std::to_string(i) +
                         ") is not below " + std::to_string(accessor.count) + " or does not increase"};
        }
        previous = at;
        std::memcpy(out.owned.data() + at * element, *values + i * element, element);
    }
    return {};
}

}  // namespace

Result<AccessorView> accessor_view(const tinygltf::Model& model, int index, int type,
                                   std::initializer_list<int> component_types, const char* what,
                                   std::size_t max_copied) {
    const std::string name = std::string(what) + " accessor " + std::to_string(index);
    const Result<const tinygltf::Accessor*> checked = checked_accessor(model, index, type, component_types, name);
    if (!checked) return checked;
    const tinygltf::Accessor& accessor = **checked;
    const std::size_t element = component_size(accessor.componentType) * component_count(type);
    AccessorView out;
    out.count = accessor.count;
    out.component_type = accessor.componentType;
    const bool copied = accessor.bufferView < 0 || accessor.sparse.isSparse;
    if (!copied) {
        Result<const unsigned char*> first =
            view_elements(model, accessor.bufferView, accessor.byteOffset, accessor.count, element, out.stride, name);
        if (!first) return first;
        out.data = *first;
        return out;
    }
    // Zeros or the dense elements, tightly packed, then the substitutions.
    if (accessor.count > max_copied) {
        return Error{name + " has " + std::to_string(accessor.count) +
                     " elements to copy (sparse or without a "
                     "bufferView); at most " +
                     std::to_string(max_copied) + " are supported"};
    }
    if (Result<void> dense = copy_dense_elements(model, accessor, element, name, out); !dense) return dense;
    if (!accessor.sparse.isSparse) return out;
    if (Result<void> substituted = apply_sparse(model, accessor, element, name, out); !substituted) {
        return substituted;
    }
    return out;
}

}  // namespace impossible::assets
