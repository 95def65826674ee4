#version 450
// The full-screen triangle of the light and post passes (chapters 14 and 15).
#extension GL_GOOGLE_include_directive : require
#include "fullscreen_triangle.glsl"

layout(location = 0) out vec2 outUv;

void main() {
    outUv = fullscreenUv(gl_VertexIndex);
    gl_Position = fullscreenPosition(outUv);
}
