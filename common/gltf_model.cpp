// glTF 2.0 models through tinygltf, into the structures the OBJ loader fills (common/model.hpp).
//
// tinygltf parses the JSON, reads the buffers and hands us the images' bytes; everything it
// trusts we check first or after: URIs (a model reads only its own files), buffer views against
// their buffers, every accessor against its buffer view, node indices and cycles, and every
// number we use. Section numbers in the comments are those of the Khronos glTF 2.0
// specification (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html).
//
// The default scene's node hierarchy is baked into the vertices (the book's Assimp import does
// the same with PreTransformVertices): one MeshData per triangle primitive of each node that has
// a mesh, in the model's own space.
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "common/check.hpp"
#include "common/files.hpp"
#include "common/model.hpp"

namespace common {
namespace {

using nlohmann::json;

// The most elements one accessor may hold (and so the most vertices or indices of a primitive):
// an accessor that reads a buffer view is bounded by its bytes too, but one made of zeros and
// sparse values (3.6.2.3) has only its count.
constexpr uint64_t kMaxAccessorElements = uint64_t{1} << 25;
// The most vertices a whole model may bake (each is a 56-byte Vertex): 64 Mi, 3.5 GiB.
constexpr uint64_t kMaxModelVertices = uint64_t{1} << 26;
// The deepest node hierarchy we walk (a longer chain is almost surely a hostile file).
constexpr int kMaxNodeDepth = 1024;

std::filesystem::path pathFromUtf8(const std::string& text) {
    return std::filesystem::path(std::u8string(text.begin(), text.end()));
}

// %XX escapes decoded (2.8 "URIs": relative references are URI-encoded).
std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        auto hex = [](char c) {
            return c >= '0' && c <= '9'   ? c - '0'
                   : c >= 'a' && c <= 'f' ? c - 'a' + 10
                   : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                          : -1;
        };
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// A quoted name for messages: at most 64 characters, control characters shown as '?'.
std::string shown(const std::string& text) {
    std::string out = text.size() > 64 ? text.substr(0, 64) + "..." : text;
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20) c = '?';
    return "'" + out + "'";
}

// A model reads only its own files: a URI is a data: URI or a relative path that stays inside
// the model's directory. An absolute path, another scheme (http:, file:) or a path that climbs out
// with ".." is refused.
void checkUri(const std::string& origin, const std::string& where, const std::string& uri) {
    if (uri.rfind("data:", 0) == 0) return;
    std::string decoded = percentDecoded(uri);
    auto fail = [&](const std::string& why) {
        throw InputError(origin + ": " + where + " " + shown(uri) + " " + why +
                         " (a model reads only files in its own directory)");
    };
    if (decoded.empty()) fail("is empty");
    if (decoded.find('\0') != std::string::npos) fail("has a NUL character");
    size_t colon = decoded.find(':'), slash = decoded.find_first_of("/\\");
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        fail("is not a relative path");  // a scheme, or a Windows drive ("C:")
    if (decoded[0] == '/' || decoded[0] == '\\') fail("is an absolute path");
    std::string cleaned = decoded;
    std::replace(cleaned.begin(), cleaned.end(), '\\', '/');
    int depth = 0;
    size_t start = 0;
    while (start <= cleaned.size()) {
        size_t end = cleaned.find('/', start);
        if (end == std::string::npos) end = cleaned.size();
        std::string part = cleaned.substr(start, end - start);
        if (part == "..") {
            if (--depth < 0) fail("leaves the model's directory");
        } else if (!part.empty() && part != ".") {
            ++depth;
        }
        start = end + 1;
    }
}

// A JSON value that must be a whole number in [0, max], when present.
bool readIndex(const json& object, const char* key, uint64_t max, uint64_t* value, const std::string& origin,
               const std::string& where) {
    if (!object.is_object() || !object.contains(key)) return false;
    const json& v = object[key];
    if (!v.is_number_integer() ||
        (v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() < 0) || v.get<uint64_t>() > max)
        throw InputError(origin + ": " + where + "." + key + " must be a whole number from 0 to " +
                         std::to_string(max));
    *value = v.get<uint64_t>();
    return true;
}

// What tinygltf takes on trust, checked on the JSON before it reads anything: the version, the
// extensions a model requires, every URI, and every buffer view against its buffer (tinygltf
// reads images out of buffer views unchecked). Returns the URIs that name files.
struct FileUris {
    std::vector<std::string> buffers, images;
};

FileUris checkGltfJson(const json& root, const std::string& origin, bool glb) {
    FileUris files;
    if (!root.is_object()) throw InputError(origin + ": not a glTF file (the JSON is not an object)");
    if (!root.contains("asset") || !root["asset"].is_object() || !root["asset"].contains("version") ||
        !root["asset"]["version"].is_string())
        throw InputError(origin + ": not a glTF file (no asset.version)");
    std::string version = root["asset"]["version"].get<std::string>();
    if (version.rfind("2.", 0) != 0)
        throw InputError(origin + ": glTF version " + shown(version) + "; only glTF 2.0 is read");
    // 3.2 "Asset" and 3.12 "Specifying Extensions": a model that requires an extension a client
    // lacks should not be loaded. We implement none of those a model can require (Draco, meshopt,
    // quantization, texture transforms, Basis Universal textures, ...).
    if (root.contains("extensionsRequired")) {
        const json& required = root["extensionsRequired"];
        if (!required.is_array()) throw InputError(origin + ": extensionsRequired is not an array");
        for (const json& name : required)
            throw InputError(origin + ": requires the extension " +
                             shown(name.is_string() ? name.get<std::string>() : name.dump()) +
                             ", which this loader does not implement");
    }
    auto array = [&](const char* key) -> const json& {
        static const json empty = json::array();
        if (!root.contains(key)) return empty;
        if (!root[key].is_array()) throw InputError(origin + ": '" + key + "' is not an array");
        return root[key];
    };
    const json& buffers = array("buffers");
    std::vector<uint64_t> bufferBytes;
    for (size_t i = 0; i < buffers.size(); ++i) {
        std::string where = "buffers[" + std::to_string(i) + "]";
        uint64_t bytes = 0;
        if (!readIndex(buffers[i], "byteLength", kMaxInputFileBytes, &bytes, origin, where) || bytes == 0)
            throw InputError(origin + ": " + where + ".byteLength is missing or 0");
        bufferBytes.push_back(bytes);
        if (buffers[i].contains("uri")) {
            if (!buffers[i]["uri"].is_string())
                throw InputError(origin + ": " + where + ".uri is not a string");
            const std::string uri = buffers[i]["uri"].get<std::string>();
            checkUri(origin, where + ".uri", uri);
            if (!uri.starts_with("data:")) files.buffers.push_back(uri);
        } else if (!glb || i != 0) {
            throw InputError(origin + ": " + where + " has no uri (only a .glb's first buffer may omit it)");
        }
    }
    const json& views = array("bufferViews");
    for (size_t i = 0; i < views.size(); ++i) {
        std::string where = "bufferViews[" + std::to_string(i) + "]";
        uint64_t buffer = 0, offset = 0, length = 0, stride = 0;
        if (bufferBytes.empty() ||
            !readIndex(views[i], "buffer", bufferBytes.size() - 1, &buffer, origin, where))
            throw InputError(origin + ": " + where + ".buffer is missing or names no buffer");
        readIndex(views[i], "byteOffset", kMaxInputFileBytes, &offset, origin, where);
        if (!readIndex(views[i], "byteLength", kMaxInputFileBytes, &length, origin, where) || length == 0)
            throw InputError(origin + ": " + where + ".byteLength is missing or 0");
        if (offset + length > bufferBytes[buffer])
            throw InputError(origin + ": " + where + " (bytes " + std::to_string(offset) + ".." +
                             std::to_string(offset + length) + ") runs past the end of buffer " +
                             std::to_string(buffer) + " (" + std::to_string(bufferBytes[buffer]) + " bytes)");
        // 5.11 "Buffer View": a stride of 4 to 252; 3.6.2.4: a multiple of 4.
        if (readIndex(views[i], "byteStride", 252, &stride, origin, where) && (stride < 4 || stride % 4 != 0))
            throw InputError(origin + ": " + where + ".byteStride " + std::to_string(stride) +
                             " is not a multiple of 4 from 4 to 252");
    }
    const json& images = array("images");
    for (size_t i = 0; i < images.size(); ++i) {
        std::string where = "images[" + std::to_string(i) + "]";
        uint64_t view = 0;
        if (images[i].is_object() && images[i].contains("uri")) {
            if (!images[i]["uri"].is_string())
                throw InputError(origin + ": " + where + ".uri is not a string");
            const std::string uri = images[i]["uri"].get<std::string>();
            checkUri(origin, where + ".uri", uri);
            if (!uri.starts_with("data:")) files.images.push_back(uri);
        } else if (images[i].is_object() && images[i].contains("bufferView") &&
                   (views.empty() ||
                    !readIndex(images[i], "bufferView", views.size() - 1, &view, origin, where))) {
            throw InputError(origin + ": " + where + ".bufferView names no buffer view");
        }
    }
    return files;
}

// The file system as tinygltf sees it: files inside the model's directory only (tinygltf also
// looks in the working directory), regular files only (a pipe would block), no path expansion
// (tinygltf's own runs the shell's wordexp on the URI), nothing written. Image files are not read
// here: tinygltf would read each one whole only for us to drop the bytes (the texture upload reads
// and decodes them, on every core), so they are refused, which tinygltf takes as a warning and
// keeps the image's URI.
struct ModelFiles {
    std::string directory;             // absolute, '/'-separated, UTF-8, no '/' at the end but "/"
    std::set<std::string> imageFiles;  // the paths tinygltf asks for the images' URIs

