#version 450
// chapter-10 lighting pass: no lighting yet (it arrives in chapter-15). The final image is the
// albedo, as in the book; --view depth shows the depth attachment instead.
#extension GL_GOOGLE_include_directive : require
#include "depth_view.glsl"

//> lighting-frag
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
    if (show.view == 2) {
        outColor = vec4(vec3(depthToGrey(texture(depthAttachment, inUv).r, show.near, show.far)), 1.0);
    } else {
        outColor = vec4(texture(albedoAttachment, inUv).rgb, 1.0);
    }
}
//< lighting-frag
