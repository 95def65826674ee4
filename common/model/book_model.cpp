// The book's converted models (book_model.hpp).
#include "common/model/book_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/animation.hpp"
#include "common/model/gltf_document.hpp"  // pathFromUtf8

namespace common {

namespace {

using nlohmann::json;

struct Reader {
    std::string file;  // for messages
    [[noreturn]] void fail(const std::string& what) const { throw InputError(file + ": " + what); }
    const json& field(const json& object, const char* name, const std::string& where) const {
        if (!object.is_object() || !object.contains(name)) fail(where + " has no \"" + name + "\"");
        return object[name];
    }
    std::string text(const json& object, const char* name, const std::string& where) const {
        const json& value = field(object, name, where);
        if (!value.is_string()) fail(where + "'s \"" + name + "\" is not a string");
        return value.get<std::string>();
    }
    uint64_t count(const json& object, const char* name, const std::string& where) const {
        const json& value = field(object, name, where);
        if (!value.is_number_unsigned()) fail(where + "'s \"" + name + "\" is not a whole number 0 or more");
        return value.get<uint64_t>();
    }
    // A factor, 0 to 1 as glTF's.
    float factor(const json& object, const char* name, const std::string& where) const {
        const json& value = field(object, name, where);
        if (!value.is_number() || !(value.get<double>() >= 0.0 && value.get<double>() <= 1.0))
            fail(where + "'s \"" + name + "\" is not a number from 0 to 1");
        return value.get<float>();
    }
};

// What a value taken from the file is, for a message: a number as written (a few characters),
// anything else by its kind alone -- never printed whole (a list nested 100,000 deep would take the
// printing's recursion past the stack).
std::string described(const json& value) {
    if (value.is_number()) return value.dump();
    if (value.is_string()) return "a string";
    if (value.is_array()) return "a list";
    if (value.is_object()) return "an object";
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    return "null";
}

// Parses the converted JSON within budgets that count what the parsed document costs, as it is
// parsed: at most kMaxBookJsonBytes of text, kMaxBookJsonDepth levels of nesting (the format nests
// 7) and kMaxBookJsonValues values and object keys, each of which costs about 100 bytes once
// parsed (docs/reliability.md measures it), so that no file can make the parse itself exhaust
// memory or the stack. `values` counts across the model's two files (NAME.json is still held while
// NAME_mat.json is parsed): one budget for both.
json parse(const std::filesystem::path& path, uint64_t& values) {
    std::error_code ec;
    if (uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxBookJsonBytes)
        throw InputError(utf8(path) + ": " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(kMaxBookJsonBytes) +
                         " our limits allow for the book's converted JSON");
    std::string bytes = readInputFile(path);
    json::parser_callback_t budget = [&](int depth, json::parse_event_t event, json&) {
        if (depth > int(kMaxBookJsonDepth))
            throw InputError(utf8(path) + ": nested deeper than " + std::to_string(kMaxBookJsonDepth) +
                             " levels (the book's converted format nests 7)");
        if (event == json::parse_event_t::value || event == json::parse_event_t::key ||
            event == json::parse_event_t::object_start || event == json::parse_event_t::array_start)
            if (++values > kMaxBookJsonValues)
                throw InputError(utf8(path) + ": more than " + std::to_string(kMaxBookJsonValues) +
                                 " JSON values and keys in the model's files, more than our limits allow "
                                 "(each costs about 100 bytes parsed)");
        return true;
    };
    json root = json::parse(bytes, budget, false);
    if (root.is_discarded()) throw InputError(utf8(path) + ": not JSON (the book's converted model)");
    return root;
}

// A sum of weights for a message: six significant digits (a file's 1e300 is not 300 of them).
std::string sumText(double sum) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", sum);
    return text;
}

// A path of the book's ("resources\\models\\tree\\trunk.png", from its sample directory, with
// Windows' backslashes or not): the file of that name beside the model's JSON.
std::filesystem::path besideJson(const std::filesystem::path& directory, std::string path, const Reader& r,
                                 const std::string& what) {
    if (hasControlCharacter(path))
        r.fail(what + " '" + oneLine(path) + "' has a control character (NUL, a line break, ...)");
    for (char& c : path)
        if (c == '\\') c = '/';
    std::filesystem::path name = pathFromUtf8(path).filename();
    if (name.empty() || name == "." || name == "..") r.fail(what + " '" + path + "' names no file");
    return directory / name;
}

// A material's texture: none where its path is empty.
TextureRef bookTexture(const std::filesystem::path& directory, const std::string& path, const Reader& r,
                       const std::string& what) {
    if (path.empty()) return {};
    return TextureRef{.image = {.file = besideJson(directory, path, r, what)}};
}

float bigEndianFloat(const uint8_t* bytes) {
    uint32_t bits = uint32_t(bytes[0]) << 24 | uint32_t(bytes[1]) << 16 | uint32_t(bytes[2]) << 8 | bytes[3];
    float value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
}

uint32_t bigEndianInt(const uint8_t* bytes) {
    return uint32_t(bytes[0]) << 24 | uint32_t(bytes[1]) << 16 | uint32_t(bytes[2]) << 8 | bytes[3];
}

// A binary file the model names, whole, within `limit` bytes; InputError naming it otherwise.
std::vector<uint8_t> readBinary(const std::filesystem::path& path, uint64_t limit, const Reader& r) {
    requireInputFile(path);
    std::error_code ec;
    uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(utf8(path) + ": cannot read it");
    if (size > limit)
        r.fail("'" + utf8(path) + "' has " + std::to_string(size) + " bytes, more than the " +
               std::to_string(limit) + " our limits allow");
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw InputError(utf8(path) + ": cannot read it");
    return bytes;
}

// The book's animations (its chapter 17, the converted JSON's "animations"): each key frame's
// joint matrices, JOML Matrix4f written by its fields (m00 .. m33: column, then row), checked and
// counted before they are kept. Returns the joints a frame has (0 when there are no animations).
uint64_t readBookAnimations(const json& root, Rig& rig, const Reader& r) {
    if (!root.contains("animations") || root["animations"].is_null()) return 0;
    const json& animations = root["animations"];
    if (!animations.is_array()) r.fail("\"animations\" is not a list");
    if (animations.size() > kMaxAnimationClips)
        r.fail(std::to_string(animations.size()) + " animations, more than the " +
               std::to_string(kMaxAnimationClips) + " our limits allow");
    uint64_t joints = 0, keys = 0;
    for (size_t a = 0; a < animations.size(); ++a) {
        const std::string where = "animation " + std::to_string(a);
        const json& frames = r.field(animations[a], "frames", where);
        if (!frames.is_array() || frames.empty()) r.fail(where + "'s \"frames\" is not a list of key frames");
        for (size_t f = 0; f < frames.size(); ++f) {
            const json& matrices =
                r.field(frames[f], "joint_matrices", where + "'s frame " + std::to_string(f));
            if (!matrices.is_array() || matrices.empty())
                r.fail(where + "'s frame " + std::to_string(f) + " has no list of joint matrices");
            if (joints == 0) joints = matrices.size();
            if (matrices.size() != joints)
                r.fail(where + "'s frame " + std::to_string(f) + " has " + std::to_string(matrices.size()) +
                       " joint matrices where the first frame has " + std::to_string(joints));
            keys += joints;
        }
        if (joints > kMaxRigJoints)
            r.fail(std::to_string(joints) + " joints, more than the " + std::to_string(kMaxRigJoints) +
                   " our limits allow");
        if (keys > kMaxAnimationKeys)
            r.fail("its animations hold more than " + std::to_string(kMaxAnimationKeys) +
                   " joint matrices, our limit");
    }
    static const char* kFields[4][4] = {{"m00", "m01", "m02", "m03"},
                                        {"m10", "m11", "m12", "m13"},
                                        {"m20", "m21", "m22", "m23"},
                                        {"m30", "m31", "m32", "m33"}};
    for (size_t a = 0; a < animations.size(); ++a) {
        const std::string where = "animation " + std::to_string(a);
        const json& animation = animations[a];
        AnimationClip clip;
        clip.name = animation.contains("name") && animation["name"].is_string()
                        ? animation["name"].get<std::string>()
                        : where;
        // Despite its name, frame_millis holds the clip's length in seconds: the book's generator
        // writes Assimp's duration over its ticks a second (ModelGenerator.java), and its key frames
        // span that length, the first at 0 and the last at its end. (The book's own Main steps a
        // key frame per update instead, at its 30 updates a second.)
        const json& millis = r.field(animation, "frame_millis", where);
        if (!millis.is_number() || !(millis.get<double>() > 0.0) || !(millis.get<double>() <= 1e9))
            r.fail(where +
                   "'s frame_millis is not a number above 0 and at most 1e9 (the clip's length in "
                   "seconds, as the book's generator writes it)");
        const json& frames = animation["frames"];
        clip.frameSeconds = millis.get<double>() / double(std::max<size_t>(frames.size() - 1, 1));
        clip.frames.reserve(frames.size() * joints);
        for (size_t f = 0; f < frames.size(); ++f)
            for (const json& m : frames[f]["joint_matrices"]) {
                glm::mat4 matrix;
                for (int c = 0; c < 4; ++c)
                    for (int row = 0; row < 4; ++row) {
                        const json& value =
                            r.field(m, kFields[c][row], where + "'s frame " + std::to_string(f));
                        if (!value.is_number() || !std::isfinite(value.get<double>()) ||
                            std::abs(value.get<double>()) > kMaxModelCoordinate)
                            r.fail(where + "'s frame " + std::to_string(f) +
                                   " has a matrix value that is not "
                                   "a finite number within 1e15");
                        matrix[c][row] = value.get<float>();
                    }
                // A joint's transform is affine: its last row (m03, m13, m23, m33) 0, 0, 0, 1. Any
                // other would be divided away, or taken for 1, unseen.
                if (std::abs(matrix[0][3]) > 1e-4f || std::abs(matrix[1][3]) > 1e-4f ||
                    std::abs(matrix[2][3]) > 1e-4f || std::abs(matrix[3][3] - 1.0f) > 1e-4f)
                    r.fail(where + "'s frame " + std::to_string(f) +
                           " has a joint matrix whose last row (m03, m13, m23, m33) is not 0, 0, 0, 1");
                clip.frames.push_back(matrix);
            }
        // The last key frame blends into the first: the clip loops after all of them.
        clip.duration = clip.frameSeconds * double(frames.size());
        rig.clips.push_back(std::move(clip));
    }
    return joints;
}

// The book's per-vertex weights (the converted JSON's "anim_meshes", one a mesh, four a vertex):
// every bone id within the frames' joints, no weight negative, their sum within
// kWeightSumTolerance of 1 (then made exactly 1; Assimp's LimitBoneWeights renormalises too).
std::vector<VertexSkin> readBookWeights(const json& animMesh, size_t vertices, uint64_t joints,
                                        const Reader& r, const std::string& where) {
    const json& weights = r.field(animMesh, "weights", where);
    const json& ids = r.field(animMesh, "bone_ids", where);
    if (!weights.is_array() || !ids.is_array() || weights.size() != 4 * vertices ||
        ids.size() != 4 * vertices)
        r.fail(where + " has not 4 weights and 4 bone ids for each of its " + std::to_string(vertices) +
               " vertices");
    std::vector<VertexSkin> skin(vertices);
    for (size_t v = 0; v < vertices; ++v) {
        double sum = 0.0;
        for (size_t k = 0; k < 4; ++k) {
            const json& weight = weights[4 * v + k];
            const json& id = ids[4 * v + k];
            if (!weight.is_number() || !(weight.get<double>() >= 0.0) || !std::isfinite(weight.get<double>()))
                r.fail(where + "'s vertex " + std::to_string(v) +
                       " has a weight that is not a number 0 or more");
            if (!id.is_number_integer() || id.get<int64_t>() < 0 ||
                uint64_t(id.get<int64_t>()) >= std::max<uint64_t>(joints, 1))
                r.fail(where + "'s vertex " + std::to_string(v) + " names bone " + described(id) +
                       "; the animations have " + std::to_string(joints) + " joints");
            skin[v].joints[k] = uint16_t(id.get<int64_t>());
            skin[v].weights[int(k)] = weight.get<float>();
            sum += weight.get<double>();
        }
        // Four weights of 0: a vertex no bone touches (the book's generator writes them for a part
        // of an animated model that no bone moves), drawn where the mesh puts it.
        if (sum == 0.0) {
            skin[v].weights = glm::vec4(0.0f);
            skin[v].joints[0] = skin[v].joints[1] = skin[v].joints[2] = skin[v].joints[3] = 0;
            continue;
        }
        if (!(std::abs(sum - 1.0) <= kWeightSumTolerance))
            r.fail(where + "'s vertex " + std::to_string(v) + "'s weights sum to " + sumText(sum) +
                   ", not 1 (nor 0: no bone)");
        skin[v].weights /= float(sum);
        int heaviest = 0;  // unused slots name the heaviest joint (weight 0), as the glTF loader's
        for (int k = 1; k < 4; ++k)
            if (skin[v].weights[k] > skin[v].weights[heaviest]) heaviest = k;
        for (int k = 0; k < 4; ++k)
            if (skin[v].weights[k] == 0.0f) skin[v].joints[k] = skin[v].joints[heaviest];
    }
    return skin;
}

}  // namespace

