// chapter-16 light pass: the directional light's visibility at a surface point, from the
// cascades' variance shadow map (set 3). Needs light_inputs.glsl first.
#include "cascades.glsl"

//> shadows
layout(set = 3, binding = 0) uniform sampler2DArray shadowMoments;
layout(std140, set = 3, binding = 1) uniform CascadeBlock {
    Cascades cascades;
};
layout(set = 3, binding = 3) uniform sampler2DArray movingMoments;  // the moving casters' map
// Whether the moving casters' map is read at all: false until a caster first moves (chapter-16
// then makes the light pipeline again with it true), so that a still scene pays nothing for it.
layout(constant_id = 5) const bool MOVING_CASTERS = false;

// The moments at `uv` of cascade `cascade`'s box (0..1 across it, clamped to its edge texels).
// The layers are addressed toroidally (chapter-16/shadow_cache.hpp): the box's texel t lies at
// (t + layerOffset) modulo the map. Where the moving casters' map holds casters of this cascade,
// the nearer occluder of the two maps -- what one map with every caster drawn would hold.
vec2 shadowMomentsAt(vec2 uv, int cascade) {
    ivec2 size = textureSize(shadowMoments, 0).xy;
    ivec2 texel = clamp(ivec2(floor(uv * vec2(size))), ivec2(0), size - 1);
    ivec3 place = ivec3((texel + cascades.layerOffset[cascade].xy) & (size - 1), cascade);  // sizes: 2^k
    vec2 moments = texelFetch(shadowMoments, place, 0).rg;
    if (MOVING_CASTERS && (cascades.moving >> cascade & 1u) != 0u) {
        vec2 moving = texelFetch(movingMoments, place, 0).rg;
        if (moving.x < moments.x) moments = moving;
    }
    return moments;
}

// The cascade whose slice holds a point at view distance `distance`: the first that ends beyond it.
int cascadeOf(float distance) {
    int cascade = 0;
    for (int i = 0; i < cascades.count - 1; ++i)
        if (distance > cascades.splitFar[i]) cascade = i + 1;
    return cascade;
}

// Chebyshev's upper bound on the fraction of light reaching depth t past the moments' occluders,
// with the book's variance floor and light-bleeding reduction.
// `varianceFloor`: the book's 0.00002 for a depth range as deep as the cascade's box is wide; our
// depth windows are deeper (computeCascades), so the floor shrinks with the square of the scale
// (cascadeUniform) and the bound stays what the book's would be for the same occluders.
float chebyshevUpperBound(vec2 moments, float t, float varianceFloor) {
    if (t <= moments.x) return 1.0;
    float variance = max(moments.y - moments.x * moments.x, varianceFloor);
    float d = t - moments.x;
    return smoothstep(0.2, 1.0, variance / (variance + d * d));
}

// Where `world` (a surface point whose unit normal is N) falls in cascade `cascade`'s map: xy its
// place across the box (0..1), z its depth. The point is first moved off its surface by one and a
// half texels of its cascade along the normal ("normal offset"): a texel holds one depth for a
// patch of surface as wide as the texel, and the patch's other points lie up to half a texel
// times the slope behind it -- at grazing light, far enough to shadow the surface itself (acne).
// An offset along the normal grows with the texel and needs no per-scene constant; the book has none.
vec3 shadowCoord(vec3 world, vec3 N, int cascade) {
    vec3 offset = world + N * (1.5 * cascades.texelSize[cascade]);
    vec4 clip = cascades.viewProjection[cascade] * vec4(offset, 1.0);
    return vec3(clip.xy * 0.5 + 0.5, clip.z);  // the shadow pass's viewport is not flipped: y down
}

// 1 where the sun reaches `world`, 0 in its shadow.
float sunVisibility(vec3 world, vec3 N, int cascade) {
    vec3 coord = shadowCoord(world, N, cascade);
    return chebyshevUpperBound(shadowMomentsAt(coord.xy, cascade), coord.z, cascades.varianceFloor[cascade]);
}
//< shadows
