// The glTF loader, part 3 of 3: the scene. glTF 2.0 models into the structures the OBJ loader
// fills (common/model/model.hpp), from the document part 1 checked (common/model/gltf_document.hpp) and the
// accessors part 2 reads (common/model/gltf_accessors.hpp).
//
// The default scene's node hierarchy is baked into the vertices (the book's Assimp import does
// the same with PreTransformVertices): one MeshData per triangle primitive of each node that has
// a mesh, in the model's own space. What that will cost -- vertices and indices after baking,
// through every node that instances a mesh, and the values decoded -- is added up from the
// sizes the file declares before anything is decoded, and a model beyond the budget
// (common/model/model.hpp) is refused then. Each primitive's corner list is made once, whatever the
// number of nodes that share it; each node then only transforms the vertices it bakes.
#include "common/model/gltf_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "common/core/check.hpp"
#include "common/core/checked.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/gltf_accessors.hpp"
#include "common/model/gltf_document.hpp"
#include "common/model/model.hpp"

namespace common {
namespace {

// The deepest node hierarchy we walk (a longer chain is almost surely a hostile file). The walk
// keeps its own stack, so depth costs no call stack; the limit is on what a real scene does.
constexpr int kMaxNodeDepth = 1024;

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
        if (seen_.insert(what).second) notes_.push_back(what);
    }
    // An extension skipped: one warning per extension, however many places use it, for the first
    // kMaxExtensionNotes; the rest are counted in one more line.
    void extension(const std::string& name, const std::string& what) {
        if (!extensions_.insert(name).second) return;
        if (extensions_.size() <= kMaxExtensionNotes) note(what);
    }
    // One line each: names from the file (extensions) may hold control characters, shown as '?'.
    void print() const {
        std::vector<std::string> notes = notes_;
        if (extensions_.size() > kMaxExtensionNotes)
            notes.push_back(std::to_string(extensions_.size() - kMaxExtensionNotes) +
                            " more extensions are skipped");
        for (const std::string& what : notes) warn(origin_ + ": " + what);
    }

private:
    std::string origin_;
    static constexpr size_t kMaxExtensionNotes = 16;
    std::vector<std::string> notes_;
    std::set<std::string> seen_, extensions_;
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
    MaterialReader(const GltfDocument& document, const GltfReader& reader, Skipped& skipped)
        : model_(document.model), reader_(reader), embedded_(document.embedded), skipped_(skipped) {}

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

// ---- Node transforms (3.5.3) ----------------------------------------------------------------

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

// ---- Nodes (3.5) ---------------------------------------------------------------------------

// A node that draws a mesh, with its transform into the model's space.
struct NodeInstance {
    int node;
    glm::dmat4 world;
};

// 3.5.1 "Scenes" and 3.5.2 "Nodes and Hierarchy": the default scene's nodes (every root node
// when there is no scene), checked to form a forest (one parent each, no cycles), walked with a
// stack of our own. Returns the nodes that have a mesh, in the order a depth-first walk meets them.
std::vector<NodeInstance> sceneInstances(const tinygltf::Model& model, const GltfReader& reader,
                                         Skipped& skipped) {
    std::vector<int> parents(model.nodes.size(), -1);
    for (size_t i = 0; i < model.nodes.size(); ++i)
        for (int child : model.nodes[i].children) {
            reader.get(model.nodes, child, "nodes[" + std::to_string(i) + "].children: node");
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
        std::vector<bool> listed(model.nodes.size(), false);
        for (int root : roots) {
            reader.get(model.nodes, root, "scenes[" + std::to_string(scene) + "].nodes: node");
            // 5.25 "Scene": its nodes are unique (each listed twice would be walked twice).
            if (listed[size_t(root)])
                reader.fail("scenes[" + std::to_string(scene) + "].nodes lists node " + std::to_string(root) +
                            " twice");
            listed[size_t(root)] = true;
            if (parents[size_t(root)] >= 0)
                reader.fail("node " + std::to_string(root) + " is a root and a child");
        }
    } else {
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (parents[i] < 0) roots.push_back(int(i));
    }

    // Depth first, children in their order, as a recursive walk would go: the stack holds what is
    // left to visit, the last entry first.
    struct Pending {
        int node;
        glm::dmat4 parent;
        int depth;
    };
    std::vector<Pending> stack;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root)
        stack.push_back({*root, glm::dmat4(1.0), 0});
    std::vector<NodeInstance> instances;
    while (!stack.empty()) {
        Pending pending = stack.back();
        stack.pop_back();
        if (pending.depth >= kMaxNodeDepth)
            reader.fail("the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " (a cycle?)");
        const tinygltf::Node& node = model.nodes[size_t(pending.node)];
        const std::string where = "nodes[" + std::to_string(pending.node) + "]";
        const glm::dmat4 world = pending.parent * localMatrix(node, reader, where);
        if (node.skin >= 0) skipped.note("skins are not applied (drawn unskinned)");
        if (node.mesh >= 0) {
            reader.get(model.meshes, node.mesh, where + ".mesh: mesh");
            instances.push_back({pending.node, world});
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, world, pending.depth + 1});
    }
    return instances;
}

