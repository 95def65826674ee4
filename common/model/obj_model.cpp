// OBJ and MTL files through tinyobjloader, checked line by line first (the book's ModelLoader
// reads OBJ through Assimp; its chapter 7).
#include "common/model/obj_model.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"

namespace common {
namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A token for a message: a megabyte-long number is quoted by its first characters.
std::string shortQuote(const std::string& token) {
    return "'" + (token.size() > 32 ? token.substr(0, 32) + "..." : token) + "'";
}

std::string at(const std::filesystem::path& file, int lineNumber) {
    return utf8(file) + ":" + std::to_string(lineNumber) + ": ";
}

// tinyobjloader reads numbers with its own parser and turns text it cannot read into 0 without
// a word, so a damaged file would load as a different model. We check the numbers we use:
// `count` tokens after `key` must be finite numbers (`optional` more may follow, then nothing but
// a comment; tinyobjloader would ignore the rest of the line).
void checkNumbers(const std::filesystem::path& file, int lineNumber, std::istringstream& tokens,
                  const std::string& key, int count, int optional) {
    for (int i = 0; i < count + optional; ++i) {
        std::string token;
        if (!(tokens >> token)) {
            if (i < count)
                throw InputError(at(file, lineNumber) + "'" + key + "' needs " + std::to_string(count) +
                                 " numbers");
            return;
        }
        char* end = nullptr;
        double value = std::strtod(token.c_str(), &end);
        // strtod also reads hexadecimal ("0x1p3" is 8), which tinyobjloader reads as 0.
        if (*end != '\0' || !std::isfinite(value) || token.find_first_of("xX") != std::string::npos)
            throw InputError(at(file, lineNumber) + "'" + key + "' has " + shortQuote(token) +
                             ", not a finite number");
    }
    if (std::string extra; tokens >> extra && extra[0] != '#')
        throw InputError(at(file, lineNumber) + "'" + key + "' has more than " +
                         std::to_string(count + optional) + " numbers");
}

// The whole of an OBJ or MTL file as text. A UTF-8 byte order mark is dropped (tinyobjloader would
// read it as part of the first keyword and lose that line); UTF-16 and binary files are refused,
// since tinyobjloader reads them as text with no faces, or as a different model.
std::string readText(const std::filesystem::path& file) {
    std::string text = readInputFile(file);
    if (text.starts_with("\xff\xfe") || text.starts_with("\xfe\xff"))
        throw InputError(utf8(file) + ": UTF-16 text; save it as UTF-8 or ASCII");
    if (text.starts_with("\xef\xbb\xbf")) text.erase(0, 3);
    // tinyobjloader ends a line at "\n", "\r\n" or a lone "\r" (old Mac files); our checks split at
    // "\n", so they would miss a line that tinyobjloader reads. Both get "\n" only.
    size_t kept = 0;
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] != '\r' || i + 1 == text.size() || text[i + 1] != '\n')
            text[kept++] = text[i] == '\r' ? '\n' : text[i];
    text.resize(kept);
    if (size_t nul = text.find('\0'); nul != std::string::npos)
        throw InputError(at(file, 1 + int(std::count(text.begin(), text.begin() + long(nul), '\n'))) +
                         "not a text file (a NUL byte)");
    return text;
}

// The keys each material of an MTL file states (tinyobjloader cannot tell a missing Pr from Pr 0),
// after checking their numbers.
using MaterialKeys = std::map<std::string, std::set<std::string>>;

void checkMtl(const std::filesystem::path& mtl, MaterialKeys& keys) {
    std::istringstream in(readText(mtl));
    std::string line, material;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream tokens(line);
        std::string key;
        tokens >> key;
        if (key == "newmtl") tokens >> material;
        keys[material].insert(key);
        if (key == "Kd" || key == "Ka" || key == "Ks") checkNumbers(mtl, number, tokens, key, 3, 0);
        if (key == "d" || key == "Tr" || key == "Pr" || key == "Pm" || key == "Ns")
            checkNumbers(mtl, number, tokens, key, 1, 0);
    }
}

