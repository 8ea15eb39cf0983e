#include "layout/gltf_accessor.hpp"

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>

namespace impossible::layout::detail {

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
    std::memcpy(f, data + i * stride, sizeof f);  // little-endian, as glTF
    return {f[0], f[1], f[2]};
}

std::uint32_t AccessorView::index(std::size_t i) const {
    const unsigned char* p = data + i * stride;
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

Result<AccessorView> accessor_view(const tinygltf::Model& model, int index, int type,
                                   std::initializer_list<int> component_types, const char* what) {
    const std::string name = std::string(what) + " accessor " + std::to_string(index);
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        return Error{name + " does not exist"};
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.sparse.isSparse) {
        return Error{name + " is sparse, which is not supported"};
    }
    if (accessor.type != type) {
        return Error{name + " must be " + type_name(type) + ", not " + type_name(accessor.type)};
    }
    if (std::find(component_types.begin(), component_types.end(), accessor.componentType) ==
        component_types.end()) {
        return Error{name + " has the unsupported component type " +
                std::to_string(accessor.componentType)};
    }
    if (accessor.bufferView < 0 ||
        static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        return Error{name + " has no buffer view (not supported)"};
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
        return Error{name + ": its buffer view names a buffer that does not exist"};
    }
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t element = component_size(accessor.componentType) * component_count(type);
    const std::size_t stride = view.byteStride == 0 ? element : view.byteStride;
    if (stride < element) {
        return Error{name + ": byte stride " + std::to_string(stride) + " is smaller than an element"};
    }
    if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength) {
        return Error{name + ": its buffer view reaches past the end of its buffer"};
    }
    AccessorView out;
    out.stride = stride;
    out.count = accessor.count;
    out.component_type = accessor.componentType;
    if (accessor.count == 0) return out;
    // accessor.byteOffset + stride * (count - 1) + element <= view.byteLength,
    // without overflow.
    const bool fits = accessor.byteOffset <= view.byteLength &&
                      element <= view.byteLength - accessor.byteOffset &&
                      accessor.count - 1 <= (view.byteLength - accessor.byteOffset - element) / stride;
    if (!fits) {
        return Error{name + " reaches past the end of its buffer view"};
    }
    out.data = buffer.data() + view.byteOffset + accessor.byteOffset;
    return out;
}

}  // namespace impossible::layout::detail
