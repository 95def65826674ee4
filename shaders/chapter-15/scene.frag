#version 450
// chapter-15 scene pass: writes the book's G-buffer -- world position, albedo, normal (normal
// map applied) and PBR data (AO, roughness, metallic) -- one colour attachment each.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.glsl"
#include "pbr.glsl"
#include "scene_surface.glsl"  // the inputs, the material and its textures: sceneSurface()

//> scene-frag
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outPbr;

void main() {
    SceneSurface surface = sceneSurface();  // scene_surface.glsl: discards cut-out texels
    outPosition = vec4(inWorldPosition, 1.0);
    outNormal = vec4(surface.normal, 1.0);
    outAlbedo = vec4(surface.albedo, 1.0);  // alpha 1 marks "a surface is here" (cleared to 0)
    // The book writes a fixed AO of 0.5 here and never reads it; ours comes from the material's
    // occlusion map (1 without one) and darkens the ambient light only (shade_pixel.glsl).
    outPbr = vec4(surface.ao, surface.roughness, surface.metallic, 1.0);
}
//< scene-frag
