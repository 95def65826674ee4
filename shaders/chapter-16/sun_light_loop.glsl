// chapter-16 light pass: shadeLights(), chapter-15's sum over the scene's lights with the sun's
// light -- the first directional light, the one the shadow map is made from -- times its
// visibility at the pixel (gVisibility, set by the caller before shadePixel). The point lights
// cast no shadow here, so their light is not darkened (the book multiplies every light's sum by
// the sun's visibility). Needs light_inputs.glsl first; chapter-15-lab's shadow study uses it too.
#ifndef SUN_LIGHT_LOOP_GLSL
#define SUN_LIGHT_LOOP_GLSL

//> light-loop
// chapter-15's loops over the scene's lights of each kind (the constants set by light_pass.cpp),
// the first directional light -- the one the shadow map is made from -- times its visibility.
layout(constant_id = 3) const int DIRECTIONAL_LIGHTS = -1;
layout(constant_id = 4) const int POINT_LIGHTS = -1;

float gVisibility = 1.0;  // the sun's, at the pixel being shaded (shadePixel's caller sets it)

vec3 shadeLights(ivec2 pixel, SurfaceSample s, vec3 N, vec3 V) {
    vec3 color = vec3(0.0);
    if (DIRECTIONAL_LIGHTS < 0) {
        for (uint i = 0u; i < scene.lightCount; ++i)
            color += (i == 0u && lights[0].directional != 0u ? gVisibility : 1.0) * shadeLight(i, s, N, V);
    } else {
        for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i)
            color += (i == 0 ? gVisibility : 1.0) * shadeLightOfKind(uint(i), true, s, N, V);
        for (int i = 0; i < POINT_LIGHTS; ++i) color += shadeLightOfKind(uint(DIRECTIONAL_LIGHTS + i), false, s, N, V);
    }
    return color;
}
//< light-loop

#endif
