#version 450
// chapter-10 lighting pass: no lighting yet (it arrives in chapter-15). The final image is the
// albedo, as in the book; --view depth shows the depth attachment instead.
#extension GL_GOOGLE_include_directive : require
#include "depth_view.glsl"
#include "srgb.glsl"

//> lighting-frag
// True when the target image's format does not sRGB-encode what we write (a _UNORM format).
layout(constant_id = 0) const bool ENCODE_SRGB = false;

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

layout(set = 0, binding = 0) uniform sampler2D albedoAttachment;
layout(set = 0, binding = 1) uniform sampler2D depthAttachment;

layout(push_constant) uniform LightingView {
    int view;  // 0 final, 1 albedo, 2 depth (the order of kChapter.views in main.cpp)
    float near;
    float far;
} show;

void main() {
    vec3 color;
    if (show.view == 2) {
        color = vec3(depthToGrey(texture(depthAttachment, inUv).r, show.near, show.far));
    } else {
        color = texture(albedoAttachment, inUv).rgb;
    }
    outColor = vec4(ENCODE_SRGB ? encodeSrgb(color) : color, 1.0);
}
//< lighting-frag
