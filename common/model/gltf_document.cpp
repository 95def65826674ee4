// The glTF loader, part 1 of 3: the document (common/model/gltf_document.hpp says what it checks).
#include "common/model/gltf_document.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/core/check.hpp"
#include "common/core/checked.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"

namespace common {

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

namespace {

using nlohmann::json;

// The largest offset or length in bytes a document may state: the largest whole number
// tinygltf's int fields hold, 2 GiB - 1 (an input file has at most 2 GiB).
constexpr uint64_t kMaxBytes = uint64_t(INT32_MAX);

// A model reads only its own files: a URI is a data: URI or a relative path that stays inside
// the model's directory. An absolute path, another scheme (http:, file:) or a path that climbs out
// with ".." is refused.
// A data: URI (RFC 2397) as glTF uses them: "data:" TYPE/SUBTYPE ";base64,". tinygltf decodes
// some types (application/octet-stream, image/png, ...) and takes the others (image/webp, an
// extension's) for file names, which our file callbacks then do not find; a URI that is not of
// this form ("data:/../outside.png") is a path, checked as one.
bool isDataUri(const std::string& uri) {
    const size_t comma = uri.find(";base64,");
    if (!uri.starts_with("data:") || comma == std::string::npos) return false;
    const std::string type = uri.substr(5, comma - 5);
    const size_t slash = type.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == type.size()) return false;
    return std::all_of(type.begin(), type.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '+' || c == '-' || c == '.';
    });
}

void checkUri(const std::string& origin, const std::string& where, const std::string& uri) {
    if (isDataUri(uri)) return;
    std::string decoded = percentDecoded(uri);
    auto fail = [&](const std::string& why) {
        throw InputError(origin + ": " + where + " " + shown(uri) + " " + why +
                         " (a model reads only files in its own directory)");
    };
    if (decoded.empty()) fail("is empty");
    if (hasControlCharacter(decoded)) fail("has a control character (NUL, a line break, ...)");
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

[[noreturn]] void refuse(const std::string& origin, const std::string& what) {
    throw InputError(origin + ": " + what);
}

// The JSON's nesting, counted on the text before any parser sees it: arrays and objects at most
// kMaxJsonDepth deep (brackets inside strings do not count).
void checkNesting(const std::string& text, const std::string& origin) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                refuse(origin, "the JSON nests arrays and objects more than " +
                                   std::to_string(kMaxJsonDepth) + " deep (at byte " + std::to_string(i) +
                                   ")");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// The fields glTF defines as indices, counts, enumerations or byte numbers (5 "Properties
// Reference"): whole numbers, never negative. tinygltf takes a field written as a fraction
// ("mode": 1.5) or below zero ("mesh": -5) as absent, which would draw another model than the
// file describes; the values of "attributes" and of a morph target, and the elements of
// "children", "nodes" and "joints", are indices too.
bool isIndexKey(const std::string& key) {
    static const std::set<std::string> keys = {
        "buffer",        "bufferView", "byteLength", "byteOffset", "byteStride", "camera",
        "componentType", "count",      "index",      "indices",    "input",      "inverseBindMatrices",
        "magFilter",     "material",   "mesh",       "minFilter",  "mode",       "node",
        "output",        "sampler",    "scene",      "skeleton",   "skin",       "source",
        "target",        "texCoord",   "wrapS",      "wrapT"};
    return keys.count(key) != 0;
}
bool holdsIndices(const std::string& key) {
    return key == "children" || key == "nodes" || key == "joints" || key == "attributes";
}  // and "targets", a primitive's morph targets: objects of indices

// tinygltf reads the whole numbers of index fields as C ints: 4294967297 would become 1, a valid
// index, and a fraction or a negative number would be no value at all. An index field beyond 32
// bits, negative or written with a fraction or an exponent is refused with its JSON path. Other
// numbers (translations, factors, an accessor's bounds) are read as doubles and may be anything
// finite; "extras" and "extensions" (application data and extensions' own fields) are not read.
// Recursion is bounded by checkNesting.
void checkWholeNumbers(const json& value, std::string& path, const std::string& origin, bool index) {
    if (value.is_number_integer() && index) {
        if (value.is_number_unsigned() ? value.get<uint64_t>() > uint64_t(INT32_MAX)
                                       : value.get<int64_t>() > INT32_MAX)
            refuse(origin, path + " is " + value.dump() + ", beyond the 32-bit whole numbers glTF uses");
        if (!value.is_number_unsigned() && value.get<int64_t>() < 0)
            refuse(origin, path + " is " + value.dump() + "; it must be a whole number of at least 0");
    } else if (value.is_number() && index) {
        refuse(origin, path + " is not written as a whole number (it reads as " + value.dump() +
                           "): write it in digits only, as 1 rather than 1.0 or 1e0");
    } else if (value.is_array()) {
        const size_t length = path.size();
        for (size_t i = 0; i < value.size(); ++i) {
            path += "[" + std::to_string(i) + "]";
            checkWholeNumbers(value[i], path, origin, index);
            path.resize(length);
        }
    } else if (value.is_object()) {
        const size_t length = path.size();
        for (const auto& [key, item] : value.items()) {
            if (key == "extras" || key == "extensions") continue;
            // A key is the file's text: at most 64 characters of it, control characters as '?'.
            std::string shownKey = key.size() > 64 ? key.substr(0, 64) + "..." : key;
            for (char& c : shownKey)
                if (static_cast<unsigned char>(c) < 0x20) c = '?';
            path += (path.empty() ? "" : ".") + shownKey;
            // An object of indices ("attributes", a morph target) passes the rule on to its
            // values; the top-level "nodes" (objects) and an animation's "target" (an object)
            // are not indices themselves.
            const bool objects = item.is_array() && !item.empty() && item[0].is_object();
            const bool indices = index || (isIndexKey(key) && !item.is_object()) ||
                                 (holdsIndices(key) && !objects) || key == "targets";
            checkWholeNumbers(item, path, origin, indices);
            path.resize(length);
        }
    }
}

// A JSON value that must be a whole number in [min, max], when present.
bool readNumber(const json& object, const char* key, uint64_t min, uint64_t max, uint64_t* value,
                const std::string& origin, const std::string& where) {
    if (!object.is_object() || !object.contains(key)) return false;
    const json& v = object[key];
    if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<int64_t>() < 0) ||
        v.get<uint64_t>() < min || v.get<uint64_t>() > max)
        refuse(origin, where + "." + key + (v.is_number() ? " is " + v.dump() + "; it" : "") +
                           " must be a whole number from " + std::to_string(min) + " to " +
                           std::to_string(max));
    *value = v.get<uint64_t>();
    return true;
}
bool readIndex(const json& object, const char* key, uint64_t max, uint64_t* value, const std::string& origin,
               const std::string& where) {
    return readNumber(object, key, 0, max, value, origin, where);
}