// ---- Meshes (3.7) --------------------------------------------------------------------------

int attribute(const tinygltf::Primitive& primitive, const char* name) {
    auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

// Whether a primitive is drawn (3.7.2.1 topology types): triangles, strips and fans are; points
// and lines are skipped with a warning; any other mode is refused.
bool drawsTriangles(const tinygltf::Primitive& primitive, const GltfReader& reader, const std::string& at,
                    Skipped& skipped) {
    const int mode = primitive.mode;
    if (mode == -1 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
        mode == TINYGLTF_MODE_TRIANGLE_FAN)
        return true;
    if (mode < 0 || mode > 6) reader.fail(at + ".mode " + std::to_string(mode) + " is not 0 to 6");
    skipped.note("points and lines are not drawn");
    return false;
}

// A node scaled by zero shows nothing (and has no inverse for its normals).
bool degenerate(const glm::dmat4& world) {
    return std::abs(glm::determinant(glm::dmat3(world))) < 1e-300;
}

std::string primitiveName(int mesh, size_t primitive) {
    return "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]";
}

// What the default scene will cost, from the counts the document declares (checked by part 1):
// refused here, before any accessor is decoded or any vertex made, when it exceeds the budget of
// common/model/model.hpp. Each mesh's cost is added up once, over its primitives; each node that draws
// it then adds that sum, so this costs the nodes plus the primitives, never their product.
void checkBudget(const tinygltf::Model& model, const std::vector<NodeInstance>& instances,
                 const GltfReader& reader, Skipped& skipped) {
    struct MeshCost {
        bool known = false;
        uint64_t vertices = 0, indices = 0;
    };
    std::vector<MeshCost> meshCosts(model.meshes.size());
    uint64_t draws = 0, vertices = 0, indices = 0, valuesRead = 0;
    std::set<int> accessorsSeen;
    auto read = [&](int accessor, const std::string& what) {
        if (accessor >= 0 && accessorsSeen.insert(accessor).second)
            valuesRead = saturatingAdd(
                valuesRead, saturatingMul(reader.count(accessor, what), reader.components(accessor)));
    };
    // One mesh's primitives, the first time a node draws it; the accessors it reads are counted
    // then (each once, however many meshes share it).
    auto meshCost = [&](int meshIndex) -> const MeshCost& {
        MeshCost& cost = meshCosts[size_t(meshIndex)];
        if (cost.known) return cost;
        cost.known = true;
        const tinygltf::Mesh& mesh = model.meshes[size_t(meshIndex)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string at = primitiveName(meshIndex, p);
            if (!drawsTriangles(primitive, reader, at, skipped)) continue;
            const int position = attribute(primitive, "POSITION");
            if (position < 0) reader.fail(at + " has no POSITION");
            const uint64_t vertexCount = reader.count(position, at + " POSITION");
            const uint64_t corners =
                primitive.indices >= 0 ? reader.count(primitive.indices, at + " indices") : vertexCount;
            const uint64_t triangles =
                primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP || primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN
                    ? (corners >= 3 ? corners - 2 : 0)
                    : corners / 3;
            const bool normals = attribute(primitive, "NORMAL") >= 0;
            // At most: flat normals give each triangle three vertices of its own; with normals, a
            // vertex is baked once however many triangles use it.
            const uint64_t baked = 3 * triangles;  // counts are at most 2^25: no wrap
            cost.vertices = saturatingAdd(cost.vertices, normals ? std::min(vertexCount, baked) : baked);
            cost.indices = saturatingAdd(cost.indices, baked);
            // A primitive's corner list: a slot for each of its vertices and each corner.
            valuesRead = saturatingAdd(valuesRead, vertexCount + baked);
            read(position, at + " POSITION");
            read(attribute(primitive, "NORMAL"), at + " NORMAL");
            if (normals) read(attribute(primitive, "TANGENT"), at + " TANGENT");
            read(attribute(primitive, "TEXCOORD_0"), at + " TEXCOORD_0");
            read(primitive.indices, at + " indices");
        }
        return cost;
    };
    for (const NodeInstance& instance : instances) {
        if (degenerate(instance.world)) continue;
        const int meshIndex = model.nodes[size_t(instance.node)].mesh;
        const MeshCost& cost = meshCost(meshIndex);
        draws = saturatingAdd(draws, model.meshes[size_t(meshIndex)].primitives.size());
        vertices = saturatingAdd(vertices, cost.vertices);
        indices = saturatingAdd(indices, cost.indices);
    }
    auto limit = [&](uint64_t value, uint64_t max, const std::string& what) {
        if (value > max)
            reader.fail("the default scene " + what + " " +
                        (value == kNoFit ? std::string("2^64 or more") : std::to_string(value)) + " (in " +
                        std::to_string(instances.size()) + (instances.size() == 1 ? " node" : " nodes") +
                        "); at most " + std::to_string(max) + " are loaded");
    };
    limit(draws, kMaxModelPrimitives, "draws primitives:");
    limit(vertices, kMaxModelVertices, "bakes vertices:");
    limit(indices, kMaxModelIndices, "bakes indices:");
    limit(valuesRead, kMaxModelValuesRead, "reads accessor values:");
}

// A triangle primitive's corners, made once however many nodes draw it: which of its vertices
// each baked vertex is (`source`), and the triangles over the baked vertices (`indices`, in the
// primitive's winding). Without normals every triangle has three vertices of its own (flat).
struct PrimitiveShape {
    const std::vector<float>* positions = nullptr;
    const std::vector<float>* normals = nullptr;
    const std::vector<float>* tangents = nullptr;
    const std::vector<float>* uvs = nullptr;
    std::vector<uint32_t> source, indices;
};

PrimitiveShape makeShape(const tinygltf::Primitive& primitive, GltfReader& reader, const std::string& where,
                         Skipped& skipped) {
    constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
    PrimitiveShape shape;
    // 3.7.2.1 "Overview": which component types each attribute may have.
    shape.positions = &reader.floats(attribute(primitive, "POSITION"), where + " POSITION",
                                     {TINYGLTF_TYPE_VEC3}, {kFloat}, false);
    const size_t vertexCount = shape.positions->size() / 3;
    auto sameCount = [&](int accessor, const char* name) {
        if (accessor >= 0 && reader.count(accessor, where + " " + name) != vertexCount)
            reader.fail(where + " " + name + " has another count than POSITION");
    };
    const int normalAccessor = attribute(primitive, "NORMAL"),
              tangentAccessor = attribute(primitive, "TANGENT"),
              uvAccessor = attribute(primitive, "TEXCOORD_0");
    sameCount(normalAccessor, "NORMAL");
    sameCount(tangentAccessor, "TANGENT");
    sameCount(uvAccessor, "TEXCOORD_0");
    if (normalAccessor >= 0)
        shape.normals =
            &reader.floats(normalAccessor, where + " NORMAL", {TINYGLTF_TYPE_VEC3}, {kFloat}, false);
    if (tangentAccessor >= 0 && normalAccessor >= 0)  // 3.7.2.1: without normals, tangents are ignored
        shape.tangents =
            &reader.floats(tangentAccessor, where + " TANGENT", {TINYGLTF_TYPE_VEC4}, {kFloat}, false);
    if (uvAccessor >= 0)
        shape.uvs = &reader.floats(
            uvAccessor, where + " TEXCOORD_0", {TINYGLTF_TYPE_VEC2},
            {kFloat, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, true);
    if (primitive.targets.size()) skipped.note("morph targets are not applied (drawn in the base shape)");
    for (const auto& [name, accessor] : primitive.attributes) {
        if (name.rfind("JOINTS_", 0) == 0) skipped.note("skins are not applied (drawn unskinned)");
        if (name.rfind("COLOR_", 0) == 0) skipped.note("vertex colours (COLOR_n) are not used");
    }

    // The primitive's corners as triangles, counter-clockwise (3.7.2.1, its topology types).
    std::vector<uint32_t> identity;
    if (primitive.indices < 0) {
        identity.resize(vertexCount);
        for (uint32_t i = 0; i < vertexCount; ++i) identity[i] = i;
    }
    const std::vector<uint32_t>& corners =
        primitive.indices >= 0 ? reader.indices(primitive.indices, vertexCount, where + " indices")
                               : identity;
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
    if (!shape.normals) {
        // 3.7.2.1: without NORMAL, flat normals: each triangle gets its own three vertices.
        shape.source = std::move(triangles);
        shape.indices.resize(shape.source.size());
        for (uint32_t i = 0; i < shape.indices.size(); ++i) shape.indices[i] = i;
    } else {
        // Only the vertices the triangles use, in the order first used.
        std::vector<uint32_t> remap(vertexCount, UINT32_MAX);
        shape.indices.reserve(triangles.size());
        for (uint32_t corner : triangles) {
            uint32_t& slot = remap[corner];
            if (slot == UINT32_MAX) {
                slot = uint32_t(shape.source.size());
                shape.source.push_back(corner);
            }
            shape.indices.push_back(slot);
        }
    }
    return shape;
}

// One triangle primitive drawn by a node, baked into the model's space.
MeshData bakePrimitive(const PrimitiveShape& shape, const glm::dmat4& world, const GltfReader& reader,
                       const std::string& where, uint32_t material) {
    const std::vector<float>& positions = *shape.positions;
    const std::vector<float>* normals = shape.normals;
    const std::vector<float>* tangents = shape.tangents;
    const std::vector<float>* uvs = shape.uvs;
    MeshData mesh;
    mesh.material = material;
    // Positions by the node's world matrix, normals by its inverse-transpose; a mirroring
    // transform (negative determinant) turns the winding around (3.7.4 "Instantiation").
    const glm::dmat3 linear(world), normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0;
    bool unusableTangent = false;  // a file's tangent along its normal, or zero
    auto vertex = [&](uint32_t i) {
        Vertex v{};
        glm::dvec4 p = world * glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0);
        v.position = glm::vec3(p);
        if (normals) {
            glm::dvec3 n0((*normals)[3 * i], (*normals)[3 * i + 1], (*normals)[3 * i + 2]);
            glm::dvec3 n = unitOr(normalMatrix * n0, glm::dvec3(0.0, 1.0, 0.0));
            v.normal = glm::vec3(n);
            if (tangents) {
                // 3.7.2.1: bitangent = cross(normal, tangent.xyz) * w, in the primitive's space;
                // tangent and bitangent transformed as directions in the surface, then the frame
                // made orthonormal about the normal (a file's tangent need not be perpendicular to
                // its normal), keeping the bitangent's side.
                glm::dvec3 t0((*tangents)[4 * i], (*tangents)[4 * i + 1], (*tangents)[4 * i + 2]);
                double w = (*tangents)[4 * i + 3] < 0.0f ? -1.0 : 1.0;
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
        if (uvs) v.uv = {(*uvs)[2 * i], (*uvs)[2 * i + 1]};  // (0, 0) is the image's first texel (3.8)
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z))
            reader.fail(where + ": a transformed position is not finite");
        return v;
    };

    mesh.vertices.reserve(shape.source.size());
    if (!normals) {
        // Flat normals, from the transformed corners of each triangle.
        for (size_t k = 0; k + 2 < shape.source.size(); k += 3) {
            Vertex a = vertex(shape.source[k]), b = vertex(shape.source[k + 1]),
                   c = vertex(shape.source[k + 2]);
            if (mirrored) std::swap(b, c);
            glm::dvec3 n =
                glm::cross(glm::dvec3(b.position - a.position), glm::dvec3(c.position - a.position));
            glm::vec3 flat =
                glm::length(n) > 0.0 ? glm::vec3(glm::normalize(n)) : glm::vec3(0.0f, 1.0f, 0.0f);
            for (Vertex* v : {&a, &b, &c}) {
                v->normal = flat;
                mesh.vertices.push_back(*v);
            }
        }
        mesh.indices = shape.indices;
    } else {
        for (uint32_t i : shape.source) mesh.vertices.push_back(vertex(i));
        mesh.indices = shape.indices;
        if (mirrored)
            for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3)
                std::swap(mesh.indices[k + 1], mesh.indices[k + 2]);
    }
    // Tangents where the file has none (3.7.2.1 asks for MikkTSpace; ours: common/model/model.cpp), or
    // where one of its tangents is unusable.
    if (!tangents || unusableTangent) computeTangents(mesh);
    return mesh;
}

}  // namespace

