#version 450
// chapter-18: the skinning pass through pointers. chapter-17's skin.comp with its four storage
// buffers replaced by the addresses each dispatch pushes (the book's chapter-18 anim_comp.glsl, its
// descriptor sets gone); the arithmetic is chapter-17's, line for line. The joint ids it reads were
// checked against the model's joints when the model was loaded: a pointer has no robust-access net.
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_buffer_reference : require

//> skin-inputs
layout(local_size_x = 32) in;  // the book's group of 32

// common::Vertex, 56 bytes.
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

layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer BindPose { Vertex vertices[]; };
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer Influences { Influence influences[]; };
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer Palette { Joint joints[]; };
layout(buffer_reference, scalar, buffer_reference_align = 4) writeonly buffer Skinned { Vertex vertices[]; };

// chapter-17/skinning_pass.hpp's SkinningAddresses: one chunk of a mesh (vertex 0 is the chunk's
// first) and the frame's palette from the model's first joint.
layout(push_constant, scalar) uniform Dispatch {
    BindPose bindPose;
    Influences influences;
    Palette palette;
    Skinned skinned;
    uint count;
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
    Vertex v = dispatch.bindPose.vertices[index];
    Influence influence = dispatch.influences.influences[index];
    // A vertex no joint moves (four weights of 0: the book's generator writes them for a part of an
    // animated model that no bone touches) stays where the mesh puts it, the bind pose.
    if (influence.weights == vec4(0.0)) {
        dispatch.skinned.vertices[index] = v;
        return;
    }
    uint joints[4] = uint[4](influence.joints.x & 0xffffu, influence.joints.x >> 16,
                             influence.joints.y & 0xffffu, influence.joints.y >> 16);
    vec4 position = vec4(0.0);
    vec3 normal = vec3(0.0), tangent = vec3(0.0), bitangent = vec3(0.0);
    for (int k = 0; k < 4; ++k) {  // all four (the book's normals use three)
        float weight = influence.weights[k];
        Joint joint = dispatch.palette.joints[joints[k]];
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
    dispatch.skinned.vertices[index] = out_;
}
//< skin-main
