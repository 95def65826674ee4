#version 450
// chapter-15-lab, --shading forward: no G-buffer. The scene pass's fragment shader lights its
// surface itself (chapter-15's sceneSurface(), the same shading as its light pass's loop over
// every light) into the light output -- the forward renderer that deferred shading is measured
// against.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "gpu_types.glsl"
#include "pbr.glsl"
#include "../chapter-15/scene_surface.glsl"

//> forward-frag
layout(location = 0) out vec4 outColor;

// The light pass's lights and scene info (light_pass.cpp), as sets 3 and 4 after the scene pass's.
layout(scalar, set = 3, binding = 0) readonly buffer Lights {
    ShaderLight lights[];
};
layout(scalar, set = 4, binding = 0) uniform Scene {
    ShaderSceneInfo scene;
};

void main() {
    SceneSurface surface = sceneSurface();
    // Camera-relative, as the light pass shades (chapter-15/light_inputs.glsl).
    vec3 position = inWorldPosition - scene.cameraPosition;
    vec3 N = surfaceNormal(surface.normal);
    vec3 V = viewDirection(position, vec3(0.0), N);
    vec3 color = scene.ambientColor * scene.ambientIntensity * surface.albedo * surface.ao;
    for (uint i = 0u; i < scene.lightCount; ++i) {  // every light, for every fragment that is shaded
        ShaderLight light = lights[i];
        bool directional = light.directional != 0u;
        vec3 lightPosition = directional ? light.position : light.position - scene.cameraPosition;
        color += evaluateLightInRange(directional, lightPosition, light.color, light.intensity, light.range, position,
                                      N, V, surface.albedo, surface.metallic, surface.roughness);
    }
    outColor = vec4(color, 1.0);
}
//< forward-frag
