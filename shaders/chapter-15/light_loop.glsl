// chapter-15 light pass: shadeLights(), the sum of every light's contribution to one surface
// point, specialised to the scene's lights. Needs light_inputs.glsl first.
//
// `sunLight` darkens the sun -- the first directional light, the one chapter-16 makes its
// shadow map from -- and no other light: chapter-15 has no shadows and passes 1.0 (exact: the
// image is the same to the bit), chapter-16 the cascades' answer at the pixel.

//> light-loop
// Every pixel is shaded by every light: a frame costs pixels x lights. The scene's lights by
// kind are fixed when the pipeline is made (light_pass.cpp; the lights buffer holds the
// directional ones first): constant trip counts, so the loops unroll, and a kind the scene lacks
// costs nothing. -1, the default (--pipelines generic): one loop over scene.lightCount that
// asks each light its kind.
layout(constant_id = 3) const int DIRECTIONAL_LIGHTS = -1;
layout(constant_id = 4) const int POINT_LIGHTS = -1;

vec3 shadeLights(ivec2 pixel, SurfaceSample s, vec3 N, vec3 V, float sunLight) {
    vec3 color = vec3(0.0);
    if (DIRECTIONAL_LIGHTS < 0) {
        for (uint i = 0u; i < scene.lightCount; ++i)
            color += (i == 0u && lights[0].directional != 0u ? sunLight : 1.0) * shadeLight(i, s, N, V);
    } else {
        for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i)
            color += (i == 0 ? sunLight : 1.0) * shadeLightOfKind(uint(i), true, s, N, V);
        for (int i = 0; i < POINT_LIGHTS; ++i)
            color += shadeLightOfKind(uint(DIRECTIONAL_LIGHTS + i), false, s, N, V);
    }
    return color;
}
//< light-loop