//> book-model
ModelData loadBookModel(const std::filesystem::path& path) {
    Reader r{utf8(path)};
    uint64_t jsonValues = 0;  // the budget of both files
    json root = parse(path, jsonValues);
    std::filesystem::path directory = path.parent_path();
    const json& meshes = r.field(root, "meshes", "the model");
    if (!meshes.is_array() || meshes.empty()) r.fail("\"meshes\" is not a list of meshes");
    if (meshes.size() > kMaxModelPrimitives)
        r.fail(std::to_string(meshes.size()) + " meshes, more than the " +
               std::to_string(kMaxModelPrimitives) + " our limits allow");
    constexpr uint64_t kVertexBytes = 14 * 4, kIndexBytes = 4;
    std::vector<uint8_t> vertices =
        readBinary(besideJson(directory, r.text(root, "vtx_path", "the model"), r, "\"vtx_path\""),
                   kMaxModelVertices * kVertexBytes, r);
    std::vector<uint8_t> indices =
        readBinary(besideJson(directory, r.text(root, "idx_path", "the model"), r, "\"idx_path\""),
                   kMaxModelIndices * kIndexBytes, r);

    // The materials: NAME_mat.json beside NAME.json, by id.
    ModelData model;
    std::map<std::string, uint32_t> materialIndex;
    std::filesystem::path materialsPath = directory / pathFromUtf8(utf8(path.stem()) + "_mat.json");
    Reader m{utf8(materialsPath)};
    json materials = parse(materialsPath, jsonValues);
    if (!materials.is_array()) m.fail("not a list of materials");
    for (size_t i = 0; i < materials.size(); ++i) {
        const json& entry = materials[i];
        std::string where = "material " + std::to_string(i);
        MaterialData material;
        material.name = m.text(entry, "id", where);
        if (material.name.empty() || materialIndex.count(material.name))
            m.fail(where + "'s id '" + material.name + "' is empty or another material's");
        const json& color = m.field(entry, "diffuse_color", where);
        std::string colorWhere = where + "'s diffuse_color";
        material.diffuse = {m.factor(color, "x", colorWhere), m.factor(color, "y", colorWhere),
                            m.factor(color, "z", colorWhere), m.factor(color, "w", colorWhere)};
        material.roughness = m.factor(entry, "roughness_factor", where);
        material.metallic = m.factor(entry, "metallic_factor", where);
        material.diffuseTexture =
            bookTexture(directory, m.text(entry, "texture_path", where), m, where + "'s texture_path");
        material.normalTexture =
            bookTexture(directory, m.text(entry, "normal_map_path", where), m, where + "'s normal_map_path");
        material.metalRoughTexture =
            bookTexture(directory, m.text(entry, "metal_rough_map", where), m, where + "'s metal_rough_map");
        // The book's scene shader takes a pixel's colour from the texture when the material has
        // one, and from diffuse_color only when it has none -- its generator writes (0, 0, 0, 1)
        // beside a texture. The texture replaces the colour, where glTF's factor multiplies it:
        // white here makes our multiplication the book's replacement.
        if (!material.diffuseTexture.empty()) material.diffuse = glm::vec4(1.0f);
        // The book's shaders discard texels of alpha below 0.5: a cut-out wherever there is alpha.
        material.alphaMode = AlphaMode::Auto;
        materialIndex[material.name] = uint32_t(model.materials.size());
        model.materials.push_back(material);
    }
    // A mesh without a material id (the book's generator writes "" for none) gets a default one.
    auto defaultMaterial = [&] {
        if (auto found = materialIndex.find(""); found != materialIndex.end()) return found->second;
        materialIndex[""] = uint32_t(model.materials.size());
        model.materials.push_back(MaterialData{.name = "default"});
        return uint32_t(model.materials.size() - 1);
    };

    // First every mesh's ranges, checked, and their sums against our limits (ranges may be named
    // more than once: a small file may ask for much work); only then anything decoded.
    struct Range {
        uint64_t vertexOffset, vertexCount, indexOffset, indexCount;
        uint32_t material;
    };
    std::vector<Range> ranges;
    uint64_t totalVertices = 0, totalIndices = 0;
    for (size_t i = 0; i < meshes.size(); ++i) {
        std::string where = "mesh " + std::to_string(i);
        const json& entry = meshes[i];
        uint64_t vertexOffset = r.count(entry, "offset_vtx", where),
                 vertexBytes = r.count(entry, "vtx_size", where);
        uint64_t indexOffset = r.count(entry, "offset_idx", where),
                 indexBytes = r.count(entry, "idx_size", where);
        // Each range within its file (compared without a sum that could wrap), whole vertices and
        // whole triangles.
        if (vertexOffset > vertices.size() || vertexBytes > vertices.size() - vertexOffset)
            r.fail(where + "'s vertices (bytes " + std::to_string(vertexOffset) + " + " +
                   std::to_string(vertexBytes) + ") lie past the end of the .vtx file (" +
                   std::to_string(vertices.size()) + " bytes)");
        if (indexOffset > indices.size() || indexBytes > indices.size() - indexOffset)
            r.fail(where + "'s indices (bytes " + std::to_string(indexOffset) + " + " +
                   std::to_string(indexBytes) + ") lie past the end of the .idx file (" +
                   std::to_string(indices.size()) + " bytes)");
        if (vertexBytes % kVertexBytes != 0)
            r.fail(where + "'s vtx_size " + std::to_string(vertexBytes) +
                   " is not a whole number of 56-byte vertices");
        if (indexBytes % (3 * kIndexBytes) != 0)
            r.fail(where + "'s idx_size " + std::to_string(indexBytes) +
                   " is not a whole number of triangles");
        uint32_t material = 0;
        std::string materialId = r.text(entry, "material_id", where);
        if (materialId.empty())
            material = defaultMaterial();
        else if (auto found = materialIndex.find(materialId); found != materialIndex.end())
            material = found->second;
        else
            r.fail(where + "'s material_id '" + materialId + "' is in none of " +
                   utf8(materialsPath.filename()));
        ranges.push_back(
            {vertexOffset, vertexBytes / kVertexBytes, indexOffset, indexBytes / kIndexBytes, material});
        totalVertices += vertexBytes / kVertexBytes;
        totalIndices += indexBytes / kIndexBytes;
        if (totalVertices > kMaxModelVertices || totalIndices > kMaxModelIndices)
            r.fail("its meshes make more than " +
                   (totalVertices > kMaxModelVertices ? std::to_string(kMaxModelVertices) + " vertices"
                                                      : std::to_string(kMaxModelIndices) + " indices") +
                   ", our limit");
    }

    // Chapter 17's animated models: the key frames (counted and checked first), then each mesh's
    // weights as its vertices are decoded.
    const uint64_t joints = readBookAnimations(root, model.rig, r);
    const json* animMeshes = nullptr;
    if (root.contains("anim_meshes") && !root["anim_meshes"].is_null()) {
        animMeshes = &root["anim_meshes"];
        if (!animMeshes->is_array() || animMeshes->size() != meshes.size())
            r.fail("\"anim_meshes\" is not a list with an entry for each of its " +
                   std::to_string(meshes.size()) + " meshes");
        if (joints == 0) r.fail("\"anim_meshes\" without \"animations\" (no joints to weigh)");
    }
    model.boundsMin = glm::vec3(std::numeric_limits<float>::max());
    model.boundsMax = glm::vec3(-std::numeric_limits<float>::max());
    // A range that several meshes name is decoded and kept once: the others draw it again -- in a
    // model without animation. An animated model's meshes each have their own anim_meshes entry
    // (the same vertices weighed to other bones), so each is decoded with its own weights (the
    // ranges' sums were checked against our limits above).
    std::map<std::array<uint64_t, 4>, uint32_t> decoded;  // range -> its mesh in model.meshes
    for (size_t i = 0; i < ranges.size(); ++i) {
        const Range& range = ranges[i];
        std::string where = "mesh " + std::to_string(i);
        const std::array<uint64_t, 4> key{range.vertexOffset, range.vertexCount, range.indexOffset,
                                          range.indexCount};
        if (auto found = decoded.find(key); found != decoded.end() && !animMeshes) {
            model.repeats.push_back({found->second, range.material});
            continue;
        }
        MeshData mesh;
        mesh.material = range.material;
        mesh.vertices.resize(size_t(range.vertexCount));
        for (size_t v = 0; v < mesh.vertices.size(); ++v) {
            const uint8_t* bytes = &vertices[size_t(range.vertexOffset) + v * kVertexBytes];
            float f[14];
            for (int k = 0; k < 14; ++k) {
                f[k] = bigEndianFloat(bytes + 4 * k);
                if (!std::isfinite(f[k]) || std::abs(f[k]) > kMaxModelCoordinate)
                    r.fail(where + "'s vertex " + std::to_string(v) +
                           " has a value that is not finite or beyond 1e15");
            }
            Vertex& vertex = mesh.vertices[v];
            vertex.position = {f[0], f[1], f[2]};
            vertex.normal = {f[3], f[4], f[5]};
            vertex.tangent = {f[6], f[7], f[8]};
            vertex.bitangent = {f[9], f[10], f[11]};
            vertex.uv = {f[12], f[13]};  // the book's generator already made v top-down (1 - v)
        }
        mesh.indices.resize(size_t(range.indexCount));
        for (size_t k = 0; k < mesh.indices.size(); ++k) {
            uint32_t index = bigEndianInt(&indices[size_t(range.indexOffset) + k * kIndexBytes]);
            if (index >= range.vertexCount)
                r.fail(where + "'s index " + std::to_string(k) + " is " + std::to_string(index) +
                       ", past its " + std::to_string(range.vertexCount) + " vertices");
            mesh.indices[k] = index;
        }
        if (animMeshes)  // each mesh's entry checked, even a mesh with nothing to draw
            mesh.skin = readBookWeights((*animMeshes)[i], mesh.vertices.size(), joints, r,
                                        "anim_meshes " + std::to_string(i));
        if (mesh.indices.empty()) continue;  // nothing to draw, and no part of the bounds
        for (const Vertex& vertex : mesh.vertices) {
            model.boundsMin = glm::min(model.boundsMin, vertex.position);
            model.boundsMax = glm::max(model.boundsMax, vertex.position);
        }
        decoded.emplace(key, uint32_t(model.meshes.size()));
        model.meshes.push_back(std::move(mesh));
    }
    if (model.meshes.empty()) r.fail("no mesh has a triangle");
    if (animMeshes) {
        // The palette: one joint per matrix of a key frame (the book's matrices are final: a
        // joint's node and inverse bind are not used); posed, the model reaches beyond its meshes.
        model.rig.joints.resize(size_t(joints));
        animatedBounds(model, model.boundsMin, model.boundsMax);
    } else {
        model.rig = {};
    }
    return model;
}
//< book-model

}  // namespace common
