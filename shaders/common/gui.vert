#version 450
// The GUI pass (common/passes/gui_pass.cpp): Dear ImGui's vertices -- a 2D
// position in window points, a font-atlas coordinate and an 8-bit colour -- to clip space with the
// scale and translation in the push constants.
#extension GL_GOOGLE_include_directive : require
#include "srgb.glsl"

//> gui-vert
// True only where the presented image has no _UNORM view and the hardware sRGB-encodes what we
// write: ImGui's colours are decoded first (common/passes/gui_pass.cpp says why this is the exception).
layout(constant_id = 0) const bool DECODE_SRGB = false;

layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;  // R8G8B8A8_UNORM: sRGB-encoded, as ImGui's styles are written

layout(push_constant) uniform GuiTransform {
    vec2 scale;      // 2 / display size (in window points)
    vec2 translate;  // -1 - display position x scale
} transform;

layout(location = 0) out vec2 outUv;
layout(location = 1) out vec4 outColor;

void main() {
    outUv = inUv;
    outColor = vec4(DECODE_SRGB ? decodeSrgb(inColor.rgb) : inColor.rgb, inColor.a);
    gl_Position = vec4(inPosition * transform.scale + transform.translate, 0.0, 1.0);
}
//< gui-vert