    explicit ModelFiles(const std::filesystem::path& dir) {
        std::u8string generic = dir.generic_u8string();
        directory.assign(generic.begin(), generic.end());
        while (directory.size() > 1 && directory.back() == '/') directory.pop_back();
    }
    // The path tinygltf asks for a URI, as its JoinPath makes it.
    std::string join(const std::string& decoded) const {
        return directory.ends_with('/') ? directory + decoded : directory + "/" + decoded;
    }
    // Image files are not read here (see above); a file that is also a buffer is.
    void skipImages(const FileUris& uris) {
        for (const std::string& uri : uris.images) imageFiles.insert(join(percentDecoded(uri)));
        for (std::string uri : uris.buffers) {
            imageFiles.erase(join(percentDecoded(uri)));
            std::replace(uri.begin(), uri.end(), '+', ' ');  // tinygltf's decoder also reads '+' as ' '
            imageFiles.erase(join(percentDecoded(uri)));
        }
    }
};

bool insideModel(const std::string& path, const ModelFiles& files) {
    const std::string& dir = files.directory;
    if (dir.ends_with('/')) return path.size() > dir.size() && path.starts_with(dir);  // the root
    return path.size() > dir.size() + 1 && path.starts_with(dir) && path[dir.size()] == '/';
}

bool fileExists(const std::string& path, void* user) {
    const ModelFiles& files = *static_cast<const ModelFiles*>(user);
    std::error_code ec;
    return insideModel(path, files) && std::filesystem::is_regular_file(pathFromUtf8(path), ec);
}

std::string expandFilePath(const std::string& path, void*) {
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const ModelFiles& files = *static_cast<const ModelFiles*>(user);
    if (!insideModel(path, files)) {
        *err = "outside the model's directory";
        return false;
    }
    if (files.imageFiles.count(path)) {
        *err = "an image file, read by the texture upload";
        return false;
    }
    try {
        std::string bytes = readInputFile(pathFromUtf8(path));
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& error) {
        *err = error.what();
        return false;
    }
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err = "a model loader writes no files";
    return false;
}

// tinygltf hands over each image's encoded bytes. Those inside the model (a data: URI, a buffer
// view) are kept, undecoded; an image file is not read here (ModelFiles): the texture upload
// reads and decodes it, on every core (common/gpu_scene.cpp).
using EmbeddedImages = std::vector<std::shared_ptr<const std::vector<uint8_t>>>;

bool keepImageBytes(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void* user) {
    auto& embedded = *static_cast<EmbeddedImages*>(user);
    if (index < 0) return false;
    if (embedded.size() <= size_t(index)) embedded.resize(size_t(index) + 1);
    if (image->uri.empty() && size > 0)
        embedded[size_t(index)] = std::make_shared<const std::vector<uint8_t>>(bytes, bytes + size);
    return true;
}

// The first line of tinygltf's error text.
std::string firstLine(std::string text) {
    text = text.substr(0, text.find('\n'));
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
    return text.empty() ? "cannot be read as glTF" : text;
}

// ---- Accessors (3.6.2) ---------------------------------------------------------------------

class GltfReader {
public:
    GltfReader(const tinygltf::Model& model, std::filesystem::path path)
        : model_(model), path_(std::move(path)), origin_(utf8(path_)) {}

