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
#include "common/model/animation.hpp"
#include "common/model/gltf_accessors.hpp"
#include "common/model/gltf_document.hpp"
#include "common/model/model.hpp"

namespace common {
namespace {

// A sum of weights for a message: six significant digits.
std::string sumText(double sum) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", sum);
    return text;
}

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
std::vector<NodeInstance> sceneInstances(const tinygltf::Model& model, const GltfReader& reader) {
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
        if (node.mesh >= 0) {
            reader.get(model.meshes, node.mesh, where + ".mesh: mesh");
            instances.push_back({pending.node, world});
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, world, pending.depth + 1});
    }
    return instances;
}

// A primitive's attribute accessor, or -1.
int attribute(const tinygltf::Primitive& primitive, const char* name) {
    auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

// ---- Skins and animations (3.7.3, 3.11) ------------------------------------------------------

// What animations move and skins pose, read before the meshes are baked. A mesh a skin poses is
// kept in its own space (3.7.3.3: the skinned node's transform is ignored; the joints place it);
// a mesh on a node that an animation moves (or moves an ancestor of) is kept in the node's space
// and carried by a joint of its own, weight 1, at the node. Other meshes are baked as before.
struct RigReader {
    Rig rig;
    std::vector<int32_t> rigNode;       // glTF node -> rig node (-1 when the model has no rig)
    std::vector<bool> animated;         // glTF node: moved by an animation, itself or an ancestor
    std::map<int, uint32_t> skinBase;   // skin -> its first joint in rig.joints
    std::map<int, uint32_t> rigidBase;  // node carried rigidly -> its joint
    bool used() const { return !rigNode.empty(); }
};

// Before anything is decoded: what the skins and animations declare, against model.hpp's budgets.
void checkRigBudget(const tinygltf::Model& model, const GltfReader& reader) {
    uint64_t joints = 0, keys = 0, values = 0;
    for (const tinygltf::Skin& skin : model.skins) joints = saturatingAdd(joints, skin.joints.size());
    // Per channel: each keeps its sampler's key times and values (channels may share a sampler).
    for (size_t a = 0; a < model.animations.size(); ++a)
        for (const tinygltf::AnimationChannel& channel : model.animations[a].channels) {
            const int s = channel.sampler;
            const std::string at =
                "animations[" + std::to_string(a) + "].samplers[" + std::to_string(s) + "]";
            const tinygltf::AnimationSampler& sampler =
                reader.get(model.animations[a].samplers, s, "animations[" + std::to_string(a) + "] sampler");
            reader.get(model.accessors, sampler.input, at + ".input: accessor");
            reader.get(model.accessors, sampler.output, at + ".output: accessor");
            keys = saturatingAdd(keys, reader.count(sampler.input, at + ".input"));
            values = saturatingAdd(values, saturatingMul(reader.count(sampler.output, at + ".output"),
                                                         reader.components(sampler.output)));
        }
    auto limit = [&](uint64_t value, uint64_t max, const std::string& what) {
        if (value > max)
            reader.fail("the model " + what + " " +
                        (value == kNoFit ? std::string("2^64 or more") : std::to_string(value)) +
                        "; at most " + std::to_string(max) + " are loaded");
    };
    limit(joints, kMaxRigJoints, "has skin joints:");
    limit(model.animations.size(), kMaxAnimationClips, "has animations:");
    limit(keys, kMaxAnimationKeys, "has animation key frames:");
    limit(values, kMaxModelValuesRead, "has animation values:");
    if (!model.skins.empty() || !model.animations.empty())
        limit(model.nodes.size(), kMaxRigNodes, "has nodes:");
}

Interpolation interpolation(const std::string& name, const GltfReader& reader, const std::string& at) {
    if (name == "LINEAR" || name.empty()) return Interpolation::Linear;
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    reader.fail(at + ".interpolation " + shown(name) + " is not LINEAR, STEP or CUBICSPLINE");
}

// Every node of the model, parents first, with its rest transform; every animation's channels.
RigReader readRig(const tinygltf::Model& model, GltfReader& reader, Skipped& skipped) {
    RigReader out;
    bool skinned = false;
    for (const tinygltf::Node& node : model.nodes) skinned = skinned || node.skin >= 0;
    if (!skinned && model.animations.empty()) return out;
    checkRigBudget(model, reader);
    // Parents first: a walk from each root (sceneInstances has checked the forest).
    std::vector<int> parents(model.nodes.size(), -1), order;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        for (int child : model.nodes[i].children) parents[size_t(child)] = int(i);
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (parents[i] < 0) order.push_back(int(i));
    for (size_t k = 0; k < order.size(); ++k)
        for (int child : model.nodes[size_t(order[k])].children) order.push_back(child);
    out.rigNode.assign(model.nodes.size(), -1);
    for (int node : order)
        out.rigNode[size_t(node)] = int32_t(out.rig.nodes.size()), out.rig.nodes.push_back({});
    for (int i : order) {
        const tinygltf::Node& node = model.nodes[size_t(i)];
        const std::string where = "nodes[" + std::to_string(i) + "]";
        RigNode& rigNode = out.rig.nodes[size_t(out.rigNode[size_t(i)])];
        rigNode.parent = parents[size_t(i)] >= 0 ? out.rigNode[size_t(parents[size_t(i)])] : -1;
        rigNode.matrix = localMatrix(node, reader, where);  // checks every number
        rigNode.hasMatrix = !node.matrix.empty();
        if (!node.translation.empty())
            rigNode.translation = {node.translation[0], node.translation[1], node.translation[2]};
        if (!node.rotation.empty())
            rigNode.rotation = glm::normalize(
                glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
        if (!node.scale.empty()) rigNode.scale = {node.scale[0], node.scale[1], node.scale[2]};
    }

    out.animated.assign(model.nodes.size(), false);
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        const std::string at = "animations[" + std::to_string(a) + "]";
        AnimationClip clip;
        clip.name = animation.name.empty() ? "animation " + std::to_string(a) : animation.name;
        std::set<std::pair<int, std::string>> targets;  // 3.11.1: each (node, path) once
        for (size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = animation.channels[c];
            const std::string where = at + ".channels[" + std::to_string(c) + "]";
            if (channel.target_path == "weights") {
                skipped.note("morph target weights are not animated");
                continue;
            }
            if (channel.target_node < 0) continue;  // 3.11.2: an extension names the target
            const tinygltf::Node& node =
                reader.get(model.nodes, channel.target_node, where + ".target.node: node");
            if (!targets.insert({channel.target_node, channel.target_path}).second)
                reader.fail(where + " animates node " + std::to_string(channel.target_node) + "'s " +
                            channel.target_path + " again (an animation targets each property once)");
            AnimationChannel out1;
            out1.node = uint32_t(out.rigNode[size_t(channel.target_node)]);
            size_t components = 3;
            if (channel.target_path == "translation") {
                out1.path = AnimatedPath::Translation;
            } else if (channel.target_path == "rotation") {
                out1.path = AnimatedPath::Rotation;
                components = 4;
            } else if (channel.target_path == "scale") {
                out1.path = AnimatedPath::Scale;
            } else {
                reader.fail(where + ".target.path " + shown(channel.target_path) +
                            " is not translation, rotation, scale or weights");
            }
            // 3.11.2: an animated node has no matrix (its TRS properties are what is animated).
            if (!node.matrix.empty())
                reader.fail(where + " animates node " + std::to_string(channel.target_node) +
                            ", which has a matrix (an animated node has translation, rotation and scale)");
            const tinygltf::AnimationSampler& sampler =
                reader.get(animation.samplers, channel.sampler, where + ".sampler: sampler");
            const std::string samplerAt = at + ".samplers[" + std::to_string(channel.sampler) + "]";
            out1.interpolation = interpolation(sampler.interpolation, reader, samplerAt);
            const std::vector<float>& times =
                reader.floats(sampler.input, samplerAt + ".input", {TINYGLTF_TYPE_SCALAR},
                              {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
            if (times.empty()) reader.fail(samplerAt + ".input has no key frames");
            // 3.11.2 (animation sampler): times in seconds, time[0] >= 0, strictly increasing.
            for (size_t k = 0; k < times.size(); ++k)
                if (times[k] < 0.0f || (k > 0 && !(times[k] > times[k - 1])))
                    reader.fail(samplerAt +
                                ".input's key frame times are not increasing from 0 or more (key " +
                                std::to_string(k) + ")");
            const bool cubic = out1.interpolation == Interpolation::CubicSpline;
            if (cubic && times.size() < 2)
                reader.fail(samplerAt + " is CUBICSPLINE with fewer than 2 key frames");
            const std::vector<float>* values = nullptr;
            if (out1.path == AnimatedPath::Rotation)
                values = &reader.floats(sampler.output, samplerAt + ".output", {TINYGLTF_TYPE_VEC4},
                                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                        true);
            else
                values = &reader.floats(sampler.output, samplerAt + ".output", {TINYGLTF_TYPE_VEC3},
                                        {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
            const size_t expected = times.size() * (cubic ? 3 : 1) * components;
            if (values->size() != expected)
                reader.fail(samplerAt + ".output has " + std::to_string(values->size() / components) +
                            " values for " + std::to_string(times.size()) + " key frames" +
                            (cubic ? " (CUBICSPLINE: 3 a key frame)" : ""));
            if (out1.path == AnimatedPath::Rotation)
                for (size_t k = cubic ? 1 : 0; k < values->size() / 4; k += cubic ? 3 : 1) {
                    const float* q = &(*values)[4 * k];
                    if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 1e-12f))
                        reader.fail(samplerAt + ".output's rotation " + std::to_string(cubic ? k / 3 : k) +
                                    " is not a unit quaternion (it is zero)");
                }
            out1.times = times;
            out1.values = *values;
            clip.duration = std::max(clip.duration, double(times.back()));
            out.animated[size_t(channel.target_node)] = true;
            clip.channels.push_back(std::move(out1));
        }
        out.rig.clips.push_back(std::move(clip));
    }
    // What an animated node carries moves with it.
    for (int i : order)
        if (parents[size_t(i)] >= 0 && out.animated[size_t(parents[size_t(i)])])
            out.animated[size_t(i)] = true;
    return out;
}

// The first palette joint of `skin` (its joints added the first time a mesh uses it).
uint32_t skinJoints(RigReader& rig, const tinygltf::Model& model, int skinIndex, GltfReader& reader,
                    const std::string& where) {
    if (auto found = rig.skinBase.find(skinIndex); found != rig.skinBase.end()) return found->second;
    const tinygltf::Skin& skin = reader.get(model.skins, skinIndex, where + ".skin: skin");
    const std::string at = "skins[" + std::to_string(skinIndex) + "]";
    if (skin.joints.empty()) reader.fail(at + " has no joints");
    const std::vector<float>* inverseBind = nullptr;
    if (skin.inverseBindMatrices >= 0) {
        inverseBind = &reader.floats(skin.inverseBindMatrices, at + ".inverseBindMatrices",
                                     {TINYGLTF_TYPE_MAT4}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
        if (inverseBind->size() / 16 < skin.joints.size())
            reader.fail(at + ".inverseBindMatrices has " + std::to_string(inverseBind->size() / 16) +
                        " matrices for " + std::to_string(skin.joints.size()) + " joints");
    }
    const uint32_t base = uint32_t(rig.rig.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        reader.get(model.nodes, skin.joints[j], at + ".joints: node");
        RigJoint joint{.node = uint32_t(rig.rigNode[size_t(skin.joints[j])])};
        if (inverseBind) {
            joint.inverseBind = glm::dmat4(glm::make_mat4(&(*inverseBind)[16 * j]));
            // 3.7.3.1: an inverse bind matrix is an affine transform, its fourth row (0, 0, 0, 1)
            // (to an exporter's rounding); another would distort the pose unseen.
            const glm::dmat4& m = joint.inverseBind;
            if (std::abs(m[0][3]) > 1e-4 || std::abs(m[1][3]) > 1e-4 || std::abs(m[2][3]) > 1e-4 ||
                std::abs(m[3][3] - 1.0) > 1e-4)
                reader.fail(at + ".inverseBindMatrices[" + std::to_string(j) +
                            "]'s fourth row is not 0, 0, 0, 1 (not an affine transform)");
        }
        rig.rig.joints.push_back(joint);
    }
    rig.skinBase[skinIndex] = base;
    return base;
}

// A primitive's influences for the baked vertices of `shape` (JOINTS_n and WEIGHTS_n, 3.7.3.2):
// every set the primitive has, at most the four largest weights kept, each vertex checked --
// a joint the skin has, no weight negative, their sum within kWeightSumTolerance of 1 (then made
// exactly 1).
std::vector<VertexSkin> readInfluences(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                       const std::vector<uint32_t>& source, uint32_t jointBase,
                                       size_t jointCount, GltfReader& reader, const std::string& where,
                                       Skipped& skipped) {
    struct Set {
        const std::vector<float>* joints;
        const std::vector<float>* weights;
    };
    std::vector<Set> sets;
    const size_t vertexCount = reader.count(attribute(primitive, "POSITION"), where + " POSITION");
    for (int n = 0;; ++n) {
        const std::string jointsName = "JOINTS_" + std::to_string(n),
                          weightsName = "WEIGHTS_" + std::to_string(n);
        const int joints = attribute(primitive, jointsName.c_str()),
                  weights = attribute(primitive, weightsName.c_str());
        if (joints < 0 && weights < 0) break;
        if (joints < 0 || weights < 0)
            reader.fail(where + " has " + (joints < 0 ? weightsName : jointsName) + " without " +
                        (joints < 0 ? jointsName : weightsName));
        if (reader.get(model.accessors, joints, where + " " + jointsName + ": accessor").normalized)
            reader.fail(where + " " + jointsName + " is normalized (joint ids are whole numbers)");
        for (int accessor : {joints, weights})
            if (reader.count(accessor, where + " " + jointsName) != vertexCount)
                reader.fail(where + " " + (accessor == joints ? jointsName : weightsName) +
                            " has another count than POSITION");
        sets.push_back(
            {&reader.floats(joints, where + " " + jointsName, {TINYGLTF_TYPE_VEC4},
                            {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                            false),
             &reader.floats(weights, where + " " + weightsName, {TINYGLTF_TYPE_VEC4},
                            {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                            true)});
    }
    std::vector<VertexSkin> skin(source.size());
    bool dropped = false;
    for (size_t v = 0; v < source.size(); ++v) {
        const size_t i = source[v];
        std::vector<std::pair<float, uint32_t>> influences;
        double sum = 0.0;
        for (const Set& set : sets)
            for (size_t c = 0; c < 4; ++c) {
                const float weight = (*set.weights)[4 * i + c], joint = (*set.joints)[4 * i + c];
                if (!(weight >= 0.0f))
                    reader.fail(where + " vertex " + std::to_string(i) + " has a negative weight");
                if (joint >= float(jointCount))  // 3.7.3.2: every id is one of the skin's joints
                    reader.fail(where + " vertex " + std::to_string(i) + " names joint " +
                                std::to_string(uint64_t(joint)) + "; its skin has " +
                                std::to_string(jointCount));
                if (weight == 0.0f) continue;
                sum += weight;
                influences.push_back({weight, uint32_t(joint)});
            }
        VertexSkin& out = skin[v];
        out.weights = glm::vec4(0.0f);
        out.joints[0] = out.joints[1] = out.joints[2] = out.joints[3] = uint16_t(jointBase);
        // Weights of 0 alone: a vertex no joint moves (the specification asks sums close to 1
        // with a SHOULD, and the glTF-Validator's own valid samples hold such vertices), drawn
        // where the mesh puts it.
        if (sum == 0.0) continue;
        if (!(std::abs(sum - 1.0) <= kWeightSumTolerance))
            reader.fail(where + " vertex " + std::to_string(i) + "'s weights sum to " + sumText(sum) +
                        ", not 1 (nor 0: no joint)");
        if (sets.size() == 1) {  // each weight stays in its slot
            // An unused slot names the vertex's heaviest joint: its weight 0 times a joint no
            // weight uses (whose matrix might not even be finite) would still be computed.
            size_t heaviest = 0;
            for (size_t c = 1; c < 4; ++c)
                if ((*sets[0].weights)[4 * i + c] > (*sets[0].weights)[4 * i + heaviest]) heaviest = c;
            for (size_t c = 0; c < 4; ++c) {
                const float weight = (*sets[0].weights)[4 * i + c];
                const size_t slot = weight == 0.0f ? heaviest : c;
                out.joints[c] = uint16_t(jointBase + uint32_t((*sets[0].joints)[4 * i + slot]));
                out.weights[int(c)] = float(weight / sum);
            }
            continue;
        }
        std::stable_sort(influences.begin(), influences.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        if (influences.size() > 4) {
            dropped = true;
            influences.resize(4);
        }
        double kept = 0.0;
        for (const auto& [weight, joint] : influences) kept += weight;
        for (size_t k = 0; k < 4; ++k) {  // unused slots: the heaviest joint, weight 0
            out.joints[k] = uint16_t(jointBase + influences[k < influences.size() ? k : 0].second);
            if (k < influences.size()) out.weights[int(k)] = float(influences[k].first / kept);
        }
    }
    if (dropped)
        skipped.note("vertices with more than four weights keep their four largest (made to sum to 1)");
    return skin;
}

// ---- Meshes (3.7) --------------------------------------------------------------------------

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
            for (const auto& [name, accessor] : primitive.attributes)
                if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0)
                    read(accessor, at + " " + name);
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

    ModelData out;
    MaterialReader materials(document, reader, skipped);
    for (int i = 0; i < int(model.materials.size()); ++i) out.materials.push_back(materials.material(i));
    for (const std::string& name : model.extensionsUsed)  // those the materials used are noted already
        skipped.extension(name, "extension " + name + " is not used");
    const uint32_t defaultMaterial = uint32_t(out.materials.size());
    // 3.9.6 "Default Material": a primitive without one is opaque white, metallic 1, roughness 1.
    out.materials.push_back(
        MaterialData{.name = "default", .roughness = 1.0f, .metallic = 1.0f, .alphaMode = AlphaMode::Opaque});

    const std::vector<NodeInstance> instances = sceneInstances(model, reader);
    checkBudget(model, instances, reader, skipped);

    RigReader rig = readRig(model, reader, skipped);

    std::map<std::pair<int, size_t>, PrimitiveShape> shapes;
    bool first = true;
    for (const NodeInstance& instance : instances) {
        const tinygltf::Node& node = model.nodes[size_t(instance.node)];
        // A skinned node's meshes stay in their own space, an animated node's in the node's.
        const bool skinnedNode = rig.used() && node.skin >= 0;
        const bool carried = rig.used() && rig.animated[size_t(instance.node)];
        if (!skinnedNode && !carried && degenerate(instance.world)) continue;
        const int meshIndex = node.mesh;
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
            const bool skins = skinnedNode && attribute(primitive, "JOINTS_0") >= 0;
            if (skinnedNode && !skins) skipped.note("a skin whose mesh has no JOINTS_0 is not applied");
            MeshData baked =
                bakePrimitive(shape->second, skins || carried ? glm::dmat4(1.0) : instance.world, reader, at,
                              primitive.material >= 0 ? uint32_t(primitive.material) : defaultMaterial);
            if (skins) {
                const uint32_t base =
                    skinJoints(rig, model, node.skin, reader, "nodes[" + std::to_string(instance.node) + "]");
                baked.skin =
                    readInfluences(model, primitive, shape->second.source, base,
                                   model.skins[size_t(node.skin)].joints.size(), reader, at, skipped);
            } else if (carried) {
                auto joint = rig.rigidBase.find(instance.node);
                if (joint == rig.rigidBase.end()) {
                    joint = rig.rigidBase.emplace(instance.node, uint32_t(rig.rig.joints.size())).first;
                    rig.rig.joints.push_back({.node = uint32_t(rig.rigNode[size_t(instance.node)])});
                }
                VertexSkin rigid;
                rigid.joints[0] = uint16_t(joint->second);
                baked.skin.assign(baked.vertices.size(), rigid);
            }
            if (rig.rig.joints.size() > kMaxRigJoints)
                reader.fail("the model's skins and animated meshes need more than " +
                            std::to_string(kMaxRigJoints) + " joints");
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
    // Posed by its clips, the model reaches beyond its meshes as stored.
    if (!rig.rig.joints.empty()) {
        out.rig = std::move(rig.rig);
        animatedBounds(out, out.boundsMin, out.boundsMax);
        if (!std::isfinite(out.boundsMin.x + out.boundsMin.y + out.boundsMin.z + out.boundsMax.x +
                           out.boundsMax.y + out.boundsMax.z) ||
            std::max({maxAbs(glm::dvec3(out.boundsMin)), maxAbs(glm::dvec3(out.boundsMax))}) >
                kMaxModelCoordinate)
            reader.fail(
                "the model's animations move it beyond 1e15 from the origin (or to a number that is not "
                "finite)");
    } else if (!model.animations.empty()) {
        skipped.note("its animations move no mesh");
    }
    skipped.print();
    return out;
}

}  // namespace common
