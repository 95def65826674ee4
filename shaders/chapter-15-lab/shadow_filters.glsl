// chapter-15-lab shadow study: the sun's visibility at a surface point, from chapter-16's cascades
// (shaders/chapter-16/shadows.glsl: the cascade by view distance, the normal offset, the book's
// variance map), or by depth comparison with percentage-closer filtering over the same cascades.
// Set 3: chapter-16's moments and cascades, and the depth of the map behind a comparison sampler.
#include "../chapter-16/shadows.glsl"

//> shadow-filters
// 0: the book's variance map (chapter-16's). 1, 2, 3: depth comparison, with PCF over 2x2, 3x3 or
// 5x5 texels -- one, four or sixteen bilinear comparison taps a texel apart, averaged. A tap
// compares the point's depth with the 2x2 texels around it and weighs the four results by where
// the point lies between their centres: the sampler does it (LINEAR with compareEnable) where the
// device filters its depth format linearly; elsewhere (PCF_GATHER: Mesa lavapipe) a gather of the
// four comparisons, weighed here -- the same filter, up to the precision of the hardware's weights.
// 4: the depth alone at one texel (binding 0 holds the depth image there, read as chapter-16 reads
// its moments), lit where the point is no deeper: chapter-16's read without the bound. (The light
// pass's shader is compiled once per filter: SHADOW_VSM, SHADOW_PCF2 ..., SHADOW_DEPTH; the half-
// float moments, vsm16, read as SHADOW_VSM.)
#if defined(SHADOW_PCF2)
const int SHADOW_FILTER = 1;
#elif defined(SHADOW_PCF3)
const int SHADOW_FILTER = 2;
#elif defined(SHADOW_PCF5)
const int SHADOW_FILTER = 3;
#elif defined(SHADOW_DEPTH)
const int SHADOW_FILTER = 4;
#else
const int SHADOW_FILTER = 0;
#endif

layout(set = 3, binding = 2) uniform sampler2DArrayShadow shadowDepth;

float bilinearComparison(vec2 uv, int cascade, float depth) {
#ifdef PCF_GATHER
    vec2 texels = uv * vec2(textureSize(shadowDepth, 0).xy) - 0.5;
    vec2 f = fract(texels);
    // The four comparisons: (0,1), (1,1), (1,0), (0,0) from the texel at floor(texels).
    vec4 lit = textureGather(shadowDepth, vec3(uv, float(cascade)), depth);
    return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
#else
    return texture(shadowDepth, vec4(uv, float(cascade), depth));  // 1 where depth <= the map's
#endif
}

float pcfVisibility(vec3 world, vec3 N, int cascade, int texels) {
    // The normal offset grows with the kernel: a tap r texels away on a surface sloped toward the
    // light reads a depth up to r texels of slope nearer the light.
    float offset = 1.5 + 0.5 * float(texels - 2);
    vec4 clip = cascades.viewProjection[cascade] * vec4(world + N * (offset * cascades.texelSize[cascade]), 1.0);
    vec2 uv = clip.xy * 0.5 + 0.5;
    vec2 texel = 1.0 / vec2(textureSize(shadowDepth, 0).xy);
    int taps = texels - 1;  // per side
    float first = -0.5 * float(taps - 1);
    float sum = 0.0;
    for (int y = 0; y < taps; ++y)
        for (int x = 0; x < taps; ++x) {
            vec2 at = uv + (vec2(first) + vec2(x, y)) * texel;
            sum += bilinearComparison(at, cascade, clip.z);
        }
    return sum / float(taps * taps);
}

float labSunVisibility(vec3 world, vec3 N, int cascade) {
    if (SHADOW_FILTER == 0) return sunVisibility(world, N, cascade);
    if (SHADOW_FILTER == 4) {
        vec3 coord = shadowCoord(world, N, cascade);
        return coord.z <= shadowMomentsAt(coord.xy, cascade).x ? 1.0 : 0.0;
    }
    return pcfVisibility(world, N, cascade, SHADOW_FILTER == 1 ? 2 : SHADOW_FILTER == 2 ? 3 : 5);
}
//< shadow-filters
