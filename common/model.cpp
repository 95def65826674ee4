// OBJ/MTL loading and tangent generation.
#include "common/model.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "common/check.hpp"

namespace common {
namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A unit vector orthogonal to unit `n` (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
glm::vec3 anyOrthogonal(const glm::vec3& n) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

// tinyobjloader reads numbers with its own parser and turns text it cannot read into 0 without
// a word, so a damaged file would load as a different model. We check the numbers we use:
// `count` tokens after `key` must be finite numbers (`optional` more may follow).
void checkNumbers(const std::filesystem::path& file, int lineNumber, std::istringstream& tokens,
                  const std::string& key, int count, int optional) {
    for (int i = 0; i < count + optional; ++i) {
        std::string token;
        if (!(tokens >> token)) {
            if (i < count)
                throw InputError(file.string() + ":" + std::to_string(lineNumber) + ": '" + key + "' needs " +
                                 std::to_string(count) + " numbers");
            return;
        }
        char* end = nullptr;
        double value = std::strtod(token.c_str(), &end);
        if (*end != '\0' || !std::isfinite(value))
            throw InputError(file.string() + ":" + std::to_string(lineNumber) + ": '" + key + "' has '" +
                             token + "', not a finite number");
    }
}

// The keys each material of an MTL file states (tinyobjloader cannot tell a missing Pr from Pr 0),
// after checking their numbers.
using MaterialKeys = std::map<std::string, std::set<std::string>>;

void checkMtl(const std::filesystem::path& mtl, MaterialKeys& keys) {
    std::ifstream in(mtl);
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

// One pass over the OBJ text: the numbers of v / vn / vt lines, and the MTL files it names.
MaterialKeys checkObjText(const std::filesystem::path& obj) {
    MaterialKeys keys;
    std::ifstream in(obj);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream tokens(line);
        std::string key;
        tokens >> key;
        if (key == "v") checkNumbers(obj, number, tokens, key, 3, 4);  // x y z [w] or x y z r g b
        if (key == "vn") checkNumbers(obj, number, tokens, key, 3, 0);
        if (key == "vt") checkNumbers(obj, number, tokens, key, 1, 2);
        if (key == "mtllib")
            for (std::string file; tokens >> file;) checkMtl(obj.parent_path() / file, keys);
    }
    return keys;
}

std::filesystem::path texturePath(const std::filesystem::path& directory, const std::string& name) {
    if (name.empty()) return {};
    std::string cleaned = name;
    for (char& c : cleaned)
        if (c == '\\') c = '/';  // MTL files written on Windows
    return directory / cleaned;
}

}  // namespace

ModelData loadObjModel(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string() + ": no such file");
    std::filesystem::path directory = path.parent_path();

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = directory.string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path.string(), config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        for (char& c : why)
            if (c == '\n') c = ' ';
        throw InputError(path.string() + ": " + (why.empty() ? "cannot parse OBJ" : why));
    }
    // tinyobjloader only warns about a material library it cannot open; we refuse the model, since
    // every material would silently fall back to white.
    if (reader.Warning().find("not found") != std::string::npos &&
        reader.Warning().find("Material") != std::string::npos)
        throw InputError(path.string() + ": a material library it names cannot be read (" +
                         reader.Warning().substr(0, reader.Warning().find('\n')) + ")");

    MaterialKeys stated = checkObjText(path);
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    ModelData model;
    for (const tinyobj::material_t& m : reader.GetMaterials()) {
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

    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const tinyobj::mesh_t& mesh = shape.mesh;
        for (size_t face = 0; face < mesh.num_face_vertices.size(); ++face) {
            if (mesh.num_face_vertices[face] != 3)
                continue;  // triangulated: anything else is a line or point
            int id = face < mesh.material_ids.size() ? mesh.material_ids[face] : -1;
            uint32_t material = (id >= 0 && size_t(id) < defaultMaterial) ? uint32_t(id) : defaultMaterial;
            MeshData& out = perMaterial[material];
            for (int corner = 0; corner < 3; ++corner) {
                const tinyobj::index_t& index = mesh.indices[face * 3 + corner];
                if (index.vertex_index < 0 || size_t(index.vertex_index) >= positions ||
                    (index.normal_index >= 0 && size_t(index.normal_index) >= normals) ||
                    (index.texcoord_index >= 0 && size_t(index.texcoord_index) >= uvs))
                    throw InputError(path.string() +
                                     ": a face refers to a vertex, normal or texture coordinate "
                                     "that does not exist");
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
                    if (!finite(v.position) || !finite(v.normal) || !std::isfinite(v.uv.x) ||
                        !std::isfinite(v.uv.y))
                        throw InputError(path.string() + ": a vertex has a non-finite coordinate");
                    out.vertices.push_back(v);
                }
                out.indices.push_back(it->second);
            }
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
    if (model.meshes.empty()) throw InputError(path.string() + ": the model has no triangles");
    return model;
}

