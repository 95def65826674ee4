// chapter-16 light pass: the directional light's visibility at a surface point, from the
// cascades' variance shadow map (set 3). Needs light_inputs.glsl first.
#include "cascades.glsl"

//> shadows
layout(set = 3, binding = 0) uniform sampler2DArray shadowMoments;
layout(std140, set = 3, binding = 1) uniform CascadeBlock {
    Cascades cascades;
};

// The cascade whose slice holds a point at view distance `distance`: the first that ends beyond it.
int cascadeOf(float distance) {
    int cascade = 0;
    for (int i = 0; i < cascades.count - 1; ++i)
        if (distance > cascades.splitFar[i]) cascade = i + 1;
    return cascade;
}

// Chebyshev's upper bound on the fraction of light reaching depth t past the moments' occluders,
// with the book's variance floor and light-bleeding reduction.
float chebyshevUpperBound(vec2 moments, float t) {
    if (t <= moments.x) return 1.0;
    float variance = max(moments.y - moments.x * moments.x, 0.00002);
    float d = t - moments.x;
    return smoothstep(0.2, 1.0, variance / (variance + d * d));
}

// 1 where the sun reaches `world` (a surface point whose unit normal is N), 0 in its shadow. The
// point is first moved off its surface by one and a half texels of its cascade along the normal
// ("normal offset"): a texel holds one depth for a patch of surface as wide as the texel, and the
// patch's other points lie up to half a texel times the slope behind it -- at grazing light, far
// enough to shadow the surface itself (acne). An offset along the normal grows with the texel and
// needs no per-scene constant; the book has none.
float sunVisibility(vec3 world, vec3 N, int cascade) {
    vec3 offset = world + N * (1.5 * cascades.texelSize[cascade]);
    vec4 clip = cascades.viewProjection[cascade] * vec4(offset, 1.0);
    vec2 uv = clip.xy * 0.5 + 0.5;  // the shadow pass's viewport is not flipped: y down
    vec2 moments = textureLod(shadowMoments, vec3(uv, float(cascade)), 0.0).rg;
    return chebyshevUpperBound(moments, clip.z);
}
//< shadows