    [[noreturn]] void fail(const std::string& what) const { throw InputError(origin_ + ": " + what); }

    // Element i of an accessor as `components` floats: float components as they are, normalized
    // integers mapped to [0, 1] or [-1, 1] (the table of 3.11 "Animations"), plain integers (indices)
    // converted. Sparse accessors get their substituted values (3.6.2.3).
    std::vector<float> floats(int index, const std::string& what, std::initializer_list<int> types,
                              std::initializer_list<int> componentTypes, bool requireNormalized) const {
        const tinygltf::Accessor& accessor = get(model_.accessors, index, what + " accessor");
        std::string where = what + " (accessor " + std::to_string(index) + ")";
        if (std::find(types.begin(), types.end(), accessor.type) == types.end())
            fail(where + " has the wrong type for its use");
        bool isFloat = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
        if (std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) ==
                componentTypes.end() ||
            (requireNormalized && !isFloat && !accessor.normalized))
            fail(where + " has a component type the specification does not allow for it (" +
                 std::to_string(accessor.componentType) + (accessor.normalized ? ", normalized" : "") + ")");
        const size_t components = size_t(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)));
        const size_t count = elementCount(accessor, where);
        std::vector<float> out(count * components, 0.0f);
        if (accessor.bufferView >= 0) {
            Span span = view(accessor.bufferView, accessor.byteOffset, count, accessor.componentType,
                             components, true, where);
            for (size_t i = 0; i < count; ++i)
                for (size_t c = 0; c < components; ++c)
                    out[i * components + c] = component(span.data + i * span.stride, c,
                                                        accessor.componentType, accessor.normalized);
        }
        if (accessor.sparse.isSparse) {
            const auto& sparse = accessor.sparse;
            if (sparse.count < 1 || size_t(sparse.count) > count)
                fail(where + " has a sparse count of " + std::to_string(sparse.count) + " for " +
                     std::to_string(count) + " elements");
            int indexType = sparse.indices.componentType;
            if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(where + " has sparse indices of component type " + std::to_string(indexType));
            Span indices = view(sparse.indices.bufferView, size_t(std::max(sparse.indices.byteOffset, 0)),
                                size_t(sparse.count), indexType, 1, false, where + " sparse indices");
            Span values = view(sparse.values.bufferView, size_t(std::max(sparse.values.byteOffset, 0)),
                               size_t(sparse.count), accessor.componentType, components, false,
                               where + " sparse values");
            for (size_t k = 0; k < size_t(sparse.count); ++k) {
                float target = component(indices.data + k * indices.stride, 0, indexType, false);
                if (!(target < float(count))) fail(where + " has a sparse index past its elements");
                for (size_t c = 0; c < components; ++c)
                    out[size_t(target) * components + c] = component(
                        values.data + k * values.stride, c, accessor.componentType, accessor.normalized);
            }
        }
        for (float value : out)
            if (!std::isfinite(value)) fail(where + " holds a non-finite number");
        return out;
    }

    // An index accessor (3.7.2.1): unsigned byte, short or int scalars, each below `vertices`.
    std::vector<uint32_t> indices(int index, size_t vertices, const std::string& what) const {
        const tinygltf::Accessor& accessor = get(model_.accessors, index, what + " accessor");
        if (accessor.type != TINYGLTF_TYPE_SCALAR || accessor.normalized ||
            (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
             accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
             accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            fail(what + " (accessor " + std::to_string(index) +
                 ") is not unsigned byte, short or int scalars (3.7.2.1)");
        std::vector<float> values;  // exact: 32-bit indices are checked below against at most 2^25 vertices
        const size_t count = elementCount(accessor, what);
        std::vector<uint32_t> out(count);
        if (accessor.bufferView >= 0 && !accessor.sparse.isSparse) {
            Span span =
                view(accessor.bufferView, accessor.byteOffset, count, accessor.componentType, 1, false, what);
            for (size_t i = 0; i < count; ++i)
                out[i] = integer(span.data + i * span.stride, accessor.componentType);
        } else {
            values = floats(index, what, {TINYGLTF_TYPE_SCALAR},
                            {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                            false);
            for (size_t i = 0; i < count; ++i)
                out[i] = values[i] < 4294967296.0f ? uint32_t(values[i]) : UINT32_MAX;
        }
        for (uint32_t i : out)
            if (i >= vertices)
                fail(what + " (accessor " + std::to_string(index) + ") refers to vertex " +
                     std::to_string(i) + " of " + std::to_string(vertices));
        return out;
    }

    size_t count(int index, const std::string& what) const {
        return elementCount(get(model_.accessors, index, what + " accessor"), what);
    }

    template <typename T>
    const T& get(const std::vector<T>& items, int index, const std::string& what) const {
        if (index < 0 || size_t(index) >= items.size())
            fail(what + " " + std::to_string(index) + " does not exist (the model has " +
                 std::to_string(items.size()) + ")");
        return items[size_t(index)];
    }

    const std::string& origin() const { return origin_; }
    const std::filesystem::path& path() const { return path_; }

private:
    struct Span {
        const uint8_t* data;
        size_t stride;
    };

    size_t elementCount(const tinygltf::Accessor& accessor, const std::string& where) const {
        if (accessor.count < 1 || accessor.count > kMaxAccessorElements)
            fail(where + " has " + std::to_string(accessor.count) + " elements (1 to " +
                 std::to_string(kMaxAccessorElements) + " are read)");
        return accessor.count;
    }

    static size_t componentBytes(int componentType) {
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

    // Where `count` elements of `components` x `componentType` start in a buffer view, and the
    // stride between them, checked to lie wholly inside the view and the view inside its buffer
    // (3.6.2.4: "the last element must fit in the buffer view").
    Span view(int viewIndex, size_t byteOffset, size_t count, int componentType, size_t components,
              bool strided, const std::string& where) const {
        const tinygltf::BufferView& view = get(model_.bufferViews, viewIndex, where + ": buffer view");
        const tinygltf::Buffer& buffer = get(model_.buffers, view.buffer, where + ": buffer");
        size_t size = componentBytes(componentType);
        if (size == 0) fail(where + " has the unknown component type " + std::to_string(componentType));
        uint64_t element = uint64_t(size) * components;
        uint64_t stride = strided && view.byteStride != 0 ? uint64_t(view.byteStride) : element;
        if (stride < element)
            fail(where + ": byteStride " + std::to_string(stride) + " is smaller than an element (" +
                 std::to_string(element) + " bytes)");
        if (byteOffset % size != 0 || view.byteOffset % size != 0)
            fail(where + " is not aligned to its component size (3.6.2.4)");
        uint64_t end = uint64_t(view.byteOffset) + byteOffset + (uint64_t(count) - 1) * stride + element;
        if (uint64_t(view.byteOffset) + view.byteLength > buffer.data.size() ||
            uint64_t(byteOffset) + (uint64_t(count) - 1) * stride + element > view.byteLength)
            fail(where + ": " + std::to_string(count) + " elements end at byte " + std::to_string(end) +
                 ", past the end of buffer view " + std::to_string(viewIndex) + " or its buffer");
        return {buffer.data.data() + view.byteOffset + byteOffset, size_t(stride)};
    }

    static uint32_t integer(const uint8_t* element, int componentType) {
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

    static float component(const uint8_t* element, size_t c, int componentType, bool normalized) {
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

    const tinygltf::Model& model_;
    std::filesystem::path path_;
    std::string origin_;
};

// Warnings for what we read but do not draw: one line each, once per model, printed when the
// model has loaded (a model that is refused gets its one error line only).
// The largest absolute component of v.
double maxAbs(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// v made unit length, or `fallback` when it has none: scaled first by its largest component, so
// that a transform of scale 1e200 (valid in a glTF file) overflows nothing.
glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    double m = maxAbs(v);
    if (!(m > 1e-300) || !std::isfinite(m)) return fallback;
    glm::dvec3 u = v / m;
    double length = glm::length(u);
    return std::isfinite(length) && length > 1e-12 ? u / length : fallback;
}

class Skipped {
public:
    explicit Skipped(std::string origin) : origin_(std::move(origin)) {}
    void note(const std::string& what) {
        if (std::find(notes_.begin(), notes_.end(), what) == notes_.end()) notes_.push_back(what);
    }
    // An extension skipped: one warning per extension, however many places use it.
    void extension(const std::string& name, const std::string& what) {
        if (extensions_.insert(name).second) note(what);
    }
    void print() const {
        for (const std::string& what : notes_)
            std::fprintf(stderr, "warning: %s: %s\n", origin_.c_str(), what.c_str());
    }

private:
    std::string origin_;
    std::vector<std::string> notes_;
    std::set<std::string> extensions_;
};

// ---- Materials (3.9) -----------------------------------------------------------------------

Wrap wrapMode(int mode) {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return Wrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return Wrap::MirroredRepeat;
        default:
            return Wrap::Repeat;  // 10497, the default
    }
}

// 5.26 "Sampler": an undefined filter is ours to choose (trilinear); a minification filter
// without "MIPMAP" samples level 0 only.
SamplerDesc samplerDesc(const tinygltf::Sampler& s) {
    SamplerDesc d;
    d.magFilter = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
    switch (s.minFilter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST:
            d = {d.magFilter, Filter::Nearest, false, Filter::Nearest};
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR:
            d = {d.magFilter, Filter::Linear, false, Filter::Nearest};
            break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
            d = {d.magFilter, Filter::Nearest, true, Filter::Nearest};
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
            d = {d.magFilter, Filter::Linear, true, Filter::Nearest};
            break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
            d = {d.magFilter, Filter::Nearest, true, Filter::Linear};
            break;
        default:
            break;  // LINEAR_MIPMAP_LINEAR, or undefined
    }
    d.wrapU = wrapMode(s.wrapS);
    d.wrapV = wrapMode(s.wrapT);
    return d;
}

class MaterialReader {
public:
    MaterialReader(const tinygltf::Model& model, const GltfReader& reader, const EmbeddedImages& embedded,
                   Skipped& skipped)
        : model_(model), reader_(reader), embedded_(embedded), skipped_(skipped) {}

    //> gltf-material
    // The metallic-roughness material (3.9.2) in the terms of the OBJ loader's MaterialData.
    MaterialData material(int index) {
        const tinygltf::Material& m = model_.materials[size_t(index)];
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        MaterialData out;
        out.name = m.name.empty() ? "material " + std::to_string(index) : m.name;
        std::string where = "materials[" + std::to_string(index) + "]";
        out.diffuse = vector4(pbr.baseColorFactor, where + ".baseColorFactor");
        out.diffuseTexture = texture(pbr.baseColorTexture, where);
        out.metallic = factor(pbr.metallicFactor, where + ".metallicFactor");
        out.roughness = factor(pbr.roughnessFactor, where + ".roughnessFactor");
        // One image: G = roughness, B = metallic (3.9.2), as the book's metal-rough texture.
        out.metalRoughTexture = texture(pbr.metallicRoughnessTexture, where);
        out.normalTexture = texture(m.normalTexture, where);
        out.normalScale = finite(m.normalTexture.scale, where + ".normalTexture.scale");
        out.occlusionTexture = texture(m.occlusionTexture, where);
        out.occlusionStrength = factor(m.occlusionTexture.strength, where + ".occlusionTexture.strength");
        // 3.9.4 "Alpha Coverage". A G-buffer pixel holds one surface: BLEND becomes a mask.
        if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
            out.alphaMode = AlphaMode::Mask;
            if (!(m.alphaCutoff >= 0.0) || !std::isfinite(m.alphaCutoff))
                reader_.fail(where + ".alphaCutoff must be a finite number of at least 0");
            // Above 1 every texel is cut; 2 says the same and stays a finite float.
            out.alphaCutoff = m.alphaMode == "MASK" ? float(std::min(m.alphaCutoff, 2.0)) : 0.5f;
            if (m.alphaMode == "BLEND")
                skipped_.note(
                    "alphaMode BLEND is drawn as MASK with a cutoff of 0.5 (a G-buffer holds one "
                    "surface per pixel)");
        } else if (m.alphaMode == "OPAQUE" || m.alphaMode.empty()) {
            out.alphaMode = AlphaMode::Opaque;
        } else {
            reader_.fail(where + ".alphaMode " + shown(m.alphaMode) + " is not OPAQUE, MASK or BLEND");
        }
        out.doubleSided = m.doubleSided;  // 3.9.5: no culling, back faces' normals flipped
        //< gltf-material
        if (m.emissiveTexture.index >= 0 ||
            std::any_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), [](double v) { return v != 0.0; }))
            skipped_.note("emissive light is not drawn");
        for (const auto& [name, value] : m.extensions)
            skipped_.extension(name, "material extension " + name + " is skipped");
        return out;
    }

private:
    glm::vec4 vector4(const std::vector<double>& values, const std::string& where) const {
        if (values.size() != 4) reader_.fail(where + " must have 4 numbers");
        glm::vec4 v;
        for (int i = 0; i < 4; ++i) v[i] = factor(values[size_t(i)], where);
        return v;
    }

    float factor(double value, const std::string& where) const {
        if (!(value >= 0.0 && value <= 1.0)) reader_.fail(where + " must be a number from 0 to 1");
        return float(value);
    }

    float finite(double value, const std::string& where) const {
        if (!std::isfinite(value) || std::abs(value) > 1e6) reader_.fail(where + " must be a finite number");
        return float(value);
    }

    // A material's texture (5.30 "Texture Info"): its image and sampler. Any textureInfo type.
    template <typename Info>
    TextureRef texture(const Info& info, const std::string& where) {
        if (info.index < 0) return {};
        const tinygltf::Texture& texture = reader_.get(model_.textures, info.index, where + ": texture");
        if (info.texCoord != 0)
            skipped_.note("textures read TEXCOORD_0 only (a material asks for another set)");
        for (const auto& [name, value] : info.extensions)
            skipped_.extension(name, "texture extension " + name + " is skipped");
        for (const auto& [name, value] : texture.extensions)
            skipped_.extension(name, "texture extension " + name + " is skipped");
        if (texture.source < 0) return {};  // allowed when an extension supplies the image
        const tinygltf::Image& image = reader_.get(model_.images, texture.source, where + ": image");
        TextureRef ref;
        if (texture.sampler >= 0)
            ref.sampler = samplerDesc(reader_.get(model_.samplers, texture.sampler, where + ": sampler"));
        size_t source = size_t(texture.source);
        if (source < embedded_.size() && embedded_[source]) {
            ref.image = {reader_.path(), embedded_[source], "image " + std::to_string(source)};
        } else if (!image.uri.empty()) {
            ref.image.file = reader_.path().parent_path() / pathFromUtf8(percentDecoded(image.uri));
        } else {
            skipped_.note("image " + std::to_string(source) + " has no data; using the default texture");
            return {};
        }
        return ref;
    }

    const tinygltf::Model& model_;
    const GltfReader& reader_;
    const EmbeddedImages& embedded_;
    Skipped& skipped_;
};

// ---- Nodes and meshes (3.5, 3.7) -----------------------------------------------------------

glm::dmat4 localMatrix(const tinygltf::Node& node, const GltfReader& reader, const std::string& where) {
    auto check = [&](const std::vector<double>& values, size_t size, const char* name) {
        if (!values.empty() && values.size() != size)
            reader.fail(where + "." + name + " must have " + std::to_string(size) + " numbers");
        for (double v : values)
            if (!std::isfinite(v)) reader.fail(where + "." + name + " holds a non-finite number");
    };
    check(node.matrix, 16, "matrix");
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    // 3.5.3 "Transformations": `matrix` (column-major), or T * R * S.
    if (!node.matrix.empty()) return glm::make_mat4(node.matrix.data());
    glm::dmat4 m(1.0);
    if (!node.translation.empty())
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (!node.rotation.empty()) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // (w, x, y, z)
        double length = glm::length(q);
        if (!(length > 1e-9)) reader.fail(where + ".rotation is not a unit quaternion");
        m = m * glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// One triangle primitive of a node, baked into the model's space.
MeshData bakePrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& world,
                       const GltfReader& reader, const std::string& where, Skipped& skipped,
                       uint32_t defaultMaterial) {
    auto attribute = [&](const char* name) {
        auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
    int positionAccessor = attribute("POSITION");
    if (positionAccessor < 0) reader.fail(where + " has no POSITION");
    // 3.7.2.1 "Overview": which component types each attribute may have.
    std::vector<float> positions =
        reader.floats(positionAccessor, where + " POSITION", {TINYGLTF_TYPE_VEC3}, {kFloat}, false);
    const size_t vertexCount = positions.size() / 3;
    auto sameCount = [&](int accessor, const char* name) {
        if (accessor >= 0 && reader.count(accessor, where + " " + name) != vertexCount)
            reader.fail(where + " " + name + " has another count than POSITION");
    };
    int normalAccessor = attribute("NORMAL"), tangentAccessor = attribute("TANGENT"),
        uvAccessor = attribute("TEXCOORD_0");
    sameCount(normalAccessor, "NORMAL");
    sameCount(tangentAccessor, "TANGENT");
    sameCount(uvAccessor, "TEXCOORD_0");
    std::vector<float> normals, tangents, uvs;
    if (normalAccessor >= 0)
        normals = reader.floats(normalAccessor, where + " NORMAL", {TINYGLTF_TYPE_VEC3}, {kFloat}, false);
    if (tangentAccessor >= 0 && normalAccessor >= 0)  // 3.7.2.1: without normals, tangents are ignored
        tangents = reader.floats(tangentAccessor, where + " TANGENT", {TINYGLTF_TYPE_VEC4}, {kFloat}, false);
    if (uvAccessor >= 0)
        uvs = reader.floats(
            uvAccessor, where + " TEXCOORD_0", {TINYGLTF_TYPE_VEC2},
            {kFloat, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, true);
    if (primitive.targets.size()) skipped.note("morph targets are not applied (drawn in the base shape)");
    for (const auto& [name, accessor] : primitive.attributes) {
        if (name.rfind("JOINTS_", 0) == 0) skipped.note("skins are not applied (drawn unskinned)");
        if (name.rfind("COLOR_", 0) == 0) skipped.note("vertex colours (COLOR_n) are not used");
    }

    // The primitive's corners as triangles, counter-clockwise (3.7.2.1, its topology types).
    std::vector<uint32_t> corners;
    if (primitive.indices >= 0) {
        corners = reader.indices(primitive.indices, vertexCount, where + " indices");
    } else {
        corners.resize(vertexCount);
        for (uint32_t i = 0; i < vertexCount; ++i) corners[i] = i;
    }
    std::vector<uint32_t> triangles;
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES || primitive.mode == -1) {
        triangles.assign(corners.begin(), corners.end() - long(corners.size() % 3));
    } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < corners.size(); ++i)  // p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}
            triangles.insert(triangles.end(), {corners[i], corners[i + 1 + i % 2], corners[i + 2 - i % 2]});
    } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (size_t i = 0; i + 2 < corners.size(); ++i)  // p_i = {v_i+1, v_i+2, v_0}
            triangles.insert(triangles.end(), {corners[i + 1], corners[i + 2], corners[0]});
    }

    MeshData mesh;
    mesh.material = primitive.material >= 0 ? uint32_t(primitive.material) : defaultMaterial;
    // Positions by the node's world matrix, normals by its inverse-transpose; a mirroring
    // transform (negative determinant) turns the winding around (3.7.4 "Instantiation").
    const glm::dmat3 linear(world), normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0;
    bool unusableTangent = false;  // a file's tangent along its normal, or zero
    auto vertex = [&](uint32_t i) {
        Vertex v{};
        glm::dvec4 p = world * glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0);
        v.position = glm::vec3(p);
        if (!normals.empty()) {
            glm::dvec3 n0(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
            glm::dvec3 n = unitOr(normalMatrix * n0, glm::dvec3(0.0, 1.0, 0.0));
            v.normal = glm::vec3(n);
            if (!tangents.empty()) {
                // 3.7.2.1: bitangent = cross(normal, tangent.xyz) * w, in the primitive's space;
                // tangent and bitangent transformed as directions in the surface, then the frame
                // made orthonormal about the normal (a file's tangent need not be perpendicular to
                // its normal), keeping the bitangent's side.
                glm::dvec3 t0(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
                double w = tangents[4 * i + 3] < 0.0f ? -1.0 : 1.0;
                glm::dvec3 t = linear * t0, b = linear * (glm::cross(n0, t0) * w);
                t = unitOr(t, glm::dvec3(0.0));
                t = unitOr(t - n * glm::dot(n, t), glm::dvec3(0.0));  // Gram-Schmidt
                if (t == glm::dvec3(0.0)) {
                    unusableTangent = true;  // computed for the whole primitive below instead
                } else {
                    glm::dvec3 side = glm::cross(n, t);
                    v.tangent = glm::vec3(t);
                    v.bitangent = glm::vec3(glm::dot(side, unitOr(b, side)) < 0.0 ? -side : side);
                }
            }
        }
        if (!uvs.empty())
            v.uv = {uvs[2 * i], uvs[2 * i + 1]};  // (0, 0) is the image's first texel (3.8 "Texture Data")
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z))
            reader.fail(where + ": a transformed position is not finite");
        return v;
    };

    if (normals.empty()) {
        // 3.7.2.1: without NORMAL, flat normals: each triangle gets its own three vertices.
        for (size_t k = 0; k + 2 < triangles.size(); k += 3) {
            Vertex a = vertex(triangles[k]), b = vertex(triangles[k + 1]), c = vertex(triangles[k + 2]);
            if (mirrored) std::swap(b, c);
            glm::dvec3 n =
                glm::cross(glm::dvec3(b.position - a.position), glm::dvec3(c.position - a.position));
            glm::vec3 flat =
                glm::length(n) > 0.0 ? glm::vec3(glm::normalize(n)) : glm::vec3(0.0f, 1.0f, 0.0f);
            for (Vertex* v : {&a, &b, &c}) {
                v->normal = flat;
                mesh.indices.push_back(uint32_t(mesh.vertices.size()));
                mesh.vertices.push_back(*v);
            }
        }
    } else {
        // Only the vertices the triangles use, in the order first used.
        std::vector<uint32_t> remap(vertexCount, UINT32_MAX);
        for (size_t k = 0; k < triangles.size(); ++k) {
            uint32_t& slot = remap[triangles[k]];
            if (slot == UINT32_MAX) {
                slot = uint32_t(mesh.vertices.size());
                mesh.vertices.push_back(vertex(triangles[k]));
            }
            mesh.indices.push_back(slot);
        }
        if (mirrored)
            for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3)
                std::swap(mesh.indices[k + 1], mesh.indices[k + 2]);
    }
    // Tangents where the file has none (3.7.2.1 asks for MikkTSpace; ours: common/model.cpp), or
    // where one of its tangents is unusable.
    if (tangents.empty() || unusableTangent) computeTangents(mesh);
    return mesh;
}

}  // namespace