// A face's corners as tinyobjloader stores them: one byte for their count.
constexpr size_t kMaxFaceCorners = 255;

// Each index of a face corner ("7", "7/2", "7//3", "-1/-1/-1") must be a whole number that fits
// an int: tinyobjloader reads them with atoi, and an overflowing one wraps around to a valid
// relative index (99999999999999999999 becomes -1, the last vertex).
void checkFace(const std::filesystem::path& obj, int lineNumber, std::istringstream& tokens) {
    size_t corners = 0;
    for (std::string corner; tokens >> corner; ++corners) {
        std::istringstream parts(corner);
        for (std::string part; std::getline(parts, part, '/');) {
            if (part.empty()) continue;
            long long index = 0;
            auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
            if (error != std::errc() || end != part.data() + part.size() || index < -INT_MAX ||
                index > INT_MAX)
                throw InputError(at(obj, lineNumber) + "'f' has " + shortQuote(part) +
                                 ", not a vertex index");
        }
    }
    if (corners > kMaxFaceCorners)
        throw InputError(at(obj, lineNumber) + "a face of " + std::to_string(corners) + " corners (at most " +
                         std::to_string(kMaxFaceCorners) + ")");
}

struct ObjText {
    MaterialKeys stated;                              // per MTL material, the keys it states
    std::vector<std::pair<std::string, int>> usemtl;  // the materials the OBJ uses, with their line
    std::set<std::string> libraries;                  // the MTL file names checked, as mtllib gives them
};

// The file names of an `mtllib` line, split as tinyobjloader splits them: at spaces (not tabs),
// a backslash keeping the next character ("my\ materials.mtl" is one name). Splitting any other
// way would check other files than the ones tinyobjloader then reads.
std::vector<std::string> mtllibNames(const std::string& line) {
    size_t start = line.find("mtllib") + 7;  // the keyword and the one blank after it
    std::vector<std::string> names;
    std::string name;
    bool escaped = false;
    for (size_t i = start; i < line.size(); ++i) {
        char c = line[i];
        if (!escaped && c == '\\') {
            escaped = true;
            continue;
        }
        if (!escaped && c == ' ') {
            if (!name.empty()) names.push_back(name);
            name.clear();
            continue;
        }
        escaped = false;
        name += c;
    }
    if (!name.empty()) names.push_back(name);
    return names;
}

// One pass over the OBJ text: the numbers of v / vn / vt lines, the indices of f lines, the MTL
// files it names and the materials it uses.
ObjText checkObjText(const std::filesystem::path& obj, const std::string& text) {
    ObjText result;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream tokens(line);
        std::string key;
        tokens >> key;
        if (key == "v") checkNumbers(obj, number, tokens, key, 3, 4);  // x y z [w] or x y z r g b
        if (key == "vn") checkNumbers(obj, number, tokens, key, 3, 0);
        if (key == "vt") checkNumbers(obj, number, tokens, key, 1, 2);
        if (key == "f") checkFace(obj, number, tokens);
        // tinyobjloader's skin weights: it converts their joint ids to int unchecked (undefined
        // behaviour for 1e38), and we use no weights.
        if (key == "vw") throw InputError(at(obj, number) + "'vw' (vertex weights) is not supported");
        // tinyobjloader's tags: "t name a/b/c" makes a, b and c ints, floats and strings of a
        // megabyte each for a line of 20 characters; we use no tags.
        if (key == "t") throw InputError(at(obj, number) + "'t' (tags) is not supported");
        if (key == "usemtl")
            if (std::string name; tokens >> name) result.usemtl.emplace_back(name, number);
        if (key == "mtllib")
            for (const std::string& file : mtllibNames(line)) {
                if (result.libraries.count(file)) continue;  // named again: checked once
                std::filesystem::path mtl = obj.parent_path() / file;
                std::error_code ec;
                if (!std::filesystem::is_regular_file(mtl, ec))
                    throw InputError(utf8(obj) + ": a material library it names cannot be read (" +
                                     utf8(mtl) + ")");
                checkMtl(mtl, result.stated);
                result.libraries.insert(file);
            }
    }
    return result;
}

