// A small glTF 2.0 writer for the files we generate: the default scene's glTF form
// (generate_default_scene), the glTF test cases (tests/unit/gltf_test.cpp, tests/tools/gltf_cases.cpp).
// It writes what the glTF 2.0 specification asks (accessor min/max for POSITION, 4-byte aligned
// views, padded GLB chunks) as .gltf + .bin, as one .gltf with data: URIs, or as .glb; the
// JSON stays open to callers, which is how the tests write files that break the rules.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace gltf {

using nlohmann::json;

// glTF's numbers (specification, 5.1.x and 5.26).
enum ComponentType : int {
    kByte = 5120,
    kUnsignedByte = 5121,
    kShort = 5122,
    kUnsignedShort = 5123,
    kUnsignedInt = 5125,
    kFloat = 5126,
};
enum Mode : int { kPoints = 0, kLines = 1, kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6 };

inline std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= bytes[i + 2];
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

inline std::vector<uint8_t> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

inline void writeBytes(const std::filesystem::path& path, const void* data, size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), std::streamsize(size));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

struct File {
    json root = {{"asset", {{"version", "2.0"}, {"generator", "vulkan-book-cpp"}}}};
    std::vector<uint8_t> bin;  // buffer 0

    static int append(json& array, json item) {
        array.push_back(std::move(item));
        return int(array.size()) - 1;
    }
    int add(const char* key, json item) { return append(root[key], std::move(item)); }

    // A buffer view of `bytes` bytes copied into buffer 0, starting 4-byte aligned.
    int view(const void* data, size_t bytes, int stride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (stride) v["byteStride"] = stride;
        bin.insert(bin.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + bytes);
        return add("bufferViews", v);
    }

    int accessor(int bufferView, int componentType, size_t count, const char* type, bool normalized = false,
                 size_t byteOffset = 0) {
        json a = {
            {"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) a["normalized"] = true;
        if (byteOffset) a["byteOffset"] = byteOffset;
        return add("accessors", a);
    }

    template <typename T>
    int values(const std::vector<T>& data, int componentType, const char* type, bool normalized = false) {
        size_t components = std::string(type) == "SCALAR" ? 1
                            : std::string(type) == "VEC2" ? 2
                            : std::string(type) == "VEC3" ? 3
                            : std::string(type) == "MAT4" ? 16
                                                          : 4;
        size_t componentBytes = componentType == kFloat || componentType == kUnsignedInt     ? 4
                                : componentType == kShort || componentType == kUnsignedShort ? 2
                                                                                             : 1;
        size_t count = data.size() * sizeof(T) / (components * componentBytes);
        return accessor(view(data.data(), data.size() * sizeof(T)), componentType, count, type, normalized);
    }

    // POSITION: the specification requires its bounds.
    int positions(const std::vector<glm::vec3>& p) {
        int index = values(p, kFloat, "VEC3");
        glm::vec3 lo = p.empty() ? glm::vec3(0) : p[0], hi = lo;
        for (const glm::vec3& v : p) lo = glm::min(lo, v), hi = glm::max(hi, v);
        root["accessors"][size_t(index)]["min"] = {lo.x, lo.y, lo.z};
        root["accessors"][size_t(index)]["max"] = {hi.x, hi.y, hi.z};
        return index;
    }

    int image(const std::string& uri) { return add("images", {{"uri", uri}}); }
    int texture(int image, int sampler = -1) {
        json t = {{"source", image}};
        if (sampler >= 0) t["sampler"] = sampler;
        return add("textures", t);
    }
    int material(json m) { return add("materials", std::move(m)); }
    int mesh(json primitives) { return add("meshes", {{"primitives", std::move(primitives)}}); }
    int node(json n) { return add("nodes", std::move(n)); }
    // The default scene, of the given root nodes.
    void scene(const std::vector<int>& roots) {
        root["scenes"] = json::array({{{"nodes", roots}}});
        root["scene"] = 0;
    }

    // name.gltf + name.bin beside it.
    void writeGltf(const std::filesystem::path& path) {
        std::filesystem::path binPath = path;
        binPath.replace_extension(".bin");
        root["buffers"] = json::array({{{"uri", binPath.filename().string()}, {"byteLength", bin.size()}}});
        writeBytes(binPath, bin.data(), bin.size());
        std::string text = root.dump(1);
        writeBytes(path, text.data(), text.size());
    }

    // One .gltf: the buffer and every image file as data: URIs (images read from `imageDir`).
    void writeEmbedded(const std::filesystem::path& path, const std::filesystem::path& imageDir) {
        json out = root;
        out["buffers"] = json::array(
            {{{"uri", "data:application/octet-stream;base64," + base64(bin)}, {"byteLength", bin.size()}}});
        if (out.contains("images"))
            for (json& image : out["images"]) {
                std::string uri = image["uri"];
                std::string mime = uri.ends_with(".png") ? "image/png" : "image/jpeg";
                image["uri"] = "data:" + mime + ";base64," + base64(readBytes(imageDir / uri));
            }
        std::string text = out.dump(1);
        writeBytes(path, text.data(), text.size());
    }

    // One .glb: JSON chunk, then the BIN chunk with the buffer and every image in buffer views.
    void writeGlb(const std::filesystem::path& path, const std::filesystem::path& imageDir) {
        File copy = *this;
        if (copy.root.contains("images"))
            for (json& image : copy.root["images"]) {
                std::string uri = image["uri"];
                std::vector<uint8_t> bytes = readBytes(imageDir / uri);
                image.erase("uri");
                image["mimeType"] = uri.ends_with(".png") ? "image/png" : "image/jpeg";
                image["bufferView"] = copy.view(bytes.data(), bytes.size());
            }
        while (copy.bin.size() % 4) copy.bin.push_back(0);
        copy.root["buffers"] = json::array({{{"byteLength", copy.bin.size()}}});
        std::string text = copy.root.dump();
        while (text.size() % 4) text += ' ';
        std::vector<uint8_t> glb;
        auto u32 = [&](uint32_t v) {
            for (int i = 0; i < 4; ++i) glb.push_back(uint8_t(v >> (8 * i)));
        };
        u32(0x46546C67u);  // "glTF"
        u32(2);
        u32(uint32_t(12 + 8 + text.size() + 8 + copy.bin.size()));
        u32(uint32_t(text.size()));
        u32(0x4E4F534Au);  // JSON
        glb.insert(glb.end(), text.begin(), text.end());
        u32(uint32_t(copy.bin.size()));
        u32(0x004E4942u);  // BIN
        glb.insert(glb.end(), copy.bin.begin(), copy.bin.end());
        writeBytes(path, glb.data(), glb.size());
    }
};

}  // namespace gltf
