#version 450
// chapter-14 light and post passes: the full-screen triangle.
#extension GL_GOOGLE_include_directive : require
#include "fullscreen_triangle.glsl"

layout(location = 0) out vec2 outUv;

void main() {
    outUv = fullscreenUv(gl_VertexIndex);
    gl_Position = fullscreenPosition(outUv);
}
