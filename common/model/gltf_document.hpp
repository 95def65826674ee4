// The glTF loader, part 1 of 3: the document (common/model/gltf_document.cpp).
//
// A .gltf or .glb file checked and parsed, before anything in it is decoded: the JSON's nesting,
// the GLB's chunks, the version and required extensions, the URIs (a model reads only its own
// files), and every number tinygltf would take on trust -- buffers, buffer views, accessors and
// their sparse parts -- each offset, size and count against what holds it, in arithmetic that
// cannot wrap (common/core/checked.hpp). A refusal names the field by its JSON path
// ("accessors[3].byteOffset"). Part 2 reads accessors (common/model/gltf_accessors.hpp), part 3 bakes
// the scene (common/model/gltf_model.cpp).
//
// Section numbers in the comments of all three are those of the Khronos glTF 2.0 specification
// (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace common {

// The deepest nesting of JSON arrays and objects a glTF document may have. A real file nests
// about 8 deep (extensions and extras a few more); tinygltf converts the JSON into its own value
// tree by recursion, so a document of 300,000 nested arrays would overflow the stack there.
inline constexpr int kMaxJsonDepth = 64;

// The most elements one accessor may hold (3.6.2): a primitive's vertices or indices. An
// accessor that reads a buffer view is bounded by its bytes too, but one made of zeros and sparse
// values (3.6.2.3) has only its count.
inline constexpr uint64_t kMaxAccessorElements = uint64_t{1} << 25;

// Encoded images that the model holds itself (a data: URI or a buffer view), by image index;
// images in files of their own are read by the texture upload.
using EmbeddedImages = std::vector<std::shared_ptr<const std::vector<uint8_t>>>;

struct GltfDocument {
    std::filesystem::path path;
    std::string origin;  // the path as UTF-8, the start of every message
    tinygltf::Model model;
    EmbeddedImages embedded;
};

// Reads, checks and parses the file. Throws InputError with one line naming the file and the
// field.
GltfDocument readGltfDocument(const std::filesystem::path& path);

// 3.6.2.2 "Accessor Data Types": the bytes of one component (0 for a type glTF does not define).
constexpr uint64_t componentBytes(uint64_t componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

// Helpers the other parts share.
std::filesystem::path pathFromUtf8(const std::string& text);
std::string percentDecoded(const std::string& uri);  // %XX escapes decoded (2.8 "URIs")
std::string shown(const std::string& text);          // quoted for a message, at most 64 characters

}  // namespace common