// Hands tinyobjloader the MTL files as checked text (through readText) instead of letting it
// open them, and only the ones checkObjText checked.
class MtlReader : public tinyobj::MaterialReader {
public:
    MtlReader(std::filesystem::path obj, const std::set<std::string>& checked)
        : obj_(std::move(obj)), checked_(checked) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning, std::string* error) override {
        if (name.empty()) return false;  // "mtllib" and blanks: tinyobjloader uses the default material
        if (!checked_.count(name))
            throw InputError(utf8(obj_) + ": material library '" + name + "' was not read as named");
        std::istringstream text(readText(obj_.parent_path() / name));
        tinyobj::LoadMtl(names, materials, &text, warning, error);
        return true;
    }

private:
    std::filesystem::path obj_;
    const std::set<std::string>& checked_;
};

// Splits a polygon into triangles (corner indices, n - 2 triangles of the polygon's winding) by
// ear clipping in the plane the polygon faces most (from its Newell normal). tinyobjloader's own
// triangulation is wrong for concave polygons: it splits a quad along its shorter diagonal, and its
// ear test of longer polygons depends on where the polygon lies relative to the origin.
std::vector<uint32_t> triangulate(const std::vector<glm::dvec3>& corners) {
    const size_t n = corners.size();
    glm::dvec3 normal(0.0);
    for (size_t i = 0; i < n; ++i)
        normal += glm::cross(corners[i] - corners[0], corners[(i + 1) % n] - corners[0]);
    glm::dvec3 size = glm::abs(normal);
    int u = 0, v = 1;  // the plane with the largest projected area, oriented so the polygon is CCW
    double sign = normal.z;
    if (size.x >= size.y && size.x >= size.z)
        u = 1, v = 2, sign = normal.x;
    else if (size.y >= size.z)
        u = 2, v = 0, sign = normal.y;
    auto cross = [&](uint32_t a, uint32_t b, uint32_t c) {
        glm::dvec3 ab = corners[b] - corners[a], ac = corners[c] - corners[a];
        return (ab[u] * ac[v] - ab[v] * ac[u]) * (sign < 0.0 ? -1.0 : 1.0);
    };
    std::vector<uint32_t> remaining(n), triangles;
    for (uint32_t i = 0; i < n; ++i) remaining[i] = i;
    for (size_t i = 0, tried = 0; remaining.size() > 3 && tried < remaining.size(); ++tried) {
        size_t m = remaining.size();
        i %= m;
        uint32_t a = remaining[(i + m - 1) % m], b = remaining[i], c = remaining[(i + 1) % m];
        bool ear = cross(a, b, c) > 0.0;         // a convex corner ...
        for (size_t k = 0; k < m && ear; ++k) {  // ... with no other corner inside or on its triangle
            uint32_t p = remaining[k];
            if (p != a && p != b && p != c)
                ear = !(cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0);
        }
        if (!ear) {
            ++i;
            continue;
        }
        triangles.insert(triangles.end(), {a, b, c});
        remaining.erase(remaining.begin() + long(i));
        tried = 0;
        i += m - 2;  // go on from the corner before the one removed
    }
    // What is left: a triangle, or a polygon without ears (self-intersecting, or flat): a fan.
    for (size_t k = 1; k + 1 < remaining.size(); ++k)
        triangles.insert(triangles.end(), {remaining[0], remaining[k], remaining[k + 1]});
    return triangles;
}

TextureRef texturePath(const std::filesystem::path& directory, const std::string& name) {
    if (name.empty()) return {};
    std::string cleaned = name;
    for (char& c : cleaned)
        if (c == '\\') c = '/';  // MTL files written on Windows
    return TextureRef{.image = {.file = directory / cleaned}};
}

}  // namespace