ModelData loadGltfModel(const std::filesystem::path& path) {
    const std::string origin = utf8(path);
    std::string bytes = readInputFile(path);
    const bool glb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;

    // The JSON: the whole .gltf, or a .glb's first chunk (4.4 "Binary glTF Layout").
    std::string jsonText;
    if (glb) {
        auto u32 = [&](size_t at) {
            uint32_t v;
            std::memcpy(&v, bytes.data() + at, 4);
            return v;
        };
        if (bytes.size() < 20) throw InputError(origin + ": a GLB file shorter than its headers");
        if (u32(4) != 2)
            throw InputError(origin + ": GLB version " + std::to_string(u32(4)) + "; only 2 is read");
        if (u32(8) != bytes.size())
            throw InputError(origin + ": the GLB header says " + std::to_string(u32(8)) +
                             " bytes, the file has " + std::to_string(bytes.size()));
        if (u32(16) != 0x4E4F534Au) throw InputError(origin + ": the GLB's first chunk is not JSON");
        if (uint64_t(u32(12)) + 20 > bytes.size())
            throw InputError(origin + ": the GLB's JSON chunk (" + std::to_string(u32(12)) +
                             " bytes) runs past the end of the file");
        jsonText.assign(bytes.data() + 20, u32(12));
        size_t next = 20 + size_t(u32(12));
        if (next < bytes.size()) {
            if (next + 8 > bytes.size() || uint64_t(u32(next)) + next + 8 > bytes.size())
                throw InputError(origin + ": the GLB's binary chunk runs past the end of the file");
            if (u32(next + 4) != 0x004E4942u)
                throw InputError(origin + ": the GLB's second chunk is not BIN");
        }
    } else {
        jsonText = bytes;
    }
    if (jsonText.starts_with("\xef\xbb\xbf")) jsonText.erase(0, 3);
    FileUris fileUris;
    {
        json root;
        try {
            root = json::parse(jsonText);
        } catch (const json::exception& error) {
            std::string what = error.what();
            size_t at = what.find("] ");
            throw InputError(origin +
                             ": invalid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
        }
        fileUris = checkGltfJson(root, origin, glb);
    }

    //> gltf-parse
    // tinygltf parses the file and reads its buffers, through our file callbacks only.
    ModelFiles files(std::filesystem::absolute(path).parent_path());
    files.skipImages(fileUris);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({fileExists, expandFilePath, readWholeFile, writeWholeFile, &files});
    EmbeddedImages embedded;
    loader.SetImageLoader(keepImageBytes, &embedded);
    tinygltf::Model model;
    std::string error, warning;
    bool parsed = glb ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                    reinterpret_cast<const unsigned char*>(bytes.data()),
                                                    unsigned(bytes.size()), files.directory)
                      : loader.LoadASCIIFromString(&model, &error, &warning, jsonText.data(),
                                                   unsigned(jsonText.size()), files.directory);
    if (!parsed) throw InputError(origin + ": " + firstLine(error));
    //< gltf-parse
    bytes.clear();
    bytes.shrink_to_fit();

    GltfReader reader(model, path);
    Skipped skipped(origin);
    if (!model.cameras.empty()) skipped.note("its cameras are not used (the scene's camera is)");
    if (!model.animations.empty()) skipped.note("animations are not played");

    ModelData out;
    MaterialReader materials(model, reader, embedded, skipped);
    for (int i = 0; i < int(model.materials.size()); ++i) out.materials.push_back(materials.material(i));
    for (const std::string& name : model.extensionsUsed)  // those the materials used are noted already
        skipped.extension(name, "extension " + name + " is not used");
    const uint32_t defaultMaterial = uint32_t(out.materials.size());
    // 3.9.6 "Default Material": a primitive without one is opaque white, metallic 1, roughness 1.
    out.materials.push_back(
        MaterialData{.name = "default", .roughness = 1.0f, .metallic = 1.0f, .alphaMode = AlphaMode::Opaque});

    // 3.5.1 "Scenes": the default scene's root nodes (every root node when there is no scene).
    std::vector<int> parents(model.nodes.size(), -1);
    for (size_t i = 0; i < model.nodes.size(); ++i)
        for (int child : model.nodes[i].children) {
            reader.get(model.nodes, child, "nodes[" + std::to_string(i) + "].children: node");
            // 3.5.2 "Nodes and Hierarchy": the nodes form a forest, one parent each.
            if (parents[size_t(child)] >= 0 || size_t(child) == i)
                reader.fail("node " + std::to_string(child) +
                            " has more than one parent or is its own child");
            parents[size_t(child)] = int(i);
        }
    // With one parent each, a node that no root reaches lies on a cycle (or below one).
    {
        std::vector<bool> reached(model.nodes.size(), false);
        std::vector<int> stack;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (parents[i] < 0) stack.push_back(int(i));
        while (!stack.empty()) {
            int node = stack.back();
            stack.pop_back();
            reached[size_t(node)] = true;
            for (int child : model.nodes[size_t(node)].children) stack.push_back(child);
        }
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!reached[i])
                reader.fail("node " + std::to_string(i) + " is on a cycle of the node hierarchy");
    }
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        roots = reader.get(model.scenes, scene, "scene").nodes;
        for (int root : roots) {
            reader.get(model.nodes, root, "scenes[" + std::to_string(scene) + "].nodes: node");
            if (parents[size_t(root)] >= 0)
                reader.fail("node " + std::to_string(root) + " is a root and a child");
        }
    } else {
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (parents[i] < 0) roots.push_back(int(i));
    }

    uint64_t vertices = 0;
    bool first = true;
    std::function<void(int, const glm::dmat4&, int)> visit = [&](int index, const glm::dmat4& parent,
                                                                 int depth) {
        if (depth > kMaxNodeDepth)
            reader.fail("the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " (a cycle?)");
        const tinygltf::Node& node = model.nodes[size_t(index)];
        std::string where = "nodes[" + std::to_string(index) + "]";
        glm::dmat4 world = parent * localMatrix(node, reader, where);
        if (node.skin >= 0) skipped.note("skins are not applied (drawn unskinned)");
        if (node.mesh >= 0) {
            const tinygltf::Mesh& mesh = reader.get(model.meshes, node.mesh, where + ".mesh: mesh");
            for (size_t p = 0; p < mesh.primitives.size(); ++p) {
                const tinygltf::Primitive& primitive = mesh.primitives[p];
                std::string at =
                    "meshes[" + std::to_string(node.mesh) + "].primitives[" + std::to_string(p) + "]";
                if (primitive.material >= 0)
                    reader.get(model.materials, primitive.material, at + ".material: material");
                int mode = primitive.mode;
                if (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                    mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                    if (mode < 0 || mode > 6)
                        reader.fail(at + ".mode " + std::to_string(mode) + " is not 0 to 6");
                    skipped.note("points and lines are not drawn");
                    continue;
                }
                // A node scaled by zero shows nothing (and has no inverse for its normals).
                if (std::abs(glm::determinant(glm::dmat3(world))) < 1e-300) continue;
                MeshData baked = bakePrimitive(primitive, world, reader, at, skipped, defaultMaterial);
                if (baked.indices.empty()) continue;
                vertices += baked.vertices.size();
                if (vertices > kMaxModelVertices)
                    reader.fail("more than " + std::to_string(kMaxModelVertices) + " vertices in all");
                for (const Vertex& v : baked.vertices) {
                    out.boundsMin = first ? v.position : glm::min(out.boundsMin, v.position);
                    out.boundsMax = first ? v.position : glm::max(out.boundsMax, v.position);
                    first = false;
                }
                out.meshes.push_back(std::move(baked));
            }
        }
        for (int child : node.children) visit(child, world, depth + 1);
    };
    for (int root : roots) visit(root, glm::dmat4(1.0), 0);
    if (out.meshes.empty()) throw InputError(origin + ": the model's default scene has no triangles");
    skipped.print();
    return out;
}

}  // namespace common
