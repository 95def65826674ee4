// Posing a model's rig at a time: its clips sampled as the glTF 2.0 specification defines them
// (3.11 "Animations", Appendix C "Interpolation": STEP, LINEAR with spherical linear interpolation
// of rotations, CUBICSPLINE), every node's matrix down the hierarchy, and the palette a skinned
// mesh's vertices name. Everything in double precision: the palette is converted to float once per
// joint for the GPU, and the same double pose skins the CPU reference the tests compare the GPU's
// vertices with (skinVertex). The book's AnimationsCache and EntityAnimation, done by time.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/model/model.hpp"

namespace common {

// A clip's time at `seconds` of playing it in a loop: in [0, duration). Looping is done in double,
// so a clock of 10^6 seconds (eleven days) still lands within a nanosecond of the right time.
double clipTime(const AnimationClip& clip, double seconds);

// The pose of `rig` at `seconds` into clip `clip` (looped), or at rest when clip < 0 or the rig
// has no clips: each node's world matrix (in the model's space) and each palette joint's matrix,
// joint = world(node) * inverseBind.
struct Pose {
    std::vector<glm::dmat4> world;
    std::vector<glm::dmat4> joints;
};
void poseRig(const Rig& rig, int clip, double seconds, Pose& pose);

// What the GPU reads per joint (std430 and scalar layout alike, 128 bytes): the joint's matrix
// and the matrix for its normals, the inverse-transpose of its upper 3x3 (zero for a joint
// scaled to nothing: its normals then come from the vertex's other joints), computed here once
// per joint and frame -- not once per vertex as in the book's shader.
struct PaletteEntry {
    glm::mat4 joint{1.0f};
    glm::mat4 normal{1.0f};
};
static_assert(sizeof(PaletteEntry) == 128, "PaletteEntry is read by the GPU with this layout");
PaletteEntry paletteEntry(const glm::dmat4& joint);

// The reference: one vertex skinned in double by linear blend skinning with all four weights,
// as shaders/chapter-17/skin.comp does in float -- position by the joints' matrices, normal by
// their normal matrices, tangent and bitangent by their upper 3x3, then the frame made
// orthonormal about the normal (tangent by Gram-Schmidt, bitangent on its side).
struct SkinnedVertex {
    glm::dvec3 position, normal, tangent, bitangent;
};
SkinnedVertex skinVertex(const Vertex& vertex, const VertexSkin& skin, const std::vector<glm::dmat4>& joints);

// Per mesh and joint, the box of the mesh's vertices that the joint moves (weight above 0), in
// the mesh's space: a skinned vertex is a weighted mean of its joints' images of it, so the posed
// mesh lies within the union of each joint's box posed by the joint.
struct SkinBounds {
    std::vector<uint32_t> joints;  // joints some vertex names with a weight
    std::vector<glm::dvec3> min, max;
    // The vertices no joint moves (all four weights 0: drawn in the bind pose), where there are any.
    bool still = false;
    glm::dvec3 stillMin{0.0}, stillMax{0.0};
};
SkinBounds skinBounds(const MeshData& mesh);
void posedBounds(const SkinBounds& bounds, const std::vector<glm::dmat4>& joints, glm::vec3& min,
                 glm::vec3& max);

// The box every skinned mesh of `model` stays within while its clips play, from the poses at rest
// and at every key time and halfway between (thinned, for a model of very many keys, clips and
// nodes, to about 2^28 node and joint poses in all): a bound for cameras and cascades, not a proof
// (a pose between samples may reach further; chapter-17 checks each frame's pose as it plays).
void animatedBounds(const ModelData& model, glm::vec3& min, glm::vec3& max);

}  // namespace common