// What tinygltf takes on trust, checked on the JSON before it reads anything: the version, the
// extensions a model requires, every URI, every buffer view against its buffer (tinygltf reads
// images out of buffer views unchecked), and every accessor against its buffer view. Returns the
// URIs that name files.
struct FileUris {
    std::vector<std::string> buffers, images;
};

struct ViewExtent {
    uint64_t length = 0, stride = 0;
};

// Bytes of one element; 3.6.2.4: each column of a matrix starts on a 4-byte boundary.
uint64_t elementSize(const std::string& type, uint64_t component) {
    if (type == "SCALAR") return component;
    if (type == "VEC2") return 2 * component;
    if (type == "VEC3") return 3 * component;
    if (type == "VEC4") return 4 * component;
    const uint64_t columns = type == "MAT2" ? 2 : type == "MAT3" ? 3 : type == "MAT4" ? 4 : 0;
    return columns * ((columns * component + 3) / 4 * 4);
}

// `count` elements of `element` bytes, `stride` apart, from `offset` of a buffer view: inside it.
void checkRange(uint64_t offset, uint64_t count, uint64_t stride, uint64_t element, uint64_t viewIndex,
                const ViewExtent& view, const std::string& origin, const std::string& where) {
    if (stride < element)
        refuse(origin, where + ": bufferViews[" + std::to_string(viewIndex) + "].byteStride " +
                           std::to_string(stride) + " is smaller than an element (" +
                           std::to_string(element) + " bytes)");
    std::optional<uint64_t> end = elementsEnd(offset, count, stride, element);
    if (!end || *end > view.length)
        refuse(origin, where + ": " + std::to_string(count) + " elements from byte " +
                           std::to_string(offset) + " end at byte " +
                           (end ? std::to_string(*end) : std::string("2^64 or more")) +
                           ", past the end of bufferViews[" + std::to_string(viewIndex) + "] (" +
                           std::to_string(view.length) + " bytes)");
}