ModelData loadObjModel(const std::filesystem::path& path) {
    std::filesystem::path directory = path.parent_path();

    // Our checks of the text first: tinyobjloader reads almost anything as some model.
    std::string text = readText(path);
    ObjText checked = checkObjText(path, text);
    MaterialKeys& stated = checked.stated;

    // Faces as written (not triangulated by tinyobjloader: see triangulate() for why).
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    std::istringstream stream(text);
    MtlReader mtlReader(path, checked.libraries);
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, &mtlReader,
                          /*triangulate=*/false, /*default_vcols_fallback=*/false)) {
        std::string why = error;
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        for (char& c : why)
            if (c == '\n') c = ' ';
        throw InputError(utf8(path) + ": " + (why.empty() ? "cannot parse OBJ" : why));
    }

    ModelData model;
    for (const tinyobj::material_t& m : materials) {
        MaterialData material;
        material.name = m.name;
        material.diffuse = glm::vec4(m.diffuse[0], m.diffuse[1], m.diffuse[2], m.dissolve);
        // Without Pr the book's default: fully rough (tinyobjloader would say 0, a mirror).
        material.roughness = stated[m.name].count("Pr") ? m.roughness : 1.0f;
        material.metallic = stated[m.name].count("Pm") ? m.metallic : 0.0f;
        material.diffuseTexture = texturePath(directory, m.diffuse_texname);
        material.normalTexture =
            texturePath(directory, m.normal_texname.empty() ? m.bump_texname : m.normal_texname);
        material.roughnessTexture = texturePath(directory, m.roughness_texname);
        material.metallicTexture = texturePath(directory, m.metallic_texname);
        material.alphaTexture = texturePath(directory, m.alpha_texname);
        model.materials.push_back(material);
    }
    uint32_t defaultMaterial = static_cast<uint32_t>(model.materials.size());
    model.materials.push_back(MaterialData{.name = "default"});  // faces without usemtl, or an unknown name

    // One mesh per material, vertices de-duplicated by their (position, normal, uv) index triple.
    struct Key {
        int v, n, t;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            return (size_t(uint32_t(k.v)) * 73856093u) ^ (size_t(uint32_t(k.n)) * 19349663u) ^
                   (size_t(uint32_t(k.t)) * 83492791u);
        }
    };
    std::vector<MeshData> perMaterial(model.materials.size());
    std::vector<std::unordered_map<Key, uint32_t, KeyHash>> seen(model.materials.size());
    std::vector<bool> needsNormals(model.materials.size(), false);
    const size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3,
                 uvs = attrib.texcoords.size() / 2;

    uint64_t bakedVertices = 0, bakedIndices = 0;
    auto addCorner = [&](MeshData& out, uint32_t material, const tinyobj::index_t& index) {
        Key key{index.vertex_index, index.normal_index, index.texcoord_index};
        auto [it, inserted] = seen[material].try_emplace(key, uint32_t(out.vertices.size()));
        if (inserted) {
            Vertex v{};
            const float* p = &attrib.vertices[3 * size_t(index.vertex_index)];
            v.position = {p[0], p[1], p[2]};
            if (index.normal_index >= 0) {
                const float* n = &attrib.normals[3 * size_t(index.normal_index)];
                v.normal = {n[0], n[1], n[2]};
            } else {
                needsNormals[material] = true;
            }
            if (index.texcoord_index >= 0) {
                const float* t = &attrib.texcoords[2 * size_t(index.texcoord_index)];
                v.uv = {t[0], 1.0f - t[1]};  // OBJ's v runs up, Vulkan's image rows run down
            }
            if (!finite(v.position) || !finite(v.normal) || !std::isfinite(v.uv.x) || !std::isfinite(v.uv.y))
                throw InputError(utf8(path) + ": a vertex has a non-finite coordinate");
            out.vertices.push_back(v);
            ++bakedVertices;
        }
        out.indices.push_back(it->second);
    };

    for (const tinyobj::shape_t& shape : shapes) {
        const tinyobj::mesh_t& mesh = shape.mesh;  // faces only: lines and points are elsewhere
        size_t offset = 0;
        for (size_t face = 0; face < mesh.num_face_vertices.size(); ++face) {
            const size_t count = mesh.num_face_vertices[face];
            if (count < 3 || offset + count > mesh.indices.size())
                throw InputError(utf8(path) + ": a face has fewer than 3 corners or too many");
            std::vector<glm::dvec3> corners;
            for (size_t corner = offset; corner < offset + count; ++corner) {
                const tinyobj::index_t& index = mesh.indices[corner];
                if (index.vertex_index < 0 || size_t(index.vertex_index) >= positions ||
                    (index.normal_index >= 0 && size_t(index.normal_index) >= normals) ||
                    (index.texcoord_index >= 0 && size_t(index.texcoord_index) >= uvs))
                    throw InputError(utf8(path) +
                                     ": a face refers to a vertex, normal or texture coordinate "
                                     "that does not exist");
                const float* p = &attrib.vertices[3 * size_t(index.vertex_index)];
                corners.emplace_back(p[0], p[1], p[2]);
            }
            int id = face < mesh.material_ids.size() ? mesh.material_ids[face] : -1;
            uint32_t material = (id >= 0 && size_t(id) < defaultMaterial) ? uint32_t(id) : defaultMaterial;
            for (uint32_t corner : triangulate(corners))
                addCorner(perMaterial[material], material, mesh.indices[offset + corner]);
            offset += count;
            // The budget of common/model/model.hpp, as the faces are read (each is paid for by its
            // bytes, so nothing before this can cost more than the file's size).
            bakedIndices += 3 * (count - 2);
            if (bakedIndices > kMaxModelIndices || bakedVertices > kMaxModelVertices)
                throw InputError(utf8(path) + ": the model has more than " +
                                 (bakedIndices > kMaxModelIndices
                                      ? std::to_string(kMaxModelIndices) + " indices"
                                      : std::to_string(kMaxModelVertices) + " vertices") +
                                 " (at face " + std::to_string(face + 1) +
                                 (shape.name.empty() ? std::string() : " of '" + shape.name + "'") +
                                 "); at most that many are loaded");
        }
    }

    bool first = true;
    for (uint32_t material = 0; material < perMaterial.size(); ++material) {
        MeshData& mesh = perMaterial[material];
        if (mesh.indices.empty()) continue;
        mesh.material = material;
        if (needsNormals[material]) {
            // No normals in the file: area-weighted face normals for the vertices that lack one.
            std::vector<glm::vec3> accumulated(mesh.vertices.size(), glm::vec3(0.0f));
            for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
                uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
                glm::vec3 n = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                         mesh.vertices[c].position - mesh.vertices[a].position);
                for (uint32_t k : {a, b, c}) accumulated[k] += n;
            }
            for (size_t k = 0; k < mesh.vertices.size(); ++k)
                if (glm::dot(mesh.vertices[k].normal, mesh.vertices[k].normal) == 0.0f)
                    mesh.vertices[k].normal = accumulated[k];
        }
        for (Vertex& v : mesh.vertices) {
            float length = glm::length(v.normal);
            v.normal =
                (length > 1e-20f && std::isfinite(length)) ? v.normal / length : glm::vec3(0.0f, 1.0f, 0.0f);
            model.boundsMin = first ? v.position : glm::min(model.boundsMin, v.position);
            model.boundsMax = first ? v.position : glm::max(model.boundsMax, v.position);
            first = false;
        }
        computeTangents(mesh);
        model.meshes.push_back(std::move(mesh));
    }
    if (model.meshes.empty()) throw InputError(utf8(path) + ": the model has no triangles");
    // Faces whose usemtl names no material of the MTL files get the default (white) material.
    std::set<std::string> warned;
    for (const auto& [name, line] : checked.usemtl)
        if (!stated.count(name) && warned.insert(name).second)
            warn(utf8(path) + ":" + std::to_string(line) + ": material '" + name +
                 "' is in none of its MTL files; using the default material");
    return model;
}

}  // namespace common
