// chapter-15-lab: the skinning study's skinning (chapter-15-lab/skinning_study.cpp), one function
// for the compute pass and the vertex shader, in every form the study compares: linear blend
// skinning (chapter-17's) or dual-quaternion skinning, joints in 32- or 16-bit floats, 4 or 8
// influences a vertex. Every buffer is an array of 32-bit words, read as the form asks.

//> study-forms
layout(constant_id = 0) const int kMethod = 0;  // 0: linear blend skinning, 1: dual quaternions
layout(constant_id = 1) const bool kHalfJoints = false;  // the palette in 16-bit floats
layout(constant_id = 2) const int kInfluences = 4;       // 4 or 8 joints a vertex
//< study-forms

// Per vertex: position and normal (6 floats).
layout(set = 0, binding = 0, std430) readonly buffer Rest { float rest[]; };
// Per vertex: kInfluences joints in 16 bits each (two to a word), then kInfluences weights.
layout(set = 0, binding = 1, std430) readonly buffer Influences { uint influences[]; };
// Per joint, linear blend: the 3x4 matrix (columns) and the 3x3 normal matrix, 21 floats in 24
// words (fp32) or 21 halves in 12 words (fp16); dual quaternions: real, then dual (8 floats).
layout(set = 0, binding = 2, std430) readonly buffer Palette { uint palette[]; };

float word(uint i) {
    return uintBitsToFloat(palette[i]);
}
// The palette's value k of joint j (linear blend), from either precision.
float paletteValue(uint j, uint k) {
    if (kHalfJoints) {
        vec2 pair = unpackHalf2x16(palette[j * 12u + k / 2u]);
        return (k & 1u) == 0u ? pair.x : pair.y;
    }
    return word(j * 24u + k);
}

vec3 rotateByQuaternion(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

//> study-skin
void skinVertex(uint vertex, out vec3 position, out vec3 normal) {
    vec3 p = vec3(rest[vertex * 6u], rest[vertex * 6u + 1u], rest[vertex * 6u + 2u]);
    vec3 n = vec3(rest[vertex * 6u + 3u], rest[vertex * 6u + 4u], rest[vertex * 6u + 5u]);
    uint base = vertex * uint(kInfluences + kInfluences / 2);
    position = vec3(0.0);
    normal = vec3(0.0);
    vec4 real = vec4(0.0), dual = vec4(0.0), first = vec4(0.0);
    for (int k = 0; k < kInfluences; ++k) {
        uint joint = (influences[base + uint(k) / 2u] >> (16u * (uint(k) & 1u))) & 0xffffu;
        float weight = uintBitsToFloat(influences[base + uint(kInfluences / 2 + k)]);
        if (kMethod == 0) {
            mat4x3 m;
            for (uint c = 0u; c < 4u; ++c)
                m[c] = vec3(paletteValue(joint, 3u * c), paletteValue(joint, 3u * c + 1u),
                            paletteValue(joint, 3u * c + 2u));
            mat3 nm;
            for (uint c = 0u; c < 3u; ++c)
                nm[c] = vec3(paletteValue(joint, 12u + 3u * c), paletteValue(joint, 13u + 3u * c),
                             paletteValue(joint, 14u + 3u * c));
            position += weight * (m * vec4(p, 1.0));
            normal += weight * (nm * n);
        } else {
            uint w = joint * 8u;
            vec4 r = vec4(word(w), word(w + 1u), word(w + 2u), word(w + 3u));
            vec4 d = vec4(word(w + 4u), word(w + 5u), word(w + 6u), word(w + 7u));
            if (k == 0) first = r;
            float s = dot(first, r) < 0.0 ? -weight : weight;  // the same hemisphere as the first
            real += s * r;
            dual += s * d;
        }
    }
    if (kMethod == 1) {
        float len = length(real);
        real /= len;
        dual /= len;
        // translation = 2 dual * conjugate(real)
        vec3 t = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
        position = rotateByQuaternion(real, p) + t;
        normal = rotateByQuaternion(real, n);
    }
}
//< study-skin
