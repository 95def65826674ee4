// chapter-15 light pass: what every pixel's shading reads besides the G-buffer -- the lights (set
// 1) and the scene info (set 2), both scalar layout, and the push constants -- and shadeLight(),
// one light's contribution to one surface point. light_shading.glsl puts the pass together.
//
// Shading happens in coordinates relative to the camera: position - camera and light - camera
// are small numbers where it matters (near the camera), however far the scene is from the world
// origin. Subtracting two nearby fp32 values is exact, so nothing is lost on the way.
#include "depth_view.glsl"
#include "gpu_types.glsl"
#include "pbr.glsl"

//> light-inputs
layout(scalar, set = 1, binding = 0) readonly buffer Lights {
    ShaderLight lights[];
};
layout(scalar, set = 2, binding = 0) uniform Scene {
    ShaderSceneInfo scene;
};

layout(push_constant) uniform LightViewBlock {
    LightView show;  // gpu_types.glsl
};

// What the G-buffer holds at one pixel, decoded (gbuffer_read.glsl's readGBuffer()).
struct SurfaceSample {
    bool surface;   // written 1 where a surface was drawn, cleared to 0
    vec3 position;  // relative to the camera
    vec3 albedo;
    vec3 normal;    // as stored
    vec3 pbr;       // AO, roughness, metallic
    float depth;
};

// Light i's contribution to a surface point (camera-relative position, unit N and V), the light
// known to be `directional` or not (a constant where the pipeline knows it: the other kind's
// code goes).
vec3 shadeLightOfKind(uint i, bool directional, SurfaceSample s, vec3 N, vec3 V) {
    ShaderLight light = lights[i];
    vec3 lightPosition = directional ? light.position : light.position - scene.cameraPosition;
    return evaluateLightInRange(directional, lightPosition, light.color, light.intensity, light.range, s.position, N,
                                V, s.albedo, s.pbr.b, s.pbr.g);
}

// Light i's contribution, its kind read from the light.
vec3 shadeLight(uint i, SurfaceSample s, vec3 N, vec3 V) {
    return shadeLightOfKind(i, lights[i].directional != 0u, s, N, V);
}
//< light-inputs
