// The glTF loader, part 2 of 3: accessors (common/model/gltf_accessors.hpp says what it reads).
#include "common/model/gltf_accessors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/core/check.hpp"
#include "common/core/checked.hpp"

namespace common {
namespace {

bool isIndexType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

uint32_t integer(const uint8_t* element, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return element[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, element, 2);
            return v;
        }
        default: {
            uint32_t v;
            std::memcpy(&v, element, 4);
            return v;
        }
    }
}

float component(const uint8_t* element, size_t c, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, element + 4 * c, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            float v = element[c];
            return normalized ? v / 255.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            float v = float(int8_t(element[c]));
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, element + 2 * c, 2);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, element + 2 * c, 2);
            return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
        }
        default: {
            uint32_t v;
            std::memcpy(&v, element + 4 * c, 4);
            return float(v);
        }
    }
}

}  // namespace

void GltfReader::fail(const std::string& what) const {
    throw InputError(document_.origin + ": " + what);
}

size_t GltfReader::count(int index, const std::string& what) const {
    const tinygltf::Accessor& accessor = get(model_.accessors, index, what + " accessor");
    // Checked on the JSON (common/model/gltf_document.cpp); again here, where it sizes an allocation.
    if (accessor.count < 1 || accessor.count > kMaxAccessorElements)
        fail(what + " (accessor " + std::to_string(index) + ") has " + std::to_string(accessor.count) +
             " elements (1 to " + std::to_string(kMaxAccessorElements) + " are read)");
    return accessor.count;
}

size_t GltfReader::components(int index) const {
    const tinygltf::Accessor& accessor = get(model_.accessors, index, "accessor");
    return size_t(std::max(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)), 0));
}

// Where `count` elements of `components` x `componentType` start in a buffer view, and the stride
// between them, checked to lie wholly inside the view and the view inside its buffer (3.6.2.4:
// "the last element must fit in the buffer view").
GltfReader::Span GltfReader::view(int viewIndex, uint64_t byteOffset, uint64_t count, int componentType,
                                  uint64_t components, bool strided, const std::string& where) const {
    const tinygltf::BufferView& view = get(model_.bufferViews, viewIndex, where + ": buffer view");
    const tinygltf::Buffer& buffer = get(model_.buffers, view.buffer, where + ": buffer");
    const uint64_t size = componentBytes(componentType);
    if (size == 0) fail(where + " has the unknown component type " + std::to_string(componentType));
    const uint64_t element = size * components;
    const uint64_t stride = strided && view.byteStride != 0 ? uint64_t(view.byteStride) : element;
    if (stride < element)
        fail(where + ": byteStride " + std::to_string(stride) + " is smaller than an element (" +
             std::to_string(element) + " bytes)");
    if (byteOffset % size != 0 || view.byteOffset % size != 0)
        fail(where + " is not aligned to its component size (3.6.2.4)");
    std::optional<uint64_t> end = elementsEnd(byteOffset, count, stride, element);
    if (!fitsIn(view.byteOffset, view.byteLength, buffer.data.size()) || !end || *end > view.byteLength)
        fail(where + ": " + std::to_string(count) + " elements from byte " + std::to_string(byteOffset) +
             " run past the end of buffer view " + std::to_string(viewIndex) + " or its buffer");
    return {buffer.data.data() + view.byteOffset + byteOffset, size_t(stride)};
}

