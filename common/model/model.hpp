// Models on the CPU side: OBJ + MTL through tinyobjloader (triangulated, vertices de-duplicated,
// one mesh per material) and glTF 2.0 through tinygltf (common/model/gltf_model.cpp: the default
// scene's nodes baked into the vertices, one mesh per triangle primitive), both into the same
// structures, with per-vertex tangents computed where the file has none. The book's ModelLoader,
// ModelData, MeshData and Material (its chapters 7-9; tangents and PBR materials from chapter 15).
#pragma once

#include <compare>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace common {

// The vertex every scene chapter uses. Its layout is described to Vulkan in common/scene/gpu_scene.cpp
// (sceneVertexInput) and declared in the shaders as locations 0..4.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 tangent;    // unit, orthogonal to the normal, along +u of the texture
    glm::vec3 bitangent;  // unit, along +v of the OBJ's coordinates: up in the image (OpenGL normal maps)
    glm::vec2 uv;         // v flipped from the OBJ's, so v = 0 is the image's first row
};
static_assert(sizeof(Vertex) == 56, "Vertex is read by the GPU with this exact layout");

// How a texture is sampled: a glTF sampler (glTF 2.0 specification, 5.26 "Sampler"); OBJ
// textures, and glTF textures without a sampler, get the default (trilinear, repeat).
enum class Filter : uint8_t { Nearest, Linear };
enum class Wrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };
struct SamplerDesc {
    Filter magFilter = Filter::Linear;
    Filter minFilter = Filter::Linear;
    bool mipmaps = true;                // false: glTF's NEAREST or LINEAR minification, level 0 only
    Filter mipFilter = Filter::Linear;  // between mip levels
    Wrap wrapU = Wrap::Repeat;
    Wrap wrapV = Wrap::Repeat;
    auto operator<=>(const SamplerDesc&) const = default;
};

// Where a texture's encoded pixels (PNG, JPEG, ...) are: a file, or bytes inside the model (a
// glTF data: URI or a GLB buffer view), shared by every material that uses them.
struct ImageSource {
    std::filesystem::path file;  // the image file; for embedded bytes, the model file
    std::shared_ptr<const std::vector<uint8_t>> embedded;
    std::string label;  // embedded bytes: which image of the model ("image 3"), for messages
    bool empty() const { return file.empty() && !embedded; }
    // What messages call it: the file, or "model.glb (image 3)".
    std::string name() const;
    bool operator==(const ImageSource& other) const {
        return file == other.file && embedded == other.embedded;
    }
    auto operator<=>(const ImageSource& other) const {
        if (auto order = file <=> other.file; order != 0) return order;
        return std::compare_three_way()(embedded.get(), other.embedded.get());
    }
};

struct TextureRef {
    ImageSource image;  // empty: no texture
    SamplerDesc sampler;
    bool empty() const { return image.empty(); }
};

// How a material treats its alpha.
enum class AlphaMode : uint8_t {
    Auto,    // OBJ: a cut-out (alpha tested at 0.5) where d or a texel's alpha is below 1
    Opaque,  // glTF OPAQUE: alpha ignored
    Mask,    // glTF MASK (and BLEND, drawn as a mask): discarded where alpha < alphaCutoff
};

// What a material says: an MTL material, or a glTF metallic-roughness material (glTF 2.0
// specification, 3.9 "Materials"). Paths are resolved against the model's directory.
struct MaterialData {
    std::string name;
    glm::vec4 diffuse{1.0f};       // Kd, with d (dissolve) as alpha; glTF baseColorFactor
    float roughness = 1.0f;        // Pr; glTF roughnessFactor
    float metallic = 0.0f;         // Pm; glTF metallicFactor
    TextureRef diffuseTexture;     // map_Kd; glTF baseColorTexture (sRGB)
    TextureRef alphaTexture;       // map_d (its first channel is the alpha); glTF: in the base colour's alpha
    TextureRef normalTexture;      // norm, or bump / map_bump; glTF normalTexture
    float normalScale = 1.0f;      // glTF normalTexture.scale: x and y of the tangent-space normal
    TextureRef metalRoughTexture;  // glTF metallicRoughnessTexture: G = roughness, B = metallic
    TextureRef roughnessTexture;   // map_Pr (first channel), when there is no metalRoughTexture
    TextureRef metallicTexture;    // map_Pm (first channel)
    TextureRef occlusionTexture;   // glTF occlusionTexture: R = ambient occlusion
    float occlusionStrength = 1.0f;
    AlphaMode alphaMode = AlphaMode::Auto;
    float alphaCutoff = 0.5f;  // AlphaMode::Mask
    bool doubleSided = false;  // glTF doubleSided: no back-face culling, back faces' normals flipped
};

