#version 450
// chapter-17: the skinning pass. One invocation per vertex of a skinned mesh: its bind-pose vertex
// blended by its four joints' matrices (linear blend skinning), written to the mesh's own vertex
// buffer, which the shadow and scene passes then draw like any static mesh. The book's
// anim_comp.glsl, right where it is fragile: a bounds check for the last group, all four weights
// for normals, tangents and bitangents, and the joints' normal matrices made once per joint on
// the CPU (chapter-17/skinning_pass.cpp), not per vertex here.
#extension GL_EXT_scalar_block_layout : require

//> skin-inputs
layout(local_size_x = 32) in;  // the book's group of 32

// common::Vertex, 56 bytes, as the vertex input reads it.
struct Vertex {
    vec3 position;
    vec3 normal;
    vec3 tangent;
    vec3 bitangent;
    vec2 uv;
};
// Four joints in 16 bits each (two to a uint), and their weights (they sum to 1).
struct Influence {
    uvec2 joints;
    vec4 weights;
};
// Per joint (common::PaletteEntry): its matrix, and the inverse-transpose of its upper 3x3.
struct Joint {
    mat4 position;
    mat4 normal;
};

layout(set = 0, binding = 0, scalar) readonly buffer BindPose { Vertex bindPose[]; };
layout(set = 0, binding = 1, scalar) readonly buffer Influences { Influence influences[]; };
layout(set = 0, binding = 2, std430) readonly buffer Palette { Joint palette[]; };
layout(set = 0, binding = 3, scalar) writeonly buffer Skinned { Vertex skinned[]; };

// The buffers above are bound to one chunk of a mesh (a mesh larger than a binding or a dispatch
// can hold takes several, skinning_pass.cpp): vertex 0 is the chunk's first.
layout(push_constant) uniform Dispatch {
    uint count;        // the chunk's vertices
    uint paletteBase;  // the model's first joint in the palette
} dispatch;
//< skin-inputs

vec3 unitOr(vec3 v, vec3 fallback) {
    float length2 = dot(v, v);
    return length2 > 1e-30 ? v * inversesqrt(length2) : fallback;
}

//> skin-main
void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= dispatch.count) return;  // the book's shader reads and writes past the buffers here
    Vertex v = bindPose[index];
    Influence influence = influences[index];
    // A vertex no joint moves (four weights of 0: the book's generator writes them for a part of an
    // animated model that no bone touches) stays where the mesh puts it, the bind pose.
    if (influence.weights == vec4(0.0)) {
        skinned[index] = v;
        return;
    }
    uint joints[4] = uint[4](influence.joints.x & 0xffffu, influence.joints.x >> 16,
                             influence.joints.y & 0xffffu, influence.joints.y >> 16);
    vec4 position = vec4(0.0);
    vec3 normal = vec3(0.0), tangent = vec3(0.0), bitangent = vec3(0.0);
    for (int k = 0; k < 4; ++k) {  // all four (the book's normals use three)
        float weight = influence.weights[k];
        Joint joint = palette[dispatch.paletteBase + joints[k]];
        position += weight * (joint.position * vec4(v.position, 1.0));
        normal += weight * (mat3(joint.normal) * v.normal);
        tangent += weight * (mat3(joint.position) * v.tangent);
        bitangent += weight * (mat3(joint.position) * v.bitangent);
    }
    // The frame made orthonormal about the normal: tangent by Gram-Schmidt, bitangent on its side.
    vec3 n = unitOr(normal, v.normal);
    vec3 t = unitOr(tangent - n * dot(n, tangent), v.tangent);
    vec3 side = cross(n, t);
    Vertex out_ = Vertex(position.xyz, n, t, dot(side, bitangent) < 0.0 ? -side : side, v.uv);
    skinned[index] = out_;
}
//< skin-main
