#version 450
// chapter-14 light pass: no lighting yet, as in the book: the albedo goes to the light output
// (R32G32B32A32_SFLOAT), or with --view depth the depth attachment as grey.
#extension GL_GOOGLE_include_directive : require
#include "depth_view.glsl"

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

layout(set = 0, binding = 0) uniform sampler2D albedoAttachment;
layout(set = 0, binding = 1) uniform sampler2D depthAttachment;

layout(push_constant) uniform LightView {
    int view;  // 0 final, 1 albedo, 2 depth
    float near;
    float far;
} show;

void main() {
    if (show.view == 2) {
        outColor = vec4(vec3(depthToGrey(texture(depthAttachment, inUv).r, show.near, show.far)), 1.0);
    } else {
        outColor = vec4(texture(albedoAttachment, inUv).rgb, 1.0);
    }
}
