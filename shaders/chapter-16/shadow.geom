#version 450
// chapter-16 shadow pass: each triangle once into every cascade's layer of the shadow map.
#extension GL_GOOGLE_include_directive : require
#include "cascades.glsl"

//> shadow-geom
// `invocations` must be a literal: the book's is its cascade count, 3, so changing the count means
// editing the shader. Ours is the most cascades the chapter allows, and the invocations past the
// count the scene uses emit nothing: one shader for any count.
layout(triangles, invocations = MAX_CASCADES) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec2 inUv[];
layout(location = 1) flat in uint inLayers[];  // the cascades this draw goes to (a bit each)
layout(location = 0) out vec2 outUv;

layout(std140, set = 0, binding = 0) uniform CascadeBlock {
    Cascades cascades;  // cascades.glsl
};

void main() {
    // Past the scene's cascades, or a cascade the draw does not go to (its layer holds what it
    // sees, or the draw's bounds miss the cascade's box): nothing.
    if (gl_InvocationID >= cascades.count || (inLayers[0] >> gl_InvocationID & 1u) == 0u) return;
    for (int i = 0; i < 3; ++i) {
        outUv = inUv[i];
        gl_Layer = gl_InvocationID;
        gl_Position = cascades.viewProjection[gl_InvocationID] * gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
//< shadow-geom
