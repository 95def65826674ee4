// chapter-15-lab light pass: chapter-15's shading of one G-buffer pixel (light_inputs.glsl,
// shade_pixel.glsl), with the G-buffer read for the layout and the loop over the lights for the
// culling the lab runs. Shared by its two forms, light.frag (chapter-15's full-screen triangle)
// and light.comp (a compute dispatch), and by the tile-bounds pass of --light-culling tiled.
//   COMPACT_GBUFFER (--gbuffer compact): no position -- it is reconstructed from the (reversed-Z)
//     depth; albedo as sqrt(albedo) in 10 bits, the normal octahedral, roughness and metallic in 16;
//   TILED_LIGHTS (--light-culling tiled): the lights from the pixel's tile list (light_tiles.glsl);
//   SUN_SHADOWS (--shadows): the sun's light darkened by chapter-16's cascade shadows, filtered as
//     the study asks (shadow_filters.glsl).
#include "../chapter-15/light_inputs.glsl"

//> compact-read
#ifdef COMPACT_GBUFFER
#include "octahedral.glsl"
layout(set = 0, binding = 0) uniform sampler2D albedoAttachment;  // sqrt(albedo), coverage
layout(set = 0, binding = 1) uniform sampler2D normalAttachment;  // octahedral
layout(set = 0, binding = 2) uniform sampler2D pbrAttachment;     // roughness, metallic
layout(set = 0, binding = 3) uniform sampler2D depthAttachment;   // reversed-Z

SurfaceSample readGBuffer(vec2 uv) {
    SurfaceSample s;
    s.depth = textureLod(depthAttachment, uv, 0.0).r;
    vec4 albedoCoverage = textureLod(albedoAttachment, uv, 0.0);
    s.surface = albedoCoverage.a > 0.5;
    s.albedo = albedoCoverage.rgb * albedoCoverage.rgb;  // stored as sqrt(albedo)
    s.pbr = vec3(1.0, textureLod(pbrAttachment, uv, 0.0).rg);  // AO (not stored: none), roughness, metallic
    s.normal = decodeOctahedral(textureLod(normalAttachment, uv, 0.0).xy);
    // The pixel's clip-space point (y up under our flipped viewport) back to camera-relative space.
    vec4 clip = vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, s.depth, 1.0);
    vec4 relative = show.clipToCameraRelative * clip;
    s.position = relative.xyz / relative.w;
    return s;
}
#else
#include "../chapter-15/gbuffer_read.glsl"  // the book's layout, and --gbuffer reference
#endif
//< compact-read

#if defined(SUN_SHADOWS)
// --shadows (the shadow study): chapter-16's loop, the sun's light times its visibility.
#include "shadow_filters.glsl"
#include "../chapter-15/light_loop.glsl"  // the sun times its visibility
#elif defined(TILED_LIGHTS)
#include "light_tiles.glsl"
#else
#include "../chapter-15/light_loop.glsl"  // chapter-15's: every light
#endif

#include "../chapter-15/shade_pixel.glsl"