// 3.6.2.3 "Sparse Accessors": calls substitute(target, value) for each of the accessor's sparse
// substitutions, its target element checked to lie below `count`. Targets are read as integers:
// through a float, indices above 2^24 would round.
template <typename Substitute>
void GltfReader::forEachSparse(const tinygltf::Accessor& accessor, size_t count, size_t components,
                               const std::string& where, Substitute substitute) const {
    if (!accessor.sparse.isSparse) return;
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || size_t(sparse.count) > count)
        fail(where + " has a sparse count of " + std::to_string(sparse.count) + " for " +
             std::to_string(count) + " elements");
    const int indexType = sparse.indices.componentType;
    if (!isIndexType(indexType))
        fail(where + " has sparse indices of component type " + std::to_string(indexType));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        fail(where + " has a negative sparse byteOffset");
    Span targets = view(sparse.indices.bufferView, uint64_t(sparse.indices.byteOffset),
                        uint64_t(sparse.count), indexType, 1, false, where + " sparse indices");
    Span values = view(sparse.values.bufferView, uint64_t(sparse.values.byteOffset), uint64_t(sparse.count),
                       accessor.componentType, components, false, where + " sparse values");
    for (size_t k = 0; k < size_t(sparse.count); ++k) {
        const uint32_t target = integer(targets.data + k * targets.stride, indexType);
        if (target >= count)
            fail(where + " has a sparse index of " + std::to_string(target) + " for " +
                 std::to_string(count) + " elements");
        substitute(target, values.data + k * values.stride);
    }
}

const std::vector<float>& GltfReader::floats(int index, const std::string& what,
                                             std::initializer_list<int> types,
                                             std::initializer_list<int> componentTypes,
                                             bool requireNormalized) {
    const tinygltf::Accessor& accessor = get(model_.accessors, index, what + " accessor");
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (std::find(types.begin(), types.end(), accessor.type) == types.end())
        fail(where + " has the wrong type for its use");
    const bool isFloat = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) ==
            componentTypes.end() ||
        (requireNormalized && !isFloat && !accessor.normalized))
        fail(where + " has a component type the specification does not allow for it (" +
             std::to_string(accessor.componentType) + (accessor.normalized ? ", normalized" : "") + ")");
    if (auto it = floats_.find(index); it != floats_.end()) return it->second;

    const size_t components = this->components(index);
    const size_t count = this->count(index, where);
    std::vector<float> out(count * components, 0.0f);
    if (accessor.bufferView >= 0) {
        Span span = view(accessor.bufferView, accessor.byteOffset, count, accessor.componentType, components,
                         true, where);
        for (size_t i = 0; i < count; ++i)
            for (size_t c = 0; c < components; ++c)
                out[i * components + c] =
                    component(span.data + i * span.stride, c, accessor.componentType, accessor.normalized);
    }
    forEachSparse(accessor, count, components, where, [&](uint32_t target, const uint8_t* value) {
        for (size_t c = 0; c < components; ++c)
            out[size_t(target) * components + c] =
                component(value, c, accessor.componentType, accessor.normalized);
    });
    for (float value : out)
        if (!std::isfinite(value)) fail(where + " holds a non-finite number");
    return floats_.emplace(index, std::move(out)).first->second;
}

const std::vector<uint32_t>& GltfReader::indices(int index, size_t vertices, const std::string& what) {
    const tinygltf::Accessor& accessor = get(model_.accessors, index, what + " accessor");
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (accessor.type != TINYGLTF_TYPE_SCALAR || accessor.normalized || !isIndexType(accessor.componentType))
        fail(where + " is not unsigned byte, short or int scalars (3.7.2.1)");
    auto it = indices_.find(index);
    if (it == indices_.end()) {
        const size_t count = this->count(index, where);
        std::vector<uint32_t> out(count, 0);
        if (accessor.bufferView >= 0) {
            Span span = view(accessor.bufferView, accessor.byteOffset, count, accessor.componentType, 1,
                             false, where);
            for (size_t i = 0; i < count; ++i)
                out[i] = integer(span.data + i * span.stride, accessor.componentType);
        }
        forEachSparse(accessor, count, 1, where, [&](uint32_t target, const uint8_t* value) {
            out[target] = integer(value, accessor.componentType);
        });
        it = indices_.emplace(index, std::move(out)).first;
    }
    for (uint32_t i : it->second)
        if (i >= vertices)
            fail(where + " refers to vertex " + std::to_string(i) + " of " + std::to_string(vertices));
    return it->second;
}

}  // namespace common