ModelData loadGltfModel(const std::filesystem::path& path) {
    const GltfDocument document = readGltfDocument(path);
    const tinygltf::Model& model = document.model;
    GltfReader reader(document);
    Skipped skipped(document.origin);
    if (!model.cameras.empty()) skipped.note("its cameras are not used (the scene's camera is)");
    if (!model.animations.empty()) skipped.note("animations are not played");

    ModelData out;
    MaterialReader materials(document, reader, skipped);
    for (int i = 0; i < int(model.materials.size()); ++i) out.materials.push_back(materials.material(i));
    for (const std::string& name : model.extensionsUsed)  // those the materials used are noted already
        skipped.extension(name, "extension " + name + " is not used");
    const uint32_t defaultMaterial = uint32_t(out.materials.size());
    // 3.9.6 "Default Material": a primitive without one is opaque white, metallic 1, roughness 1.
    out.materials.push_back(
        MaterialData{.name = "default", .roughness = 1.0f, .metallic = 1.0f, .alphaMode = AlphaMode::Opaque});

    const std::vector<NodeInstance> instances = sceneInstances(model, reader, skipped);
    checkBudget(model, instances, reader, skipped);

    std::map<std::pair<int, size_t>, PrimitiveShape> shapes;
    bool first = true;
    for (const NodeInstance& instance : instances) {
        if (degenerate(instance.world)) continue;
        const int meshIndex = model.nodes[size_t(instance.node)].mesh;
        const tinygltf::Mesh& mesh = model.meshes[size_t(meshIndex)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string at = primitiveName(meshIndex, p);
            if (primitive.material >= 0)
                reader.get(model.materials, primitive.material, at + ".material: material");
            if (!drawsTriangles(primitive, reader, at, skipped)) continue;
            auto shape = shapes.find({meshIndex, p});
            if (shape == shapes.end())
                shape =
                    shapes.emplace(std::pair{meshIndex, p}, makeShape(primitive, reader, at, skipped)).first;
            if (shape->second.indices.empty()) continue;
            MeshData baked =
                bakePrimitive(shape->second, instance.world, reader, at,
                              primitive.material >= 0 ? uint32_t(primitive.material) : defaultMaterial);
            for (const Vertex& v : baked.vertices) {
                out.boundsMin = first ? v.position : glm::min(out.boundsMin, v.position);
                out.boundsMax = first ? v.position : glm::max(out.boundsMax, v.position);
                first = false;
            }
            out.meshes.push_back(std::move(baked));
        }
    }
    if (out.meshes.empty())
        throw InputError(document.origin + ": the model's default scene has no triangles");
    skipped.print();
    return out;
}

}  // namespace common
