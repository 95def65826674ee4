#version 450
// chapter-15 scene pass: writes the book's G-buffer -- world position, albedo, normal (normal
// map applied) and PBR data (AO, roughness, metallic) -- one colour attachment each. Compiled a
// second time with COMPACT_GBUFFER for --gbuffer compact: no position (the light pass
// reconstructs it from depth), the normal octahedral-encoded in 2 x 16 bits, albedo in 3 x 10
// bits (gamma 2), roughness and metallic in 2 x 16 bits (no AO: occlusion maps are not drawn).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"
#include "octahedral.glsl"
#include "pbr.glsl"
#include "scene_surface.glsl"  // the inputs, the material and its textures: sceneSurface()

//> scene-frag
#ifdef COMPACT_GBUFFER
layout(location = 0) out vec4 outAlbedo;  // A2B10G10R10_UNORM: sqrt(albedo), alpha = coverage
layout(location = 1) out vec2 outNormal;  // R16G16_UNORM, octahedral
layout(location = 2) out vec2 outPbr;     // R16G16_UNORM: roughness, metallic
#else
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outPbr;
#endif

void main() {
    SceneSurface surface = sceneSurface();  // scene_surface.glsl: discards cut-out texels
#ifdef COMPACT_GBUFFER
    outNormal = encodeOctahedral(surface.normal);
    // Gamma 2 puts the 10 bits where the eye needs them (dark values), like sRGB but cheap to undo.
    outAlbedo = vec4(sqrt(surface.albedo), 1.0);  // alpha 1 marks "a surface is here" (cleared to 0)
    outPbr = vec2(surface.roughness, surface.metallic);
#else
    outPosition = vec4(inWorldPosition, 1.0);
    outNormal = vec4(surface.normal, 1.0);
    outAlbedo = vec4(surface.albedo, 1.0);  // alpha 1 marks "a surface is here" (cleared to 0)
    // The book writes a fixed AO of 0.5 here and never reads it; ours comes from the material's
    // occlusion map (1 without one) and darkens the ambient light only (light_shading.glsl).
    outPbr = vec4(surface.ao, surface.roughness, surface.metallic, 1.0);
#endif
}
//< scene-frag
