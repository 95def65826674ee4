#version 450
// chapter-16 shadow pass: the scene's positions to world space; the geometry shader takes them to
// each cascade. Texture coordinates for the cut-outs' alpha test, and the cascades the draw goes to
// (its firstInstance, a bit per cascade: shadow_pass.cpp culls each draw per cascade).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"

//> shadow-vert
layout(location = 0) in vec3 inPosition;
layout(location = 4) in vec2 inUv;

layout(location = 0) out vec2 outUv;
layout(location = 1) flat out uint outLayers;

layout(push_constant) uniform DrawBlock {
    DrawConstants draw;  // gpu_types.glsl: the scene pass's (the normal matrix is not read)
};

void main() {
    gl_Position = draw.model * vec4(inPosition, 1.0);
    outUv = inUv;
    outLayers = uint(gl_InstanceIndex);
}
//< shadow-vert
