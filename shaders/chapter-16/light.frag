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

const vec3 kCascadeColors[4] = vec3[](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.25, 0.25, 1.0),
                                      vec3(1.0, 1.0, 0.25));

void main() {
    SurfaceSample s = readGBuffer(inUv);
    vec3 world = s.position + scene.cameraPosition;
    int cascade = cascadeOf(-(cascades.cameraView * vec4(world, 1.0)).z);
    float visibility = s.surface && cascades.count > 0 ? sunVisibility(world, surfaceNormal(s.normal), cascade) : 1.0;
    if (show.view == 6) {  // --view shadow-map: each cascade's layer side by side, depth as grey
        float x = inUv.x * float(cascades.count);
        int layer = min(int(x), cascades.count - 1);
        outColor = vec4(vec3(shadowMomentsAt(vec2(fract(x), inUv.y), layer).r), 1.0);
        return;
    }
    if (show.view == 8) {  // --view visibility: the sun's visibility alone, white where it reaches
        outColor = vec4(vec3(visibility), 1.0);
        return;
    }
    outColor = shadePixel(s, ivec2(gl_FragCoord.xy), visibility);
    // --view cascades (7): the final image tinted by the cascade each pixel takes its shadow from.
    if (show.view == 7 && s.surface && cascades.count > 0) outColor.rgb *= kCascadeColors[cascade];
}
//< light-frag