// A skinned vertex's influences (glTF 2.0 specification, 3.7.3 "Skins"; the book's AnimMeshData):
// four joints of the model's palette (ModelData::rig.joints) and their weights, which are not
// negative and sum to 1. An unused slot has joint 0 and weight 0.
struct VertexSkin {
    uint16_t joints[4] = {0, 0, 0, 0};
    glm::vec4 weights{1.0f, 0.0f, 0.0f, 0.0f};
};

struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    uint32_t material = 0;  // index into ModelData::materials
    // Empty for a static mesh; else one per vertex: the mesh is posed by the rig's joints, and
    // its vertices are in the space the joints' inverse bind matrices expect.
    std::vector<VertexSkin> skin;
};

// ---- Animation (glTF 2.0 specification, 3.7.3 "Skins" and 3.11 "Animations"; the book's
// Animation, AnimatedFrame) ----

// A node of the model's hierarchy as the animations see it: its parent (an earlier index, or -1)
// and its rest transform -- a matrix, or translation, rotation and scale (T * R * S).
struct RigNode {
    int32_t parent = -1;
    bool hasMatrix = false;  // glTF's `matrix`: never animated (3.11: targets have TRS)
    glm::dmat4 matrix{1.0};
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
};

// One entry of the palette a skinned mesh's vertices name: a node, and the matrix that takes a
// vertex from the mesh's space to the node's (glTF's inverseBindMatrices; identity for a mesh
// that an animated node carries rigidly).
struct RigJoint {
    uint32_t node = 0;
    glm::dmat4 inverseBind{1.0};
};

enum class Interpolation : uint8_t { Step, Linear, CubicSpline };
enum class AnimatedPath : uint8_t { Translation, Rotation, Scale };

// One animated property of one node (3.11.1): key frame times in seconds, strictly increasing,
// and their values (3 or 4 floats a key; with CubicSpline, in-tangent, value, out-tangent).
struct AnimationChannel {
    uint32_t node = 0;
    AnimatedPath path = AnimatedPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<float> values;
};

// A clip: glTF's animation (channels on nodes), or the book's format, which stores every joint's
// final matrix for each key frame (`frames`, joints x key frames, `frameSeconds` apart).
struct AnimationClip {
    std::string name;
    double duration = 0.0;  // seconds: the last key frame's time (0: one key frame)
    std::vector<AnimationChannel> channels;
    double frameSeconds = 0.0;
    std::vector<glm::mat4> frames;  // the book's format: frame f's joint j at [f * joints + j]
};

struct Rig {
    std::vector<RigNode> nodes;  // parents before children
    std::vector<RigJoint> joints;
    std::vector<AnimationClip> clips;
    bool empty() const { return joints.empty(); }
};

// A mesh drawn once more with another material: a model that names one range of vertices and
// indices several times (the book's converted format) holds the range once, as one mesh.
struct MeshRepeat {
    uint32_t mesh = 0;
    uint32_t material = 0;
};

