#version 450
// The GUI pass (chapter-14/gui_pass.cpp, common/gui_pass.cpp): Dear ImGui's vertices -- a 2D
// position in pixels, a font-atlas coordinate and an 8-bit colour -- to clip space with the
// scale and translation in the push constants.
//> gui-vert
layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;  // R8G8B8A8_UNORM: sRGB-encoded, as ImGui's styles are written

layout(push_constant) uniform GuiTransform {
    vec2 scale;      // 2 / display size
    vec2 translate;  // -1 - display position x scale
} transform;

layout(location = 0) out vec2 outUv;
layout(location = 1) out vec4 outColor;

// The presented image is _SRGB, which encodes what we write: decode ImGui's colours first.
vec3 srgbToLinear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
    outUv = inUv;
    outColor = vec4(srgbToLinear(inColor.rgb), inColor.a);
    gl_Position = vec4(inPosition * transform.scale + transform.translate, 0.0, 1.0);
}
//< gui-vert
