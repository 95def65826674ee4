#version 450
// pointer_test (tests/chapters/pointer_test.cpp): chapter-18's DrawBlock and pulledVertex(), read
// from a compute shader, one invocation per index; every field written back as floats.
#extension GL_GOOGLE_include_directive : require
#define PULLED_INDEX gl_GlobalInvocationID.x
#include "../chapter-18/pulled_mesh.glsl"

layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 0) writeonly buffer Results {
    float results[];
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i == 0u) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) results[4 * c + r] = draw.model[c][r];
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) results[16 + 3 * c + r] = draw.normalMatrix[c][r];
    }
    Vertex v = pulledVertex();
    uint base = 25u + 14u * i;
    float fields[14] = float[14](v.position.x, v.position.y, v.position.z, v.normal.x, v.normal.y, v.normal.z,
                                 v.tangent.x, v.tangent.y, v.tangent.z, v.bitangent.x, v.bitangent.y,
                                 v.bitangent.z, v.uv.x, v.uv.y);
    for (uint k = 0u; k < 14u; ++k) results[base + k] = fields[k];
}