void checkAccessor(const json& accessor, const std::vector<ViewExtent>& views, const std::string& origin,
                   const std::string& where) {
    if (!accessor.is_object()) refuse(origin, where + " is not an object");
    uint64_t count = 0, componentType = 0, offset = 0, view = 0;
    if (!readNumber(accessor, "count", 1, kMaxAccessorElements, &count, origin, where))
        refuse(origin, where + ".count is missing");
    if (!readNumber(accessor, "componentType", 0, UINT32_MAX, &componentType, origin, where) ||
        componentBytes(componentType) == 0)
        refuse(origin, where + ".componentType is missing or not one of glTF's (3.6.2.2)");
    const std::string type =
        accessor.contains("type") && accessor["type"].is_string() ? accessor["type"].get<std::string>() : "";
    const uint64_t component = componentBytes(componentType), element = elementSize(type, component);
    if (element == 0) refuse(origin, where + ".type " + shown(type) + " is not one of glTF's (3.6.2.2)");
    readIndex(accessor, "byteOffset", kMaxBytes, &offset, origin, where);
    if (offset % component != 0)
        refuse(origin, where + ".byteOffset " + std::to_string(offset) +
                           " is not a multiple of its component size (3.6.2.4)");
    const bool hasView = accessor.contains("bufferView");
    if (hasView) {
        if (views.empty() || !readIndex(accessor, "bufferView", views.size() - 1, &view, origin, where))
            refuse(origin, where + ".bufferView names no buffer view");
        const uint64_t stride = views[view].stride != 0 ? views[view].stride : element;
        checkRange(offset, count, stride, element, view, views[view], origin, where);
    } else if (offset != 0) {
        refuse(origin, where + " has a byteOffset but no bufferView");
    }
    if (!accessor.contains("sparse")) return;
    // 3.6.2.3 "Sparse Accessors": count substitutions, their indices and values each read
    // tightly packed from a buffer view of their own.
    const json& sparse = accessor["sparse"];
    const std::string at = where + ".sparse";
    if (!sparse.is_object()) refuse(origin, at + " is not an object");
    uint64_t sparseCount = 0;
    if (!readNumber(sparse, "count", 1, count, &sparseCount, origin, at))
        refuse(origin, at + ".count is missing");
    auto part = [&](const char* name, uint64_t partElement, bool indices) {
        const std::string in = at + "." + name;
        if (!sparse.contains(name) || !sparse[name].is_object()) refuse(origin, in + " is missing");
        const json& p = sparse[name];
        uint64_t partView = 0, partOffset = 0, partType = 0;
        if (views.empty() || !readIndex(p, "bufferView", views.size() - 1, &partView, origin, in))
            refuse(origin, in + ".bufferView is missing or names no buffer view");
        readIndex(p, "byteOffset", kMaxBytes, &partOffset, origin, in);
        if (indices) {
            if (!readIndex(p, "componentType", UINT32_MAX, &partType, origin, in) ||
                (partType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 partType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 partType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                refuse(origin, in + ".componentType must be unsigned byte, short or int (5121, 5123, 5125)");
            partElement = componentBytes(partType);
        }
        if (partOffset % (indices ? partElement : component) != 0)
            refuse(origin, in + ".byteOffset " + std::to_string(partOffset) +
                               " is not a multiple of its component size (3.6.2.4)");
        checkRange(partOffset, sparseCount, partElement, partElement, partView, views[partView], origin, in);
    };
    part("indices", 0, true);
    part("values", element, false);
}

FileUris checkGltfJson(const json& root, const std::string& origin, bool glb) {
    FileUris files;
    if (!root.is_object()) refuse(origin, "not a glTF file (the JSON is not an object)");
    if (!root.contains("asset") || !root["asset"].is_object() || !root["asset"].contains("version") ||
        !root["asset"]["version"].is_string())
        refuse(origin, "not a glTF file (no asset.version)");
    std::string version = root["asset"]["version"].get<std::string>();
    if (version.rfind("2.", 0) != 0)
        refuse(origin, "glTF version " + shown(version) + "; only glTF 2.0 is read");
    // 3.2 "Asset" and 3.12 "Specifying Extensions": a model that requires an extension a client
    // lacks should not be loaded. We implement none of those a model can require (Draco, meshopt,
    // quantization, texture transforms, Basis Universal textures, ...).
    if (root.contains("extensionsRequired")) {
        const json& required = root["extensionsRequired"];
        if (!required.is_array()) refuse(origin, "extensionsRequired is not an array");
        for (const json& name : required)
            refuse(origin, "requires the extension " +
                               shown(name.is_string() ? name.get<std::string>() : name.dump()) +
                               ", which this loader does not implement");
    }
    auto array = [&](const char* key) -> const json& {
        static const json empty = json::array();
        if (!root.contains(key)) return empty;
        if (!root[key].is_array()) refuse(origin, std::string("'") + key + "' is not an array");
        return root[key];
    };
    const json& buffers = array("buffers");
    std::vector<uint64_t> bufferBytes;
    for (size_t i = 0; i < buffers.size(); ++i) {
        std::string where = "buffers[" + std::to_string(i) + "]";
        uint64_t bytes = 0;
        if (!readNumber(buffers[i], "byteLength", 1, kMaxBytes, &bytes, origin, where))
            refuse(origin, where + ".byteLength is missing");
        bufferBytes.push_back(bytes);
        if (buffers[i].contains("uri")) {
            if (!buffers[i]["uri"].is_string()) refuse(origin, where + ".uri is not a string");
            const std::string uri = buffers[i]["uri"].get<std::string>();
            checkUri(origin, where + ".uri", uri);
            if (!isDataUri(uri)) files.buffers.push_back(uri);
        } else if (!glb || i != 0) {
            refuse(origin, where + " has no uri (only a .glb's first buffer may omit it)");
        }
    }
    const json& views = array("bufferViews");
    std::vector<ViewExtent> extents;
    for (size_t i = 0; i < views.size(); ++i) {
        std::string where = "bufferViews[" + std::to_string(i) + "]";
        uint64_t buffer = 0, offset = 0, length = 0, stride = 0;
        if (bufferBytes.empty() ||
            !readIndex(views[i], "buffer", bufferBytes.size() - 1, &buffer, origin, where))
            refuse(origin, where + ".buffer is missing or names no buffer");
        readIndex(views[i], "byteOffset", kMaxBytes, &offset, origin, where);
        if (!readNumber(views[i], "byteLength", 1, kMaxBytes, &length, origin, where))
            refuse(origin, where + ".byteLength is missing");
        if (!fitsIn(offset, length, bufferBytes[buffer]))
            refuse(origin, where + " (bytes " + std::to_string(offset) + ".." +
                               std::to_string(offset + length) + ") runs past the end of buffer " +
                               std::to_string(buffer) + " (" + std::to_string(bufferBytes[buffer]) +
                               " bytes)");
        // 5.11 "Buffer View": a stride of 4 to 252; 3.6.2.4: a multiple of 4.
        if (readIndex(views[i], "byteStride", 252, &stride, origin, where) && (stride < 4 || stride % 4 != 0))
            refuse(origin,
                   where + ".byteStride " + std::to_string(stride) + " is not a multiple of 4 from 4 to 252");
        extents.push_back({length, stride});
    }
    const json& accessors = array("accessors");
    for (size_t i = 0; i < accessors.size(); ++i)
        checkAccessor(accessors[i], extents, origin, "accessors[" + std::to_string(i) + "]");
    const json& images = array("images");
    for (size_t i = 0; i < images.size(); ++i) {
        std::string where = "images[" + std::to_string(i) + "]";
        uint64_t view = 0;
        if (images[i].is_object() && images[i].contains("uri")) {
            if (!images[i]["uri"].is_string()) refuse(origin, where + ".uri is not a string");
            const std::string uri = images[i]["uri"].get<std::string>();
            checkUri(origin, where + ".uri", uri);
            if (!isDataUri(uri)) files.images.push_back(uri);
        } else if (images[i].is_object() && images[i].contains("bufferView") &&
                   (views.empty() ||
                    !readIndex(images[i], "bufferView", views.size() - 1, &view, origin, where))) {
            refuse(origin, where + ".bufferView names no buffer view");
        }
    }
    std::string path;
    checkWholeNumbers(root, path, origin, false);
    return files;
}

// The file system as tinygltf sees it: files inside the model's directory only (tinygltf also
// looks in the working directory), regular files only (a pipe would block), no path expansion
// (tinygltf's own ran the shell's wordexp on the URI before version 2.6), nothing written. Image files are
// not read here: tinygltf would read each one whole only for us to drop the bytes (the texture upload reads
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
// reads and decodes it, on every core (common/scene/gpu_scene.cpp).
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

// The JSON of the file: the whole .gltf, or a .glb's first chunk (4.4 "Binary glTF Layout"),
// its chunks checked against the file's length.
std::string jsonOf(const std::string& bytes, bool glb, const std::string& origin) {
    if (!glb) return bytes;
    auto u32 = [&](uint64_t at) {
        uint32_t v;
        std::memcpy(&v, bytes.data() + at, 4);
        return uint64_t(v);
    };
    const uint64_t size = bytes.size();
    if (size < 20) refuse(origin, "a GLB file shorter than its headers");
    if (u32(4) != 2) refuse(origin, "GLB version " + std::to_string(u32(4)) + "; only 2 is read");
    if (u32(8) != size)
        refuse(origin, "the GLB header says " + std::to_string(u32(8)) + " bytes, the file has " +
                           std::to_string(size));
    if (u32(16) != 0x4E4F534Au) refuse(origin, "the GLB's first chunk is not JSON");
    const uint64_t jsonLength = u32(12);
    if (!fitsIn(20, jsonLength, size))
        refuse(origin, "the GLB's JSON chunk (" + std::to_string(jsonLength) +
                           " bytes) runs past the end of the file");
    const uint64_t next = 20 + jsonLength;
    if (next < size) {
        if (!fitsIn(next, 8, size) || !fitsIn(next + 8, u32(next), size))
            refuse(origin, "the GLB's binary chunk runs past the end of the file");
        if (u32(next + 4) != 0x004E4942u) refuse(origin, "the GLB's second chunk is not BIN");
    }
    return bytes.substr(20, size_t(jsonLength));
}
}  // namespace

GltfDocument readGltfDocument(const std::filesystem::path& path) {
    GltfDocument document;
    document.path = path;
    document.origin = utf8(path);
    const std::string& origin = document.origin;
    std::string bytes = readInputFile(path);
    const bool glb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    std::string jsonText = jsonOf(bytes, glb, origin);
    if (jsonText.starts_with("\xef\xbb\xbf")) jsonText.erase(0, 3);
    checkNesting(jsonText, origin);
    FileUris fileUris;
    {
        json root;
        try {
            root = json::parse(jsonText);
        } catch (const json::exception& error) {
            std::string what = error.what();
            size_t at = what.find("] ");
            refuse(origin, "invalid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
        }
        fileUris = checkGltfJson(root, origin, glb);
    }

    //> gltf-parse
    // tinygltf parses the file and reads its buffers, through our file callbacks only.
    ModelFiles files(std::filesystem::absolute(path).parent_path());
    files.skipImages(fileUris);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({fileExists, expandFilePath, readWholeFile, writeWholeFile, &files});
    loader.SetImageLoader(keepImageBytes, &document.embedded);
    std::string error, warning;
    bool parsed = glb ? loader.LoadBinaryFromMemory(&document.model, &error, &warning,
                                                    reinterpret_cast<const unsigned char*>(bytes.data()),
                                                    unsigned(bytes.size()), files.directory)
                      : loader.LoadASCIIFromString(&document.model, &error, &warning, jsonText.data(),
                                                   unsigned(jsonText.size()), files.directory);
    if (!parsed) refuse(origin, firstLine(error));
    //< gltf-parse
    return document;
}

}  // namespace common