// Corner i (0..7) of the box min..max: bit 0 of i picks max.x, bit 1 max.y, bit 2 max.z.
template <typename Vec>
Vec boxCorner(int i, const Vec& min, const Vec& max) {
    return Vec((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
}

struct ModelData {
    std::vector<MeshData> meshes;
    std::vector<MeshRepeat> repeats;             // drawn after the meshes, in this order
    std::vector<MaterialData> materials;         // at least one: a default white material
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // the meshes as stored (skinned ones unposed)
    Rig rig;                                     // empty: nothing is skinned or animated
};

// What one model may cost (docs/reliability.md, "What a model may cost"). The glTF loader
// decides it from the sizes the file declares, before it decodes an accessor or makes a vertex,
// and refuses a model beyond it in one line naming the limit and the value; an OBJ file pays for
// each triangle with its own bytes, and its faces are checked as they are converted. Sized for
// the largest scenes a reader opens: the book's Sponza has about 262,000 triangles in 103
// primitives, Amazon Lumberyard Bistro about 2.8 M (8.4 M vertices even flat-shaded).
//
// Primitives drawn, each once per node that draws its mesh: 20,000. Each becomes a mesh of its
// own, with two buffers and a draw (about 20 KB of host memory each on lavapipe).
inline constexpr uint64_t kMaxModelPrimitives = 20000;
// Vertices after baking (flat normals, strips and fans unrolled, every node instance): 8 Mi,
// 56 bytes each, 448 MiB -- held three times while a model is uploaded (the CPU copy, the staging
// copy, the device's, which lavapipe keeps in host memory): the largest model admitted peaks
// under 2 GB (docs/reliability.md).
inline constexpr uint64_t kMaxModelVertices = uint64_t{1} << 23;
// Indices after baking: 32 Mi (11 M triangles), 128 MiB.
inline constexpr uint64_t kMaxModelIndices = uint64_t{1} << 25;
// Values decoded from glTF accessors (each accessor once) and the corner lists of the distinct
// primitives (a slot per vertex and per corner): 128 Mi, 512 MiB of floats.
inline constexpr uint64_t kMaxModelValuesRead = uint64_t{1} << 27;

// Animation budgets (docs/reliability.md, "What a model may cost"), checked from the sizes the file
// declares before anything is decoded: joints in a model's palette (a vertex names them in 16 bits;
// the palette is uploaded each frame, 128 bytes a joint), nodes an animation may move, clips and
// key frames in all (each key's values count among kMaxModelValuesRead too).
inline constexpr uint64_t kMaxRigJoints = 4096;
inline constexpr uint64_t kMaxRigNodes = 65536;
inline constexpr uint64_t kMaxAnimationClips = 1024;
inline constexpr uint64_t kMaxAnimationKeys = uint64_t{1} << 24;
// The book's converted JSON (NAME.json and NAME_mat.json), parsed: at most 256 MiB of text a file,
// 16 levels of nesting (the format nests 7), and 4 Mi values and object keys in the two files
// together (numbers, strings, lists, objects, keys), some 100 bytes each once parsed: about 0.5 GB
// for the documents, beside the text, the .vtx and .idx bytes and the meshes decoded from them,
// within the 2 GB a model may peak at (docs/reliability.md). Bob's animation is some 150,000.
inline constexpr uint64_t kMaxBookJsonBytes = uint64_t{256} << 20;
inline constexpr uint64_t kMaxBookJsonDepth = 16;
inline constexpr uint64_t kMaxBookJsonValues = uint64_t{1} << 22;
// How far a vertex's weights may sum from 1 and still be taken (renormalised): what 8-bit
// quantised weights can miss by (four roundings of 1/510 each). Beyond it a model is refused.
inline constexpr double kWeightSumTolerance = 1.0 / 64.0;

// The largest distance from the origin along any axis that a vertex may have after baking: its
// square, and sums of such squares, stay finite in 32-bit floats (loadModel refuses the rest).
inline constexpr float kMaxModelCoordinate = 1e15f;

// Computes per-vertex tangents and bitangents from positions, normals and UVs: per-triangle UV
// derivatives, accumulated per vertex, then made orthogonal to the normal (Gram-Schmidt).
// Zero-area triangles and degenerate UVs contribute nothing; a vertex left without a usable
// tangent gets an arbitrary unit vector orthogonal to its normal. The result is always finite.
void computeTangents(MeshData& mesh);

}  // namespace common
