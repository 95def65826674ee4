// The glTF loader, part 2 of 3: accessors (3.6.2), read out of the document that part 1
// (common/model/gltf_document.hpp) checked.
//
// Each accessor is decoded at most once per load, however many primitives and nodes use it: the
// values are kept and handed out by reference. Bounds were checked on the JSON already; they are
// checked here again, in the same arithmetic that cannot wrap, right where the bytes are read.
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "common/model/gltf_document.hpp"

namespace common {

class GltfReader {
public:
    explicit GltfReader(const GltfDocument& document) : document_(document), model_(document.model) {}

    [[noreturn]] void fail(const std::string& what) const;

    // Accessor `index` as `components` floats per element, for the use `what` (a message's
    // subject): float components as they are, normalized integers mapped to [0, 1] or [-1, 1]
    // (3.11's table), sparse substitutions applied (3.6.2.3). Refused unless the accessor's type
    // is one of `types` and its component type one of `componentTypes` (normalized unless float
    // when `requireNormalized`), or when a value is not finite.
    const std::vector<float>& floats(int index, const std::string& what, std::initializer_list<int> types,
                                     std::initializer_list<int> componentTypes, bool requireNormalized);

    // An index accessor (3.7.2.1): unsigned byte, short or int scalars, read as integers (sparse
    // ones too), each below `vertices`.
    const std::vector<uint32_t>& indices(int index, size_t vertices, const std::string& what);

    // An accessor's element count, as the document declares it (checked: 1 to kMaxAccessorElements).
    size_t count(int index, const std::string& what) const;

    // The accessor's components per element (1 for SCALAR, 3 for VEC3, ...).
    size_t components(int index) const;

    template <typename T>
    const T& get(const std::vector<T>& items, int index, const std::string& what) const {
        if (index < 0 || size_t(index) >= items.size())
            fail(what + " " + std::to_string(index) + " does not exist (the model has " +
                 std::to_string(items.size()) + ")");
        return items[size_t(index)];
    }

    const std::string& origin() const { return document_.origin; }
    const std::filesystem::path& path() const { return document_.path; }

private:
    struct Span {
        const uint8_t* data;
        size_t stride;
    };
    Span view(int viewIndex, uint64_t byteOffset, uint64_t count, int componentType, uint64_t components,
              bool strided, const std::string& where) const;
    template <typename Substitute>
    void forEachSparse(const tinygltf::Accessor& accessor, size_t count, size_t components,
                       const std::string& where, Substitute substitute) const;

    const GltfDocument& document_;
    const tinygltf::Model& model_;
    std::map<int, std::vector<float>> floats_;      // decoded accessors, by index
    std::map<int, std::vector<uint32_t>> indices_;  // decoded index accessors, by index
};

}  // namespace common
