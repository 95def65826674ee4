// chapter-15 light pass: the shading of one G-buffer pixel by the scene's lights, put together
// from its parts -- the lights, scene info and push constants (light_inputs.glsl), the G-buffer
// (gbuffer_read.glsl), the loop over the lights (below) and the pixel's colour (shade_pixel.glsl).
// light.frag runs it for each pixel of a full-screen triangle.
#include "light_inputs.glsl"
#include "gbuffer_read.glsl"

//> light-loop
// Every pixel is shaded by every light: a frame costs pixels x lights.
vec3 shadeLights(ivec2 pixel, SurfaceSample s, vec3 N, vec3 V) {
    vec3 color = vec3(0.0);
    for (uint i = 0u; i < scene.lightCount; ++i) color += shadeLight(i, s, N, V);
    return color;
}
//< light-loop

#include "shade_pixel.glsl"
