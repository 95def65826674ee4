#version 450
// chapter-15 light pass: Cook-Torrance lighting of every G-buffer pixel by the scene's lights,
// plus ambient light; or, with --view, one attachment.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "depth_view.glsl"
#include "gpu_types.glsl"
#include "pbr.glsl"

//> light-frag
layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

layout(set = 0, binding = 0) uniform sampler2D positionAttachment;
layout(set = 0, binding = 1) uniform sampler2D albedoAttachment;
layout(set = 0, binding = 2) uniform sampler2D normalAttachment;
layout(set = 0, binding = 3) uniform sampler2D pbrAttachment;
layout(set = 0, binding = 4) uniform sampler2D depthAttachment;

layout(scalar, set = 1, binding = 0) readonly buffer Lights {
    Light lights[];
};
layout(scalar, set = 2, binding = 0) uniform Scene {
    SceneInfo scene;
};

layout(push_constant) uniform Show {
    vec4 boundsMin;  // xyz: the scene's bounds, to show positions as colours
    vec4 boundsMax;
    int view;  // 0 final, 1 position, 2 albedo, 3 normal, 4 pbr, 5 depth
    float near;
    float far;
} show;

void main() {
    float depth = texture(depthAttachment, inUv).r;
    vec3 worldPosition = texture(positionAttachment, inUv).xyz;
    vec3 albedo = texture(albedoAttachment, inUv).rgb;
    vec3 normal = texture(normalAttachment, inUv).xyz;
    vec3 pbr = texture(pbrAttachment, inUv).rgb;  // AO, roughness, metallic

    if (show.view == 1) {
        outColor = vec4(clamp((worldPosition - show.boundsMin.xyz) / (show.boundsMax.xyz - show.boundsMin.xyz), 0.0, 1.0), 1.0);
    } else if (show.view == 2) {
        outColor = vec4(albedo, 1.0);
    } else if (show.view == 3) {
        outColor = vec4(depth < 1.0 ? normal * 0.5 + 0.5 : vec3(0.0), 1.0);
    } else if (show.view == 4) {
        outColor = vec4(pbr, 1.0);
    } else if (show.view == 5) {
        outColor = vec4(vec3(depthToGrey(depth, show.near, show.far)), 1.0);
    } else if (depth >= 1.0) {
        outColor = vec4(0.0, 0.0, 0.0, 1.0);  // nothing was drawn here: no surface to light
    } else {
        vec3 N = surfaceNormal(normal);
        vec3 V = viewDirection(worldPosition, scene.cameraPosition, N);
        vec3 color = scene.ambientColor * scene.ambientIntensity * albedo;
        for (uint i = 0u; i < scene.lightCount; ++i) {
            Light light = lights[i];
            color += evaluateLight(light.directional != 0u, light.position, light.color, light.intensity,
                                   worldPosition, N, V, albedo, pbr.b, pbr.g);
        }
        outColor = vec4(color, 1.0);
    }
}
//< light-frag
