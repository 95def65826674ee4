#version 450
// chapter-16 light pass: chapter-15's (light_shading.glsl), with the sun's light darkened where
// the cascades' shadow map says it does not reach -- the sun's only: the point lights cast no
// shadow here, so their light is not darkened (the book multiplies every light's sum by the sun's
// visibility).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "../chapter-15/light_shading.glsl"
#include "shadows.glsl"

//> light-frag
layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outColor;

void main() {
    SurfaceSample s = readGBuffer(inUv);
    vec3 world = s.position + scene.cameraPosition;
    int cascade = cascadeOf(-(cascades.cameraView * vec4(world, 1.0)).z);
    // At most one read of the shadow map per pixel: at the surface point, or with --view
    // shadow-map (6) at the pixel's place in its cascade's layer, the layers side by side (depth
    // as grey). (A second read in a branch of its own costs every pixel on a CPU driver, taken or
    // not.) None where nothing was drawn, nor where the surface faces away from the sun: the sun's
    // light is 0 there whatever its visibility (the visibility view reads it all the same).
    vec3 N = surfaceNormal(s.normal);
    bool showMap = show.view == 6 && cascades.count > 0;
    bool lookUp = showMap || (s.surface && cascades.count > 0 && (dot(N, cascades.toSun.xyz) > 0.0 || show.view == 8));
    float x = inUv.x * float(cascades.count);
    int layer = showMap ? min(int(x), cascades.count - 1) : cascade;
    vec3 coord = showMap ? vec3(fract(x), inUv.y, 0.0) : shadowCoord(world, N, cascade);
    vec2 moments = vec2(1.0);  // nothing nearer the sun than the far side: lit
    if (lookUp) moments = shadowMomentsAt(coord.xy, layer);
    if (showMap) {
        outColor = vec4(vec3(moments.r), 1.0);
        return;
    }
    float visibility = lookUp ? chebyshevUpperBound(moments, coord.z, cascades.varianceFloor[cascade]) : 1.0;
    if (show.view == 8) {  // --view visibility: the sun's visibility alone, white where it reaches
        outColor = vec4(vec3(visibility), 1.0);
        return;
    }
    outColor = shadePixel(s, ivec2(gl_FragCoord.xy), visibility);
    // --view cascades (7): the final image tinted by the cascade each pixel takes its shadow from:
    // red, green, blue, yellow.
    if (show.view == 7 && s.surface && cascades.count > 0)
        outColor.rgb *= vec3(cascade == 0 || cascade == 3 ? 1.0 : 0.25, cascade == 1 || cascade == 3 ? 1.0 : 0.25,
                             cascade == 2 ? 1.0 : 0.25);
}
//< light-frag