const ModelData& loadObjModelCached(ModelCache& cache, const std::filesystem::path& path) {
    auto it = cache.find(path);
    if (it == cache.end()) it = cache.emplace(path, loadObjModel(path)).first;
    return it->second;
}

void computeTangents(MeshData& mesh) {
    std::vector<glm::dvec3> tangents(mesh.vertices.size(), glm::dvec3(0.0));
    std::vector<glm::dvec3> bitangents(mesh.vertices.size(), glm::dvec3(0.0));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        uint32_t ids[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        const Vertex &a = mesh.vertices[ids[0]], &b = mesh.vertices[ids[1]], &c = mesh.vertices[ids[2]];
        // Solve [e1 e2] = [t b] * [du; dv] in double: UV areas of a texel or less are common.
        glm::dvec3 e1 = glm::dvec3(b.position - a.position), e2 = glm::dvec3(c.position - a.position);
        // uv.y was flipped at load; the tangent frame follows the OBJ's v (up in the image), the
        // convention normal maps are authored in, so the v differences are negated back.
        glm::dvec2 d1 = glm::dvec2(b.uv - a.uv) * glm::dvec2(1, -1),
                   d2 = glm::dvec2(c.uv - a.uv) * glm::dvec2(1, -1);
        double det = d1.x * d2.y - d2.x * d1.y;
        double area = glm::length(glm::cross(e1, e2));
        if (!(std::abs(det) > 1e-12) || !(area > 1e-20)) continue;  // degenerate UVs or zero area
        glm::dvec3 t = (e1 * d2.y - e2 * d1.y) / det;
        glm::dvec3 bt = (e2 * d1.x - e1 * d2.x) / det;
        // Weight by the triangle's area so slivers do not dominate; t and bt scale with 1/det,
        // so normalise first.
        double tl = glm::length(t), bl = glm::length(bt);
        if (!(tl > 0.0) || !(bl > 0.0) || !std::isfinite(tl) || !std::isfinite(bl)) continue;
        for (uint32_t id : ids) {
            tangents[id] += t / tl * area;
            bitangents[id] += bt / bl * area;
        }
    }
    for (size_t k = 0; k < mesh.vertices.size(); ++k) {
        Vertex& v = mesh.vertices[k];
        glm::dvec3 n = glm::dvec3(v.normal);
        glm::dvec3 t = tangents[k] - n * glm::dot(n, tangents[k]);  // Gram-Schmidt
        double length = glm::length(t);
        glm::vec3 tangent =
            (length > 1e-12 && std::isfinite(length)) ? glm::vec3(t / length) : anyOrthogonal(v.normal);
        // The bitangent is the cross product, flipped where the UVs are mirrored.
        glm::vec3 bitangent = glm::cross(v.normal, tangent);
        if (glm::dot(glm::dvec3(bitangent), bitangents[k]) < 0.0) bitangent = -bitangent;
        v.tangent = tangent;
        v.bitangent = bitangent;
    }
}

}  // namespace common
