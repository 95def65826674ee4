#version 450
// chapter-15-lab shadow study: the scene's positions straight into one cascade's clip space,
// without chapter-16's geometry shader -- the cascade from gl_ViewIndex (MULTIVIEW: one pass,
// each cascade a view of VK_KHR_multiview) or from gl_InstanceIndex (one pass per cascade, each
// drawn with its cascade as firstInstance).
#extension GL_GOOGLE_include_directive : require
#ifdef MULTIVIEW
#extension GL_EXT_multiview : require
#endif
#include "gpu_types.glsl"
#include "../chapter-16/cascades.glsl"

//> shadow-cascade-vert
layout(location = 0) in vec3 inPosition;
layout(location = 4) in vec2 inUv;

layout(location = 0) out vec2 outUv;

layout(std140, set = 0, binding = 0) uniform CascadeBlock {
    Cascades cascades;
};

layout(push_constant) uniform DrawBlock {
    DrawConstants draw;  // the scene pass's (the normal matrix is not read)
};

void main() {
#ifdef MULTIVIEW
    uint index = gl_ViewIndex;
#else
    uint index = uint(gl_InstanceIndex);
#endif
    gl_Position = cascades.viewProjection[index] * (draw.model * vec4(inPosition, 1.0));
    outUv = inUv;
}
//< shadow-cascade-vert
