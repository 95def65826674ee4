#version 450
// chapter-15-lab scene pass for --gbuffer compact: chapter-15's surface (scene_surface.glsl)
// into 16 bytes per pixel. No position (the light pass reconstructs it from depth), the normal
// octahedral-encoded in 2 x 16 bits, albedo in 3 x 10 bits (gamma 2), roughness and metallic in
// 2 x 16 bits (no AO: occlusion maps are not drawn).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"
#include "octahedral.glsl"
#include "pbr.glsl"
#include "../chapter-15/scene_surface.glsl"

//> scene-compact
layout(location = 0) out vec4 outAlbedo;  // A2B10G10R10_UNORM: sqrt(albedo), alpha = coverage
layout(location = 1) out vec2 outNormal;  // R16G16_UNORM, octahedral
layout(location = 2) out vec2 outPbr;     // R16G16_UNORM: roughness, metallic

void main() {
    SceneSurface surface = sceneSurface();  // discards cut-out texels
    outNormal = encodeOctahedral(surface.normal);
    // Gamma 2 puts the 10 bits where the eye needs them (dark values), like sRGB but cheap to undo.
    outAlbedo = vec4(sqrt(surface.albedo), 1.0);  // alpha 1 marks "a surface is here" (cleared to 0)
    outPbr = vec2(surface.roughness, surface.metallic);
}
//< scene-compact
