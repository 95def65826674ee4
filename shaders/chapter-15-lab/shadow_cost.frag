#version 450
// What chapter-16's shadow read costs a pixel, step by step (bench/shadow_read.sh; docs/performance.md,
// "The shadow read, pixel by pixel"): chapter-16's light pass (shaders/chapter-16/light.frag, the
// final image only) with the sun's visibility put together one step more per variant, each
// compiled with SHADOW_COST = the step:
//   0 none:   chapter-15's light pass (the sun fully visible);
//   1 choice: + the pixel's cascade (its view distance against the splits) and whether it faces the sun;
//   2 place:  + where the point falls in its cascade's map (normal offset, the cascade's matrix);
//   3 read:   + the map's texel there, compared with the point's depth (lit or not);
//   4 bound:  + Chebyshev's bound on the moments -- chapter-16's visibility, the same image.
// Steps 1 and 2 keep their result alive with a test no pixel passes (cascade 5, a depth past 3),
// so that the compiler cannot drop them and the image stays chapter-15's.
// The shader has chapter-16's light pass's interface: the bench runs chapter-16 with it in place
// of light.frag.spv.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "../chapter-15/light_shading.glsl"
#include "../chapter-16/shadows.glsl"

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

void main() {
    SurfaceSample s = readGBuffer(inUv);
    float visibility = 1.0;
#if SHADOW_COST >= 1
    vec3 world = s.position + scene.cameraPosition;
    vec3 N = surfaceNormal(s.normal);
    int cascade = cascadeOf(-(cascades.cameraView * vec4(world, 1.0)).z);
    bool lookUp = s.surface && cascades.count > 0 && dot(N, cascades.toSun.xyz) > 0.0;
#if SHADOW_COST == 1
    if (lookUp && cascade == 5) visibility = 0.5;
#else
    vec3 coord = shadowCoord(world, N, cascade);
#if SHADOW_COST == 2
    if (lookUp && coord.z > 3.0) visibility = 0.5;
#else
    vec2 moments = vec2(1.0);
    if (lookUp) moments = shadowMomentsAt(coord.xy, cascade);
#if SHADOW_COST == 3
    visibility = coord.z <= moments.x ? 1.0 : 0.0;
#else
    visibility = lookUp ? chebyshevUpperBound(moments, coord.z, cascades.varianceFloor[cascade]) : 1.0;
#endif
#endif
#endif
#endif
    outColor = shadePixel(s, ivec2(gl_FragCoord.xy), visibility);
}
